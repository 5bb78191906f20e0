"""docs/finite-mobility.md: every command it shows runs, and its table is what the
package computes."""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.cli import app

DOC = (Path(__file__).resolve().parents[1] / "docs" / "finite-mobility.md").read_text()


def _commands() -> list[str]:
    blocks = re.findall(r"```bash\n(.*?)```", DOC, flags=re.S)
    return [line for block in blocks for line in block.splitlines()
            if line.startswith("coopkin ")]


@pytest.mark.parametrize("command", _commands())
def test_every_command_of_the_page_runs(command, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(app, shlex.split(command)[1:])
    assert result.exit_code == 0, result.output
    written = [p.read_text() for p in tmp_path.glob("*.md")]
    assert ("inite mobility" in result.stdout or '"finite": {' in result.stdout
            or any("Finite mobility at the witness" in text for text in written))


def _rows() -> list[list[str]]:
    table = DOC.split("## The examples")[1].split("\n\n")[1]
    rows = [[c.strip() for c in line.strip("|").split("|")] for line in table.splitlines()]
    return rows[2:]


def test_the_table_of_examples_is_what_the_package_computes():
    assert len(_rows()) == 12
    for name, where, first, finite, kind in _rows():
        name = name.strip("`").split("`")[0]
        at = None if where == "home" else where.strip("`").split("`")[0]
        fm = load(name).finite_mobility(at)
        assert str(fm.first_order) == first, (name, where)
        if fm.dimension is None:
            assert finite == f"undecided, {fm.bounds[0]} to {fm.bounds[1]}"
        else:
            assert finite == str(fm.dimension)
        assert kind.split(":")[0].split(" (")[0].split(" at ")[0].replace(" ", "_") in (
            fm.classification, "undecided"), (name, kind, fm.classification)
        if "branches" in kind:
            assert kind.endswith(f"{len(fm.branches)} branches")

