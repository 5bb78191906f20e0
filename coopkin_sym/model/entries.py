"""The entries of a model file: their structure (pydantic, types only), the problems
they have written in the file's own terms, unique names, exact numbers, vectors,
angles and placements. Meaning is checked by :mod:`coopkin_sym.model.model` and the
modules that build arms (:mod:`coopkin_sym.model.arm_entries`) and contacts
(:mod:`coopkin_sym.model.contact_entries`).

Example
-------
>>> problems = []
>>> _vector([1, 0], "contacts[0].normal", {}, problems, rational=True) is None
True
>>> problems
['contacts[0].normal: expected 3 numbers, got 2']
"""

from __future__ import annotations

import difflib
import keyword
import re
import reprlib
from collections.abc import Mapping
from typing import Any

import sympy as sp
from pydantic import BaseModel, ConfigDict, StrictBool, StrictStr, ValidationError

from coopkin_sym.errors import UndeclaredSymbol
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import NumberError, brief, parse_number
from coopkin_sym.model.dh import IDENTITY, Frame, frame_from_xyz_rpy
from coopkin_sym.model.structure import Vector

_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
#: A URDF link name that a contact can write after its arm (``ARM/LINK``): not all
#: digits (``ARM/K`` counts joints), no slash, no space.
_LINK_NAME = re.compile(r"(?!\d+$)[^/\s]+")

#: Names a parameter or joint may not have: they mean something else in SymPy text.
RESERVED_NAMES: frozenset[str] = frozenset(
    {"pi", "deg", "E", "I", "oo", "nan", "zoo", "atan", "sqrt", "Rational", "Integer"}
) | frozenset(keyword.kwlist)


class _Entry(BaseModel):
    """Structure of one entry of a model file (types only; meaning is checked later)."""

    model_config = ConfigDict(extra="forbid")


class _TopIn(_Entry):
    name: StrictStr | None = None
    parameters: list[Any] | None = None
    arms: list[Any] | None = None
    contacts: list[Any] | None = None
    object: Any = None
    planar: StrictBool | None = None


class _ObjectIn(_Entry):
    point: list[Any] | None = None
    rpy: list[Any] | None = None


class _ArmIn(_Entry):
    name: StrictStr
    joints: list[Any] | None = None
    dh: list[Any] | None = None
    convention: StrictStr | None = None
    base: Any = None
    urdf: StrictStr | None = None
    mjcf: StrictStr | None = None
    tip: StrictStr | None = None
    prefix: StrictStr | None = None
    snap: Any = None
    passive: list[StrictStr] | None = None


#: The keys of an arm that say what it is made of (and, for an arm read from a URDF
#: file, which chain and joint names): when one of them cannot be read, the arm is not
#: built, and contacts on it are not checked against it.
_ARM_SHAPE = frozenset({"joints", "dh", "urdf", "mjcf"})
_URDF_CHOICE = frozenset({"tip", "prefix"})


class _DHRowIn(_Entry):
    name: StrictStr
    type: StrictStr
    actuated: StrictBool = True
    theta: Any = 0
    d: Any = 0
    a: Any = 0
    alpha: Any = 0


class _PlacementIn(_Entry):
    xyz: list[Any] | None = None
    rpy: list[Any] | None = None


class _JointIn(_Entry):
    name: StrictStr
    type: StrictStr
    axis: list[Any]
    point: list[Any] | None = None
    actuated: StrictBool = True


class _ContactIn(_Entry):
    name: StrictStr
    link: StrictStr | None = None
    point: list[Any] | None = None
    site: StrictStr | None = None
    normal: list[Any] | None = None
    model: StrictStr
    frame: StrictStr | None = None


def _join(path: str, loc: tuple[int | str, ...] | list[int | str]) -> str:
    """``arms[0]`` + ``("joints", 1, "type")`` -> ``arms[0].joints[1].type``."""
    out = path
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += f".{part}" if out else str(part)
    return out or "(top level)"


_REPR = reprlib.Repr()
_REPR.maxlevel, _REPR.maxstring, _REPR.maxother, _REPR.maxlong = 2, 60, 60, 60
_REPR.maxlist = _REPR.maxdict = _REPR.maxtuple = 4


def _brief(value: object) -> str:
    """A short view of a value (never the repr of a whole large one)."""
    try:
        text = _REPR.repr(value)
    except ValueError:           # an integer too long to print
        text = f"<{type(value).__name__}>"
    text = " ".join(text.split())
    return text if len(text) <= 60 else text[:57] + "..."


def _render(exc: ValidationError, path: str, cls: type[_Entry]) -> list[str]:
    """Pydantic's errors, one line each, in the model file's own terms."""
    out = []
    for err in exc.errors(include_url=False):
        loc, kind, value = tuple(err["loc"]), err["type"], err.get("input")
        if kind == "missing":
            out.append(f"{_join(path, loc[:-1])}: missing key '{loc[-1]}'")
        elif kind == "extra_forbidden":
            key = str(loc[-1])
            close = difflib.get_close_matches(key, list(cls.model_fields), n=1)
            hint = f" (did you mean '{close[0]}'?)" if close else ""
            out.append(f"{_join(path, loc[:-1])}: unknown key {brief(key)}{hint}")
        elif kind == "invalid_key":
            out.append(f"{_join(path, loc[:-1])}: key {_brief(loc[-1])} is not a name "
                       f"(keys are words such as 'name')")
        elif kind == "string_type":
            out.append(f"{_join(path, loc)}: expected text, got {_brief(value)}")
        elif kind == "list_type":
            out.append(f"{_join(path, loc)}: expected a list, got {_brief(value)}")
        elif kind in ("model_type", "model_attributes_type", "dict_type"):
            out.append(f"{_join(path, loc)}: expected a mapping (key: value), "
                       f"got {_brief(value)}")
        else:
            message = " ".join(str(err["msg"]).split())
            out.append(f"{_join(path, loc)}: {message[:1].lower()}{message[1:]}")
    return out


def _validate(cls: type[_Entry], raw: object, path: str,
              problems: list[str]) -> tuple[Any, set[str]]:
    """Validate ``raw`` against ``cls``; collect problems.

    Returns the validated entry and the set of fields that were wrong. When only some
    fields are wrong (unknown keys, bad optional fields) the rest is still returned,
    so that later checks can find more problems; otherwise the entry is ``None``.
    """
    try:
        return cls.model_validate(raw), set()
    except ValidationError as exc:
        problems.extend(_render(exc, path, cls))
        if not isinstance(raw, Mapping):
            return None, set()
        bad = {str(e["loc"][0]) for e in exc.errors() if e["loc"]}
        kept = {k: v for k, v in raw.items() if k in cls.model_fields and k not in bad}
        try:
            return cls.model_validate(kept), bad
        except ValidationError:
            return None, bad


class _Names:
    """Every name in the model must be unique (and valid); remembers where each is."""

    def __init__(self, problems: list[str]):
        self.problems = problems
        self.where: dict[str, str] = {}   # name -> path of its "name" field

    def add(self, name: str, path: str, *, symbol: bool) -> bool:
        if not _IDENTIFIER.fullmatch(name):
            self.problems.append(f"{path}: {brief(name)} is not a valid name (letters, digits "
                                 f"and underscores, not starting with a digit)")
            return False
        if symbol and name in RESERVED_NAMES:
            self.problems.append(f"{path}: '{name}' is reserved (it means something else "
                                 f"in SymPy text); choose another name")
            return False
        if name in self.where:
            self.problems.append(f"{path}: duplicate name '{name}' (already used at "
                                 f"{self.where[name]})")
            return False
        self.where[name] = path
        return True


class _UndeclaredProblem(str):
    """The line of a number that uses an undeclared name: not reported when the
    parameter list could not be read (the names it meant are unknown)."""


def _number_problem(exc: NumberError) -> str:
    return _UndeclaredProblem(exc) if isinstance(exc, UndeclaredSymbol) else str(exc)


def _vector(raw: list[Any], path: str, parameters: dict[str, sp.Symbol],
            problems: list[str], *, rational: bool) -> Vector | None:
    """Three exact numbers; ``rational`` forbids parameters."""
    if len(raw) != 3:
        problems.append(f"{path}: expected 3 numbers, got {len(raw)}")
        return None
    out = []
    for value in raw:
        try:
            number = parse_number(value, parameters, path)
        except NumberError as exc:
            problems.append(_number_problem(exc))
            return None
        if rational and not number.is_Rational:
            problems.append(f"{path}: {brief(value)} uses a parameter; this vector must have "
                            f"rational entries without parameters")
            return None
        out.append(number)
    return (out[0], out[1], out[2])


def _unit_problem(v: Vector) -> str | None:
    """Why ``v`` is not an exact unit vector, or ``None`` if it is one."""
    length2 = sum((x**2 for x in v), sp.Integer(0))
    if length2 == 1:
        return None
    if length2 == 0:
        return "not a unit vector (zero vector)"
    hint = ""
    root = sp.sqrt(length2)
    if root.is_Rational:
        hint = "; did you mean [" + ", ".join(str(x / root) for x in v) + "]?"
    return f"not a unit vector (squared length {length2}){hint}"


def _vec_text(v) -> str:
    text = "(" + ", ".join(sp.sstr(x) for x in v) + ")"
    return text if len(text) <= 60 else text[:57] + "..."


def _is_zero(x: sp.Expr) -> bool:
    return sp.simplify(sp.expand(x)) == 0


def _angle(value: Any, path: str, problems: list[str]) -> ExactAngle | None:
    """An exact angle with rational cosine and sine (the one angle parser)."""
    try:
        return ExactAngle.parse(value, path)
    except NumberError as exc:
        problems.append(str(exc))
        return None


def _number(value: Any, path: str, parameters: dict[str, sp.Symbol],
            problems: list[str]) -> sp.Expr | None:
    try:
        return parse_number(value, parameters, path)
    except NumberError as exc:
        problems.append(_number_problem(exc))
        return None


def _placement(raw: Any, path: str, parameters: dict[str, sp.Symbol],
               problems: list[str], point_key: str = "xyz") -> Frame | None:
    """A placement (``xyz``, ``rpy``), the identity when not given; ``point_key``
    names the origin's key in messages."""
    if raw is None:
        return IDENTITY
    entry, bad = _validate(_PlacementIn, raw, path, problems)
    if entry is None or bad:
        return None
    xyz = (_vector(entry.xyz, f"{path}.{point_key}", parameters, problems, rational=False)
           if entry.xyz is not None else (0, 0, 0))
    rpy_raw = entry.rpy if entry.rpy is not None else [0, 0, 0]
    if len(rpy_raw) != 3:
        problems.append(f"{path}.rpy: expected 3 angles (roll, pitch, yaw), got "
                        f"{len(rpy_raw)}")
        return None
    rpy = [_angle(v, f"{path}.rpy[{k}]", problems) for k, v in enumerate(rpy_raw)]
    if xyz is None or None in rpy:
        return None
    return frame_from_xyz_rpy(xyz, rpy)
