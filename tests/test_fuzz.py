"""Fuzzing the inputs: model dictionaries, CLI options, report JSON.

Whatever the input, the outcome is success or the package's own error
(:class:`~coopkin_sym.errors.CoopkinError`, or exit status 2 with one line on the
command line), within a bounded time per example, and no text is ever run: some
inputs carry payloads that would create a marker file if evaluated.
"""

from __future__ import annotations

import copy
import json
import os
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.locus.types import Component, FloatCheck, Locus
from coopkin_sym.cli import app
from coopkin_sym.errors import CoopkinError
from coopkin_sym.present.report import (
    locus_from_json,
    render_html,
    render_json,
    render_latex,
    render_markdown,
)

MARKER = Path(__file__).resolve().parent / "_fuzz_marker_must_not_exist"
PAYLOADS = [
    f"__import__('os').system('touch {MARKER}')",
    f"__import__('pathlib').Path('{MARKER}').touch()",
    f"open('{MARKER}', 'w')",
    f"(lambda: open('{MARKER}', 'w'))()",
    f"().__class__.__base__.__subclasses__()[0]('{MARKER}')",
    f"Integer(open('{MARKER}','w'))",
    f"L + exec(\"open('{MARKER}','w')\")",
]
SECONDS = 5.0          # the bound on one example (the budgets keep it far lower)
FUZZ = settings(max_examples=int(os.environ.get("COOPKIN_FUZZ_EXAMPLES", "40")), deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])

BASE = {"name": "x", "parameters": ["L"],
        "arms": [{"name": "a1", "joints": [
            {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]},
            {"name": "d2", "type": "prismatic", "axis": [1, 0, 0]}]}],
        "contacts": [{"name": "c1", "link": "a1/2", "point": ["L", 0, 0],
                      "normal": [1, 0, 0], "model": "soft"},
                     {"name": "c2", "link": "base", "point": [0, "L/2", 0],
                      "model": "hard"}]}

expression_text = st.text(alphabet="0123456789.eE+-*/^()L pi atan sqrt Rational Integer,x_",
                          max_size=40)
numbers = st.one_of(st.integers(-10**1200, 10**1200), st.integers(-5, 5),
                    st.floats(allow_nan=True, allow_infinity=True),
                    st.fractions(max_denominator=10**6))
leaves = st.one_of(numbers, expression_text, st.sampled_from(PAYLOADS), st.none(),
                   st.booleans(), st.text(max_size=20),
                   st.sampled_from(["revolute", "prismatic", "hard", "soft", "complete",
                                    "frictionless", "base", "a1/1", "a1/2", "a1/" + "9" * 30,
                                    "010", "1:30", "q1", "L"]))
values = st.recursive(leaves, lambda inner: st.one_of(
    st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=8), inner, max_size=3)),
    max_leaves=12)


def _paths(tree, prefix=()):
    yield prefix
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from _paths(v, (*prefix, k))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from _paths(v, (*prefix, i))


@st.composite
def mutated(draw, base):
    """``base`` with a few entries replaced, deleted or added."""
    tree = copy.deepcopy(base)
    for _ in range(draw(st.integers(1, 4))):
        paths = [p for p in _paths(tree) if p]
        path = draw(st.sampled_from(paths))
        parent = tree
        for key in path[:-1]:
            parent = parent[key]
        action = draw(st.sampled_from(["replace", "replace", "delete", "add"]))
        if action == "replace":
            parent[path[-1]] = draw(values)
        elif action == "delete" and isinstance(parent, dict):
            del parent[path[-1]]
        elif isinstance(parent, dict):
            parent[draw(st.text(max_size=8))] = draw(values)
        elif isinstance(parent, list):
            parent.append(draw(values))
    return tree


def _bounded(call):
    start = time.monotonic()
    try:
        call()
    except CoopkinError as exc:
        assert "\n" not in str(exc) or all(line for line in str(exc).splitlines())
    assert time.monotonic() - start < SECONDS


@pytest.fixture(autouse=True, scope="module")
def no_marker():
    MARKER.unlink(missing_ok=True)
    yield
    assert not MARKER.exists(), "a payload ran"


@FUZZ
@given(mutated(BASE))
def test_model_dictionaries(tree):
    def run():
        system = load(tree)
        system.analyze()
    _bounded(run)
    assert not MARKER.exists()


runner = CliRunner()
option_text = st.one_of(expression_text, st.sampled_from(PAYLOADS),
                        st.text(max_size=30),
                        st.builds(lambda a, b: f"{a}={b}", st.sampled_from(
                            ["q1", "q2", "L", "x", ""]), expression_text))


@FUZZ
@given(st.sampled_from(["--at", "--free", "--grid", "--motion", "--pair", "--workers",
                        "--timeout", "--max-depth"]), option_text)
def test_cli_option_strings(option, text):
    commands = {"--at": ["analyze", "paper-case1-hard"],
                "--free": ["analyze", "paper-case1-hard"],
                "--grid": ["sweep", "paper-case1-hard"],
                "--motion": ["draw", "paper-case1-hard", "-o", "/nonexistent/x.png"],
                "--pair": ["locus", "paper-case1-hard", "-o", "/nonexistent/r.md"],
                "--workers": ["sweep", "paper-case1-hard", "--grid", "q1=0..1:2"],
                "--timeout": ["locus", "paper-case1-hard", "-o", "/nonexistent/r.md"],
                "--max-depth": ["locus", "paper-case1-hard", "-o", "/nonexistent/r.md"]}
    args = commands[option] + [option, text]
    if option == "--grid":
        args = commands[option] + ["--grid", f"q1={text}..1:3"]
    start = time.monotonic()
    result = runner.invoke(app, args)
    assert time.monotonic() - start < SECONDS
    assert result.exit_code in (0, 2), (args, result.output)
    assert "Traceback" not in result.output
    if result.exit_code == 2 and result.stderr.startswith("coopkin: error: "):
        assert result.stderr.count("\n") >= 1
    assert not MARKER.exists()


GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
REPORT = json.loads(render_json(Locus(
    "demo", ["t_q1", "t_q2", "L"], "L=1", GENERIC,
    [Component(["t_q1 + 1", "t_q2 + 1"], dict(GENERIC, Nm=3), {"q1": "-pi/2", "q2": "0"},
               True, kind="isolated", condition="q1 = -pi/2, q2 = 0",
               float_checks=[FloatCheck(0.0, "L=1", {"q1": "-pi/2"}, GENERIC, GENERIC)])],
    unexplored=["x"], seconds=0.5)))


@FUZZ
@given(st.one_of(mutated(REPORT), st.text(max_size=60)), st.booleans())
def test_report_json(data, as_text):
    if as_text and not isinstance(data, str):
        data = json.dumps(data, default=str)

    def run():
        locus = locus_from_json(data)
        for render in (render_markdown, render_html, render_latex):
            render(locus)
    _bounded(run)
    assert not MARKER.exists()
