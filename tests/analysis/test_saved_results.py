"""Sweep and manipulability results written as JSON and read back: the package's
output validates against the documented schemas (docs/sweep.schema.json,
docs/manipulability.schema.json, and docs/analyze-json.schema.json for
``Analysis.as_json``), reading it back gives an equal result, and a bad entry is one
package error naming it."""

from __future__ import annotations

import csv
import dataclasses
import json
import sys
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from random_systems import random_system
from strategies import random_systems
from typer.testing import CliRunner

import coopkin_sym
from coopkin_sym.analysis.manipulability import Manipulability
from coopkin_sym.analysis.sweep import SweepResult, grid
from coopkin_sym.cli import app
from coopkin_sym.errors import ManipulabilityError, MissingDependency, ModelError, SweepError

jsonschema = pytest.importorskip("jsonschema")
DOCS = Path(__file__).resolve().parents[2] / "docs"


def schema(name: str):
    data = json.loads((DOCS / name).read_text())
    jsonschema.Draft202012Validator.check_schema(data)
    return jsonschema.Draft202012Validator(data)


SWEEP, MANIPULABILITY = schema("sweep.schema.json"), schema("manipulability.schema.json")
SWEEP_CSV = schema("sweep-csv.schema.json")
QUICK = ["paper-case1-hard", "paper-case1-soft", "paper-case1-planar", "five-bar",
         "planar-two-fingers", "paper-case2-hard"]


def errors(validator, data) -> list[str]:
    return [e.message for e in validator.iter_errors(data)]


def round_trip_sweep(result: SweepResult) -> None:
    assert errors(SWEEP, result.to_json()) == []
    assert errors(SWEEP, json.loads(result.json_text())) == []
    back = SweepResult.from_json(result.json_text())
    assert back == result
    assert back.to_json() == result.to_json()
    assert back.to_csv() == result.to_csv()
    assert SweepResult.from_json(result.to_json()) == result
    data = result.to_json()                 # every column the header names is in each point
    header = data["header"]
    named = set(header["columns"]) | set(header.get("float_columns", ()))
    assert all(named <= point.keys() for point in data["points"])
    assert all(list(point) == header["columns"] for point in data["points"])
    assert list(data["header"]["kinds"]) == data["header"]["joints"]
    with tempfile.TemporaryDirectory() as folder:
        table = Path(folder) / "sweep.csv"
        result.write(table)
        metadata = json.loads(Path(f"{table}.json").read_text())
        assert errors(SWEEP_CSV, metadata) == []
        assert metadata == result.csv_metadata()
        assert table.read_text().splitlines()[0].split(",") == metadata["header"]["columns"]
        assert SweepResult.read(table) == result


def round_trip_manipulability(m: Manipulability) -> None:
    data = m.to_json()
    assert errors(MANIPULABILITY, data) == []
    back = Manipulability.from_json(json.dumps(data))
    assert back == m
    assert back.to_json() == data


@pytest.mark.parametrize("name", QUICK)
def test_shipped_examples_round_trip(name, tmp_path):
    system = coopkin_sym.load(name)
    first = system.model.joints[0].name
    spec = ",".join(f"{j}=-pi..pi:5" for j in system.joint_names[:2])
    result = system.sweep(grid(system, spec))
    round_trip_sweep(result)
    result.write(tmp_path / "sweep.json")
    assert SweepResult.read(tmp_path / "sweep.json") == result
    points = system.sweep([f"{first}=pi/2", f"{first}=2*atan(1/3)", f"{first}=pi"])
    round_trip_sweep(points)
    m = system.analyze().manipulability()
    round_trip_manipulability(m)
    m.write(tmp_path / "m.json")
    assert Manipulability.read(tmp_path / "m.json") == m


def test_a_snapped_grid_keeps_its_requested_angles():
    system = coopkin_sym.load("paper-case1-hard")
    result = system.sweep(grid(system, "q1=-pi..pi:7,q2=-pi/3..pi:4"))
    assert result.summary()["snapped_values"] == 7
    back = SweepResult.from_json(result.json_text())
    assert back == result and back.snapped == result.snapped


def test_symbolic_and_parametric_ellipsoids_round_trip():
    for name, kwargs in [("paper-case1-soft", {"generic": True}),
                         ("paper-case1-hard", {"free": ["q1"]})]:
        a = coopkin_sym.load(name).analyze(**kwargs)
        m = a.manipulability(length="L")
        assert m.to_json()["symbols"]["L"] == "positive"
        round_trip_manipulability(m)


@settings(max_examples=15, deadline=None, derandomize=True,
          suppress_health_check=list(HealthCheck))
@given(random_systems(max_arms=2, max_joints=2, max_contacts=2), st.integers(2, 4))
def test_random_systems_round_trip(model, count):
    """Random systems (the same ones at every run), their manipulability at home with
    every length 1: a symbolic ellipsoid of a random system can need more memory than
    the machine has (the symbolic round trip has its own test above)."""
    try:
        system = coopkin_sym.load(model)
    except ModelError:
        return
    spec = ",".join(f"{j}=-pi..pi:{count}" if system.model.joints[k].type == "revolute"
                    else f"{j}=-1..1:{count}"
                    for k, j in enumerate(system.joint_names[:2]))
    round_trip_sweep(system.sweep(grid(system, spec)))
    lengths = ",".join(f"{p.name}=1" for p in system.model.parameters) or None
    round_trip_manipulability(system.analyze(lengths).manipulability())


@pytest.mark.parametrize("seed", range(4))
def test_seeded_random_systems_round_trip(seed):
    system = coopkin_sym.load(random_system(seed))
    spec = ",".join(f"{j.name}=-pi..pi:3" for j in system.model.joints[:2]
                    if j.type == "revolute") or None
    if spec:
        round_trip_sweep(system.sweep(grid(system, spec)))
    round_trip_manipulability(system.analyze().manipulability())


@pytest.fixture(scope="module")
def sweep_json() -> dict:
    return coopkin_sym.load("paper-case1-hard").sweep(
        ["q1=pi/2,q2=pi/2", "q1=0,q2=pi"]).to_json()


def bad(data: dict, path: tuple, value) -> dict:
    data = json.loads(json.dumps(data))
    if path[:2] == ("header", "float_columns"):     # files of earlier versions: no kinds
        del data["header"]["kinds"]
    node = data
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return data


@pytest.mark.parametrize("path, value, message", [
    (("points", 1, "q2"), "pi/3", "not a sweep result: points[1].q2: angle 'pi/3' is "
                                  "not exact"),
    (("points", 0, "q1"), "__import__('os')", "not a sweep result: points[0].q1: "),
    (("points", 0, "Nm"), "3", "not a sweep result: points[0].Nm: expected an integer, "
                               "got '3'"),
    (("points", 0, "Nm"), -1, "not a sweep result: points[0].Nm: expected a count"),
    (("points", 0, "exact_recheck"), 1, "not a sweep result: points[0].exact_recheck: "
                                        "expected true or false, got 1"),
    (("points", 0, "extra"), "x", "not a sweep result: points[0].extra: unknown entry"),
    (("header", "prime"), 2**40, "not a sweep result: header.prime: expected a prime"),
    (("header", "counts", "points"), 3, "not a sweep result: header.counts.points: 3 "
                                        "does not match the points (2)"),
    (("header", "joints"), ["q1", "q1"], "not a sweep result: header.joints: a joint is "
                                         "named twice"),
    (("header", "float_columns"), {"q1_x": "", "q2_rad": ""},
     "not a sweep result: header.float_columns.q1_x: expected q1_rad or q1_float"),
    (("header", "kinds", "q1"), "spherical", "not a sweep result: header.kinds.q1: "
                                            "expected revolute or prismatic, got 'spherical'"),
    (("header", "kinds"), {"q1": "revolute"}, "not a sweep result: header.kinds.q2: missing"),
    (("header", "columns"), ["q1", "q1_rad", "q2", "q2_rad", "Nm", "Nc", "Ni", "Nr", "Ng",
                             "Nd", "Nh", "exact_recheck"],
     "not a sweep result: header.columns: expected q1, q2, Nm, Nc, Ni, Nr, Ng, Nd, Nh, "
     "exact_recheck"),
])
def test_a_bad_sweep_entry_is_one_error_naming_it(sweep_json, path, value, message):
    with pytest.raises(SweepError) as info:
        SweepResult.from_json(bad(sweep_json, path, value))
    assert str(info.value).startswith(message)
    assert "\n" not in str(info.value)


def test_bad_sweep_texts_and_files(tmp_path):
    with pytest.raises(SweepError, match="^not a sweep result: line 1, column 2: not "
                                         "valid JSON"):
        SweepResult.from_json("{x")
    with pytest.raises(SweepError, match="^not a sweep result: expected a JSON object"):
        SweepResult.from_json("[1]")
    with pytest.raises(SweepError, match="^/dev/null: is a character device"):
        SweepResult.read("/dev/null")
    (tmp_path / "s.json").write_text('{"header": {}, "points": [], "header": 1}')
    with pytest.raises(SweepError, match="duplicate key 'header'"):
        SweepResult.read(tmp_path / "s.json")


@pytest.mark.parametrize("key, value, message", [
    ("shape", [["1/2", "0"]], "not a manipulability result: shape: expected a square "
                              "matrix of 2 rows"),
    ("index", "exec(1)", "not a manipulability result: index: 'exec(1)' uses unknown "
                         "function exec"),
    ("index", "t_q9", "not a manipulability result: index: "),
    ("rank", 3, "not a manipulability result: rank: expected 0 to 2, got 3"),
    ("rank", True, "not a manipulability result: rank: expected an integer, got true"),
    ("symbols", {"L": "imaginary"}, "not a manipulability result: symbols.L: expected "
                                    "one of positive, real, none"),
    ("extra", 1, "not a manipulability result: extra: unknown entry"),
])
def test_a_bad_manipulability_entry_is_one_error_naming_it(key, value, message):
    good = coopkin_sym.load("five-bar").analyze("L=1").manipulability(
        ["v_x", "v_y"], point=[0, 2, 0]).to_json()
    with pytest.raises(ManipulabilityError) as info:
        Manipulability.from_json({**good, key: value})
    assert str(info.value).startswith(message)


def test_analysis_as_json_validates_against_the_analyze_schema():
    """``as_json`` is the document of ``coopkin analyze --json`` without the words the
    presentation layer adds: the schema's ``$defs/data``."""
    from referencing import Registry, Resource

    root = json.loads((DOCS / "analyze-json.schema.json").read_text())
    registry = Registry().with_resource("urn:analyze", Resource.from_contents(root))
    data = jsonschema.Draft202012Validator({"$ref": "urn:analyze#/$defs/data"},
                                           registry=registry)
    cases = [("paper-case1-hard", None), ("paper-case1-hard", "q1=-pi/6,q2=pi/6"),
             ("paper-case2-hard", "q1=pi/3,q3=pi/4"), ("five-bar", "q1=pi/2"),
             ("five-bar", "q1=pi/3"), ("paper-case1-planar", "q1=pi/2")]
    for name, at in cases:
        out = coopkin_sym.load(name).analyze(at).as_json()
        assert errors(data, out) == [], (name, at)
    generic = coopkin_sym.load("paper-case2-hard").analyze(generic=True).as_json()
    assert errors(data, generic) == []
    assert not data.is_valid({k: v for k, v in generic.items() if k != "certificate"})


# --- the table: a plain CSV and its metadata, the commented CSV of earlier versions --------
CASE1 = coopkin_sym.load("paper-case1-hard")
SNAPPED = CASE1.sweep(grid(CASE1, "q1=0..pi/3:3,q2=-pi/2..pi/2:2"), at="L=1")
POINTS = CASE1.sweep(["q1=pi/2,q2=pi", "q1=0"])

# written by the versions before the metadata file (SNAPPED and POINTS, and a prismatic
# joint of case 2)
OLD_SNAPPED = """\
# system: paper case 1, hard/hard
# fixed: L=1
# generic numbers (swept joints symbolic): Nm=2 Nc=2 Ni=1 Nr=0 Ng=1 Nd=4 Nh=0
# points: 6; certified modulo p = 2147483647: 6; rechecked exactly over Q: 0
# snapped: 2 grid angles with an irrational tan(q/2) were replaced by a nearby angle \
with a rational tan(q/2), |dq| <= 1e-09 rad (largest 3.28e-10 rad); the angles \
written are the exact ones used
# q1_rad: q1 in radians, a float (the exact value is in column q1)
# q2_rad: q2 in radians, a float (the exact value is in column q2)
q1,q1_rad,q2,q2_rad,Nm,Nc,Ni,Nr,Ng,Nd,Nh,exact_recheck
0,0.0,-pi/2,-1.5707963267948966,2,2,1,0,1,4,0,false
0,0.0,pi/2,1.5707963267948966,2,2,1,0,1,4,0,false
2*atan(10864/40545),0.523598775270617,-pi/2,-1.5707963267948966,2,2,1,0,1,4,0,false
2*atan(10864/40545),0.523598775270617,pi/2,1.5707963267948966,2,2,1,0,1,4,0,false
2*atan(29681/51409),1.0471975515242795,-pi/2,-1.5707963267948966,2,2,1,0,1,4,0,false
2*atan(29681/51409),1.0471975515242795,pi/2,1.5707963267948966,2,2,1,0,1,4,0,false
"""
OLD_POINTS = """\
# system: paper case 1, hard/hard
# fixed: home, parameters symbolic
# generic numbers (swept joints symbolic): Nm=2 Nc=2 Ni=1 Nr=0 Ng=1 Nd=4 Nh=0
# points: 2; certified modulo p = 2147483647: 2; rechecked exactly over Q: 0
# snapped: none: every angle is exact as requested
# q1_rad: q1 in radians, a float (the exact value is in column q1)
# q2_rad: q2 in radians, a float (the exact value is in column q2)
q1,q1_rad,q2,q2_rad,Nm,Nc,Ni,Nr,Ng,Nd,Nh,exact_recheck
pi/2,1.5707963267948966,pi,3.141592653589793,2,2,1,0,1,4,0,false
0,0.0,0,0.0,2,2,1,0,1,4,0,false
"""
OLD_PRISMATIC = """\
# system: paper case 2, two SCARA robots, hard/hard
# fixed: L=1
# generic numbers (swept joints symbolic): Nm=8 Nc=6 Ni=1 Nr=2 Ng=1 Nd=0 Nh=0
# points: 3; certified modulo p = 2147483647: 3; rechecked exactly over Q: 0
# snapped: none: every angle is exact as requested
# q4_float: q4 as a float (the exact value is in column q4)
q4,q4_float,Nm,Nc,Ni,Nr,Ng,Nd,Nh,exact_recheck
-1/3,-0.3333333333333333,8,6,1,2,1,0,0,false
1/3,0.3333333333333333,8,6,1,2,1,0,0,false
1,1.0,8,6,1,2,1,0,0,false
"""


def test_the_csv_is_plain_and_its_metadata_is_next_to_it(tmp_path):
    pd = pytest.importorskip("pandas")
    SNAPPED.write(tmp_path / "map.csv")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["map.csv", "map.csv.json"]
    frame = pd.read_csv(tmp_path / "map.csv")               # no option needed
    assert list(frame.columns) == SNAPPED.csv_columns() and len(frame) == 6
    assert frame["Nm"].tolist() == SNAPPED.numbers[:, 0].tolist()
    assert frame["q1"].tolist()[2] == "2*atan(10864/40545)"
    assert str(frame["exact_recheck"].dtype) == "bool"
    header = json.loads((tmp_path / "map.csv.json").read_text())["header"]
    assert header == SNAPPED.header() and errors(SWEEP_CSV, {"header": header}) == []
    assert [s["requested"] for s in header["snapping"]["snapped"]] == ["pi/6", "pi/3"]
    back = SweepResult.read(tmp_path / "map.csv")
    assert back == SNAPPED and back.snapped == SNAPPED.snapped and back.bound == 1e-9


def test_a_commented_csv_of_earlier_versions_is_read(tmp_path):
    (tmp_path / "points.csv").write_text(OLD_POINTS)
    assert SweepResult.read(tmp_path / "points.csv") == POINTS       # nothing is lost
    assert POINTS.to_csv() == "".join(x + "\n" for x in OLD_POINTS.splitlines()[7:])
    (tmp_path / "snapped.csv").write_text(OLD_SNAPPED)
    back = SweepResult.read(tmp_path / "snapped.csv")
    assert back.to_csv() == SNAPPED.to_csv() and back.rows() == SNAPPED.rows()
    assert back.bound == 1e-9 and back.snapped == []        # no requested angles in it
    unsnapped = [[dataclasses.replace(v, requested=None, error=None) for v in vs]
                 for vs in SNAPPED.levels]
    assert back == dataclasses.replace(SNAPPED, levels=tuple(map(tuple, unsnapped)))
    case2 = coopkin_sym.load("paper-case2-hard")
    prismatic = case2.sweep(grid(case2, "q4=-1/3..1:3"), at="L=1")
    (tmp_path / "prismatic.csv").write_text(OLD_PRISMATIC)
    back = SweepResult.read(tmp_path / "prismatic.csv")
    assert back.kinds == ("prismatic",) and back.bound is None     # not in the file
    assert back == dataclasses.replace(prismatic, bound=None)


def test_a_json_of_earlier_versions_is_read():
    """Its header named the CSV's float columns (``float_columns``) instead of ``kinds``."""
    for result in (SNAPPED, POINTS):
        data = result.to_json()
        header = data["header"]
        del header["kinds"]
        header["float_columns"] = result.float_columns()
        assert errors(SWEEP, data) == []
        assert SweepResult.from_json(data) == result
        header["kinds"] = {"q1": "revolute", "q2": "revolute"}
        assert errors(SWEEP, data) != []                      # one of them, not both


def _write(folder: Path, text: str, metadata: dict | None = None) -> Path:
    path = folder / "t.csv"
    path.write_text(text)
    if metadata is not None:
        (folder / "t.csv.json").write_text(json.dumps(metadata))
    return path


def _cells(text: str, line: int, column: str, value: str) -> str:
    rows = list(csv.reader(text.splitlines()))
    start = next(k for k, r in enumerate(rows) if r and r[0] == "q1")
    rows[line - 1][rows[start].index(column)] = value
    return "".join(",".join(r) + "\n" for r in rows)


@pytest.mark.parametrize("line, column, value, message", [
    (2, "Nm", "3.5", "line 2, column Nm: expected a count (an integer, 0 or more), got '3.5'"),
    (3, "Nh", "-1", "line 3, column Nh: expected a count (an integer, 0 or more), got '-1'"),
    (2, "q1", "__import__('os')", "line 2, column q1: "),
    (3, "q2", "pi/3", "line 3, column q2: angle 'pi/3' is not exact"),
    (2, "exact_recheck", "yes", "line 2, column exact_recheck: expected true or false, "
                                "got 'yes'"),
    (2, "q1_rad", "nan", "line 2, column q1_rad: 'nan' is not a finite number"),
])
def test_a_bad_cell_is_one_error_naming_file_line_and_column(tmp_path, line, column, value,
                                                             message):
    for text, metadata in ((POINTS.to_csv(), POINTS.csv_metadata()), (OLD_POINTS, None)):
        shift = 0 if metadata is not None else 7          # the commented lines first
        path = _write(tmp_path, _cells(text, line + shift, column, value), metadata)
        with pytest.raises(SweepError) as info:
            SweepResult.read(path)
        shifted = message.replace(f"line {line}", f"line {line + shift}")
        assert str(info.value).startswith(f"not a sweep result: {path}: {shifted}")
        assert "\n" not in str(info.value)


def test_bad_tables_and_metadata(tmp_path):
    text = POINTS.to_csv()
    path = _write(tmp_path, text)
    with pytest.raises(SweepError, match=r"t\.csv: no metadata file .*t\.csv\.json next to "
                                         r"it \(written with the table by SweepResult"):
        SweepResult.read(path)
    meta = POINTS.csv_metadata()
    for change, message in [
            (("prime", 2**40), "header.prime: expected a prime below 2**31"),
            (("columns", meta["header"]["joints"]), "header.columns: expected q1, q1_rad,"),
            (("float_columns", {"q1_rad": "", "q2_x": ""}),
             "header.float_columns.q2_x: expected q2_rad or q2_float"),
            (("kinds", {}), "header.kinds: unknown entry")]:
        bad_meta = json.loads(json.dumps(meta))
        bad_meta["header"][change[0]] = change[1]
        _write(tmp_path, text, bad_meta)
        with pytest.raises(SweepError) as info:
            SweepResult.read(path)
        assert str(info.value).startswith(f"not a sweep result: {path}.json: {message}")
    _write(tmp_path, text.replace("q2_rad", "q2_float", 1), meta)
    with pytest.raises(SweepError, match=r"t\.csv: line 1: expected the columns q1,q1_rad,"
                                         r"q2,q2_rad,Nm,Nc,Ni,Nr,Ng,Nd,Nh,exact_recheck$"):
        SweepResult.read(path)
    _write(tmp_path, text + "pi,3.14,2\n", meta)
    with pytest.raises(SweepError, match=r"t\.csv: line 4: expected 12 cells, got 3$"):
        SweepResult.read(path)
    _write(tmp_path, text, {**meta, "header": {**meta["header"], "counts": {
        **meta["header"]["counts"], "points": 3}}})
    with pytest.raises(SweepError, match="header.counts.points: 3 does not match the "
                                         r"points \(2\)"):
        SweepResult.read(path)


@pytest.mark.parametrize("line, old, new, message", [
    (3, "Nm=2 Nc=2", "Nm=2, Nc=2", "line 3: expected '# generic numbers (swept joints "
                                   "symbolic): Nm=... Nc=..."),
    (4, "points: 2;", "points: 3;", "header.counts.points: 3 does not match the points (2)"),
    (7, "# q2_rad:", "# q2_x:", "line 6: expected one '# <float column>: <meaning>' line "
                                "per float column of line 8"),
    (8, "q2_rad", "q2_x", "line 6: expected one '# <float column>: <meaning>' line"),
])
def test_a_bad_commented_csv_is_one_error_naming_the_line(tmp_path, line, old, new, message):
    lines = OLD_POINTS.splitlines()
    assert old in lines[line - 1]
    lines[line - 1] = lines[line - 1].replace(old, new)
    path = _write(tmp_path, "\n".join(lines) + "\n")
    with pytest.raises(SweepError) as info:
        SweepResult.read(path)
    assert str(info.value).startswith(f"not a sweep result: {path}: {message}")


def test_parquet(tmp_path):
    pd = pytest.importorskip("pandas")
    pytest.importorskip("pyarrow")
    SNAPPED.write(tmp_path / "map.parquet")
    frame = pd.read_parquet(tmp_path / "map.parquet")
    pd.testing.assert_frame_equal(frame, SNAPPED.to_pandas())
    assert frame.attrs["header"] == SNAPPED.header()
    assert frame["q1"].tolist()[2] == "2*atan(10864/40545)"
    out = tmp_path / "cli.parquet"
    result = CliRunner().invoke(app, ["sweep", "paper-case1-hard", "--grid",
                                      "q1=0..pi/3:3,q2=-pi/2..pi/2:2", "--at", "L=1",
                                      "-o", str(out), "--no-progress"])
    assert result.exit_code == 0, result.output
    pd.testing.assert_frame_equal(pd.read_parquet(out), frame)
    with pytest.raises(SweepError, match=r"cli\.parquet: a Parquet table is read with "
                                         r"pandas\.read_parquet \(SweepResult\.read reads"):
        SweepResult.read(out)


def test_parquet_without_pyarrow_says_what_to_install(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "pyarrow", None)        # import pyarrow fails
    with pytest.raises(MissingDependency, match="^writing a sweep as .parquet needs pandas "
                                                "and pyarrow: pip install pandas pyarrow$"):
        POINTS.write(tmp_path / "map.parquet")
    result = CliRunner().invoke(app, ["sweep", "paper-case1-hard", "--grid", "q1=0..1:2",
                                      "-o", str(tmp_path / "map.parquet")])
    assert result.exit_code == 2
    assert result.stderr == ("coopkin: error: writing a sweep as .parquet needs pandas and "
                             "pyarrow: pip install pandas pyarrow\n")
    assert list(tmp_path.iterdir()) == []
