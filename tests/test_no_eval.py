"""No text from outside is ever evaluated as code.

The source scan finds every call that could evaluate text (``sympify``,
``parse_expr``, ``eval``, ``exec``, ``S(str...)``) anywhere in the package; the only
accepted ones would carry ``# parse-ok``, and none does (the package generates no
code). The marker tests hand payloads that would create a file
if evaluated to every entry that takes text, and check the file never appears.
"""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest
import sympy as sp
from typer.testing import CliRunner

import coopkin_sym
from coopkin_sym import load
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.cli import app
from coopkin_sym.errors import CoopkinError
from coopkin_sym.exact.parse import (
    NumberError,
    exact_expr,
    parse_angle,
    parse_expression,
    parse_number,
)
from coopkin_sym.present.report import locus_from_json, render_json, write_report
from coopkin_sym.present.sentences import describe_joint_motion, describe_twist, twist_words

PACKAGE = Path(coopkin_sym.__file__).parent
#: Calls that can evaluate text, found in the syntax tree (not in comments or docs):
#: SymPy's evaluating readers under any name, Python's builtins called by name.
SYMPY_READERS = {"sympify", "parse_expr", "S"}
BUILTINS = {"eval", "exec", "compile", "__import__"}


def calls(source: str) -> list[tuple[int, str]]:
    """``(line, name)`` of every call that can evaluate text."""
    out = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Call):
            func = node.func
            if isinstance(func, ast.Name) and func.id in SYMPY_READERS | BUILTINS:
                out.append((node.lineno, func.id))
            elif isinstance(func, ast.Attribute) and (
                    func.attr in SYMPY_READERS or func.attr in BUILTINS and isinstance(
                        func.value, ast.Name) and func.value.id == "builtins"):
                out.append((node.lineno, func.attr))
    return sorted(out)


def offenders() -> list[str]:
    """``path:line: text`` of every evaluating call not marked ``# parse-ok``."""
    out = []
    for path in sorted(PACKAGE.rglob("*.py")):
        lines = path.read_text().splitlines()
        for number, _ in calls(path.read_text()):
            if "# parse-ok" not in lines[number - 1]:
                out.append(f"{path.relative_to(PACKAGE.parent)}:{number}: "
                           f"{lines[number - 1].strip()}")
    return out


def test_the_scan_finds_what_it_looks_for():
    for line in ["x = sp.sympify(text)", "parse_expr(s)", "eval(t)", "exec(code)",
                 "sp.S(str(v))", "y = sympify (a)", "f = compile(s, 'x', 'exec')",
                 "builtins.eval(t)", "sympy.parsing.sympy_parser.parse_expr(t)"]:
        assert calls(line), line
    for line in ["parse_expression(text, [], 'x')", "x.evalf(30)", "self._eval_power(e)",
                 "exact_expr(e)", "# sympify(x)", "'eval(x)'", "sp.S.Zero",
                 "re.compile(r'x')"]:
        assert not calls(line), line


def test_no_text_is_evaluated_anywhere_in_the_package():
    found = offenders()
    assert not found, "\n".join(found)


def test_no_evaluation_is_marked_as_accepted():
    marked = [(p.relative_to(PACKAGE).as_posix(), name) for p in PACKAGE.rglob("*.py")
              for number, name in calls(p.read_text())
              if "# parse-ok" in p.read_text().splitlines()[number - 1]]
    assert marked == []


# ----------------------------------------------------------------- payloads


def payloads(marker: Path) -> list[str]:
    m = str(marker)
    return [
        f"__import__('os').system('touch {m}')",
        f"__import__('pathlib').Path('{m}').touch()",
        f"open('{m}', 'w')",
        f"(lambda: open('{m}', 'w'))()",
        f"[c for c in ().__class__.__base__.__subclasses__()][0]('{m}')",
        f"exec(\"open('{m}','w')\")",
        f"eval(\"open('{m}','w')\")",
        f"Symbol('x').__class__.__init__.__globals__['__builtins__']['open']('{m}','w')",
        f"Integer(open('{m}','w'))",
        f"Rational(1, __import__('os').system('touch {m}'))",
        f"sqrt(__import__('os').system('touch {m}'))",
        f"atan(1)+__import__('os').system('touch {m}')",
        f"L*0 + __import__('os').system('touch {m}')",
        f"1 if open('{m}','w') else 0",
        f"CRootOf(x**2 - open('{m}','w'), 0)",
    ]


@pytest.fixture()
def marker(tmp_path):
    path = tmp_path / "MARKER"
    yield path
    assert not path.exists(), "a payload ran"


BASE = {"name": "x", "parameters": ["L"],
        "arms": [{"name": "a1", "joints": [{"name": "q1", "type": "revolute",
                                            "axis": [0, 0, 1], "point": [0, 0, 0]}]},
                 {"name": "a2", "joints": [{"name": "q2", "type": "revolute",
                                            "axis": [0, 0, 1], "point": ["L", 0, 0]}]}],
        "contacts": [{"name": "c1", "link": "a1/1", "point": [0, "L", 0],
                      "normal": [1, 0, 0], "model": "hard"},
                     {"name": "c2", "link": "a2/1", "point": ["L", "L", 0],
                      "normal": [-1, 0, 0], "model": "hard"}]}


def _refused(call):
    try:
        call()
    except CoopkinError:
        return True
    return False


def test_parser_entries_never_run_code(marker):
    L = sp.Symbol("L", positive=True)
    for text in payloads(marker):
        assert _refused(lambda t=text: parse_expression(t, ["L", "x"], "x"))
        assert _refused(lambda t=text: parse_number(t, {"L": L}, "x"))
        assert _refused(lambda t=text: parse_angle(t, "q1"))
        assert _refused(lambda t=text: exact_expr(t, {"L": L}, "x"))


def test_model_files_never_run_code(marker, tmp_path):
    for text in payloads(marker):
        model = json.loads(json.dumps(BASE))
        model["contacts"][0]["point"][1] = text
        assert _refused(lambda m=model: load(m))
        model = json.loads(json.dumps(BASE))
        model["arms"][0]["joints"][0]["axis"][2] = text
        assert _refused(lambda m=model: load(m))
        path = tmp_path / "m.json"
        path.write_text(json.dumps(model))
        assert _refused(lambda p=path: load(p))


def test_api_entries_taking_text_never_run_code(marker):
    system = load(BASE)
    analysis = system.analyze("L=2")
    generic = system.analyze(generic=True)
    for text in payloads(marker):
        assert _refused(lambda t=text: system.analyze(f"q1={t}"))
        assert _refused(lambda t=text: system.analyze({"q1": t}))
        assert _refused(lambda t=text: system.analyze({"L": t}))
        assert _refused(lambda t=text: analysis.joint_velocities([t, 0, 0, 0, 0, 0]))
        assert _refused(lambda t=text: analysis.object_velocities([t, 0]))
        assert _refused(lambda t=text: generic.joint_velocities([t, 0, 0, 0, 0, 0]))
        assert _refused(lambda t=text: describe_twist([t, 0, 0, 0, 0, 1], analysis))
        assert _refused(lambda t=text: describe_joint_motion([t, 1], analysis))
        assert _refused(lambda t=text: twist_words([t, 0, 0, 0, 0, 1]))
        assert _refused(lambda t=text: system.sweep([f"q1={t}"]))
        assert _refused(lambda t=text: system.sweep(["q1=0"], at=f"L={t}"))


def _report(text: str, k: int) -> dict:
    """A report whose every text field a user could edit holds ``text``: equations,
    witness, fixed values, the condition (as text, or as data every other time)."""
    generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
    locus = Locus("demo", ["t_q1", "t_q2", "L"], "L=1", generic, [Component(
        ["t_q1", "t_q1 - 1"], dict(generic, Nm=3), {"q1": "0", "q2": "0"}, True,
        condition="q1 = 0", kind="isolated")])
    data = json.loads(render_json(locus))
    data["fixed"] = f"L={text}"
    comp = data["components"][0]
    comp.update(equations=[text, f"t_q1 - {text}"], witness={"q1": text, "q2": "0"},
                condition=f"q1 = {text}")
    if k % 2:
        comp.pop("condition_data")
    else:
        comp["condition_data"] = [[{"value": "q1", "equals": text, "kind": "revolute"}],
                                  [{"vanishes": text}]]
    return data


def test_reports_read_back_never_run_code(marker, tmp_path):
    for k, text in enumerate(payloads(marker)):
        data = _report(text, k)
        try:
            locus = locus_from_json(data)
        except CoopkinError:
            continue
        for suffix in (".md", ".html", ".tex", ".json"):
            out = tmp_path / f"r{k}{suffix}"
            try:
                write_report(locus, out)
            except CoopkinError:
                pass


def test_cli_options_never_run_code(marker, tmp_path):
    runner = CliRunner()
    for text in payloads(marker):
        for args in (["analyze", "paper-case1-hard", "--at", f"q1={text}"],
                     ["analyze", "paper-case1-hard", "--free", text],
                     ["sweep", "paper-case1-hard", "--grid", f"q1=0..{text}:3"],
                     ["draw", "paper-case1-hard", "-o", str(tmp_path / "x.png"),
                      "--motion", text],
                     ["locus", "paper-case1-hard", "-o", str(tmp_path / "r.md"),
                      "--pair", text]):
            result = runner.invoke(app, args)
            assert result.exit_code == 2, (args, result.output)
            assert "Traceback" not in result.output


def test_number_error_is_the_package_error():
    assert issubclass(NumberError, CoopkinError)
    assert issubclass(NumberError, ValueError)
