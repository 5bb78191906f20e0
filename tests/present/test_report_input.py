"""Reports read back are validated like model files; user text cannot escape LaTeX or
Markdown."""

from __future__ import annotations

import json
import re

import pytest
from typer.testing import CliRunner

from coopkin_sym.analysis.locus.types import Component, FloatCheck, Locus
from coopkin_sym.cli import app
from coopkin_sym.present.report import (
    ReportError,
    locus_from_json,
    render_json,
    render_latex,
    render_markdown,
)

runner = CliRunner()
GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}


def locus(**changes) -> Locus:
    comp = Component(["t_q1 + 1", "t_q2 + 1"], dict(GENERIC, Nm=3, Nc=3, Nh=1),
                     {"q1": "-pi/2", "q2": "-pi/2"}, True, kind="isolated",
                     condition="q1 = q2 = -pi/2",
                     float_checks=[FloatCheck(0.0, "L=1", {"q1": "-pi/2", "q2": "-pi/2"},
                                              dict(GENERIC, Nm=3), GENERIC)],
                     algebraic_witness={"point": {"q1": "-pi/6"}, "alpha": "t_q1",
                                        "root_of": "alpha**2 + 4*alpha + 1",
                                        "root": "-2 + sqrt(3)", "interval": ["-1", "0"],
                                        "approx": {"q1": "-0.5235987756"}})
    base = Locus("demo", ["t_q1", "t_q2", "L"], "L=1", GENERIC, [comp],
                 unexplored=["nothing"], seconds=1.5)
    for key, value in changes.items():
        setattr(base, key, value)
    return base


def tree(**changes) -> dict:
    data = json.loads(render_json(locus()))
    for path, value in changes.items():
        target = data
        keys = path.split("__")
        for key in keys[:-1]:
            target = target[int(key)] if key.isdigit() else target[key]
        last = keys[-1]
        if value is KeyError:
            del target[last]
        else:
            target[int(last) if last.isdigit() else last] = value
    return data


def refused(data) -> list[str]:
    with pytest.raises(ReportError) as info:
        locus_from_json(data)
    lines = str(info.value).splitlines()
    assert all(line.startswith("not a locus report: ") for line in lines)
    return lines


def test_round_trip_of_a_full_report():
    assert locus_from_json(render_json(locus())) == locus()
    assert locus_from_json(json.loads(render_json(locus()))) == locus()


@pytest.mark.parametrize(("changes", "message"), [
    ({"systm": "x"}, "(top level): unknown key 'systm'"),
    ({"components__0__witnes": {}}, "components[0]: unknown key 'witnes'"),
    ({"system": KeyError}, "(top level): missing key 'system'"),
    ({"components__0__equations": "t_q1"}, "components[0].equations: input should be a "
                                          "valid list"),
    ({"components__0__real": "yes"}, "components[0].real: input should be a valid boolean"),
    ({"seconds": "1.5"}, "seconds"),
    ({"components__0__equations__0": "1/t_q1"}, "components[0].equations[0]: '1/t_q1' is "
                                               "not a polynomial"),
    ({"components__0__equations__0": "t_q9 - 1"}, "uses undeclared symbol t_q9"),
    ({"components__0__equations__0": "__import__('os').system('x')"},
     "uses unknown function __import__"),
    ({"components__0__witness__q1": "1e5000"}, "components[0].witness.q1: '1e5000' is too "
                                              "large"),
    ({"components__0__witness__q1": "exec('1')"}, "unknown function exec"),
    ({"variables__0": "pi"}, "variables[0]: 'pi' is reserved"),
    ({"variables__0": "a b"}, "variables[0]: 'a b' is not a name"),
    ({"variables__1": "t_q1"}, "given twice"),
    ({"generic__Nq": 3}, "generic: unknown number 'Nq'"),
    ({"components__0__numbers__Nm": -1}, "a count cannot be negative"),
    ({"components__0__parent": 7},
     "components[0].parent: no component #7 (there are 1, numbered from 1)"),
    ({"components__0__kind": "blob"}, "components[0].kind: unknown kind 'blob'"),
    ({"components__0__algebraic_witness__approx__q1": "nan; rm -rf"}, "is not a decimal "
                                                                      "number"),
    ({"components__0__float_checks__0__distance": -1.0}, "must be a finite number"),
    ({"fixed": "L=1,q1"}, "fixed: expected NAME=VALUE, got 'q1'"),
    ({"fixed": "L=open('x')"}, "fixed.L: 'open('x')' uses unknown function open"),
])
def test_report_problems_are_one_line_each(changes, message):
    lines = refused(tree(**changes))
    assert any(message in line for line in lines), lines


def test_several_problems_at_once():
    lines = refused(tree(**{"components__0__equations__0": "1/t_q1", "variables__0": "pi"}))
    assert len(lines) >= 2


def test_report_text_within_budgets():
    assert "nested more than 32 deep" in refused("[" * 100_000 + "]" * 100_000)[0]
    assert "more than 1000 digits" in refused('{"seconds": ' + "9" * 5000 + "}")[0]
    assert "not valid JSON" in refused("{")[0]
    assert "expected a mapping" in refused("[]")[0]


def test_reports_keep_added_fields_of_the_dataclass():
    """A field that Component gains later is read back (any plain value), while a key
    that is no field is refused."""
    data = tree()
    data["components"][0]["not_a_field"] = 1
    assert any("unknown key 'not_a_field'" in line for line in refused(data))


# ------------------------------------------------------------------ LaTeX and Markdown

EVIL = "demo\n\\immediate\\write18{touch /tmp/owned}\n% \\input{/etc/passwd}\u2028\\def\\x{}"


def _user_tex_is_inert(tex: str) -> None:
    """Outside our own ``%`` comment lines no user text is a command; user text in a
    comment stays on that line."""
    for line in tex.splitlines():
        if line.startswith("%"):
            continue
        clean = line.replace(r"\textbackslash{}", "")
        for command in (r"\immediate", r"\write18", r"\input{/etc", r"\def\x"):
            assert command not in clean, line
        assert not re.search(r"(?<!\\)%", line), line


def test_latex_escapes_every_user_string():
    evil = locus(system=EVIL, notes=[EVIL], unexplored=[EVIL])
    # (equations and conditions are exact data: no text of a user reaches them)
    evil.components[0].stated_meaning = [EVIL]
    evil.components[0].witness = {"q1": EVIL}
    tex = render_latex(evil, {("q1", "q2"): "r_q1_q2.png"})
    _user_tex_is_inert(tex)
    assert tex.splitlines()[0].startswith("% Singularity-locus report of demo ")


def test_markdown_keeps_user_text_on_its_line():
    evil = locus(system="demo\n# injected heading\n<script>alert(1)</script>")
    evil.components[0].witness = {"q1": "x``<img src=x onerror=alert(1)>``"}
    md = render_markdown(evil)
    assert not any(line.startswith("# injected") for line in md.splitlines())
    assert "<script>" not in md and "\\<script\\>" in md
    # the code span's fence is longer than any run of backticks inside it
    assert "``` q1=x``<img src=x onerror=alert(1)>`` ```" in md


def test_analyze_latex_keeps_the_model_name_in_its_comment(tmp_path):
    path = tmp_path / "m.json"
    path.write_text(json.dumps({
        "name": "x\n\\immediate\\write18{touch /tmp/owned}\n",
        "arms": [{"name": "a", "joints": [{"name": "q1", "type": "revolute",
                                           "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
        "contacts": [{"name": "c", "link": "a/1", "point": [1, 0, 0], "model": "hard"}]}))
    result = runner.invoke(app, ["analyze", str(path), "--latex"])
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert lines[0].startswith("% x \\immediate")
    assert not any(line.startswith("\\immediate") for line in lines)


def test_a_witness_root_of_degree_four_is_read_back():
    # SymPy writes roots beyond degree two as CRootOf(polynomial in t, k): the name t
    # is the polynomial's variable there, not a variable of the report
    root = "CRootOf(16*t**4 + 120*t**3 + 145*t**2 - 300*t - 225, 0)"
    data = tree(components__0__algebraic_witness__root=root)
    again = locus_from_json(data)
    assert again.components[0].algebraic_witness["root"] == root
    # the same name outside CRootOf is still refused in a root (a root is a number)
    assert any("uses undeclared symbol t" in line
               for line in refused(tree(components__0__algebraic_witness__root="t + 1")))


def test_a_refused_variable_is_one_problem_not_one_per_equation_using_it():
    # the equations use t_q1, which the refused entry may have meant: they used to get
    # one "uses undeclared symbol t_q1" each; the rest of each text is still checked
    lines = refused(tree(variables__0="t_q1**2",
                         components__0__equations__1="1/t_q2 + exec('x')"))
    assert lines == [
        "not a locus report: variables[0]: 't_q1**2' is not a name",
        "not a locus report: components[0].equations[1]: '1/t_q2 + exec('x')' uses "
        "unknown function exec (allowed: atan, sqrt)"]


@pytest.mark.parametrize(("changes", "message"), [
    # a key named like a type was dropped from the path ("float_checks[0].Nm")
    ({"components__0__float_checks__0__float": {"Nm": "a"}},
     "components[0].float_checks[0].float.Nm: input should be a valid integer (got 'a')"),
    ({"generic": {"int": "a"}}, "generic.int: input should be a valid integer (got 'a')"),
    # a key with a line break broke the line; a key that is no name is quoted
    ({"generic": {"N\nm": "a"}}, "generic['N m']: input should be a valid integer (got 'a')"),
    ({"generic": {"": "a"}}, "generic['']: input should be a valid integer (got 'a')"),
    # a number of either type: one line, not one per type tried
    ({"seconds": "a"}, "seconds: input should be a number (got 'a')"),
    ({"components__0__float_checks__0__distance": None},
     "components[0].float_checks[0].distance: input should be a number (got 'None')"),
])
def test_structure_problems_name_their_entry_on_one_line(changes, message):
    assert refused(tree(**changes)) == [f"not a locus report: {message}"]


def test_a_certificate_table_key_with_a_line_break_stays_on_its_line():
    data = json.loads(render_json(locus()))
    data["certificate"] = {
        "system": "demo", "certified": False, "summary": "not certified: x",
        "depths": {}, "charts": {"t\nq": {"certified": False, "why": "", "tests": 1,
                                          "failed": 2}},
        "tests": 1, "certified_by": {}, "failed": [], "notes": [], "seconds": 0}
    assert refused(data) == ["not a locus report: certificate.charts['t q']: counts must "
                             "satisfy 0 <= failed <= tests"]


def test_equations_are_read_without_sympy(monkeypatch):
    # a report's equation of 10,000 terms took 5 s through SymPy (expand, Poly),
    # 40,000 terms 21 s; the polynomials now come from the parser's own arithmetic
    from coopkin_sym.exact.polynomial import NamedPolynomial

    def refuse(*args, **kwargs):
        raise AssertionError("an equation went through SymPy")
    monkeypatch.setattr(NamedPolynomial, "from_sympy", refuse)
    monkeypatch.setattr("sympy.expand", refuse)
    read = locus_from_json(tree(components__0__equations__0="(t_q1 + 1)**2/4 - t_q2"))
    assert read.components[0].equations[0].text == "t_q1**2/4 + t_q1/2 - t_q2 + 1/4"
