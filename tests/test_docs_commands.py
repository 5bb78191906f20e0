"""Every ``coopkin`` command shown in README.md and docs/*.md runs in a test, and prints
what the docs show.

The commands are collected from the docs, so that one added later is run too: the
``$ coopkin ...`` lines of the ```console blocks (the lines under one, up to the next
``$``, are what it prints) and the ``coopkin ...`` lines or ``&& coopkin ...`` parts of
the ```bash and ```sh blocks; ``# comments`` are left out, and ``> FILE`` writes what
the command prints to FILE. The commands of one block run in order in one empty
folder (a later one reads what an earlier one wrote), with the input files the docs
do not ship written first (:data:`INPUTS`).

A sample is matched whole, line by line: a line ``...`` stands for any number of lines
and ``...`` (or ``…``) inside a line for any text; a line giving the time taken
(``1.025 s``) is left out on both sides. A JSON sample (``{`` to ``}``) writes each
member of the printed object on one line, compact: it is matched member by member the
same way. The exit status is the one the sample implies: 3 for a run cut by its time
bound or its budget of terms, 2 for any other error, else 0.

A command shown without a sample has its checks in :data:`WITHOUT_SAMPLE` (lines it
prints, files it writes); one that another test runs is in :data:`ELSEWHERE`, naming
that test, which is checked to collect it."""

from __future__ import annotations

import json
import re
import shlex
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coopkin_sym.cli import app

ROOT = Path(__file__).resolve().parents[1]
FILES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
TIME = re.compile(r"^\s*\d+(\.\d+)? s$")
GAP = ("...", "…")
SHELLS = ("bash", "sh")


# ------------------------------------------------------------------ collecting


@dataclass(frozen=True)
class Run:
    """One command of a block: its text (comments left out), its arguments after
    ``coopkin``, the file its output is redirected to, and the sample under it (None:
    none shown)."""

    command: str
    args: tuple[str, ...]
    target: str | None
    shown: tuple[str, ...] | None


@dataclass(frozen=True)
class Block:
    where: str                  # "README.md:81", the line of the opening fence
    runs: tuple[Run, ...]


def _run(text: str, shown: list[str] | None) -> Run | None:
    """The run of one command line, or None when it is not a ``coopkin`` command."""
    words = shlex.split(text, comments=True)
    if not words or words[0] != "coopkin":
        return None
    target = None
    for k, word in enumerate(words):
        if word.startswith(">"):
            target = word[1:] or words[k + 1]
            words = words[:k]
            break
    return Run(" ".join(words), tuple(words[1:]), target,
               tuple(shown) if shown else None)


def _fences(text: str):
    """``(info, first line number, body lines)`` of each fenced block."""
    info, start, body = None, 0, []
    for number, line in enumerate(text.splitlines(), 1):
        if info is None and line.startswith("```"):
            info, start, body = line[3:].strip(), number, []
        elif info is not None and line.strip() == "```":
            yield info, start, body
            info = None
        elif info is not None:
            body.append(line)


def _block_runs(info: str, body: list[str]) -> list[Run]:
    runs: list[Run] = []
    if info == "console":
        pending: list[tuple[str, list[str]]] = []
        for line in body:
            if line.startswith("$ "):
                pending.append((line[2:], []))
            elif pending:
                pending[-1][1].append(line)
        runs = [_run(text, shown) for text, shown in pending]
    elif info in SHELLS:
        for line in body:
            words = shlex.split(line, comments=True)
            parts, part = [], []
            for word in [*words, "&&"]:
                if word == "&&":
                    parts.append(part)
                    part = []
                else:
                    part.append(word)
            runs += [_run(shlex.join(p), None) for p in parts]
    return [r for r in runs if r is not None]


def collect() -> list[Block]:
    blocks = []
    for path in FILES:
        for info, start, body in _fences(path.read_text(encoding="utf-8")):
            runs = _block_runs(info, body)
            if runs:
                blocks.append(Block(f"{path.relative_to(ROOT)}:{start}", tuple(runs)))
    return blocks


BLOCKS = collect()
RUNS = [run for block in BLOCKS for run in block.runs]


# ------------------------------------------------------------------ matching


def _pattern(line: str) -> re.Pattern:
    parts = re.split(r"\.\.\.|…", line.rstrip())
    return re.compile(".*".join(re.escape(p) for p in parts))


def matches(shown: list[str], printed: list[str]) -> bool:
    """Whether ``printed`` is ``shown`` line by line, a line ``...`` standing for any
    number of lines and ``...`` inside a line for any text.

    >>> matches(["a ...", "...", "c"], ["a b", "x", "y", "c"])
    True
    >>> matches(["a", "c"], ["a", "b", "c"])
    False
    """
    gaps = [line.strip() in GAP for line in shown]
    patterns = [None if gap else _pattern(line) for line, gap in zip(shown, gaps,
                                                                       strict=True)]
    # reach[j]: the first i lines shown match the first j lines printed
    reach = [True] + [False] * len(printed)
    for gap, pattern in zip(gaps, patterns, strict=True):
        if gap:
            for j in range(1, len(reach)):
                reach[j] = reach[j] or reach[j - 1]
        else:
            reach = [False] + [reach[j] and bool(pattern.fullmatch(printed[j].rstrip()))
                               for j in range(len(printed))]
    return reach[-1]


def _members(text: str) -> list[str]:
    """The members of the JSON object ``text``, one line each, compact."""
    return [f"{json.dumps(k)}: {json.dumps(v, ensure_ascii=False)}"
            for k, v in json.loads(text).items()]


def _without_time(lines) -> list[str]:
    return [line for line in lines if not TIME.match(line)]


def check_sample(shown: tuple[str, ...], output: str) -> None:
    shown_lines = _without_time(shown)
    printed = _without_time(output.splitlines())
    if shown_lines[0] == "{" and shown_lines[-1] == "}":
        shown_lines = [line.strip().removesuffix(",") for line in shown_lines[1:-1]]
        printed = _members(output)
    assert matches(shown_lines, printed), "\n".join(
        ["shown:", *shown_lines, "", "printed:", *printed])


def expected_status(shown: tuple[str, ...] | None) -> int:
    """The exit status a sample implies."""
    errors = [line for line in shown or () if line.startswith("coopkin: error: ")]
    if not errors:
        return 0
    cut = any("time bound of" in line or "over the budget of" in line for line in errors)
    return 3 if cut else 2


# ------------------------------------------------------------------ inputs


BAD_YAML = """\
name: bad
parameters: [L, pi]
arms:
  - name: a1
    joints:
      - {name: q1, type: revolute, axis: [0, 0, 2], point: [0, 0, 0]}
      - {name: q2, type: rotary, axis: [0, 0, 1], point: [0, 0, 0]}
      - {name: q3, type: prismatic, axis: [0, 0, 0]}
  - name: a2
    joints:
      - {name: q4, type: revolute, axis: [0, 0, 1]}
contacts:
  - {name: c1, link: a1/4, point: [0, 0, 0], model: hard}
  - {name: c2, link: a3/1, point: [sqrt(2), 0, 0], normal: [1, 1, 0], model: soft}
  - {name: c3, link: a2/1, point: [1/L, 0, 0], nromal: [1, 0, 0], model: frictionless}
  - {name: c1, link: a2/1, point: [x, 0, 0], model: sticky}
"""


def _builder(name: str, *sizes: int) -> Callable[[], str]:
    def text() -> str:
        from coopkin_sym.model import builders

        return json.dumps(getattr(builders, name)(*sizes))
    return text


#: The input files of the commands shown that the docs do not ship, as the docs
#: describe them: a model with one mistake of each kind, a hand whose generic
#: decomposition takes minutes (its numbers a tenth of a second), a cell whose locus
#: search takes minutes (its generic numbers under a second).
INPUTS: dict[str, Callable[[], str]] = {
    "bad.yaml": lambda: BAD_YAML,
    "hand.json": _builder("spatial_hand", 3, 7),
    "cell.json": _builder("arm_cell", 3, 3),
}


# ------------------------------------------------------------------ commands without a sample


def _lines_in_order(*wanted: str) -> Callable[[Path, str], None]:
    def check(folder: Path, output: str) -> None:
        rest = iter(output.splitlines())
        missing = [line for line in wanted if line not in rest]
        assert not missing, (missing, output[-2000:])
    return check


def _examples(folder: Path, output: str) -> None:
    shipped = sorted(p.stem for p in (ROOT / "coopkin_sym" / "model" / "examples")
                     .glob("*.yaml"))
    lines = output.splitlines()
    assert [line.split()[0] for line in lines] == shipped
    assert all(len(line.split(maxsplit=1)) == 2 for line in lines)


def _four_bar_file(folder: Path, output: str) -> None:
    assert output == ""                     # the model went to the file
    shipped = ROOT / "coopkin_sym" / "model" / "examples" / "four-bar.yaml"
    assert (folder / "my-model.yaml").read_text() == shipped.read_text()
    again = CliRunner().invoke(app, ["analyze", "my-model.yaml"])
    assert "Nm = 1  Nc = 1  Ni = 0  Nr = 0  Ng = 1  Nd = 2  Nh = 0" in again.stdout


def _degrees(folder: Path, output: str) -> None:
    radians = CliRunner().invoke(app, ["analyze", "paper-case1-hard", "--at", "q1=pi/2"])
    assert output == radians.output
    assert "Configuration: q1=pi/2" in output.splitlines()


def _version(folder: Path, output: str) -> None:
    from coopkin_sym import version

    assert output.splitlines() == [f"coopkin {version()}"]
    assert re.fullmatch(r"\d+\.\d+\.\d+\S*", version())


def _generic_json(folder: Path, output: str) -> None:
    document = json.loads(output)
    assert document["numbers"] == {"Nm": 8, "Nc": 6, "Ni": 1, "Nr": 2, "Ng": 1, "Nd": 0,
                                   "Nh": 0}
    assert (document["point"], document["classes"]) == (
        "symbolic", ["redundant", "indeterminate", "graspable"])


def _sweep(folder: Path, output: str) -> None:
    assert output.splitlines() == [
        "32761 points: 32399 certified modulo 2147483647, 362 rechecked exactly; 352 "
        "snapped angles; wrote map.csv and map.csv.json"]
    rows = (folder / "map.csv").read_text().splitlines()
    assert rows[0] == "q2,q2_rad,q3,q3_rad,Nm,Nc,Ni,Nr,Ng,Nd,Nh,exact_recheck"
    assert len(rows) == 1 + 181 * 181
    header = json.loads((folder / "map.csv.json").read_text())["header"]
    assert (header["system"], header["counts"]["points"]) == (
        "paper case 2, two SCARA robots, hard/hard", 181 * 181)


def _picture(folder: Path, output: str) -> None:
    assert output.splitlines() == ["wrote scara.png"]
    assert (folder / "scara.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


CASE2_HOME = _lines_in_order("System: paper case 2, two SCARA robots, hard/hard",
                             "Configuration: home (all joints at 0)",
                             "Nm = 8  Nc = 6  Ni = 1  Nr = 2  Ng = 1  Nd = 0  Nh = 0")

#: The checks of each command the docs show without a sample (every one must have one).
WITHOUT_SAMPLE: dict[str, Callable[[Path, str], None]] = {
    "coopkin analyze paper-case2-hard": CASE2_HOME,
    "coopkin examples": _examples,
    "coopkin examples four-bar --show": _four_bar_file,
    "coopkin analyze paper-case1-hard --at q1=90deg": _degrees,
    "coopkin --version": _version,
    "coopkin analyze paper-case1-hard": _lines_in_order(
        "Configuration: home (all joints at 0)", "Symbols: L",
        "Nm = 2  Nc = 2  Ni = 1  Nr = 0  Ng = 1  Nd = 4  Nh = 0", "C12 (6 x 1)",
        "  v_x | L"),
    "coopkin analyze paper-case1-hard --at q1=pi/2,q2=2*atan(1/3),L=1000": _lines_in_order(
        "Configuration: q1=pi/2,q2=2*atan(1/3),L=1000",
        "Nm = 2  Nc = 2  Ni = 1  Nr = 0  Ng = 1  Nd = 4  Nh = 0", "C11 (6 x 1)",
        "  v_z | 4000"),
    "coopkin manipulability five-bar --at L=1 --controlled v_x,v_y --point 0,2,0":
        _lines_in_order("E = [[1/2, 0], [0, 1/2]]", "det E = 1/4", "rank E = 2 of 2"),
    "coopkin analyze paper-case2-hard --generic --json": _generic_json,
    "coopkin sweep paper-case2-hard --grid q2=-pi..pi:181,q3=-pi..pi:181 -o map.csv":
        _sweep,
    "coopkin draw paper-case2-hard --motion indeterminate:1 -o scara.png": _picture,
}


def _finite_page_commands() -> list[str]:
    import test_docs_finite

    return [" ".join(shlex.split(c)) for c in test_docs_finite._commands()]


#: Commands another test runs: command -> (that test, the commands it collects).
ELSEWHERE: dict[str, tuple[str, Callable[[], list[str]]]] = {
    command: ("tests/test_docs_finite.py::test_every_command_of_the_page_runs",
              _finite_page_commands)
    for command in [
        "coopkin analyze four-bar --at q1=-pi/2,q2=-pi/2 --finite",
        "coopkin analyze shaky-pinned-bars --finite",
        "coopkin analyze paper-case1-hard --at q1=pi/2,q2=-pi/2 --finite --json",
        "coopkin locus four-bar --finite -o four-bar-locus.md",
        "coopkin analyze bennett-linkage --finite",
        "coopkin analyze bricard-linkage --finite",
        "coopkin analyze paper-case1-planar --at q1=pi/3,q2=pi/3 --finite",
        "coopkin locus paper-case1-hard --finite -o case1-locus.md",
        "coopkin analyze seven-r-loop --finite",
        "coopkin analyze parallel-cranks --finite --json",
        "coopkin analyze seven-r-loop --at q4=pi/3 --finite",
        "coopkin analyze bennett-linkage --at q1=pi/6,q2=2*atan((65*sqrt(3)-70)/311),"
        "q3=pi/6,q4=2*atan((65*sqrt(3)-70)/311) --finite",
    ]}

#: The commands over about 3 s: a block holding one is a slow test.
SLOW = {
    "coopkin analyze panda-two-arm-box --generic",
    "coopkin locus paper-case1-hard -o case1.html",
    "coopkin locus paper-case1-hard -o case1.html --certify",
    "coopkin sweep paper-case2-hard --grid q2=-pi..pi:181,q3=-pi..pi:181 -o map.csv",
    "coopkin draw paper-case2-hard --motion indeterminate:1 -o scara.png",
    "coopkin analyze hand.json --generic --timeout 5",
    "coopkin locus cell.json -o r.md --timeout 5",
}


def _run_here(block: Block) -> list[Run]:
    """The runs of ``block`` this test runs: all of them, unless each is one of
    ELSEWHERE shown without a sample (left to that test)."""
    if all(run.command in ELSEWHERE and run.shown is None for run in block.runs):
        return []
    return list(block.runs)


HERE = [b for b in BLOCKS if _run_here(b)]


# ------------------------------------------------------------------ the tests


def test_the_commands_of_the_docs_are_collected():
    where = {b.where.split(":")[0] for b in BLOCKS}
    assert {"README.md", "docs/model-format.md", "docs/locus-report.md",
            "docs/analyze-json.md", "docs/finite-mobility.md", "docs/index.md"} <= where
    texts = [r.command for r in RUNS]
    assert "coopkin examples four-bar --show" in texts          # "> file" left out
    assert "coopkin analyze paper-case2-hard" in texts          # from "... && coopkin ..."
    assert len(RUNS) >= 38, len(RUNS)


def test_every_command_collected_is_run_by_a_test():
    collected = {r.command for r in RUNS}
    here = {r.command for b in HERE for r in b.runs}
    assert not collected - here - set(ELSEWHERE), collected - here - set(ELSEWHERE)
    for command, (test, commands) in ELSEWHERE.items():
        assert command in commands(), (command, test)
    # each list names only commands the docs show
    for name, entries in [("ELSEWHERE", ELSEWHERE), ("WITHOUT_SAMPLE", WITHOUT_SAMPLE),
                          ("SLOW", SLOW)]:
        assert set(entries) <= collected, (name, set(entries) - collected)
    assert {a for r in RUNS for a in r.args if a in INPUTS} == set(INPUTS)


def test_every_command_without_a_sample_has_its_checks():
    bare = {r.command for b in HERE for r in b.runs if r.shown is None}
    assert bare <= set(WITHOUT_SAMPLE), bare - set(WITHOUT_SAMPLE)


def _invoke(run: Run, folder: Path) -> tuple[int, str]:
    for arg in run.args:
        if arg in INPUTS and not (folder / arg).exists():
            (folder / arg).write_text(INPUTS[arg](), encoding="utf-8")
    result = CliRunner().invoke(app, list(run.args))
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception
    if run.target is None:
        return result.exit_code, result.output
    (folder / run.target).write_text(result.stdout, encoding="utf-8")
    return result.exit_code, result.stderr      # what the terminal still shows


def _param(block: Block):
    slow = any(run.command in SLOW for run in block.runs)
    return pytest.param(block, id=block.where, marks=[pytest.mark.slow] if slow else [])


@pytest.mark.parametrize("block", [_param(b) for b in HERE])
def test_a_block_of_the_docs_prints_what_it_shows(block, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    for run in _run_here(block):
        status, output = _invoke(run, tmp_path)
        assert status == expected_status(run.shown), (run.command, status, output[-3000:])
        if run.shown is not None:
            check_sample(run.shown, output)
        if run.command in WITHOUT_SAMPLE:     # shown once without a sample
            WITHOUT_SAMPLE[run.command](tmp_path, output)


# ------------------------------------------------------------------ the checks themselves


def test_a_sample_with_a_line_left_out_without_a_gap_does_not_match():
    printed = "System: x\nNm = 2\nGrasp classes: none\n"
    check_sample(("System: x", "...", "Grasp classes: ..."), printed)
    with pytest.raises(AssertionError):
        check_sample(("System: x", "Grasp classes: none"), printed)
    with pytest.raises(AssertionError):
        check_sample(("System: x", "Nm = 3", "..."), printed)


def test_a_json_sample_is_matched_member_by_member():
    printed = json.dumps({"a": 1, "b": [1, 2], "c": {"d": "text"}}, indent=2)
    check_sample(("{", '  "a": 1,', '  "b": [1, 2],', "  ...", "}"), printed)
    check_sample(("{", "  ...", '  "c": {"d": "te..."}', "}"), printed)
    with pytest.raises(AssertionError):
        check_sample(("{", '  "a": 1,', '  "c": {"d": "text"}', "}"), printed)
    with pytest.raises(AssertionError):
        check_sample(("{", '  "b": [1, 3],', "  ...", "}"), printed)


def test_the_exit_status_a_sample_implies():
    assert expected_status(None) == 0
    assert expected_status(("coopkin: error: bad.yaml: x",)) == 2
    assert expected_status(("x", "coopkin: error: time bound of 5 s reached during y")) == 3
    assert expected_status(("coopkin: error: manipulability: ... over the budget of 2,000",
                            )) == 3


def test_a_redirection_and_the_parts_of_a_shell_line_are_read():
    runs = _block_runs("bash", ["pip install . && coopkin analyze x --at q1=0  # home"])
    assert runs == [Run("coopkin analyze x --at q1=0", ("analyze", "x", "--at", "q1=0"),
                        None, None)]
    runs = _block_runs("console", ["$ coopkin examples a --show > m.yaml   # start here",
                                   "$ pip install y", "$ coopkin --version", "coopkin 1"])
    assert runs == [Run("coopkin examples a --show", ("examples", "a", "--show"), "m.yaml",
                        None), Run("coopkin --version", ("--version",), None, ("coopkin 1",))]
