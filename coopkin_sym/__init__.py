"""coopkin_sym: exact mobility and kinematic analysis of cooperating robot systems.

Given arms (revolute and prismatic joints), one object and the contacts between them
(hard finger, soft finger, complete constraint, frictionless), it computes exactly
the mobility ``Nm``, connectivity ``Nc``, indeterminacy ``Ni`` and redundancy ``Nr``
of the system (Bicchi, Melchiorri and Balluchi, ICRA 1992), the subspaces behind
them and the joint-to-object velocity maps, over the rationals or over fields of
rational functions of the joint variables and link lengths.

Example
-------
>>> import coopkin_sym
>>> a = coopkin_sym.load("paper-case1-hard").analyze()
>>> a.numbers.Nm, a.numbers.Ni
(2, 1)
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from coopkin_sym.analysis.renderers import load_before_render
from coopkin_sym.errors import (
    ArgumentError,
    BlockTooLarge,
    ConfigurationError,
    CoopkinError,
    DrawError,
    FiniteMobilityError,
    InfeasibleMotion,
    LocusError,
    ManipulabilityError,
    ModelError,
    OutputSkipped,
    ReportError,
    SkippedForTime,
    SweepError,
    TimeLimitReached,
)

if TYPE_CHECKING:  # pragma: no cover
    from coopkin_sym.analysis.batch import BatchResult
    from coopkin_sym.analysis.irrational import IrrationalAnalysis
    from coopkin_sym.analysis.locus.certify import Certificate
    from coopkin_sym.analysis.locus.families import Family
    from coopkin_sym.analysis.locus.types import Component, Locus, ended_at_bound
    from coopkin_sym.analysis.locus.verify import Verification
    from coopkin_sym.analysis.manipulability import Manipulability
    from coopkin_sym.analysis.mobility import Analysis, Motion
    from coopkin_sym.analysis.numbers import NUMBER_NAMES, Numbers
    from coopkin_sym.analysis.passive import PASSIVE_NUMBER_NAMES, PassiveNumbers
    from coopkin_sym.analysis.sweep import SweepResult, grid, sweep
    from coopkin_sym.analysis.views import contact_points, same_span
    from coopkin_sym.exact.bounded import checkpoint as keep_result
    from coopkin_sym.exact.bounded import deliver as deliver_part
    from coopkin_sym.exact.bounded import report as report_step
    from coopkin_sym.model.configuration import Configuration
    from coopkin_sym.model.examples import describe_example, example_path
    from coopkin_sym.model.examples import list_examples as examples
    from coopkin_sym.model.model import Model
    from coopkin_sym.present.blocks import named_latex
    from coopkin_sym.present.certificate import completeness_text
    from coopkin_sym.present.draw import draw_system as draw
    from coopkin_sym.present.draw import save_picture
    from coopkin_sym.present.files import check_output_path, write_files
    from coopkin_sym.present.finite import finite_latex, finite_lines
    from coopkin_sym.present.manipulability import manipulability_json, manipulability_text
    from coopkin_sym.present.remarks import grouped_remark_texts, remark_text, remark_texts
    from coopkin_sym.present.report import check_target as check_report_target
    from coopkin_sym.present.report import parse_pairs, write_report
    from coopkin_sym.present.sentences import (
        component_sentences,
        irrational_sentences,
        sentences,
    )
    from coopkin_sym.present.text import (
        analysis_json,
        analysis_latex,
        analysis_parts,
        analysis_text,
        irrational_latex,
        irrational_text,
    )
    from coopkin_sym.present.verification import summary_lines as verification_lines
    from coopkin_sym.present.verification import verification_json
    from coopkin_sym.system import (
        System,
        analyze_many,
        load,
        read_locus,
        run_bounded,
    )

#: Where each public name lives; its module is imported on first access (PEP 562), so
#: that ``import coopkin_sym`` and the ``coopkin`` command start quickly.
_LAZY = {
    "Analysis": "coopkin_sym.analysis.mobility",
    "BatchResult": "coopkin_sym.analysis.batch",
    "Certificate": "coopkin_sym.analysis.locus.certify",
    "Component": "coopkin_sym.analysis.locus.types",
    "Configuration": "coopkin_sym.model.configuration",
    "Family": "coopkin_sym.analysis.locus.families",
    "IrrationalAnalysis": "coopkin_sym.analysis.irrational",
    "Locus": "coopkin_sym.analysis.locus.types",
    "Manipulability": "coopkin_sym.analysis.manipulability",
    "Model": "coopkin_sym.model.model",
    "Motion": "coopkin_sym.analysis.mobility",
    "NUMBER_NAMES": "coopkin_sym.analysis.numbers",
    "Numbers": "coopkin_sym.analysis.numbers",
    "PASSIVE_NUMBER_NAMES": "coopkin_sym.analysis.passive",
    "PassiveNumbers": "coopkin_sym.analysis.passive",
    "SweepResult": "coopkin_sym.analysis.sweep",
    "System": "coopkin_sym.system",
    "Verification": "coopkin_sym.analysis.locus.verify",
    "analysis_json": "coopkin_sym.present.text",
    "analysis_latex": "coopkin_sym.present.text",
    "analysis_parts": "coopkin_sym.present.text",
    "analysis_text": "coopkin_sym.present.text",
    "analyze_many": "coopkin_sym.system",
    "check_output_path": "coopkin_sym.present.files",
    "check_report_target": "coopkin_sym.present.report",
    "completeness_text": "coopkin_sym.present.certificate",
    "component_sentences": "coopkin_sym.present.sentences",
    "contact_points": "coopkin_sym.analysis.views",
    "deliver_part": "coopkin_sym.exact.bounded",
    "keep_result": "coopkin_sym.exact.bounded",
    "describe_example": "coopkin_sym.model.examples",
    "draw": "coopkin_sym.present.draw",
    "ended_at_bound": "coopkin_sym.analysis.locus.types",
    "example_path": "coopkin_sym.model.examples",
    "examples": "coopkin_sym.model.examples",
    "finite_latex": "coopkin_sym.present.finite",
    "finite_lines": "coopkin_sym.present.finite",
    "grid": "coopkin_sym.analysis.sweep",
    "irrational_latex": "coopkin_sym.present.text",
    "irrational_sentences": "coopkin_sym.present.sentences",
    "irrational_text": "coopkin_sym.present.text",
    "load": "coopkin_sym.system",
    "manipulability_json": "coopkin_sym.present.manipulability",
    "manipulability_text": "coopkin_sym.present.manipulability",
    "named_latex": "coopkin_sym.present.blocks",
    "parse_pairs": "coopkin_sym.present.report",
    "read_locus": "coopkin_sym.system",
    "grouped_remark_texts": "coopkin_sym.present.remarks",
    "remark_text": "coopkin_sym.present.remarks",
    "remark_texts": "coopkin_sym.present.remarks",
    "report_step": "coopkin_sym.exact.bounded",
    "run_bounded": "coopkin_sym.system",
    "same_span": "coopkin_sym.analysis.views",
    "save_picture": "coopkin_sym.present.draw",
    "sentences": "coopkin_sym.present.sentences",
    "sweep": "coopkin_sym.analysis.sweep",
    "verification_json": "coopkin_sym.present.verification",
    "verification_lines": "coopkin_sym.present.verification",
    "write_files": "coopkin_sym.present.files",
    "write_report": "coopkin_sym.present.report",
}

#: Public names that are another name in their module.
_RENAMED = {"check_report_target": "check_target", "deliver_part": "deliver",
            "keep_result": "checkpoint",
            "draw": "draw_system", "examples": "list_examples",
            "report_step": "report", "verification_lines": "summary_lines"}


#: The subpackages, also imported on first access (``coopkin_sym.model.examples``).
_SUBPACKAGES = ("analysis", "exact", "model", "present", "system")


def version() -> str:
    """The version of the installed package, from its metadata.

    Returns
    -------
    str
        The version string of the distribution ``coopkin_sym`` (as ``pyproject.toml``
        states it), or ``"unknown"`` when the package runs from a source tree that is
        not installed.

    Example
    -------
    >>> import coopkin_sym
    >>> coopkin_sym.version() == coopkin_sym.__version__
    True
    """
    from importlib.metadata import PackageNotFoundError
    from importlib.metadata import version as distribution_version

    try:
        return distribution_version("coopkin_sym")
    except PackageNotFoundError:  # pragma: no cover - a source tree not installed
        return "unknown"


def __getattr__(name: str) -> Any:
    if name == "__version__":      # read from the metadata on first use
        value = globals()["__version__"] = version()
        return value
    if name in _SUBPACKAGES:
        return importlib.import_module(f"coopkin_sym.{name}")
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'coopkin_sym' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), _RENAMED.get(name, name))
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


def _install_display() -> None:
    """The renderers and actions of the presentation layer, installed on first use."""
    from coopkin_sym.present import actions, display  # noqa: F401  (they register)


load_before_render(_install_display)

__all__ = [
    "Analysis",
    "ArgumentError",
    "BatchResult",
    "BlockTooLarge",
    "Certificate",
    "Component",
    "Configuration",
    "ConfigurationError",
    "CoopkinError",
    "DrawError",
    "Family",
    "FiniteMobilityError",
    "InfeasibleMotion",
    "IrrationalAnalysis",
    "Locus",
    "LocusError",
    "Manipulability",
    "ManipulabilityError",
    "Model",
    "ModelError",
    "Motion",
    "NUMBER_NAMES",
    "Numbers",
    "OutputSkipped",
    "PASSIVE_NUMBER_NAMES",
    "PassiveNumbers",
    "ReportError",
    "SkippedForTime",
    "SweepError",
    "SweepResult",
    "TimeLimitReached",
    "System",
    "Verification",
    "analysis_json",
    "analysis_latex",
    "analysis_parts",
    "analysis_text",
    "analyze_many",
    "check_output_path",
    "check_report_target",
    "completeness_text",
    "component_sentences",
    "contact_points",
    "deliver_part",
    "describe_example",
    "draw",
    "ended_at_bound",
    "example_path",
    "examples",
    "finite_latex",
    "finite_lines",
    "grid",
    "irrational_latex",
    "irrational_sentences",
    "irrational_text",
    "keep_result",
    "load",
    "manipulability_json",
    "manipulability_text",
    "named_latex",
    "parse_pairs",
    "read_locus",
    "grouped_remark_texts",
    "remark_text",
    "remark_texts",
    "report_step",
    "run_bounded",
    "same_span",
    "save_picture",
    "sentences",
    "sweep",
    "verification_json",
    "verification_lines",
    "version",
    "write_files",
    "write_report",
]
