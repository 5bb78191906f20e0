"""Every ```python block of README.md and docs/*.md runs as a script.

Each block is written to a file and run by a fresh interpreter in a subprocess (as a
reader pasting it into ``script.py`` would run it), with this checkout's package first
on the path, in an empty directory. A block must therefore run standalone: its imports
and data in the block itself, the work under ``if __name__ == "__main__":`` when it
starts worker processes. A block whose top-level imports name a package that is not
installed (``distributed``, ``pandas``) is skipped, saying which; the blocks that start
a cluster of processes are slow tests (``python -m pytest -m slow``)."""

from __future__ import annotations

import ast
import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
FILES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
BLOCK = re.compile(r"^```python\n(.*?)^```$", re.M | re.S)


def _blocks() -> list:
    out = []
    for path in FILES:
        text = path.read_text(encoding="utf-8")
        for match in BLOCK.finditer(text):
            line = text.count("\n", 0, match.start()) + 1
            slow = "LocalCluster" in match[1]
            out.append(pytest.param(match[1], id=f"{path.name}:{line}",
                                    marks=[pytest.mark.slow] if slow else []))
    return out


BLOCKS = _blocks()


def test_the_docs_have_python_blocks():
    ids = [b.id for b in BLOCKS]
    assert len(ids) >= 4 and any(i.startswith("README.md:") for i in ids)
    assert any(i.startswith("sweep-files.md:") for i in ids)


def _missing(code: str) -> list[str]:
    """The packages the block's top-level imports name that are not installed."""
    names = []
    for node in ast.parse(code).body:
        if isinstance(node, ast.Import):
            names += [a.name.split(".")[0] for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            names.append(node.module.split(".")[0])
    return sorted({n for n in names if importlib.util.find_spec(n) is None})


@pytest.mark.parametrize("code", BLOCKS)
def test_a_python_block_runs_as_a_script(code, tmp_path):
    missing = _missing(code)
    if missing:
        pytest.skip(f"needs {', '.join(missing)}")
    script = tmp_path / "script.py"
    script.write_text(code, encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])]), "MPLBACKEND": "Agg"}
    done = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    assert "Traceback" not in done.stderr
