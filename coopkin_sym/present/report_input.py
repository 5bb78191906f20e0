"""Reports read back: validated like model files before anything uses them.

A locus report (the JSON of :func:`coopkin_sym.present.report.render_json`) is a file people
exchange, so reading one back is reading untrusted input. The tree is read within the
budgets of :mod:`coopkin_sym.model.trees`, its structure checked by pydantic (unknown keys
refused, every type strict), and every text that is an expression (equations,
witnesses, fixed values, points of float checks, algebraic witnesses) is read by the
package's parser (:func:`coopkin_sym.exact.parse.parse_expression`): an equation must be
a polynomial in the report's variables. Problems come one line each, naming the
entry (``components[0].equations[1]: ...``).

Example
-------
>>> tree = {"system": "demo", "variables": ["t_q1"], "fixed": "", "generic": {"Nm": 1},
...         "components": [{"equations": ["t_q1 - 1"], "numbers": {"Nm": 2},
...                         "witness": {"q1": "pi/2"}, "real": True}]}
>>> validate_report(tree).components[0].witness
{'q1': 'pi/2'}
>>> validate_report(dict(tree, variables=["pi"]))   # doctest: +ELLIPSIS
Traceback (most recent call last):
...
coopkin_sym.errors.ReportInputError: not a locus report: variables[0]: 'pi' is ...
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections.abc import Mapping
from typing import Any, Literal

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    StrictBool,
    StrictFloat,
    StrictInt,
    StrictStr,
    ValidationError,
    create_model,
)

from coopkin_sym.analysis.locus.conditions import (
    Clause,
    Condition,
    Related,
    Value,
    Vanishes,
    vanishing,
)
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import Certificate, Check, Component, FloatCheck, Locus
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.errors import CoopkinError, ReportInputError
from coopkin_sym.exact.angles import cotangent_name, joint_of
from coopkin_sym.exact.parse import (
    FUNCTIONS,
    NumberError,
    brief,
    parse_expression,
    parse_polynomial,
)
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.model.configuration import top_level_parts
from coopkin_sym.model.trees import TreeError, check_tree, read_text
from coopkin_sym.present.certificate import certificate_read, completeness_text

__all__ = ["ReportInputError", "validate_report"]

KINDS = ("hypersurface", "subvariety", "isolated", "chart")
_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_RESERVED = {*FUNCTIONS, "pi", "CRootOf", "E", "I", "oo", "nan", "zoo"}
#: A name used as a symbol (not called as a function).
_SYMBOL_USE = re.compile(r"\b([A-Za-z_][A-Za-z0-9_]*)\b(?!\s*\()")
_DECIMAL = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")



class _In(BaseModel):
    model_config = ConfigDict(extra="forbid")


Names = dict[StrictStr, StrictStr]


class _FloatCheckIn(_In):
    distance: StrictFloat | StrictInt
    scale: StrictStr
    point: Names
    exact: dict[StrictStr, StrictInt]
    float: dict[StrictStr, StrictInt]
    agree: StrictBool | None = None


class _AlgebraicIn(_In):
    point: Names
    alpha: StrictStr = ""
    root_of: StrictStr = ""
    root: StrictStr = ""
    interval: list[StrictStr] = Field(default_factory=list)
    approx: Names = Field(default_factory=dict)


class _ClauseIn(_In):
    """One clause of a condition (see
    :func:`coopkin_sym.analysis.locus.conditions.clause_json`)."""

    value: StrictStr | None = None
    equals: StrictStr | None = None
    kind: StrictStr | None = None
    related: tuple[StrictStr, StrictStr] | None = None
    sign: StrictInt | None = None
    plus_pi: StrictBool | None = None
    vanishes: StrictStr | None = None


class _FieldIn(_In):
    """The number field of an algebraic witness's finite mobility."""

    alpha: StrictStr
    minimal_polynomial: StrictStr
    tangents: Names = Field(default_factory=dict)


class _AlongIn(_In):
    """The finite mobility along a component beyond its witness."""

    how: Literal["constant_rank", "second_point"]
    dimension: StrictInt | None
    classification: Literal["regular", "kinematic_singularity", "bifurcation", "cusp", "cone",
                            "shaky", "undecided"]
    point: Names | None = None
    bounds: tuple[StrictInt, StrictInt] | None = None
    reason: StrictStr | None = None


class _FiniteIn(_In):
    """The finite mobility at a component's witness (``coopkin locus --finite``)."""

    dimension: StrictInt | None
    bounds: tuple[StrictInt, StrictInt]
    first_order: StrictInt
    classification: Literal["regular", "kinematic_singularity", "bifurcation", "cusp", "cone",
                            "shaky", "undecided"]
    reason: StrictStr
    order: StrictInt
    branches: list[StrictInt]
    assumptions: list[Literal["unit_length", "frictionless_flat_face", "closure_expansion",
                              "closure_saturation_inconclusive"]] = []
    field: _FieldIn | None = None
    along: _AlongIn | None = None


class _CheckIn(_In):
    chart: StrictStr
    depth: StrictInt
    inside: StrictInt | None
    matrix: StrictStr
    kind: StrictStr
    certified: StrictBool
    why: StrictStr = ""
    backend: StrictStr = ""
    seconds: StrictFloat | StrictInt = 0


class _TallyIn(_In):
    certified: StrictBool
    why: StrictStr
    tests: StrictInt
    failed: StrictInt


class _CertificateIn(_In):
    system: StrictStr
    certified: StrictBool
    summary: StrictStr
    depths: dict[StrictStr, _TallyIn]
    charts: dict[StrictStr, _TallyIn]
    tests: StrictInt
    certified_by: dict[StrictStr, StrictInt]
    failed: list[_CheckIn]
    checks: list[_CheckIn] | None = None
    notes: list[StrictStr]
    seconds: StrictFloat | StrictInt


#: A remark: its sentence (a report), or its kind and facts (:meth:`Locus.to_json`).
RemarkIn = StrictStr | dict[StrictStr, Any]


class _CheckDataIn(_In):
    chart: StrictStr
    depth: StrictInt
    inside: StrictInt | None
    matrix: StrictStr
    kind: StrictStr
    certified: StrictBool
    why: RemarkIn | None = None
    backend: StrictStr = ""
    seconds: StrictFloat | StrictInt = 0


class _TallyDataIn(_In):
    certified: StrictBool
    why: RemarkIn | None
    tests: StrictInt
    failed: StrictInt


class _CertificateDataIn(_In):
    """A certificate as data (:meth:`~coopkin_sym.analysis.locus.types.Certificate.to_json`):
    a table's ``why`` is ``{"check": index}`` (a test of ``checks``) or a remark."""

    system: StrictStr
    certified: StrictBool
    refused: RemarkIn | None = None
    depths: dict[StrictStr, _TallyDataIn]
    charts: dict[StrictStr, _TallyDataIn]
    checks: list[_CheckDataIn]
    notes: list[RemarkIn]
    untested_beyond: StrictInt | None = None
    seconds: StrictFloat | StrictInt


#: The type of each known field; a field of the dataclass not listed here (added
#: later) is accepted with any plain value, and a key that is no field is refused.
_COMPONENT_TYPES: dict[str, Any] = {
    "equations": list[StrictStr], "numbers": dict[StrictStr, StrictInt],
    "witness": Names | None, "real": StrictBool, "kind": StrictStr,
    "condition": StrictStr, "drops": list[StrictStr],
    "changes": dict[StrictStr, tuple[StrictInt, StrictInt]], "meaning": list[StrictStr],
    "decided": RemarkIn, "witness_checked": StrictBool,
    "float_checks": list[_FloatCheckIn], "depth": StrictInt, "parent": StrictInt | None,
    "algebraic_witness": _AlgebraicIn | None, "real_points": StrictStr,
    "outside": list[StrictStr], "finite": _FiniteIn | None, "chart": list[StrictStr],
}
_LOCUS_TYPES: dict[str, Any] = {
    "system": StrictStr, "variables": list[StrictStr], "fixed": StrictStr,
    "generic": dict[StrictStr, StrictInt], "parameter_conditions": list[RemarkIn],
    "dropped": list[RemarkIn], "unexplored": list[RemarkIn], "notes": list[RemarkIn],
    "seconds": StrictFloat | StrictInt,
    "certificate": _CertificateIn | _CertificateDataIn | None,
    "locked_joints": list[StrictStr], "locked": dict[StrictStr, Any] | None,
}


def _model_of(cls: type, types: dict[str, Any], extra: dict[str, Any], name: str,
              skip: tuple[str, ...] = ()):
    fields: dict[str, Any] = {}
    for f in dataclasses.fields(cls):
        if f.name in skip:
            continue
        kind = types.get(f.name, Any)
        if f.default is not dataclasses.MISSING:
            fields[f.name] = (kind, f.default)
        elif f.default_factory is not dataclasses.MISSING:
            fields[f.name] = (kind, Field(default_factory=f.default_factory))
        else:
            fields[f.name] = (kind, ...)
    fields.update(extra)
    return create_model(name, __base__=_In, **fields)


# a report states what changes on a component in words ("meaning") and its grasp
# classes ("classes", derived from its numbers: read, then recomputed when needed); the
# computed component keeps the exact data instead ("shown"), which a report does not carry
_ComponentIn = _model_of(Component, _COMPONENT_TYPES,
                         {"meaning": (list[StrictStr], Field(default_factory=list)),
                          "classes": (list[StrictStr], Field(default_factory=list)),
                          "condition_data": (list[list[_ClauseIn]] | None, None)},
                         "_ComponentIn", skip=("shown", "stated_meaning"))
_LocusIn = _model_of(Locus, {**_LOCUS_TYPES, "components": list[_ComponentIn]},
                     {"float_summary": (dict[StrictStr, StrictInt] | None, None),
                      # what an independent check found when the report was written
                      # (coopkin locus --verify): a document, not read back
                      "verification": (dict[StrictStr, Any] | None, None),
                      "generic_classes": (list[StrictStr], Field(default_factory=list)),
                      "completeness": (StrictStr | None, None)},
                     "_LocusIn")


def _path(loc: tuple) -> str:
    """``components[0].witness.q1``; a key that is not a plain name is quoted and
    shortened (``generic['a b']``), so that a path is always one short line."""
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        elif not _IDENTIFIER.fullmatch(str(part)):
            out += f"[{brief(str(part))}]"
        else:
            out += f".{part}" if out else str(part)
    return out or "(top level)"


#: Fields that take a number of either type (``StrictFloat | StrictInt``): pydantic
#: ends the path of their errors with the type it tried, once per type.
_EITHER_NUMBER = ("seconds", "distance")
_TYPE_TAGS = ("str", "int", "float", "bool", "none")


def _render(exc: ValidationError) -> list[str]:
    out = []
    for err in exc.errors(include_url=False):
        loc = tuple(p for p in err["loc"] if not (isinstance(p, str) and (
            p.startswith("function-") or p in ("_FloatCheckIn", "_AlgebraicIn",
                                               "_CertificateIn", "_CertificateDataIn",
                                               "str", "dict[str,any]"))))
        message = " ".join(str(err["msg"]).split())
        if len(loc) >= 2 and loc[-1] in _TYPE_TAGS and loc[-2] in _EITHER_NUMBER:
            loc, message = loc[:-1], "input should be a number"   # one line, not two
        kind = err["type"]
        if kind == "missing":
            out.append(f"{_path(loc[:-1])}: missing key '{loc[-1]}'")
        elif kind == "extra_forbidden":
            out.append(f"{_path(loc[:-1])}: unknown key {brief(str(loc[-1]))}")
        else:
            out.append(f"{_path(loc)}: {message[:1].lower()}{message[1:]}"
                       f" (got {brief(err.get('input'))})")
    return sorted(_one_remark_line(dict.fromkeys(out)))


def _one_remark_line(lines) -> list[str]:
    """The two lines of a remark that is neither a sentence nor a mapping, as one."""
    lines = list(lines)
    for line in list(lines):
        where, sep, got = line.partition(": input should be a valid dictionary (got ")
        twin = f"{where}: input should be a valid string (got {got}"
        if sep and twin in lines:
            lines.remove(twin)
            lines[lines.index(line)] = (f"{where}: input should be a sentence or a remark "
                                        f"(a mapping with its kind) (got {got}")
    return lines


class _Checker:
    """The meaning of a structurally valid report: names, expressions, indices."""

    def __init__(self, tree):
        self.tree = tree
        self.problems: list[str] = []
        self.variables: list[str] = []
        self.variables_read = True   # False when an entry of ``variables`` is refused
        self.polynomials: dict[str, NamedPolynomial] = {}  # entry -> its polynomial
        self.conditions: dict[str, Condition] = {}         # component -> its condition

    def add(self, where: str, message: str) -> None:
        self.problems.append(f"{where}: {message}")

    def name(self, where: str, text: str) -> bool:
        if not _IDENTIFIER.fullmatch(text):
            self.add(where, f"{brief(text)} is not a name")
            return False
        if text in _RESERVED:
            self.add(where, f"{brief(text)} is reserved (it means something else in "
                            "expressions)")
            return False
        return True

    def expression(self, where: str, text: str, names, polynomial: bool = False) -> None:
        if names is self.variables and not self.variables_read:
            # a variable was refused: its entry has the error, and a name of this text
            # that may be it is not reported again (the rest of the text is checked)
            names = [*names, *(n for n in dict.fromkeys(_SYMBOL_USE.findall(text))
                               if n not in _RESERVED)]
        try:
            if polynomial:  # read once, without SymPy: the component keeps it
                read = parse_polynomial(text, names, where)
                self.polynomials[where] = NamedPolynomial.from_flint(
                    read, read.context().names())
            else:
                parse_expression(text, names, where)
        except NumberError as exc:
            self.problems.append(str(exc))

    def read(self, text: str, where: str) -> NamedPolynomial:
        """A polynomial in the report's variables, read without SymPy."""
        read = parse_polynomial(text, self.variables, where)
        return NamedPolynomial.from_flint(read, read.context().names())

    def condition(self, where: str, c) -> None:
        """The component's condition as data: from ``condition_data`` when the report
        has it, else read from its text (a report of an earlier version), else its
        equations (a text that does not read as a condition)."""
        kinds = {joint_of(v): "revolute" for v in self.variables if joint_of(v)}
        if c.condition_data is None:
            try:
                self.conditions[where] = Condition.parse(c.condition, kinds,
                                                         f"{where}.condition", self.read)
            except NumberError:
                eqs = [self.polynomials.get(f"{where}.equations[{k}]")
                       for k in range(len(c.equations))]
                self.conditions[where] = vanishing([e for e in eqs if e is not None])
            return
        alternatives = []
        for i, alt in enumerate(c.condition_data):
            clauses = []
            for j, clause in enumerate(alt):
                read = self.clause(f"{where}.condition_data[{i}][{j}]", clause, kinds)
                if read is not None:
                    clauses.append(read)
            alternatives.append(tuple(clauses))
        self.conditions[where] = Condition(tuple(alternatives))

    def clause(self, where: str, clause, kinds: Mapping[str, str]) -> Clause | None:
        given = [k for k in ("value", "related", "vanishes") if getattr(clause, k) is not None]
        if len(given) != 1:
            self.add(where, "a clause is one of value (with equals), related (with sign) "
                            "or vanishes")
            return None
        try:
            if clause.value is not None:
                if self.name(f"{where}.value", clause.value) and clause.equals is not None:
                    value = parse_expression(clause.equals, [], f"{where}.equals")
                    return Value(clause.value, value, clause.kind
                                 or kinds.get(clause.value, "prismatic"))
                self.add(where, "a value clause needs a name and what it equals")
            elif clause.related is not None:
                if clause.sign not in (1, -1):
                    self.add(f"{where}.sign", "the sign is 1 or -1")
                elif all(self.name(f"{where}.related", n) for n in clause.related):
                    return Related(*clause.related, clause.sign, bool(clause.plus_pi))
            else:
                return Vanishes(self.read(clause.vanishes, f"{where}.vanishes"))
        except NumberError as exc:
            self.problems.append(str(exc))
        return None

    def numbers(self, where: str, numbers: Mapping[str, int]) -> None:
        for key, value in numbers.items():
            if key not in NUMBER_NAMES:
                self.add(where, f"unknown number {brief(key)} (expected "
                                f"{', '.join(NUMBER_NAMES)})")
            elif value < 0:
                self.add(f"{where}.{key}", f"a count cannot be negative, got {value}")

    def point(self, where: str, point: Mapping[str, str]) -> None:
        for key, value in point.items():
            if self.name(f"{where}", key):
                self.expression(f"{where}.{key}", value, self.variables)

    def assignments(self, where: str, text: str) -> None:
        """``fixed``: ``NAME=VALUE,...`` (commas inside parentheses belong to values)."""
        if not text.strip():
            return
        for part in top_level_parts(text):
            name, sep, value = part.partition("=")
            if not sep:
                self.add(where, f"expected NAME=VALUE, got {brief(part)}")
            elif self.name(where, name.strip()):
                self.expression(f"{where}.{name.strip()}", value, self.variables)

    def run(self, locus) -> None:
        seen: set[str] = set()
        for i, v in enumerate(locus.variables):
            if self.name(f"variables[{i}]", v):
                if v in seen:
                    self.add(f"variables[{i}]", f"{brief(v)} given twice")
                seen.add(v)
                self.variables.append(v)
            else:
                self.variables_read = False
        # s_<joint> = cot(q/2), the chart at q = pi, for every t_<joint>
        self.variables += [cotangent_name(v[2:]) for v in list(self.variables)
                           if v.startswith("t_") and cotangent_name(v[2:]) not in seen]
        self.numbers("generic", locus.generic)
        self.assignments("fixed", locus.fixed)
        if not math.isfinite(locus.seconds) or locus.seconds < 0:  # float-ok: a check
            self.add("seconds", "must be a finite number of seconds, at least 0")
        n = len(locus.components)
        for k, c in enumerate(locus.components):
            self.component(f"components[{k}]", c, n)
        for key in ("parameter_conditions", "dropped", "unexplored", "notes"):
            for k, r in enumerate(getattr(locus, key)):
                self.remark(f"{key}[{k}]", r)
        if isinstance(locus.certificate, _CertificateDataIn):
            self.certificate_data("certificate", locus.certificate, n)
        elif locus.certificate is not None:
            self.certificate("certificate", locus.certificate, n)

    def remark(self, where: str, value) -> None:
        """A remark as data: a known kind with exactly its facts."""
        if isinstance(value, Mapping):
            try:
                _remark(value)
            except CoopkinError as exc:
                self.add(where, str(exc))

    def certificate_data(self, where: str, cert, count: int) -> None:
        """A certificate as data: its remarks, the tests its tables name, indices."""
        self.remark(f"{where}.refused", cert.refused)
        for j, r in enumerate(cert.notes):
            self.remark(f"{where}.notes[{j}]", r)
        for j, check in enumerate(cert.checks):
            self.remark(f"{where}.checks[{j}].why", check.why)
            if check.inside is not None and not 0 <= check.inside < count:
                self.add(f"{where}.checks[{j}].inside", f"no component with index "
                                                       f"{check.inside}")
            if check.depth < 0:
                self.add(f"{where}.checks[{j}].depth", "cannot be negative")
        for table in ("depths", "charts"):
            for key, entry in getattr(cert, table).items():
                at = _path((where, table, key))
                if table == "depths" and not key.isdigit():
                    self.add(f"{where}.depths", f"{brief(key)} is not a depth")
                if min(entry.tests, entry.failed) < 0 or entry.failed > entry.tests:
                    self.add(at, "counts must satisfy 0 <= failed <= tests")
                if isinstance(entry.why, Mapping) and set(entry.why) == {"check"}:
                    k = entry.why["check"]
                    if not (isinstance(k, int) and 0 <= k < len(cert.checks)):
                        self.add(f"{at}.why", f"no test with index {brief(str(k))}")
                else:
                    self.remark(f"{at}.why", entry.why)

    def certificate(self, where: str, cert, count: int) -> None:
        """A certificate's summary agrees with its verdict; counts and depths are
        counts; the components its tests name exist."""
        if cert.certified != (cert.summary == "complete (certified)"):
            self.add(f"{where}.summary", f"{brief(cert.summary)} does not agree with "
                                         f"certified = {str(cert.certified).lower()}")
        if not cert.certified and not cert.summary.startswith("not certified: "):
            self.add(f"{where}.summary", "a certificate that does not certify starts with "
                                         "'not certified: '")
        if cert.tests < 0 or any(v < 0 for v in cert.certified_by.values()):
            self.add(f"{where}.tests", "a count cannot be negative")
        for table in ("depths", "charts"):
            for key, entry in getattr(cert, table).items():
                if table == "depths" and not key.isdigit():
                    self.add(f"{where}.depths", f"{brief(key)} is not a depth")
                if min(entry.tests, entry.failed) < 0 or entry.failed > entry.tests:
                    self.add(_path((where, table, key)), "counts must satisfy 0 <= "
                                                         "failed <= tests")
        for name in ("failed", "checks"):
            for j, check in enumerate(getattr(cert, name) or []):
                if check.inside is not None and not 0 <= check.inside < count:
                    self.add(f"{where}.{name}[{j}].inside", f"no component with index "
                                                           f"{check.inside}")
                if check.depth < 0:
                    self.add(f"{where}.{name}[{j}].depth", "cannot be negative")

    def component(self, where: str, c, count: int) -> None:
        for i, eq in enumerate(c.equations):
            self.expression(f"{where}.equations[{i}]", eq, self.variables, polynomial=True)
        for i, eq in enumerate(c.outside):
            self.expression(f"{where}.outside[{i}]", eq, self.variables, polynomial=True)
        self.condition(where, c)
        for i, joint in enumerate(c.chart):
            self.name(f"{where}.chart[{i}]", joint)
        self.numbers(f"{where}.numbers", c.numbers)
        self.remark(f"{where}.decided", c.decided)
        if c.witness is not None:
            self.point(f"{where}.witness", c.witness)
        if c.kind not in KINDS:
            self.add(f"{where}.kind", f"unknown kind {brief(c.kind)} (expected "
                                      f"{', '.join(KINDS)})")
        for key, pair in c.changes.items():
            if key not in NUMBER_NAMES:
                self.add(f"{where}.changes", f"unknown number {brief(key)}")
            elif min(pair) < 0:
                self.add(f"{where}.changes.{key}", "a count cannot be negative")
        if c.depth < 0:
            self.add(f"{where}.depth", f"cannot be negative, got {c.depth}")
        if c.parent is not None and not 1 <= c.parent <= count:
            self.add(f"{where}.parent", f"no component #{c.parent} (there are {count}, "
                                        "numbered from 1)")
        if c.real_points not in ("", "witness", "undecided"):
            self.add(f"{where}.real_points", f"unknown value {brief(c.real_points)} "
                                             "(expected witness or undecided)")
        for j, f in enumerate(c.float_checks):
            at = f"{where}.float_checks[{j}]"
            if not math.isfinite(f.distance) or f.distance < 0:  # float-ok: a check
                self.add(f"{at}.distance", "must be a finite number, at least 0")
            self.point(f"{at}.point", f.point)
            self.numbers(f"{at}.exact", f.exact)
            self.numbers(f"{at}.float", f.float)
        if c.algebraic_witness is not None:
            self.algebraic(f"{where}.algebraic_witness",
                           c.algebraic_witness.model_dump(exclude_unset=True))

    def algebraic(self, where: str, w: Mapping[str, Any]) -> None:
        self.point(f"{where}.point", w.get("point", {}))
        for key, value in w.get("approx", {}).items():
            if not _DECIMAL.fullmatch(value.strip()):
                self.add(f"{where}.approx.{key}", f"{brief(value)} is not a decimal number")
        for i, value in enumerate(w.get("interval", [])):
            for piece in value.split(";"):
                self.expression(f"{where}.interval[{i}]", piece, [])
        for key in ("root_of", "root"):
            for piece in w.get(key, "").split(";"):
                if piece.strip():
                    # a root is a number: a name in it can only be CRootOf's variable
                    names = [] if key == "root" else [
                        n for n in dict.fromkeys(_IDENTIFIER.findall(piece))
                        if n not in _RESERVED]
                    self.expression(f"{where}.{key}", piece, names,
                                    polynomial=key == "root_of")


def validate_report(data: Mapping | str) -> Locus:
    """A :class:`~coopkin_sym.analysis.locus.types.Locus` from report JSON (text or parsed),
    checked as described in the module docstring.

    Raises
    ------
    ReportInputError
        One line per problem, each naming the entry.
    """
    if isinstance(data, str | bytes):
        try:
            text = data.decode("utf-8") if isinstance(data, bytes) else data
            tree = read_text(text, ".json", exact_floats=False)
        except (TreeError, UnicodeDecodeError) as exc:
            raise ReportInputError([f"(top level): {exc}"]) from None
    else:
        tree = data
        try:
            check_tree(tree)
        except TreeError as exc:
            raise ReportInputError([f"(top level): {exc}"]) from None
    if not isinstance(tree, Mapping):
        raise ReportInputError([f"(top level): expected a mapping, got "
                                f"{type(tree).__name__}"])
    try:
        parsed = _LocusIn.model_validate(tree)
    except ValidationError as exc:
        raise ReportInputError(_render(exc)) from None
    checker = _Checker(tree)
    checker.run(parsed)
    if checker.problems:
        raise ReportInputError(checker.problems)
    return _to_locus(parsed, checker)


def _remark(value) -> Remark | str:
    """A remark from report data: a sentence as it is, or a kind and its facts."""
    if isinstance(value, Mapping):
        facts = {k: v for k, v in value.items() if k != "kind"}
        return Remark.of(str(value.get("kind")), **facts)
    return value


def _certificate_data(cert) -> Certificate:
    """A :class:`Certificate` back from its data (validated)."""
    checks = [Check(c.chart, c.depth, c.inside, c.matrix, c.kind, c.certified,
                    None if c.why is None else _remark(c.why), c.backend, c.seconds)
              for c in cert.checks]

    def table(entry) -> dict:
        why = entry.why
        if isinstance(why, Mapping) and set(why) == {"check"}:
            why = checks[why["check"]]
        elif why is not None:
            why = _remark(why)
        return {"certified": entry.certified, "why": why, "tests": entry.tests,
                "failed": entry.failed}

    return Certificate(cert.system, cert.certified,
                       None if cert.refused is None else _remark(cert.refused),
                       {int(k): table(v) for k, v in cert.depths.items()},
                       {k: table(v) for k, v in cert.charts.items()}, checks,
                       [_remark(n) for n in cert.notes], cert.untested_beyond, cert.seconds)


def _to_locus(parsed, checker: _Checker) -> Locus:
    polynomials = checker.polynomials
    comps = []
    for i, c in enumerate(parsed.components):
        values = {f.name: getattr(c, f.name) for f in dataclasses.fields(Component)
                  if f.name not in ("shown", "stated_meaning")}
        values["stated_meaning"] = list(c.meaning)
        # the report's polynomials and condition, as the checker read them
        where = f"components[{i}]"
        values["equations"] = [polynomials[f"{where}.equations[{k}]"]
                               for k in range(len(c.equations))]
        values["outside"] = [polynomials[f"{where}.outside[{k}]"]
                             for k in range(len(c.outside))]
        values["condition"] = checker.conditions[where]
        values["chart"] = tuple(c.chart)
        values["changes"] = {k: tuple(v) for k, v in c.changes.items()}
        values["decided"] = _remark(c.decided)
        if c.parent is not None:  # the report's numbering (#1, #2, ...) -> an index
            values["parent"] = c.parent - 1
        values["float_checks"] = [
            FloatCheck(distance=f.distance, scale=f.scale, point=dict(f.point),
                       exact=dict(f.exact), float=dict(f.float)) for f in c.float_checks]
        if c.algebraic_witness is not None:
            values["algebraic_witness"] = c.algebraic_witness.model_dump(exclude_unset=True)
        if c.finite is not None:
            values["finite"] = dict(c.finite.model_dump(exclude_none=True),
                                    dimension=c.finite.dimension,
                                    bounds=list(c.finite.bounds))
            if c.finite.along is not None:       # undecided there: its dimension is None
                along = values["finite"]["along"]
                along["dimension"] = c.finite.along.dimension
                if "bounds" in along:
                    along["bounds"] = list(along["bounds"])
        comps.append(Component(**values))
    values = {f.name: getattr(parsed, f.name) for f in dataclasses.fields(Locus)}
    values["components"] = comps
    for key in ("parameter_conditions", "dropped", "unexplored", "notes"):
        values[key] = [_remark(r) for r in values[key]]
    if isinstance(parsed.certificate, _CertificateDataIn):
        values["certificate"] = _certificate_data(parsed.certificate)
    elif parsed.certificate is not None:
        values["certificate"] = certificate_read(parsed.certificate)
    if parsed.locked is not None:  # the locus of the locked system, read the same way
        try:
            values["locked"] = validate_report(parsed.locked)
        except ReportInputError as exc:
            raise ReportInputError([f"locked.{line}" for line in exc.problems]) from None
    locus = Locus(**values)
    said = completeness_text(locus)
    if parsed.completeness is not None and parsed.completeness != said:
        raise ReportInputError([f"completeness: {brief(parsed.completeness)} does not agree "
                                f"with the certificate ({brief(said)})"])
    return locus
