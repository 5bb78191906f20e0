"""The package's layers, checked on its source: imports only go down, and no cycle.

The layers: ``errors``/``limits`` (base) < ``exact`` < ``model`` < ``analysis`` <
``present`` < the public facade (``coopkin_sym``, ``system``, ``cli``). Every import of
a package module counts, at the top of a file or inside a function, so that a
dependency cannot hide.
"""

from __future__ import annotations

import ast
import builtins
from pathlib import Path

import pytest

import coopkin_sym

PACKAGE = Path(coopkin_sym.__file__).resolve().parent
LAYERS = ("base", "exact", "model", "analysis", "present", "facade")


def _module_name(path: Path) -> str:
    parts = ("coopkin_sym", *path.relative_to(PACKAGE).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def layer(module: str) -> str:
    """The layer of a module of the package."""
    parts = module.split(".")
    if len(parts) >= 2 and parts[1] in ("exact", "model", "analysis", "present"):
        return parts[1]
    if module in ("coopkin_sym.errors", "coopkin_sym.limits"):
        return "base"
    return "facade"


def imports(module: str) -> set[str]:
    """The package modules that ``module`` imports (anywhere in its source)."""
    path = MODULES[module]
    package = module if path.name == "__init__.py" else module.rsplit(".", 1)[0]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            targets = [(a.name, []) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                name = ".".join(base + ([node.module] if node.module else []))
            else:
                name = node.module or ""
            targets = [(name, [a.name for a in node.names])]
        else:
            continue
        for name, names in targets:
            if not name.startswith("coopkin_sym"):
                continue
            subs = [f"{name}.{n}" for n in names if f"{name}.{n}" in MODULES]
            found.update(subs or [name])
    found.discard(module)
    return found


GRAPH = {m: imports(m) for m in MODULES}


def test_every_import_goes_down_or_stays_in_its_layer():
    upward = [f"{m} ({layer(m)}) imports {t} ({layer(t)})"
              for m, targets in GRAPH.items() for t in sorted(targets)
              if LAYERS.index(layer(t)) > LAYERS.index(layer(m))]
    assert upward == []


def test_no_import_cycle():
    state: dict[str, int] = {}
    cycles: list[list[str]] = []

    def visit(m: str, stack: list[str]) -> None:
        state[m] = 1
        stack.append(m)
        for t in sorted(GRAPH.get(m, ())):
            if t not in MODULES:
                continue
            if state.get(t) == 1:
                cycles.append(stack[stack.index(t):] + [t])
            elif t not in state:
                visit(t, stack)
        stack.pop()
        state[m] = 2

    for m in sorted(MODULES):
        if m not in state:
            visit(m, [])
    # a package's __init__ re-exporting its own submodules is not a cycle of ideas
    real = [c for c in cycles
            if not any(a == b.rsplit(".", 1)[0] or b == a.rsplit(".", 1)[0]
                       for a, b in zip(c, c[1:], strict=False))]
    assert real == []


@pytest.mark.parametrize("module", ["coopkin_sym.exact", "coopkin_sym.model",
                                    "coopkin_sym.analysis", "coopkin_sym.present"])
def test_layers_exist_and_hold_modules(module):
    inside = [m for m in MODULES if m.startswith(module + ".")]
    assert len(inside) >= 3, inside


def test_the_checker_sees_an_upward_import(tmp_path):
    """The check can fail: a planted upward import is found."""
    source = "from coopkin_sym.present.sentences import sentences\n"
    tree = ast.parse(source)
    node = tree.body[0]
    assert isinstance(node, ast.ImportFrom)
    assert layer(node.module) == "present"
    assert LAYERS.index(layer(node.module)) > LAYERS.index(layer("coopkin_sym.exact.ring"))


def test_every_public_class_has_an_example():
    """Every public class's docstring carries an example (run by the doctests)."""
    missing = []
    for module, path in MODULES.items():
        for node in ast.parse(path.read_text(), str(path)).body:
            if isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
                if ">>>" not in (ast.get_docstring(node) or ""):
                    missing.append(f"{module}.{node.name}")
    assert missing == []


# --- every error a package error --------------------------------------------------------

#: Built-in exceptions raised where a Python protocol expects them, never for bad input:
#: (module, exception, function) -> why. An entry that no longer matches a raise fails
#: the test, so the list cannot outlive the code.
PROTOCOL_RAISES = {
    ("coopkin_sym", "AttributeError", "__getattr__"): "module attributes (PEP 562)",
    ("coopkin_sym.analysis.irrational", "AttributeError", "__getattr__"):
        "an attribute no analysis has (the rational-only ones are NotAvailable)",
    ("coopkin_sym.analysis.locus.remarks", "KeyError", "__getitem__"): "the mapping protocol",
    ("coopkin_sym.analysis.locus.remarks", "TypeError", "__contains__"):
        "a Remark is data: `in` on its text is refused",
    ("coopkin_sym.analysis.locus.remarks", "TypeError", "__iter__"):
        "a Remark is data: iterating over its text is refused",
    ("coopkin_sym.exact.numberfield", "ZeroDivisionError", "inverse"):
        "division by zero in a field, as for Python's numbers",
    ("coopkin_sym.exact.ratfunc", "ZeroDivisionError", "make"):
        "division by zero in a field, as for Python's numbers",
    ("coopkin_sym.exact.ratfunc", "ZeroDivisionError", "__truediv__"):
        "division by zero in a field, as for Python's numbers",
    ("coopkin_sym.present.files", "OSError", "_keep_aside"):
        "caught by write_files, which raises the caller's package error",
    ("coopkin_sym.cli", "KeyboardInterrupt", "_interrupted"): "Ctrl-C unwinds the command",
    ("coopkin_sym.cli", "Exit", "*"): "the command's exit status (typer)",
    ("coopkin_sym.cli", "SystemExit", "_terminated"): "SIGTERM/SIGHUP: exit 128 + signal",
}
#: An internal invariant (raised only by a bug, never by input) and an abstract method.
INVARIANTS = ("AssertionError", "NotImplementedError")


def _raises(path: Path):
    """(function name, raised expression) for every ``raise X`` / ``raise X(...)``."""
    tree = ast.parse(path.read_text(), str(path))
    found = []

    def visit(node, function):
        for child in ast.iter_child_nodes(node):
            name = (child.name if isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef)
                    else function)
            if isinstance(child, ast.Raise) and child.exc is not None:
                exc = child.exc.func if isinstance(child.exc, ast.Call) else child.exc
                found.append((function, exc, child.lineno))
            visit(child, name)

    visit(tree, "<module>")
    caught = {n.id for h in ast.walk(tree) if isinstance(h, ast.ExceptHandler) and h.type
              for n in ast.walk(h.type) if isinstance(n, ast.Name)}
    return found, caught


def _resolve(module, expr):
    """The object a raised name or dotted name stands for in ``module``, or None."""
    parts = []
    while isinstance(expr, ast.Attribute):
        parts.append(expr.attr)
        expr = expr.value
    if not isinstance(expr, ast.Name):
        return None
    value = getattr(module, expr.id, getattr(builtins, expr.id, None))
    for part in reversed(parts):
        value = getattr(value, part, None)
    return value


def test_every_error_raised_is_a_package_error():
    """Every exception class the package raises is a :class:`CoopkinError` (so a user
    catches the package's refusals with one class), a private one its own module
    catches, an internal invariant, or a protocol exception listed above."""
    import importlib

    from coopkin_sym.errors import CoopkinError

    wrong, used = [], set()
    for name, path in MODULES.items():
        if name.endswith("__main__"):
            continue              # importing it runs the command
        module = importlib.import_module(name)
        found, caught = _raises(path)
        for function, expr, line in found:
            value = _resolve(module, expr)
            if not (isinstance(value, type) and issubclass(value, BaseException)):
                continue          # a variable or a function that builds the error
            if issubclass(value, CoopkinError) or value.__name__ in INVARIANTS:
                continue
            if value.__name__.startswith("_") and value.__name__ in caught:
                continue          # control flow inside the module
            key = next((k for k in ((name, value.__name__, function),
                                    (name, value.__name__, "*")) if k in PROTOCOL_RAISES),
                       None)
            if key is not None:
                used.add(key)
                continue
            wrong.append(f"{path.relative_to(PACKAGE.parent)}:{line}: {function} raises "
                         f"{value.__name__}")
    assert wrong == []
    assert sorted(set(PROTOCOL_RAISES) - used) == []


#: The size rules (issue: one module, one idea): a module of at most this many lines,
#: a function of at most this many, a public function with at most this many
#: parameters (``self``/``cls`` not counted).
MAX_MODULE_LINES = 800
MAX_FUNCTION_LINES = 80
MAX_PUBLIC_PARAMETERS = 8

#: Modules and functions still over a size rule, each to be split: this list only
#: shrinks (a test fails when an entry is no longer needed).
OVER_SIZE: set[str] = set()


def _over_size() -> list[str]:
    """Every module over :data:`MAX_MODULE_LINES` and every function over
    :data:`MAX_FUNCTION_LINES` lines or (public) over :data:`MAX_PUBLIC_PARAMETERS`
    parameters, as ``path`` or ``path:function``."""
    found = []
    for path in MODULES.values():
        text = path.read_text()
        where = str(path.relative_to(PACKAGE.parent))
        if len(text.splitlines()) > MAX_MODULE_LINES:
            found.append(where)
        for node in ast.walk(ast.parse(text, str(path))):
            if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            args = node.args
            names = [a.arg for a in (*args.posonlyargs, *args.args, *args.kwonlyargs)]
            count = len([n for n in names if n not in ("self", "cls")])
            too_many = not node.name.startswith("_") and count > MAX_PUBLIC_PARAMETERS
            if node.end_lineno - node.lineno + 1 > MAX_FUNCTION_LINES or too_many:
                found.append(f"{where}:{node.name}")
    return found


def test_modules_and_functions_keep_their_size():
    """No module over about 800 lines, no function over 80, no public function over 8
    parameters, apart from the listed ones still to be split (and none listed that
    already fits)."""
    found = set(_over_size())
    assert sorted(found - OVER_SIZE) == []
    assert sorted(OVER_SIZE - found) == []


def test_the_size_rules_see_a_long_function(tmp_path, monkeypatch):
    """The size check counts a function's lines and a public function's parameters."""
    source = tmp_path / "coopkin_sym" / "demo.py"
    source.parent.mkdir()
    body = "\n".join(f"    x{i} = {i}" for i in range(MAX_FUNCTION_LINES))
    source.write_text(f"def long():\n{body}\n\ndef wide(a, b, c, d, e, f, g, h, i):\n"
                      "    return a\n")
    monkeypatch.setattr(__import__(__name__), "MODULES", {"coopkin_sym.demo": source})
    monkeypatch.setattr(__import__(__name__), "PACKAGE", source.parent)
    assert sorted(_over_size()) == ["coopkin_sym/demo.py:long", "coopkin_sym/demo.py:wide"]
