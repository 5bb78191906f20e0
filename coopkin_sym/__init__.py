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
    BlockTooLarge,
    ConfigurationError,
    CoopkinError,
    InfeasibleMotion,
    ManipulabilityError,
    ModelError,
)

if TYPE_CHECKING:  # pragma: no cover
    from coopkin_sym.analysis.batch import BatchResult
    from coopkin_sym.analysis.irrational import IrrationalAnalysis
    from coopkin_sym.analysis.locus.types import Component, Locus
    from coopkin_sym.analysis.mobility import Analysis, Motion
    from coopkin_sym.analysis.numbers import Numbers
    from coopkin_sym.analysis.sweep import SweepResult
    from coopkin_sym.model.configuration import Configuration
    from coopkin_sym.model.model import Model
    from coopkin_sym.system import System, analyze_many, load

#: Where each public name lives; its module is imported on first access (PEP 562), so
#: that ``import coopkin_sym`` and the ``coopkin`` command start quickly.
_LAZY = {
    "Analysis": "coopkin_sym.analysis.mobility",
    "BatchResult": "coopkin_sym.analysis.batch",
    "Component": "coopkin_sym.analysis.locus.types",
    "Configuration": "coopkin_sym.model.configuration",
    "IrrationalAnalysis": "coopkin_sym.analysis.irrational",
    "Locus": "coopkin_sym.analysis.locus.types",
    "Model": "coopkin_sym.model.model",
    "Motion": "coopkin_sym.analysis.mobility",
    "Numbers": "coopkin_sym.analysis.numbers",
    "SweepResult": "coopkin_sym.analysis.sweep",
    "System": "coopkin_sym.system",
    "analyze_many": "coopkin_sym.system",
    "load": "coopkin_sym.system",
}


#: The subpackages, also imported on first access (``coopkin_sym.model.examples``).
_SUBPACKAGES = ("analysis", "exact", "model", "present", "system")


def __getattr__(name: str) -> Any:
    if name in _SUBPACKAGES:
        return importlib.import_module(f"coopkin_sym.{name}")
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'coopkin_sym' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
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
    "BatchResult",
    "BlockTooLarge",
    "Component",
    "Configuration",
    "ConfigurationError",
    "CoopkinError",
    "InfeasibleMotion",
    "IrrationalAnalysis",
    "Locus",
    "ManipulabilityError",
    "Model",
    "ModelError",
    "Motion",
    "Numbers",
    "SweepResult",
    "System",
    "analyze_many",
    "load",
]
__version__ = "0.1.0"
