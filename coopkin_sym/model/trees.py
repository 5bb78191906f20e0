"""Reading YAML and JSON files into plain trees, safely and within budgets.

Model files and reports read back are trees of mappings, lists and scalars. This
module reads them with bounded work whatever the input: the file must be a regular
file (a named pipe or ``/dev/zero`` is refused before it is read) and is read up to
:data:`~coopkin_sym.limits.MAX_FILE_BYTES` (a 50 MB file is refused at once), YAML is
read from libyaml's event stream (no recursion, so deep nesting cannot crash it) and
built here, with

* the YAML 1.2 core schema, with the forms YAML 1.1 reads differently refused as
  ambiguous: ``010`` (1.1: the octal 8), ``1:30`` (1.1: 90), ``0x1F``, ``0o17``;
  ``yes``/``no``/``on``/``off`` are text, only ``true``/``false`` are truth values;
  floats stay text, so that the number parser reads them exactly;
* aliases counted as copies: the whole tree, aliases expanded, has at most
  :data:`~coopkin_sym.limits.MAX_NODES` entries (a 1 KB alias bomb is refused
  without being expanded, and no message ever shows an expanded value);
* nesting up to :data:`~coopkin_sym.limits.MAX_DEPTH`, integers up to
  :data:`~coopkin_sym.limits.MAX_DIGITS` digits, no duplicate keys, no tags beyond
  the standard ones.

Every problem is a :class:`TreeError` with one line, naming the line and column.

Example
-------
>>> read_text("a: [1, 2.50, yes, '1:30']", ".yaml")
{'a': [1, '2.50', 'yes', '1:30']}
>>> read_text("a: 010", ".yaml")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
coopkin_sym.errors.TreeError: line 1, column 4: 010 is ambiguous (YAML 1.1 reads ... or 8
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Mapping
from pathlib import Path

import yaml

from coopkin_sym import limits
from coopkin_sym.errors import TreeError
from coopkin_sym.model.input_files import read_input_bytes, size_text

__all__ = ["TreeError", "check_tree", "read_file", "read_text"]



_NULL = re.compile(r"~|null|Null|NULL|")
_BOOL = {"true": True, "True": True, "TRUE": True, "false": False, "False": False,
         "FALSE": False}
# digits may be grouped with underscores (1_000.5), as YAML 1.1 allowed
_INT = re.compile(r"[-+]?[0-9](?:_?[0-9])*")
_FLOAT = re.compile(r"[-+]?(?:\.[0-9](?:_?[0-9])*|[0-9](?:_?[0-9])*(?:\.(?:[0-9](?:_?[0-9])*)?)?)"
                    r"(?:[eE][-+]?[0-9]+)?|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN)")
_OTHER_INT = re.compile(r"[-+]?0[oOxXbB][0-9a-fA-F_]+|[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+"
                        r"(?:\.[0-9_]*)?")
_STANDARD_TAGS = {"tag:yaml.org,2002:str", "tag:yaml.org,2002:int",
                  "tag:yaml.org,2002:float", "tag:yaml.org,2002:bool",
                  "tag:yaml.org,2002:null", "tag:yaml.org,2002:map",
                  "tag:yaml.org,2002:seq"}


def read_file(path: str | os.PathLike) -> object:
    """Read a ``.json`` file (by its suffix) or a YAML file into a plain tree (the
    file itself is read by :func:`~coopkin_sym.model.input_files.read_input_bytes`:
    a regular file only, within the size budget).

    Raises
    ------
    TreeError
        Unreadable, not a regular file, not UTF-8 text, too large, not valid
        YAML/JSON, or over a budget.
    """
    path = Path(path)
    data = read_input_bytes(path)
    if b"\x00" in data:
        raise TreeError("not a text file (it holds NUL bytes)")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise TreeError("not a text file (UTF-8 expected)") from None
    return read_text(text, path.suffix)


def read_text(text: str, suffix: str = ".yaml", *, exact_floats: bool = True) -> object:
    """Read YAML or JSON text (JSON when ``suffix`` is ``.json``) into a plain tree,
    within the budgets of :mod:`coopkin_sym.limits` (see the module docstring).
    Floats stay text (read exactly later) unless ``exact_floats`` is false (JSON only:
    reports hold measured seconds and distances as floats)."""
    if len(text) > limits.MAX_FILE_BYTES:
        raise TreeError(f"the text is longer than {size_text(limits.MAX_FILE_BYTES)}")
    if suffix.lower() == ".json":
        tree = _read_json(text, exact_floats)
        check_tree(tree)
        return tree
    return _read_yaml(text)


# ------------------------------------------------------------------ JSON


class _DuplicateKey(ValueError):
    pass


def _json_pairs(pairs: list[tuple[str, object]]) -> dict[str, object]:
    out: dict[str, object] = {}
    for key, value in pairs:
        if key in out:
            raise _DuplicateKey(key)
        out[key] = value
    return out


def _json_int(text: str) -> int:
    if len(text.lstrip("-")) > limits.MAX_DIGITS:
        raise _TooLong(text)
    return int(text)


class _TooLong(ValueError):
    pass


def _read_json(text: str, exact_floats: bool = True) -> object:
    try:
        return json.loads(text, parse_float=str if exact_floats else float,
                          parse_constant=str, parse_int=_json_int,
                          object_pairs_hook=_json_pairs)
    except json.JSONDecodeError as exc:
        raise TreeError(f"line {exc.lineno}, column {exc.colno}: not valid JSON: "
                        f"{exc.msg}") from None
    except _DuplicateKey as exc:
        raise TreeError(f"not valid JSON: duplicate key {_short(str(exc))}") from None
    except _TooLong:
        raise TreeError(f"an integer of more than {limits.MAX_DIGITS} digits (too "
                        "large)") from None
    except RecursionError:
        raise TreeError(f"nested more than {limits.MAX_DEPTH} deep") from None


# ------------------------------------------------------------------ YAML


def _short(text: str) -> str:
    text = " ".join(text[:100].split())
    return f"'{text[:40]}...'" if len(text) > 40 else f"'{text}'"


def _where(event) -> str:
    mark = getattr(event, "start_mark", None)
    return f"line {mark.line + 1}, column {mark.column + 1}: " if mark else ""


def _scalar(event) -> object:
    """A YAML 1.2 core-schema value; floats stay text (read exactly later)."""
    value, tag = event.value, event.tag
    if tag not in (None, "!") and tag not in _STANDARD_TAGS:
        raise TreeError(f"{_where(event)}tag {_short(tag)} is not accepted (plain "
                        "YAML values only)")
    plain = not event.style and (tag is None or event.implicit[0])
    if tag == "tag:yaml.org,2002:str" or (not plain and tag is None) or tag == "!":
        return value
    if _NULL.fullmatch(value):
        return None
    if value in _BOOL:
        return _BOOL[value]
    if _INT.fullmatch(value):
        value = value.replace("_", "")
        digits = value.lstrip("+-")
        if len(digits) > 1 and digits[0] == "0":
            raise TreeError(f"{_where(event)}{value} is ambiguous (YAML 1.1 reads a leading "
                            f"zero as octal: {_octal(digits)}); write "
                            f"{digits.lstrip('0') or '0'}, or {_octal(digits)}")
        if len(digits) > limits.MAX_DIGITS:
            raise TreeError(f"{_where(event)}an integer of more than {limits.MAX_DIGITS} "
                            "digits (too large)")
        return int(value)
    if _FLOAT.fullmatch(value):
        return value.replace("_", "")
    if _OTHER_INT.fullmatch(value):
        raise TreeError(f"{_where(event)}{_short(value)} is ambiguous (YAML 1.1 reads it "
                        "as a number in another base or in base 60); write the number in "
                        "decimal, or quote it as text")
    return value


def _octal(digits: str) -> str:
    return str(int(digits, 8)) if re.fullmatch(r"[0-7]+", digits) else "not octal"


def _read_yaml(text: str) -> object:
    """Build the tree from libyaml's events, counting every node (aliases as copies)
    and the nesting, without recursion."""
    anchors: dict[str, tuple[object, int]] = {}
    stack: list[list] = []     # [container, key or _NO_KEY, anchor, count at start]
    count = 0
    documents = 0
    root: object = None
    try:
        events = yaml.parse(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
        for event in events:
            if isinstance(event, yaml.DocumentStartEvent):
                documents += 1
                if documents > 1:
                    raise TreeError(f"{_where(event)}more than one YAML document")
                continue
            if isinstance(event, yaml.StreamStartEvent | yaml.StreamEndEvent
                          | yaml.DocumentEndEvent):
                continue
            if isinstance(event, yaml.MappingEndEvent | yaml.SequenceEndEvent):
                container, key, anchor, start = stack.pop()
                if isinstance(container, dict) and key is not _NO_KEY:
                    raise TreeError(f"{_where(event)}a key without a value")
                if anchor is not None:
                    anchors[anchor] = (container, count - start)
                value, size = container, 0
            elif isinstance(event, yaml.AliasEvent):
                if event.anchor not in anchors:
                    raise TreeError(f"{_where(event)}unknown alias *{_short(event.anchor)}")
                value, size = anchors[event.anchor]
                count += size
                if count > limits.MAX_NODES:
                    raise TreeError(f"{_where(event)}more than {limits.MAX_NODES:,} entries "
                                    "once aliases are expanded (too large)")
            else:
                count += 1
                if count > limits.MAX_NODES:
                    raise TreeError(f"{_where(event)}more than {limits.MAX_NODES:,} entries "
                                    "(too large)")
                if isinstance(event, yaml.ScalarEvent):
                    value = _scalar(event)
                    if event.anchor is not None:
                        anchors[event.anchor] = (value, 1)
                else:
                    if len(stack) >= limits.MAX_DEPTH:
                        raise TreeError(f"{_where(event)}nested more than "
                                        f"{limits.MAX_DEPTH} deep")
                    if event.tag not in (None, "!") and event.tag not in _STANDARD_TAGS:
                        raise TreeError(f"{_where(event)}tag {_short(event.tag)} is not "
                                        "accepted (plain YAML values only)")
                    container = {} if isinstance(event, yaml.MappingStartEvent) else []
                    stack.append([container, _NO_KEY, event.anchor, count])
                    continue
            if not stack:
                root = value
                continue
            top = stack[-1]
            if isinstance(top[0], list):
                top[0].append(value)
            elif top[1] is _NO_KEY:
                if isinstance(value, dict | list):
                    raise TreeError(f"{_where(event)}a key must be a plain value, not a "
                                    "mapping or a list")
                if value in top[0]:
                    raise TreeError(f"{_where(event)}not valid YAML: duplicate key "
                                    f"{_short(str(value))}")
                top[1] = value
            else:
                top[0][top[1]] = value
                top[1] = _NO_KEY
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        where = f"line {mark.line + 1}, column {mark.column + 1}: " if mark else ""
        problem = getattr(exc, "problem", None) or "unreadable"
        raise TreeError(f"{where}not valid YAML: {' '.join(str(problem).split())}") from None
    return root


_NO_KEY = object()


# ------------------------------------------------------------------ trees from Python


def check_tree(tree: object) -> None:
    """Check a tree handed over as Python objects (a dict for ``load``, a parsed
    report) against the same budgets as a file: nesting, entries (a list used twice
    counts twice), integer digits, text length; a tree that contains itself is
    refused. Iterative: no recursion."""
    active: set[int] = set()          # the containers on the path being walked
    todo: list[tuple[object, int, bool]] = [(tree, 0, False)]
    count = 0
    while todo:
        node, depth, leaving = todo.pop()
        if leaving:
            active.discard(id(node))
            continue
        count += 1
        if count > limits.MAX_NODES:
            raise TreeError(f"more than {limits.MAX_NODES:,} entries (too large)")
        if isinstance(node, Mapping | list | tuple):
            if depth >= limits.MAX_DEPTH:
                raise TreeError(f"nested more than {limits.MAX_DEPTH} deep")
            if id(node) in active:
                raise TreeError("an entry contains itself")
            active.add(id(node))
            todo.append((node, depth, True))
            children = [*node.keys(), *node.values()] if isinstance(node, Mapping) \
                else list(node)
            todo.extend((child, depth + 1, False) for child in children)
        elif isinstance(node, int) and not isinstance(node, bool):
            if abs(node) >= limits.integer_bound():
                raise TreeError(f"an integer of more than {limits.MAX_DIGITS} digits "
                                "(too large)")
        elif isinstance(node, str) and len(node) > limits.MAX_EXPRESSION_TEXT:
            raise TreeError(f"a text of more than {limits.MAX_EXPRESSION_TEXT:,} "
                            "characters (too large)")
