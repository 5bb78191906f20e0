"""What importing the package and the command line loads: nothing heavy until it is used.

Each check runs in a fresh interpreter (the test session has imported everything).
``import coopkin_sym`` and ``import coopkin_sym.cli`` load neither SymPy's consumers
nor NumPy, Matplotlib, pandas, pydantic, YAML, the locus machinery or the reports;
``coopkin analyze`` at a rational point loads the kinematics and the text, not the
number-field path, the locus, the reports or the pictures. The public names still
import, and the renderers are installed when a result is first displayed.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: Never loaded by ``import coopkin_sym`` or ``import coopkin_sym.cli``.
HEAVY = ("sympy", "numpy", "matplotlib", "pandas", "pydantic", "yaml", "defusedxml",
         "rich", "coopkin_sym.system", "coopkin_sym.model.model",
         "coopkin_sym.analysis.mobility", "coopkin_sym.analysis.irrational",
         "coopkin_sym.analysis.locus.search", "coopkin_sym.analysis.locus.certify",
         "coopkin_sym.analysis.locus.verify", "coopkin_sym.exact.groebner",
         "coopkin_sym.analysis.sweep", "coopkin_sym.present.report",
         "coopkin_sym.present.draw", "coopkin_sym.present.locus_plot",
         "coopkin_sym.present.display")

#: Not loaded by ``coopkin analyze MODEL --at ...`` at a rational point.
NOT_FOR_ANALYZE = ("numpy", "matplotlib", "pandas", "defusedxml",
                   "coopkin_sym.analysis.irrational", "coopkin_sym.analysis.locus.search",
                   "coopkin_sym.analysis.locus.certify", "coopkin_sym.analysis.locus.types",
                   "coopkin_sym.exact.groebner", "coopkin_sym.analysis.sweep",
                   "coopkin_sym.present.report", "coopkin_sym.present.draw",
                   "coopkin_sym.present.locus_plot", "coopkin_sym.present.display")


def _loaded_after(code: str, names: tuple[str, ...]) -> dict[str, bool]:
    """Run ``code`` in a fresh interpreter; which of ``names`` are then in sys.modules."""
    probe = (f"{code}\nimport json, sys\n"
             f"print(json.dumps({{n: n in sys.modules for n in {list(names)!r}}}))")
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get(
        "PYTHONPATH", "")}
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         env=env, check=True, cwd=ROOT).stdout
    return json.loads(out.strip().splitlines()[-1])


@pytest.mark.parametrize("code", ["import coopkin_sym", "import coopkin_sym.cli"])
def test_importing_loads_nothing_heavy(code):
    loaded = _loaded_after(code, HEAVY)
    assert [n for n, there in loaded.items() if there] == []


def test_the_probe_sees_a_loaded_module():
    """The check can fail: a module that is imported is reported."""
    assert _loaded_after("import coopkin_sym.analysis.sweep", ("numpy",)) == {"numpy": True}


def test_analyze_at_a_rational_point_loads_only_its_path():
    code = ("import contextlib, io\n"
            "from coopkin_sym.cli import main\n"
            "import sys\n"
            "sys.argv = ['coopkin', 'analyze', 'paper-case2-hard', '--at', 'q1=pi/2,L=1']\n"
            "with contextlib.redirect_stdout(io.StringIO()) as out:\n"
            "    with contextlib.suppress(SystemExit):\n"
            "        main()\n"
            "assert 'Nm' in out.getvalue(), out.getvalue()")
    loaded = _loaded_after(code, NOT_FOR_ANALYZE)
    assert [n for n, there in loaded.items() if there] == []


def test_public_names_import_and_renderers_install_on_first_display():
    code = ("import sys\n"
            "import coopkin_sym\n"
            "from coopkin_sym import (Analysis, BlockTooLarge, Component, Configuration,\n"
            "    ConfigurationError, CoopkinError, InfeasibleMotion, IrrationalAnalysis,\n"
            "    Locus, ManipulabilityError, Model, ModelError, Motion, Numbers,\n"
            "    SweepResult, System, load)\n"
            "assert sorted(coopkin_sym.__all__) == sorted(n for n in coopkin_sym.__all__\n"
            "                                            if hasattr(coopkin_sym, n))\n"
            "assert set(coopkin_sym.__all__) <= set(dir(coopkin_sym))\n"
            "a = load('paper-case1-hard').analyze()\n"
            "before = 'coopkin_sym.present.display' in sys.modules\n"
            "html = a._repr_html_()\n"
            "assert not before and html.startswith('<div'), (before, html)\n"
            "assert a.numbers._repr_latex_() is not None\n"
            "assert coopkin_sym.model.examples.list_examples()\n")
    assert _loaded_after(code, ("coopkin_sym.present.display",)) == {
        "coopkin_sym.present.display": True}


def test_renderers_install_when_a_result_is_displayed_without_the_public_names():
    """A result made through the layers directly shows the same as through ``load``."""
    code = ("from coopkin_sym.model.model import load_model\n"
            "from coopkin_sym.analysis.mobility import analyze\n"
            "from coopkin_sym.model.configuration import Configuration\n"
            "m = load_model('paper-case1-hard')\n"
            "a = analyze(m, Configuration.parse(m, 'q1=pi/2'))\n"
            "assert a._repr_html_().startswith('<div')\n")
    assert _loaded_after(code, ("coopkin_sym.present.display",)) == {
        "coopkin_sym.present.display": True}


def test_an_unknown_public_name_is_an_attribute_error():
    import coopkin_sym

    with pytest.raises(AttributeError, match="no attribute 'Nothing'"):
        coopkin_sym.Nothing  # noqa: B018
