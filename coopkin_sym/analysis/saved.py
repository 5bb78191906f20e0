"""Results read back from their JSON: untrusted input, checked entry by entry.

A sweep or a manipulability result written as JSON (``to_json``) is a file people
exchange; reading one back reads it within the budgets of
:mod:`coopkin_sym.model.trees` (a file through
:func:`~coopkin_sym.model.input_files.read_input_text`), checks every entry's type,
and reads every exact text with the package's one parser
(:mod:`coopkin_sym.exact.parse`). The first problem is one error of the caller's
class naming the entry (``points[3].q1: ...``).

Example
-------
>>> from coopkin_sym.errors import SweepError
>>> entries = Entries(SweepError, "not a sweep result")
>>> tree = entries.tree('{"header": {"prime": "7"}}')
>>> entries.field(tree["header"], "prime", int, "header")
Traceback (most recent call last):
...
coopkin_sym.errors.SweepError: not a sweep result: header.prime: expected an integer, got '7'
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from typing import Any

from coopkin_sym.errors import TreeError
from coopkin_sym.exact.parse import brief
from coopkin_sym.model.input_files import read_input_text
from coopkin_sym.model.trees import check_tree, read_text

_KIND_NAMES = {str: "a text", int: "an integer", bool: "true or false", list: "a list",
               dict: "an object", float: "a number"}


class Entries:
    """Checks of one document's entries; ``error`` is the package error raised, its
    message led by ``what`` (``"not a sweep result"``).

    Example
    -------
    >>> from coopkin_sym.errors import ManipulabilityError
    >>> Entries(ManipulabilityError, "not a manipulability result").keys(
    ...     {"rank": 1, "x": 2}, ("rank",), "")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ManipulabilityError: not a manipulability result: x: unknown entry
    """

    def __init__(self, error: type[Exception], what: str):
        self.error = error
        self.what = what

    def fail(self, where: str, message: str) -> Exception:
        """The error naming the entry ``where`` (raise it)."""
        return self.error(f"{self.what}: {where}: {message}" if where
                          else f"{self.what}: {message}")

    def tree(self, data: Mapping | str) -> dict:
        """JSON text (or a tree already read) within the budgets, as a dict."""
        try:
            if isinstance(data, str):
                tree = read_text(data, ".json", exact_floats=False)
            else:
                check_tree(data)
                tree = data
        except TreeError as exc:
            raise self.fail("", str(exc)) from None
        if not isinstance(tree, Mapping):
            raise self.fail("", f"expected a JSON object, got {type(tree).__name__}")
        return dict(tree)

    def file(self, path: str | os.PathLike) -> dict:
        """The document in the file ``path`` (a regular file, within the budgets)."""
        try:
            text = read_input_text(path)
        except TreeError as exc:
            raise self.error(f"{os.fspath(path)}: {exc}") from None
        return self.tree(text)

    def keys(self, tree: object, required: Sequence[str], where: str,
             optional: Sequence[str] = ()) -> Mapping:
        """``tree`` as an object with exactly the ``required`` keys (and maybe the
        ``optional`` ones)."""
        if not isinstance(tree, Mapping):
            raise self.fail(where, f"expected an object, got {_shown(tree)}")
        for key in tree:
            if key not in required and key not in optional:
                raise self.fail(_at(where, str(key)), "unknown entry")
        for key in required:
            if key not in tree:
                raise self.fail(_at(where, key), "missing")
        return tree

    def field(self, tree: Mapping, key: str, kind: type, where: str, *,
              none: bool = False) -> Any:
        """``tree[key]`` checked to be of ``kind`` (``float`` takes integers too; None
        only when ``none``)."""
        return self.value(tree[key], kind, _at(where, key), none=none)

    def value(self, value: object, kind: type, where: str, *, none: bool = False) -> Any:
        """``value`` checked to be of ``kind`` (see :meth:`field`)."""
        if value is None and none:
            return None
        ok = isinstance(value, kind) and not (kind is int and isinstance(value, bool))
        if kind is float:
            ok = isinstance(value, int | float) and not isinstance(value, bool)
        if not ok:
            raise self.fail(where, f"expected {_KIND_NAMES.get(kind, kind.__name__)}, "
                                   f"got {_shown(value)}")
        return value

    def texts(self, tree: Mapping, key: str, where: str) -> list[str]:
        """``tree[key]``: a list of texts."""
        items = self.field(tree, key, list, where)
        return [self.value(x, str, f"{_at(where, key)}[{k}]") for k, x in enumerate(items)]


def _shown(value: object) -> str:
    """A JSON value as it was written (a text quoted and shortened)."""
    if isinstance(value, str):
        return brief(value)
    if value is None or isinstance(value, bool | int | float):
        return json.dumps(value)
    return "a list" if isinstance(value, list) else "an object"


def _at(where: str, key: str) -> str:
    return f"{where}.{key}" if where else key


__all__ = ["Entries"]
