"""Console samples of README.md and docs/ are what the commands print.

Each sample below is a ```console block: its ``$ coopkin ...`` lines are run in order in
an empty folder, and the lines under each command must be what it prints (all of them
for a whole sample, in order for one cut short); a line giving the time taken (``1.025
s``) is the one that may differ."""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coopkin_sym.cli import app

ROOT = Path(__file__).resolve().parents[1]
TIME = re.compile(r"^\s*\d+(\.\d+)? s$")

#: (file, the first command of the sample, whether the sample shows every line printed)
SAMPLES = [
    ("README.md", "coopkin locus paper-case1-hard -o case1.html", True),
    ("docs/locus-report.md", "coopkin locus paper-case1-hard -o checked.json --verify", True),
    ("docs/model-format.md", "coopkin analyze paper-case1-hard --at q1=pi/3", False),
]


def _sample(file: str, first: str) -> list[tuple[str, list[str]]]:
    text = (ROOT / file).read_text(encoding="utf-8")
    block = text.split(f"```console\n$ {first}", 1)[1].split("```", 1)[0]
    runs: list[tuple[str, list[str]]] = []
    for line in f"$ {first}{block}".splitlines():
        if line.startswith("$ "):
            runs.append((line[2:], []))
        else:
            runs[-1][1].append(line)
    return runs


def _in_order(shown: list[str], printed: list[str]) -> bool:
    rest = iter(printed)
    return all(line in rest for line in shown)


@pytest.mark.parametrize(("file", "first", "whole"), SAMPLES,
                         ids=[f"{f}:{c.split()[1]}" for f, c, _ in SAMPLES])
def test_a_console_sample_is_what_the_commands_print(file, first, whole, tmp_path,
                                                      monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    runs = _sample(file, first)
    assert runs and all(shown for _, shown in runs[:1])
    for command, shown in runs:
        args = shlex.split(command, comments=True)
        assert args[0] == "coopkin"
        result = CliRunner().invoke(app, args[1:])
        assert result.exit_code == 0, (command, result.output)
        printed = [line for line in result.stdout.splitlines() if not TIME.match(line)]
        shown = [line for line in shown if not TIME.match(line)]
        if whole:
            assert printed == shown, command
        else:
            assert _in_order(shown, printed), (command, printed)
