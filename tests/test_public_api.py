"""The notebooks use the public API only: ``coopkin_sym``'s top-level names and the
methods of the objects they return; every public name resolves."""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

import pytest

import coopkin_sym

FOLDER = Path(__file__).resolve().parents[1] / "notebooks"


def _cells() -> list[tuple[str, int, str]]:
    spec = importlib.util.spec_from_file_location("notebook_builder",
                                                  FOLDER / "make_notebooks.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return [(name, k, cell.source) for name, cells in module.NOTEBOOKS.items()
            for k, cell in enumerate(cells) if cell.cell_type == "code"]


def _deep_uses(source: str) -> list[str]:
    """Imports of the package's submodules, and ``coopkin_sym.<submodule>.`` uses."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith(
                "coopkin_sym."):
            found.append(f"from {node.module} import ...")
        elif isinstance(node, ast.Import):
            found += [a.name for a in node.names if a.name.startswith("coopkin_sym.")]
        elif (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
              and node.value.id == "coopkin_sym" and node.attr not in coopkin_sym.__all__):
            found.append(f"coopkin_sym.{node.attr}")
    return found


def test_the_notebooks_use_only_the_public_api():
    deep = [(name, k, use) for name, k, source in _cells() for use in _deep_uses(source)]
    assert deep == []


@pytest.mark.parametrize("name", coopkin_sym.__all__)
def test_every_public_name_resolves(name):
    assert getattr(coopkin_sym, name) is not None
