"""The notebooks and the command line use the public API only: ``coopkin_sym``'s
top-level names and the methods of the objects they return; every public name
resolves."""

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


def _imported_names(source: str) -> list[str]:
    """Names imported from ``coopkin_sym`` itself that it does not make public."""
    return [f"from coopkin_sym import {a.name}" for node in ast.walk(ast.parse(source))
            if isinstance(node, ast.ImportFrom) and node.module == "coopkin_sym"
            and not node.level for a in node.names
            if a.name not in coopkin_sym.__all__ and a.name != "__version__"]


PACKAGE = Path(coopkin_sym.__file__).resolve().parent

#: The command line: its commands and their options.
COMMAND_LINE = ("cli.py", "cli_options.py")


@pytest.mark.parametrize("name", COMMAND_LINE)
def test_the_command_line_uses_only_the_public_api(name):
    source = (PACKAGE / name).read_text(encoding="utf-8")
    own = "from coopkin_sym.cli_options import ..."    # the command line's own options
    deep = [use for use in _deep_uses(source) + _imported_names(source) if use != own]
    assert deep == []


def test_the_check_of_the_command_line_sees_a_deep_import():
    """The check can fail: a deep import, a private name and a deep attribute are seen."""
    source = ("from coopkin_sym.present.text import analysis_text\n"
              "from coopkin_sym import load, _LAZY\n"
              "import coopkin_sym\ncoopkin_sym.present\n")
    assert _deep_uses(source) + _imported_names(source) == [
        "from coopkin_sym.present.text import ...", "coopkin_sym.present",
        "from coopkin_sym import _LAZY"]


def test_the_notebooks_use_only_the_public_api():
    deep = [(name, k, use) for name, k, source in _cells() for use in _deep_uses(source)]
    assert deep == []


@pytest.mark.parametrize("name", coopkin_sym.__all__)
def test_every_public_name_resolves(name):
    assert getattr(coopkin_sym, name) is not None
