"""Exact sweeps: every point agrees with the exact analysis; modular certification,
exact rechecks of singular points, grids and snapping, executors, the CLI."""

from __future__ import annotations

import json
import random
import sys
from concurrent.futures import ProcessPoolExecutor
from fractions import Fraction

import flint
import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from independent import reference_analysis
from strategies import random_configurations, random_systems
from typer.testing import CliRunner

import coopkin_sym
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.analysis.sweep import (
    SweepError,
    SweepResult,
    Value,
    compile_system,
    grid,
    parse_grid,
    sweep,
)
from coopkin_sym.cli import app
from coopkin_sym.errors import MissingDependency
from coopkin_sym.exact import modular
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import parse_angle

CASE1 = coopkin_sym.load("paper-case1-hard")
CASE2 = coopkin_sym.load("paper-case2-hard")
runner = CliRunner()


def assert_agrees_with_analyze(system, result) -> None:
    """All seven numbers at every point equal those of ``System.analyze``."""
    assert len(result) > 0
    for i in range(len(result)):
        expected = system.analyze(at=result.at_text(i)).numbers.as_dict()
        got = dict(zip(NUMBER_NAMES, result.numbers[i].tolist(), strict=True))
        assert got == expected, result.at_text(i)


# --- case study 1: every point, singular points found and rechecked ------------------
@pytest.mark.parametrize("at", [None, "L=3"])
def test_case1_grid_agrees_with_analyze_at_every_point(at):
    g = grid(CASE1, "q1=-pi..pi:5,q2=-pi..pi:5")
    assert [v.text for v in g.levels[0]] == ["-pi", "-pi/2", "0", "pi/2", "pi"]
    res = CASE1.sweep(g, at=at)
    assert len(res) == 25 and res.joints == ("q1", "q2")
    assert_agrees_with_analyze(CASE1, res)


def test_case1_singular_points_found_and_rechecked():
    res = sweep(CASE1, grid(CASE1, "q1=-pi..pi:5,q2=-pi..pi:5"), at="L=1")
    generic = res.generic.as_dict()
    assert generic == {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
    special = {(r["q1"], r["q2"]) for r in res.rows()
               if {k: r[k] for k in NUMBER_NAMES} != generic}
    # both links on the contact line (vertical): an extra motion and a hyperstatic force
    assert special == {("-pi/2", "-pi/2"), ("-pi/2", "pi/2"), ("pi/2", "-pi/2"),
                       ("pi/2", "pi/2")}
    for r in res.rows():
        if (r["q1"], r["q2"]) in special:
            assert r["exact_recheck"] is True
            assert (r["Nm"], r["Nc"], r["Nh"]) == (3, 3, 1)
    # the certified points are exactly the generic ones here
    assert res.summary() == {"points": 25, "certified_mod_p": 21, "rechecked_exact": 4,
                             "snapped_values": 0}
    assert (res.certified == ~res.rechecked).all()


def test_pi_is_swept_through_the_second_chart():
    res = sweep(CASE1, ["q1=pi,q2=pi", "q1=pi,q2=-pi/2", "q1=-pi,q2=pi/2"], at="L=2")
    assert [res.point(i) for i in range(3)] == [
        {"q1": "pi", "q2": "pi"}, {"q1": "pi", "q2": "-pi/2"}, {"q1": "pi", "q2": "pi/2"}]
    assert_agrees_with_analyze(CASE1, res)


# --- case study 2 ----------------------------------------------------------------------
@pytest.mark.parametrize("spec, at", [
    ("q1=-pi..pi:5,q2=-pi..pi:5", "L=1"),
    ("q2=-pi/2..pi/2:3,q5=-1..1:3", "L=2,q3=pi/2"),
    ("q7=-pi..pi:4,q8=0..pi:3", None),
])
def test_case2_grid_agrees_with_analyze_at_every_point(spec, at):
    res = CASE2.sweep(grid(CASE2, spec), at=at)
    assert_agrees_with_analyze(CASE2, res)


def test_case2_singular_line_is_rechecked():
    res = sweep(CASE2, grid(CASE2, "q1=-pi..pi:5,q2=-pi..pi:5"), at="L=1")
    rows = res.rows()
    singular = {(r["q1"], r["q2"]) for r in rows if r["Nr"] == 3}
    # the first arm's two links aligned along the y axis: one more redundant motion
    assert singular == {(a, b) for a in ("-pi", "-pi/2", "0", "pi/2", "pi")
                        for b in ("-pi/2", "pi/2")}
    assert all(r["exact_recheck"] for r in rows if (r["q1"], r["q2"]) in singular)
    assert res.numbers[:, 0].tolist() == [8] * 25


def test_single_point_numbers_agree_with_analyze():
    compiled = compile_system(CASE2, CASE2.joint_names, "L=1")
    rng = random.Random(7)
    kinds = [j.type for j in CASE2.model.joints]
    for trial in range(6):
        values = []
        for kind in kinds:
            if kind == "prismatic":
                f = Fraction(rng.randint(-9, 9), rng.randint(1, 5))
                values.append(Value(str(f), f.numerator, f.denominator))
            elif trial % 2:
                values.append(Value.from_tangent(rng.choice([None, 0, 1, -1])))
            else:
                values.append(Value.from_tangent(Fraction(rng.randint(-9, 9),
                                                          rng.randint(1, 9))))
        at = ",".join(f"{j}={v.text}" for j, v in zip(CASE2.joint_names, values,
                                                      strict=True))
        expected = CASE2.analyze(at=at + ",L=1").numbers
        assert compiled.numbers_at(values) == expected, at
        assert compiled.numbers(at) == expected


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_random_systems_agree_with_independent_reference(data):
    model = data.draw(random_systems(with_parameter=data.draw(st.booleans())))
    at, text = data.draw(random_configurations(model))
    joints = [j["name"] for arm in model["arms"] for j in arm["joints"]]
    assume(joints)
    params = {str(p) for p in model.get("parameters") or []}
    items = [p.split("=", 1) for p in text.split(",")]
    point = ",".join(f"{k}={v}" for k, v in items if k in joints)
    fixed = ",".join(f"{k}={v}" for k, v in items if k in params) or None
    ref = reference_analysis(model, at)
    system = coopkin_sym.load(model)
    res = system.sweep([point], at=fixed)
    assert res.numbers_at(0).as_dict() == {k: ref[k] for k in NUMBER_NAMES}
    # the same point with only the first joint swept, the rest fixed
    first = [f"{k}={v}" for k, v in items if k == joints[0]]
    rest = [f"{k}={v}" for k, v in items if k != joints[0]]
    res1 = system.sweep(first, at=",".join(rest) or None)
    assert res1.numbers_at(0).as_dict() == {k: ref[k] for k in NUMBER_NAMES}


# --- points, grids, snapping ---------------------------------------------------------
def test_explicit_points_defaults_and_duplicates():
    points = ["q1=pi/2,q2=pi/2", {"q1": "pi/2"}, {"q2": (0, 1), "q1": "2*atan(1/3)"}]
    res = CASE1.sweep(points, at="q2=pi/2,L=5")
    assert res.joints == ("q1", "q2")
    assert [res.point(i) for i in range(3)] == [
        {"q1": "pi/2", "q2": "pi/2"}, {"q1": "pi/2", "q2": "pi/2"},
        {"q1": "2*atan(1/3)", "q2": "pi/2"}]
    assert res.at == "L=5" and res.bound is None and res.snapped == []
    assert_agrees_with_analyze(CASE1, res)
    # one exact evaluation per distinct value
    assert [len(v) for v in res.levels] == [2, 1]


@pytest.mark.parametrize("points, message", [
    ([], "no points"),
    (["q3=0"], "unknown joint 'q3'"),
    (["L=1"], "L is a parameter"),
    (["q1=pi/3"], "not exact"),
    (["q1=0,q1=1"], "given more than once"),
    (["q1"], "expected NAME=VALUE"),
])
def test_bad_points_are_clear_errors(points, message):
    with pytest.raises(coopkin_sym.ConfigurationError, match=message):
        CASE1.sweep(points)


def test_snapping_is_exact_bounded_and_reported():
    g = grid(CASE1, "q1=0..pi/3:3,q2=-pi/2..pi/2:2")
    texts = [v.text for v in g.levels[0]]
    assert texts[0] == "0" and g.levels[1][0].text == "-pi/2"
    assert [s["requested"] for s in g.snapped] == ["pi/6", "pi/3"]
    for s, v in zip(g.snapped, g.levels[0][1:], strict=True):
        assert s["used"] == v.text and v.snapped
        cos, sin = parse_angle(v.text, "q1")                 # exact, rational tan(q/2)
        assert Fraction(str(sin / (1 + cos))) == Fraction(v.num, v.den)
        requested = sp.pi * (1 if s["requested"] == "pi" else sp.sympify(s["requested"]) /
                             sp.pi)
        dq = abs(2 * sp.atan(sp.Rational(v.num, v.den)) - requested)
        assert dq.evalf(50) <= sp.Rational(1, 10**9)          # the stated bound holds
        assert s["error_rad"] <= 1e-9                          # float-ok: reported value
    res = CASE1.sweep(g, at="L=1")
    assert res.bound == 1e-9 and len(res.snapped) == 2
    assert_agrees_with_analyze(CASE1, res)
    csv = res.to_csv()
    note = res.csv_metadata()["header"]["snapping"]["note"]     # next to the CSV
    assert note.startswith("2 grid angles with an irrational tan(q/2)")
    assert "|dq| <= 1e-09 rad" in note
    assert not any(line.startswith("#") for line in csv.splitlines())
    head = res.to_json()["header"]["snapping"]
    assert head["bound_rad"] == 1e-9 and [s["requested"] for s in head["snapped"]] == [
        "pi/6", "pi/3"]


def test_grid_values_and_texts():
    g = grid(CASE2, {"q1": ("-pi", "pi", 9), "q4": ("-1/2", "1", 4), "q8": ("1/2", "1/2", 1)})
    assert g.shape == (9, 4, 1) and len(g) == 36
    assert [v.text for v in g.levels[0]][::2] == ["-pi", "-pi/2", "0", "pi/2", "pi"]
    assert [(v.num, v.den) for v in g.levels[0]][::2] == [(1, 0), (-1, 1), (0, 1), (1, 1),
                                                          (1, 0)]
    assert [v.text for v in g.levels[1]] == ["-1/2", "0", "1/2", "1"]
    assert g.levels[2][0].snapped and g.levels[2][0].requested == "1/2"
    first = next(iter(g))
    assert first == {"q1": "-pi", "q4": "-1/2", "q8": g.levels[2][0].text}


def test_value_text_is_the_canonical_angle_text():
    for t in [Fraction(1, 3), Fraction(-5, 2), Fraction(7), Fraction(1), Fraction(-1), 0]:
        v = Value.from_tangent(t)
        t = sp.Rational(str(t))
        cos, sin = (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)
        assert v.text == ExactAngle.from_cos_sin(cos, sin).text
        assert Value.from_angle(ExactAngle.from_cos_sin(cos, sin)) == v
    assert Value.from_tangent(None).text == ExactAngle.from_cos_sin(-1, 0).text == "pi"


@pytest.mark.parametrize("spec, message", [
    ("q9=0..1:3", "unknown joint 'q9'"),
    ("L=0..1:3", "L is a parameter"),
    ("q1=0..1", "expected NAME=LO..HI:COUNT"),
    ("q1=0:3", "expected NAME=LO..HI:COUNT"),
    ("q1=..1:3", "expected NAME=LO..HI:COUNT"),
    ("q1=0..1:x", "is not an integer"),
    ("q1=0..1:0", "zero points"),
    ("q1=0..1:-2", "zero points"),
    ("q1=0..y:3", "undeclared symbol y"),
    ("q1=0..1:2,q1=0..1:2", "more than once"),
    ("", "no joint given"),
])
def test_bad_grids_are_clear_errors(spec, message):
    with pytest.raises(SweepError, match=message):
        grid(CASE1, spec)


def test_prismatic_grid_must_be_rational():
    with pytest.raises(SweepError, match="rational ends"):
        grid(CASE2, "q4=0..pi:3")
    assert parse_grid("q1=Rational(-1, 2)..1:3") == {"q1": ("Rational(-1, 2)", "1", 3)}


# --- executors ---------------------------------------------------------------------------
def test_process_pool_gives_the_serial_result():
    g = grid(CASE1, "q1=-pi..pi:9,q2=-pi/2..pi/2:5")
    serial = CASE1.sweep(g, at="L=1", chunk=7)
    with ProcessPoolExecutor(2) as pool:
        parallel = CASE1.sweep(g, at="L=1", executor=pool, chunk=7)
    assert (parallel.numbers == serial.numbers).all()
    assert (parallel.rechecked == serial.rechecked).all()
    assert parallel.rows() == serial.rows()
    assert serial.rechecked.sum() == 4           # (+-pi/2, +-pi/2)


def test_progress_bar_does_not_change_the_result(capsys):
    g = grid(CASE1, "q1=-pi..pi:5,q2=0..pi/2:2")
    assert (CASE1.sweep(g, progress=True).numbers == CASE1.sweep(g).numbers).all()


# --- the modular layer --------------------------------------------------------------------
def test_rank_profile_matches_flint_modulo_p():
    rng = np.random.default_rng(3)
    p = 101
    batch = []
    for k in range(200):
        rank = k % 5
        a = rng.integers(-3, 4, (5, rank)) @ rng.integers(-3, 4, (rank, 7))
        batch.append(a % p)
    stack = np.array(batch, dtype=np.int64).transpose(1, 2, 0).copy()
    ranks, first = modular.rank_profile(stack.copy(), p, prefix=3)
    for i, a in enumerate(batch):
        assert ranks[i] == flint.nmod_mat(a.tolist(), p).rank()
        assert first[i] == flint.nmod_mat(a[:, :3].tolist(), p).rank()


def test_modular_evaluation_matches_integer_evaluation():
    rng = random.Random(5)
    p = modular.PRIME
    exps = np.array([[rng.randint(0, 3) for _ in range(3)] for _ in range(20)])
    coefs = [rng.randint(-10**12, 10**12) for _ in range(20)]
    entries = np.array([rng.randrange(4) for _ in range(20)])
    points = [[rng.randint(-10**6, 10**6) for _ in range(3)] for _ in range(6)]
    got = modular.evaluate(exps, modular.residues(coefs, p), entries, 4,
                           modular.residues([x for pt in zip(*points, strict=True) for x in pt], p)
                           .reshape(3, 6), p)
    for b, pt in enumerate(points):
        want = [0] * 4
        for e, c, k in zip(exps.tolist(), coefs, entries.tolist(), strict=True):
            want[k] += c * pt[0] ** e[0] * pt[1] ** e[1] * pt[2] ** e[2]
        assert got[:, b].tolist() == [w % p for w in want]


# --- the command line ---------------------------------------------------------------------
def test_cli_csv_content(tmp_path):
    args = ["sweep", "paper-case1-hard", "--grid", "q1=-pi/2..pi/2:3,q2=-pi/2..pi/2:3",
            "--at", "L=1"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    table = result.stdout.splitlines()          # a plain CSV: no comment lines
    assert table[0] == "q1,q1_rad,q2,q2_rad,Nm,Nc,Ni,Nr,Ng,Nd,Nh,exact_recheck"
    assert table[1] == ("-pi/2,-1.5707963267948966,-pi/2,-1.5707963267948966,"
                        "3,3,1,0,1,4,1,true")
    assert table[5] == "0,0.0,0,0.0,2,2,1,0,1,4,0,false"
    assert len(table) == 10
    out = tmp_path / "map.csv"                  # -o: the same table, its metadata next to it
    result = runner.invoke(app, [*args, "-o", str(out), "--no-progress"])
    assert result.exit_code == 0, result.output
    assert f"wrote {out} and {out}.json" in result.stdout
    assert out.read_text().splitlines() == table
    header = json.loads((tmp_path / "map.csv.json").read_text())["header"]
    assert header["at"] == "L=1" and header["columns"] == table[0].split(",")
    assert header["snapping"]["note"] == "none: every angle is exact as requested"


def test_cli_json_and_files(tmp_path):
    out = tmp_path / "sweep.json"
    result = runner.invoke(app, ["sweep", "paper-case1-hard", "--grid", "q1=0..pi/2:3",
                                 "--at", "q2=pi/2,L=2", "-o", str(out), "--workers", "2"])
    assert result.exit_code == 0, result.output
    assert "3 points" in result.stdout and "1 snapped" in result.stdout
    data = json.loads(out.read_text())
    assert data["header"]["at"] == "q2=pi/2,L=2"
    assert data["header"]["snapping"]["bound_rad"] == 1e-9
    assert data["header"]["snapping"]["snapped"][0]["requested"] == "pi/4"
    assert [p["q1"] for p in data["points"]][::2] == ["0", "pi/2"]
    assert data["points"][2] == {"q1": "pi/2", "Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0,
                                 "Ng": 1, "Nd": 4, "Nh": 1, "exact_recheck": True}
    csv = tmp_path / "sweep.csv"
    result = runner.invoke(app, ["sweep", "paper-case1-hard", "--grid", "q1=0..pi/2:3",
                                 "-o", str(csv), "--no-progress"])
    assert result.exit_code == 0, result.output
    assert csv.read_text().splitlines()[0] == "q1,q1_rad,Nm,Nc,Ni,Nr,Ng,Nd,Nh,exact_recheck"
    back = SweepResult.read(csv)
    assert back.to_csv() == csv.read_text() and back.summary()["snapped_values"] == 1
    result = runner.invoke(app, ["sweep", "paper-case1-hard", "--grid", "q1=0..1:2",
                                 "--json"])
    assert json.loads(result.stdout)["header"]["counts"]["points"] == 2


@pytest.mark.parametrize("args, message", [
    (["--grid", "q7=0..1:3"], "unknown joint 'q7'"),
    (["--grid", "q1=0..1;3"], "expected NAME=LO..HI:COUNT"),
    (["--grid", "q1=0..1:0"], "zero points"),
    (["--grid", "q1=0..1:2", "--at", "q2=pi/3"], "not exact"),
    (["--grid", "q1=0..1:2", "-o", "out.txt"], "unknown table (--output) format"),
])
def test_cli_errors_are_clean_and_write_nothing(tmp_path, args, message):
    out = tmp_path / "out.csv"
    full = ["sweep", "paper-case1-hard", *args]
    if "-o" not in args:
        full += ["-o", str(out)]
    result = runner.invoke(app, full)
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    assert result.stderr.startswith("coopkin: error: ") and message in result.stderr
    assert "Traceback" not in result.stderr
    assert not out.exists() and list(tmp_path.iterdir()) == []


# --- float columns and pandas -------------------------------------------------------------
def _table(csv: str) -> list[list[str]]:
    assert not any(line.startswith("#") for line in csv.splitlines())
    return [line.split(",") for line in csv.splitlines()]


def test_csv_has_a_float_column_next_to_each_exact_one():
    res = CASE1.sweep(grid(CASE1, "q1=-pi..pi:5,q2=pi/6..pi/6:1"), at="L=1")
    csv = res.to_csv()
    assert res.csv_metadata()["header"]["float_columns"]["q1_rad"] == (
        "q1 in radians, a float (the exact value is in column q1)")
    head, *rows = _table(csv)
    assert head[:4] == ["q1", "q1_rad", "q2", "q2_rad"]
    for row in rows:
        for k in (0, 2):                      # the float is the exact angle, rounded
            exact = sp.sympify(row[k]).evalf(30)
            assert abs(float(row[k + 1]) - float(exact)) <= 1e-15   # float-ok: the check
        assert all(x.isdigit() for x in row[4:11])                  # numbers: integers
    assert [r[0:2] for r in rows][::2] == [["-pi", "-3.141592653589793"],
                                           ["0", "0.0"], ["pi", "3.141592653589793"]]
    assert rows[0][2].startswith("2*atan(")    # pi/6 snapped to an exact angle
    assert res.header()["float_columns"] == res.float_columns()
    assert res.rows()[0].keys() == {"q1", "q2", "Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh",
                                    "exact_recheck"}   # the JSON points stay exact


def test_prismatic_float_column():
    case2 = coopkin_sym.load("paper-case2-hard")
    res = case2.sweep(grid(case2, "q4=-1/3..1:3"), at="L=1")
    head, first, *_ = _table(res.to_csv())
    assert head[:2] == ["q4", "q4_float"] and first[:2] == ["-1/3", "-0.3333333333333333"]


def test_to_pandas():
    pd = pytest.importorskip("pandas")
    res = CASE1.sweep(grid(CASE1, "q1=-pi/2..pi/2:3,q2=-pi/2..pi/2:3"), at="L=1")
    df = res.to_pandas()
    assert isinstance(df, pd.DataFrame) and len(df) == 9
    assert list(df.columns) == res.csv_columns()
    assert all(str(df[k].dtype) == "int64" for k in ("Nm", "Nc", "Ni", "Nr", "Ng", "Nd",
                                                       "Nh"))
    assert str(df["q1_rad"].dtype) == "float64" and str(df["exact_recheck"].dtype) == "bool"
    assert df["q1"].tolist() == [r["q1"] for r in res.rows()]
    assert df["Nm"].tolist() == res.numbers[:, 0].tolist()
    assert df.attrs["header"]["system"] == "paper case 1, hard/hard"
    assert df.loc[df["Nm"] == 3, ["q1", "q2"]].values.tolist() == [
        ["-pi/2", "-pi/2"], ["-pi/2", "pi/2"], ["pi/2", "-pi/2"], ["pi/2", "pi/2"]]


def test_to_pandas_without_pandas(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)       # import pandas fails
    res = CASE1.sweep(["q1=pi/2"])
    with pytest.raises(MissingDependency, match="pip install pandas"):
        res.to_pandas()


def test_a_swept_angle_may_be_given_as_text_an_exact_angle_or_a_pair():
    c = compile_system(CASE1, ["q1", "q2"], "L=1")
    by_text = c.numbers({"q1": "-pi/2", "q2": "-pi/2"})
    by_angle = c.numbers({"q1": ExactAngle(-1, 1), "q2": ExactAngle(-2, 2)})
    by_pair = c.numbers({"q1": (0, -1), "q2": (sp.Integer(0), sp.Integer(-1))})
    assert by_text == by_angle == by_pair and by_text.Nm == 3
    assert c.value("q1", ExactAngle(1, 0)) == Value("pi", 1, 0)
    assert c.numbers({"q1": ExactAngle(1, 3)}) == c.numbers({"q1": "2*atan(1/3)"})
