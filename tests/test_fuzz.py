"""Fuzzing the inputs: model dictionaries, URDF files, DH tables, CLI options, report
JSON.

Whatever the input, the outcome is success or the package's own error
(:class:`~coopkin_sym.errors.CoopkinError`, one line per problem naming the entry, or
exit status 2 with one line on the command line), and no text is ever run: some
inputs carry payloads that would create a marker file if evaluated. Every case runs in
a forked child within a wall-clock bound and a memory bound (:mod:`fuzz_bounds`): a
case that hits either fails with its input shown. MJCF files are not read by the
package yet, so there is nothing of theirs to fuzz.

``COOPKIN_FUZZ_EXAMPLES`` sets the number of examples per test (40 by default);
``COOPKIN_FUZZ_CAMPAIGN=1`` adds the campaigns (marked ``slow``), ten times longer.
"""

from __future__ import annotations

import atexit
import copy
import json
import os
import re
import shutil
import tempfile
from fractions import Fraction
from pathlib import Path

import mpmath
import pytest
import sympy as sp
from fuzz_bounds import CASE_SECONDS, Outcome, run_bounded
from fuzz_inputs import (
    PAYLOAD_MARKER_NAME,
    dh_models,
    expressions,
    mutated,
    payloads,
    report_entries_changed,
    report_leaves,
    urdf_documents,
)
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strategies import random_systems
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.locus.certify import certify_locus
from coopkin_sym.analysis.locus.types import Component, FloatCheck, Locus
from coopkin_sym.cli import app
from coopkin_sym.errors import NumberError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import (
    parse_angle,
    parse_expression,
    parse_number,
    parse_polynomial,
)
from coopkin_sym.model.urdf import DEFAULT_BOUND, read_urdf_text
from coopkin_sym.present.report import (
    locus_from_json,
    render_html,
    render_json,
    render_latex,
    render_markdown,
)
from coopkin_sym.present.report_input import validate_report

MARKER = Path(__file__).resolve().parent / PAYLOAD_MARKER_NAME
PAYLOADS = payloads(str(MARKER))
EXAMPLES = int(os.environ.get("COOPKIN_FUZZ_EXAMPLES", "40"))
# deadline=None: the bound on a case is the child's wall clock (fuzz_bounds), which
# also ends a case that never returns; hypothesis's deadline only judges cases that end
FUZZ = settings(max_examples=EXAMPLES, deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.filter_too_much])
CAMPAIGN = settings(FUZZ, max_examples=10 * EXAMPLES)
#: The campaigns (ten times the examples) run with COOPKIN_FUZZ_CAMPAIGN=1 only.
campaign = pytest.mark.skipif(not os.environ.get("COOPKIN_FUZZ_CAMPAIGN"),
                              reason="set COOPKIN_FUZZ_CAMPAIGN=1 for the long campaign")
WORK = Path(tempfile.mkdtemp(prefix="coopkin-fuzz-"))   # files of the cases, removed at exit
atexit.register(shutil.rmtree, WORK, True)

#: One line of an error: "where: what is wrong" (the entry, then the problem).
_LINE = re.compile(r"[^\s:][^\n]*?: \S.*")
#: The longest line an error may have (values are quoted shortened, never whole).
MAX_LINE = 1500


def _shown(what: object) -> str:
    """The input of a case, shortened for a failure message (hypothesis prints it
    whole as the falsifying example)."""
    text = repr(what)
    return text if len(text) <= 3000 else f"{text[:2000]} ... {text[-800:]}"


def problem_lines(outcome: Outcome, what: object) -> list[str]:
    """The lines of the package error of ``outcome``, after checking that the case
    ended within its bounds with a result or that error, one line per problem, each
    naming its entry."""
    shown = _shown(what)
    assert outcome.failure is None, f"{shown}\n{outcome.failure}"
    assert not MARKER.exists(), f"a payload ran: {shown}"
    if outcome.kind == "result":
        return []
    lines = outcome.message.split("\n")
    for line in lines:
        assert _LINE.fullmatch(line) and line == line.strip(), (shown, outcome.message)
        assert len(line) <= MAX_LINE, (shown, line[:300])
        assert "Traceback" not in line, (shown, outcome.message)
    return lines


@pytest.fixture(autouse=True, scope="module")
def no_marker():
    MARKER.unlink(missing_ok=True)
    yield
    assert not MARKER.exists(), "a payload ran"


# ----------------------------------------------------------------- model dictionaries

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


def _load_and_analyze(tree) -> list[int]:
    numbers = load(tree).analyze().numbers
    return [numbers.Nm, numbers.Nc]


PLANAR = {"name": "planar", "planar": True, "parameters": ["L"],
          "arms": [{"name": "a1", "joints": [
              {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0],
               "actuated": False},
              {"name": "q2", "type": "revolute", "axis": [0, 0, 1], "point": ["L", 0, 0]}]},
              {"name": "a2", "joints": [
                  {"name": "q3", "type": "revolute", "axis": [0, 0, 1], "point": [0, "L", 0]}]}],
          "contacts": [{"name": "c1", "link": "a1/2", "point": ["2*L", 0, 0],
                        "normal": [-1, 0, 0], "model": "hard"},
                       {"name": "c2", "link": "a2/1", "point": [0, "2*L", 0],
                        "normal": [0, -1, 0], "model": "complete"}],
          "object": {"point": ["L", "L", 0], "rpy": [0, 0, "pi/2"]}}
model_dictionaries = st.one_of(
    mutated(BASE, values), mutated(PLANAR, values),
    random_systems(max_arms=3, max_joints=3, max_contacts=3, with_parameter=True)
    .flatmap(lambda model: mutated(model, values)))


@FUZZ
@given(model_dictionaries)
def test_model_dictionaries(tree):
    problem_lines(run_bounded(lambda: _load_and_analyze(tree)), tree)


# ----------------------------------------------------------------------- expressions


def _read_expression(text: str) -> list[str]:
    """Every reading of the one parser: a value or a NumberError each."""
    readers = [lambda: parse_expression(text, ["t", "s"], "x"),
               lambda: parse_number(text, {"L": sp.Symbol("L", positive=True)}, "x"),
               lambda: parse_angle(text, "x"),
               lambda: parse_polynomial(text, ["t", "s"], "x")]
    out = []
    for read in readers:
        try:
            out.append(str(read())[:100])
        except NumberError as exc:
            assert "\n" not in str(exc) and str(exc).startswith("x: "), str(exc)
            out.append(f"error: {exc}")
    return out


@FUZZ
@given(expressions())
def test_expressions(text):
    problem_lines(run_bounded(lambda: _read_expression(text)), text)


@pytest.mark.slow
@campaign
@CAMPAIGN
@given(expressions(depth=6))
def test_expressions_campaign(text):
    problem_lines(run_bounded(lambda: _read_expression(text)), text)


# ------------------------------------------------------------------------ URDF files


def _read_urdf(data: bytes, tip: str | None) -> list[tuple[str, str, str, float]]:
    text = data.decode("utf-8", errors="surrogateescape")
    arm = read_urdf_text(text, "r.urdf", tip=tip)
    return [(s.where, s.given, s.exact, s.error) for s in arm.snapped]


def _snap_distance(where: str, given: str, exact: str) -> mpmath.mpf:
    """How far the exact value of a snap is from the float given, in radians (the
    caller's 400 digits are enough for any float, 1e308 included)."""
    if where.endswith(" axis"):
        v = [mpmath.mpf(float(x)) for x in given.split()]  # float-ok: the URDF's floats
        w = [mpmath.mpf(Fraction(x).numerator) / Fraction(x).denominator
             for x in exact.strip("()").split(",")]
        dot = sum(a * b for a, b in zip(v, w, strict=True)) / mpmath.norm(v)
        return mpmath.acos(max(-1, min(1, dot)))
    x = mpmath.mpf(float(given))  # float-ok: the URDF's float, exactly
    cos, sin = ExactAngle.parse(exact, where).cos_sin
    c, s = mpmath.mpf(cos.p) / cos.q, mpmath.mpf(sin.p) / sin.q
    return abs(mpmath.atan2(mpmath.sin(x) * c - mpmath.cos(x) * s,
                            mpmath.cos(x) * c + mpmath.sin(x) * s))


def check_urdf_text(data: bytes, tip: str | None, seconds: float = CASE_SECONDS) -> None:
    """:func:`read_urdf_text` of the document: an arm whose every snap is within the
    bound, as it states, or one line naming the file."""
    outcome = run_bounded(lambda: _read_urdf(data, tip), seconds)
    lines = problem_lines(outcome, (data[:3000], tip))
    assert outcome.kind == "result" or outcome.error_type == "UrdfError", outcome
    for line in lines:
        assert line.startswith("r.urdf: "), (data[:3000], tip, line)
    with mpmath.workdps(400):
        for where, given, exact, error in outcome.value or []:
            distance = _snap_distance(where, given, exact)
            # the stated distance is a float estimate: acos of a float dot product
            # near 1 (an axis 1.4e-8 rad away is stated 0.0)
            assert distance <= DEFAULT_BOUND * (1 + 1e-9) and abs(distance - error) <= 1e-7, (
                where, given, exact, error, mpmath.nstr(distance, 5))


def _urdf_model(path: Path, tip: str | None) -> dict:
    arm = {"name": "a1", "urdf": str(path)}
    if tip is not None:
        arm["tip"] = tip
    return {"name": "urdf", "arms": [arm, {"name": "a2", "joints": [
                {"name": "q", "type": "revolute", "axis": [0, 0, 1], "point": [1, 0, 0]}]}],
            "contacts": [{"name": "c1", "link": "a1/1", "point": [0, 0, 1], "model": "hard"},
                         {"name": "c2", "link": "a2/1", "point": [1, 0, 1], "model": "soft"}]}


def check_urdf_file(data: bytes, tip: str | None, seconds: float = CASE_SECONDS) -> None:
    """The document as the file of a model's ``urdf:`` arm: a system (analyzed at
    home), or one line per problem, each naming its entry (``arms[0].urdf: ...`` for
    the file)."""
    path = WORK / "r.urdf"
    path.write_bytes(data)
    model = _urdf_model(path, tip)
    lines = problem_lines(run_bounded(lambda: _load_and_analyze(model), seconds),
                          (data[:3000], tip))
    for line in lines:
        assert re.match(r"(arms|contacts)\[\d+\]", line), (data[:3000], tip, line)


# Inputs that once escaped coopkin_sym/model/urdf.py (hangs, Python errors, a wrong
# snap); each is a regression example below.


@FUZZ
@given(urdf_documents())
def test_urdf_text(case):
    check_urdf_text(*case)


@FUZZ
@given(urdf_documents())
def test_urdf_arms_of_models(case):
    check_urdf_file(*case)


@pytest.mark.slow
@campaign
@CAMPAIGN
@given(urdf_documents())
def test_urdf_campaign(case):
    check_urdf_text(*case)
    check_urdf_file(*case)


def _one_joint(axis: str = "0 0 1", rpy: str = "0 0 0") -> bytes:
    return (f'<robot name="r"><link name="b"/><link name="t"/><joint name="q" '
            f'type="revolute"><parent link="b"/><child link="t"/><origin xyz="0 0 0" '
            f'rpy="{rpy}"/><axis xyz="{axis}"/></joint></robot>').encode("utf-8", "surrogateescape")


#: A chain b - t, and apart from it a loop c1 -> c2 -> c1: the tip c1 is on the loop.
LOOP = (b'<robot name="r"><link name="b"/><link name="t"/><link name="c1"/>'
        b'<link name="c2"/><joint name="q" type="revolute"><parent link="b"/>'
        b'<child link="t"/></joint><joint name="x1" type="fixed"><parent link="c1"/>'
        b'<child link="c2"/></joint><joint name="x2" type="fixed"><parent link="c2"/>'
        b'<child link="c1"/></joint></robot>')


def _long_chain(joints: int) -> bytes:
    links = "".join(f'<link name="l{i}"/>' for i in range(joints + 1))
    chain = "".join(f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child '
                    f'link="l{i + 1}"/><origin xyz="0 0 0.1" rpy="0.3 0.2 0.1"/></joint>'
                    for i in range(joints))
    return f'<robot name="r">{links}{chain}</robot>'.encode()


URDF_REGRESSIONS = [
    # a tip on a loop of parent/child links walked for ever
    pytest.param("text", LOOP, "c1", id="tip-on-a-loop"),
    pytest.param("file", LOOP, "c2", id="tip-on-a-loop-file"),
    # no budget on joints and links: 70,000 joints ran for minutes
    pytest.param("text", _long_chain(70_000), None, id="70000-joints"),
    # axis entries: OverflowError, ZeroDivisionError, an error naming neither the file
    # nor the joint
    pytest.param("text", _one_joint(axis="1e400 0 0"), None, id="axis-1e400"),
    pytest.param("file", _one_joint(axis="1e-400 0 0"), None, id="axis-1e-400"),
    pytest.param("text", _one_joint(axis="1e-200 1e-200 0"), None, id="axis-1e-200"),
    pytest.param("text", _one_joint(axis="1e200 1e200 0"), None, id="axis-1e200"),
    # an angle of 1e16 rad snapped 0.39 rad away, stated as 5e-8
    pytest.param("text", _one_joint(rpy="1e16 0 0"), None, id="rpy-1e16"),
    # text with a lone surrogate raised UnicodeEncodeError
    pytest.param("text", _one_joint(rpy="0 0 1.5\udce9"), None, id="lone-surrogate"),
]


@pytest.mark.parametrize(("route", "data", "tip"), URDF_REGRESSIONS)
def test_urdf_inputs_that_once_escaped(route, data, tip):
    (check_urdf_text if route == "text" else check_urdf_file)(data, tip, seconds=2.0)


# ------------------------------------------------------------------------- DH tables


def check_dh_model(tree: dict) -> None:
    problem_lines(run_bounded(lambda: _load_and_analyze(tree)), tree)


@FUZZ
@given(dh_models(str(MARKER)))
def test_dh_tables(tree):
    check_dh_model(tree)


@pytest.mark.slow
@campaign
@CAMPAIGN
@given(dh_models(str(MARKER)))
def test_dh_campaign(tree):
    check_dh_model(tree)


# ----------------------------------------------------------------------- CLI options

runner = CliRunner()
option_text = st.one_of(expression_text, st.sampled_from(PAYLOADS),
                        st.text(max_size=30),
                        st.builds(lambda a, b: f"{a}={b}", st.sampled_from(
                            ["q1", "q2", "L", "x", ""]), expression_text))


def _invoke(args: list[str]) -> tuple[int, str, str]:
    result = runner.invoke(app, args)
    return result.exit_code, result.stdout, result.stderr


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
    outcome = run_bounded(lambda: _invoke(args))
    problem_lines(outcome, args)
    code, out, err = outcome.value
    assert code in (0, 2), (args, out, err)
    assert "Traceback" not in out + err
    if code == 2 and err.startswith("coopkin: error: "):
        assert err.count("\n") >= 1


# ----------------------------------------------------------------------- report JSON

GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
REPORT = json.loads(render_json(Locus(
    "demo", ["t_q1", "t_q2", "L"], "L=1", GENERIC,
    [Component(["t_q1 + 1", "t_q2 + 1"], dict(GENERIC, Nm=3), {"q1": "-pi/2", "q2": "0"},
               True, kind="isolated", condition="q1 = -pi/2, q2 = 0",
               float_checks=[FloatCheck(0.0, "L=1", {"q1": "-pi/2"}, GENERIC, GENERIC)])],
    unexplored=["x"], seconds=0.5)))


def _real_report() -> dict:
    """The JSON report of ``coopkin locus paper-case1-hard -o r.json``, cut to three
    components (each mutation then hits the parts that matter more often)."""
    tree = json.loads(render_json(load("paper-case1-hard").locus()))
    tree["components"] = tree["components"][:3]
    for component in tree["components"]:
        component["float_checks"] = component["float_checks"][:1]
    return tree


REAL_REPORT = _real_report()


def _certified_report_with_locked_joints() -> dict:
    """The JSON report of ``coopkin locus underactuated-finger --certify``: a
    certificate, and the locus of the system with its actuators locked (``locked``)."""
    system = load("underactuated-finger")
    locus = system.locus()
    locus.certificate = certify_locus(system, locus, timeout=10)
    tree = json.loads(render_json(locus))
    tree["components"] = tree["components"][:2]
    tree["locked"]["components"] = tree["locked"]["components"][:2]
    return tree


CERTIFIED_REPORT = _certified_report_with_locked_joints()


def _read_and_render(data) -> int:
    locus = locus_from_json(data)
    markdown, html, latex = (render(locus) for render in (render_markdown, render_html,
                                                           render_latex))
    # text from the report never becomes markup (the strategies plant these); in
    # Markdown, a code span shows its text as it is, and \< is a plain <
    outside_code = re.sub(r"`[^`\n]*`", "", markdown)
    assert "<script" not in html.lower()
    assert not re.search(r"(?<!\\)<script", outside_code, re.IGNORECASE)
    assert "\\input{/etc" not in latex, "a LaTeX command from the report was kept"
    return len(locus.components)


def check_report(data) -> None:
    """A report read back (and rendered) or one line per problem naming the entry;
    :func:`validate_report` agrees with :func:`locus_from_json`."""
    first = run_bounded(lambda: _read_and_render(data))
    problem_lines(first, data)
    second = run_bounded(lambda: len(validate_report(data).components))
    problem_lines(second, data)
    assert (first.kind, first.value) == (second.kind, second.value), (_shown(data), first, second)
    if first.kind == "error":
        assert first.error_type == "ReportError" and second.error_type == "ReportInputError"
        assert first.message == second.message, (first.message, second.message)


def _as_text(data, how: str):
    if how == "tree" or isinstance(data, str):
        return data
    text = json.dumps(data, default=str)
    if how == "truncated":
        return text[:len(text) // 2]
    if how == "bytes":
        return text.encode("utf-8")
    return text


report_cases = st.tuples(
    st.one_of(mutated(REPORT, values), mutated(REAL_REPORT, report_leaves(str(MARKER))),
              mutated(REAL_REPORT, report_leaves(str(MARKER)), max_changes=12),
              report_entries_changed(REAL_REPORT, str(MARKER)),
              report_entries_changed(REAL_REPORT, str(MARKER)),
              mutated(CERTIFIED_REPORT, report_leaves(str(MARKER))),
              report_entries_changed(CERTIFIED_REPORT, str(MARKER)),
              st.text(max_size=60)),
    st.sampled_from(["tree", "text", "text", "truncated", "bytes"]))


@FUZZ
@given(report_cases)
def test_report_json(case):
    check_report(_as_text(*case))


@pytest.mark.slow
@campaign
@CAMPAIGN
@given(report_cases)
def test_report_json_campaign(case):
    check_report(_as_text(*case))


def test_a_report_with_an_equation_of_30000_terms_is_read_within_the_bound():
    # within the budgets (terms, characters); it took 16 s through SymPy
    tree = copy.deepcopy(REAL_REPORT)
    tree["components"][0]["equations"][0] = " + ".join(
        f"t_q1**{i}*t_q2**{j}" for i in range(173) for j in range(173))
    outcome = run_bounded(lambda: len(validate_report(tree).components[0].equations[0]
                                      .terms))
    problem_lines(outcome, "an equation of 30,000 terms")
    assert outcome.value == 173 * 173


def check_verify(data: str) -> list[str]:
    """``coopkin verify MODEL FILE``: exit 0 or 1 with a verdict, or 2 with the error
    (one line per problem). Returns the lines of the error."""
    path = WORK / "report.json"
    path.write_text(data)
    args = ["verify", "paper-case1-hard", str(path), "--max-points", "20", "--lines", "1"]
    outcome = run_bounded(lambda: _invoke(args), seconds=2 * CASE_SECONDS)
    problem_lines(outcome, data)
    code, out, err = outcome.value
    assert code in (0, 1, 2), (_shown(data), code, out, err)
    assert "Traceback" not in out + err, (_shown(data), out, err)
    if code != 2:
        return []
    lines = err.splitlines()
    assert lines[0].startswith("coopkin: error: ") and all(lines), (_shown(data), err)
    return lines


@settings(FUZZ, max_examples=max(3, EXAMPLES // 10))
@given(st.one_of(mutated(REAL_REPORT, report_leaves(str(MARKER))),
                 report_entries_changed(REAL_REPORT, str(MARKER))))
def test_verify_command_on_mutated_reports(tree):
    check_verify(json.dumps(tree, default=str))


# cli verify wrapped the report's problems in 'FILE: not a locus report (not a locus
# report: ...)', the parenthesis open over several lines
def test_verify_names_the_file_and_the_entry_once_per_problem():
    tree = copy.deepcopy(REAL_REPORT)
    tree["components"][0]["equations"][0] = "1/t_q1"
    tree["components"][1]["kind"] = "blob"
    lines = check_verify(json.dumps(tree))
    assert len(lines) == 2, lines
    for line, entry in zip(lines, ["components[0].equations[0]", "components[1].kind"],
                           strict=True):
        assert line.count("not a locus report") == 1 and line.count("report.json") == 1
        assert entry in line and line.count("(") == line.count(")"), line
