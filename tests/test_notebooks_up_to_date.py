"""The committed notebooks are those ``notebooks/make_notebooks.py`` makes now.

Two checks per notebook:

- its cells (kind, id, source) and metadata are the ones the builder writes, and it was
  committed with its outputs (quick, nothing runs);
- run again, it prints the same thing: every text output (standard output, and the
  ``text/*`` forms of results and displays: plain text, LaTeX, Markdown, HTML) equals the
  committed one once the volatile parts are masked by the builder's ``normalize``
  (timings, memory addresses, temporary paths, float digits past the fourth significant
  one). Exact content (integers, rationals, matrices, equations) is compared as printed.
  Pictures and standard error (warnings that depend on library versions) are not
  compared. This runs every notebook (a few minutes), so it is marked ``slow``.

A failure names the notebook, the cell and the difference; regenerate with
``python notebooks/make_notebooks.py`` (or with the notebook's number after it).
"""

from __future__ import annotations

import difflib
import importlib.util
from pathlib import Path

import nbformat
import pytest

FOLDER = Path(__file__).resolve().parents[1] / "notebooks"


def _load_builder():
    """``notebooks/make_notebooks.py`` as a module (the folder is not a package)."""
    spec = importlib.util.spec_from_file_location("notebook_builder",
                                                  FOLDER / "make_notebooks.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


builder = _load_builder()
NAMES = list(builder.NOTEBOOKS)


def _label(name: str, index: int, cell) -> str:
    first = cell.source.splitlines()[0] if cell.source else ""
    return f"{name}, cell {index} (id {cell.get('id')}, starting {first!r})"


def _regenerate(name: str) -> str:
    return f"regenerate with: python notebooks/make_notebooks.py {name.split('_')[0]}"


def _diff(old: str, new: str, limit: int = 30) -> str:
    lines = list(difflib.unified_diff(old.splitlines(), new.splitlines(), "committed",
                                      "now", lineterm="", n=1))
    if len(lines) > limit:
        lines = lines[:limit] + [f"... ({len(lines) - limit} more diff lines)"]
    return "\n".join(lines)


@pytest.mark.parametrize("name", NAMES)
def test_committed_cells_are_the_built_ones(name):
    committed = nbformat.read(FOLDER / name, as_version=4)
    built = builder.build(name, builder.NOTEBOOKS[name])
    problems = []
    if committed.metadata != built.metadata:
        problems.append(f"metadata {dict(committed.metadata)} != {dict(built.metadata)}")
    if len(committed.cells) != len(built.cells):
        problems.append(f"{len(committed.cells)} cells committed, {len(built.cells)} built")
    for index, (old, new) in enumerate(zip(committed.cells, built.cells, strict=False)):
        if (old.cell_type, old.get("id"), old.source) != (new.cell_type, new.get("id"),
                                                            new.source):
            problems.append(f"{_label(name, index, new)} differs:\n"
                            + _diff(f"[{old.cell_type}]\n{old.source}",
                                    f"[{new.cell_type}]\n{new.source}"))
        elif old.cell_type == "code" and old.get("execution_count") is None:
            problems.append(f"{_label(name, index, new)} was committed without running")
    if problems:
        pytest.fail(f"notebooks/{name} is not what make_notebooks.py builds; "
                    f"{_regenerate(name)}\n" + "\n".join(problems), pytrace=False)


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_committed_outputs_are_current(name):
    committed = nbformat.read(FOLDER / name, as_version=4)
    fresh = builder.execute(builder.build(name, builder.NOTEBOOKS[name]))
    if len(committed.cells) != len(fresh.cells):
        pytest.fail(f"notebooks/{name}: {len(committed.cells)} cells committed, "
                    f"{len(fresh.cells)} built; {_regenerate(name)}", pytrace=False)
    problems = []
    for index, (old, new) in enumerate(zip(committed.cells, fresh.cells, strict=True)):
        if new.cell_type != "code":
            continue
        before, now = builder.printed(old), builder.printed(new)
        if before == now:
            continue
        if [kind for kind, _ in before] != [kind for kind, _ in now]:
            problems.append(f"{_label(name, index, new)}: outputs "
                            f"{[kind for kind, _ in before]} committed, "
                            f"{[kind for kind, _ in now]} now")
            continue
        for (kind, old_text), (_, new_text) in zip(before, now, strict=True):
            if old_text != new_text:
                problems.append(f"{_label(name, index, new)}, {kind}:\n"
                                + _diff(old_text, new_text))
    if problems:
        pytest.fail(f"notebooks/{name} prints something else now; {_regenerate(name)}\n"
                    + "\n\n".join(problems), pytrace=False)
