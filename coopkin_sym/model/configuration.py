"""Where to analyze: exact values for some joint variables and parameters.

A :class:`Configuration` says which joint variables stay symbolic (``free``) and gives
every other joint an exact value: a revolute angle as an
:class:`~coopkin_sym.exact.angles.ExactAngle` (rational tangent half-angle, or q = pi),
a prismatic displacement as a rational or a polynomial in the parameters. Parameters
without a value stay symbolic.
Unset joints are at home (q = 0).

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> m = load_model("paper-case1-hard")
>>> c = Configuration.parse(m, "q1=pi/2,L=2")
>>> c.revolute["q1"], c.revolute["q1"].cos_sin, c.parameters["L"]
(ExactAngle(num=1, den=1), (0, 1), 2)
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace

import sympy as sp

from coopkin_sym.errors import ConfigurationError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import NumberError, brief, parse_number
from coopkin_sym.model.model import Model


@dataclass(frozen=True)
class Configuration:
    """Exact values of joint variables and parameters, and the free joints.

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> c = Configuration.parse(load_model("paper-case1-hard"), "q1=pi/2,L=2", free=["q2"])
    >>> c.at_text(), sorted(c.free)
    ('q1=pi/2,L=2', ['q2'])
    """

    revolute: Mapping[str, ExactAngle] = field(default_factory=dict)
    prismatic: Mapping[str, sp.Expr] = field(default_factory=dict)
    parameters: Mapping[str, sp.Rational] = field(default_factory=dict)
    free: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        for name, angle in self.revolute.items():
            if not isinstance(angle, ExactAngle):
                raise ConfigurationError(f"{name}: a revolute value of a configuration is an "
                                         f"ExactAngle, got {brief(repr(angle))}")

    @classmethod
    def parse(
        cls,
        model: Model,
        at: str | Mapping[str, object] | None = None,
        free: Iterable[str] | str | None = None,
    ) -> Configuration:
        """Read ``at`` (``"q1=pi/2,q2=2*atan(1/3),d4=1/2,L=1000"`` or a mapping) and
        the free joints (names, or ``"all"``) for ``model``.

        Revolute values are angles in ``--at`` syntax, :class:`ExactAngle` values, or
        exact ``(cos, sin)`` pairs; a joint both given a value and declared free is an
        error.
        """
        items = _split_at(at)
        joints = {j.name: j for j in model.joints}
        params = {p.name: p for p in model.parameters}
        if free == "all":
            free_set = frozenset(joints)
        else:
            free_set = frozenset([free] if isinstance(free, str) else (free or ()))
        unknown = sorted(free_set - set(joints))
        if unknown:
            raise ConfigurationError(
                f"free: unknown joint {', '.join(unknown)} (joints: {', '.join(joints)})")
        revolute: dict[str, ExactAngle] = {}
        prismatic: dict[str, sp.Expr] = {}
        values: dict[str, sp.Rational] = {}
        for name, value in items:
            where = f"--at {name}"
            if name in joints:
                if name in free_set:
                    raise ConfigurationError(f"{where}: joint {name} is also declared free")
                if joints[name].type == "revolute":
                    revolute[name] = _angle(value, where)
                else:
                    prismatic[name] = _number(value, params, where)
            elif name in params:
                v = _number(value, {}, where)
                if v <= 0:
                    raise ConfigurationError(f"{where}: parameters are lengths and must be "
                                             f"positive, got {v}")
                values[name] = v
            else:
                safe = [r.name for r in getattr(model, "renamed", ()) if r.given == name]
                if safe:
                    raise ConfigurationError(
                        f"{where}: {brief(name)} is called {safe[0]} here (a name of a URDF "
                        f"file that is not a variable name gets a safe one)")
                known = ", ".join(list(joints) + list(params))
                raise ConfigurationError(f"{where}: unknown name {brief(name)} (known: {known})")
        # a prismatic displacement may use parameters; substitute the given values
        subs = {params[n]: v for n, v in values.items()}
        prismatic = {n: e if e.is_Rational else sp.expand(e.subs(subs))
                     for n, e in prismatic.items()}
        return cls(revolute, prismatic, values, free_set)

    def at_text(self) -> str:
        """This configuration in ``--at`` syntax (free joints left out)."""
        return assignments_text({**{n: a.text for n, a in self.revolute.items()},
                                 **{n: sp.sstr(v) for n, v in self.prismatic.items()},
                                 **{n: sp.sstr(v) for n, v in self.parameters.items()}})


class NotInPoint(KeyError, ConfigurationError):
    """A name a :class:`Point` does not give (a ``KeyError``, as a mapping raises).

    Example
    -------
    >>> issubclass(NotInPoint, KeyError) and issubclass(NotInPoint, ConfigurationError)
    True
    """


@dataclass(frozen=True, eq=False)
class Point(Configuration, Mapping):
    """A configuration with every joint and parameter given (no free joint), exact,
    whose names come in a fixed ``order``; read as a mapping, it is its ``--at``
    texts (``point["q1"] == "pi/2"``, ``dict(point)``), so it is equal to the mapping
    of the same texts. Witnesses of a locus, points of a sweep and of ``--at`` share
    this type; an analysis takes it as it is (nothing is parsed again).

    Example
    -------
    >>> import sympy as sp
    >>> p = Point.of({"q1": ExactAngle(1, 1)}, parameters={"L": sp.Integer(1)})
    >>> dict(p), p == {"q1": "pi/2", "L": "1"}, p.at_text()
    ({'q1': 'pi/2', 'L': '1'}, True, 'q1=pi/2,L=1')
    >>> p.moved("q1", ExactAngle(1, 0))["q1"], p.moved("q1", (0, -1))["q1"]
    ('pi', '-pi/2')
    """

    order: tuple[str, ...] = ()

    @classmethod
    def of(cls, revolute: Mapping[str, ExactAngle | tuple] | None = None,
           prismatic: Mapping[str, sp.Expr] | None = None,
           parameters: Mapping[str, sp.Rational] | None = None,
           order: Iterable[str] | None = None) -> Point:
        """The point of these exact values, named in ``order`` (default: revolute,
        prismatic, then parameters, each in the order given); a revolute value is an
        :class:`ExactAngle` or an exact ``(cos, sin)`` pair."""
        revolute = {n: _angle(a, n) for n, a in (revolute or {}).items()}
        prismatic = dict(prismatic or {})
        parameters = dict(parameters or {})
        names = tuple(order) if order is not None else (*revolute, *prismatic, *parameters)
        return cls(revolute, prismatic, parameters, frozenset(), names)

    def moved(self, name: str, value) -> Point:
        """This point with ``name`` set to ``value`` (an :class:`ExactAngle` or an
        exact ``(cos, sin)`` pair for a revolute joint, an exact number otherwise): a
        new name goes last."""
        order = self.order if name in self.order else (*self.order, name)
        if name in self.revolute:
            return replace(self, revolute={**self.revolute, name: _angle(value, name)},
                           order=order)
        if name in self.prismatic:
            return replace(self, prismatic={**self.prismatic, name: value}, order=order)
        return replace(self, parameters={**self.parameters, name: value}, order=order)

    def __getitem__(self, name: str) -> str:
        if name in self.revolute and name in self.order:
            return self.revolute[name].text
        for values in (self.prismatic, self.parameters):
            if name in values and name in self.order:
                return sp.sstr(values[name])
        raise NotInPoint(name)

    def __iter__(self) -> Iterator[str]:
        return iter(self.order)

    def __len__(self) -> int:
        return len(self.order)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Point):
            return (self.order == other.order and dict(self.revolute) == dict(other.revolute)
                    and dict(self.prismatic) == dict(other.prismatic)
                    and dict(self.parameters) == dict(other.parameters))
        if isinstance(other, Mapping):
            return dict(self.items()) == dict(other.items())
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]

    def at_text(self) -> str:
        """The point in ``--at`` syntax, in its order."""
        return assignments_text(self)


def _split_at(at) -> list[tuple[str, object]]:
    return split_assignments(at, "--at")


def split_assignments(text, context: str) -> list[tuple[str, object]]:
    """``"q1=pi/2,L=2"`` (or a mapping) as ``[(name, value), ...]``; errors
    (:class:`ConfigurationError`) start with ``context``."""
    if text is None:
        return []
    if isinstance(text, Mapping):
        return [(str(k), v) for k, v in text.items()]
    items = []
    for part in top_level_parts(str(text)):
        part = part.strip()
        if not part:
            continue
        if "=" not in part:
            raise ConfigurationError(f"{context}: expected NAME=VALUE, got {brief(part)}")
        name, value = part.split("=", 1)
        items.append((name.strip(), value.strip()))
    names = [n for n, _ in items]
    dups = sorted({n for n in names if names.count(n) > 1})
    if dups:
        raise ConfigurationError(f"{context}: {', '.join(dups)} given more than once")
    return items


def assignments_text(values: Mapping[str, object] | Iterable[tuple[str, object]]) -> str:
    """Names and their ``--at`` texts (a mapping, or ``(name, text)`` pairs) as one
    ``--at`` text, ``"q1=pi/2,L=2"``: the one writer of a point, which
    :func:`split_assignments` reads back. Each value is written by ``str`` (an angle
    already as :attr:`~coopkin_sym.exact.angles.ExactAngle.text`).

    Example
    -------
    >>> assignments_text({"q1": ExactAngle(1, 3).text, "L": 2})
    'q1=2*atan(1/3),L=2'
    >>> split_assignments(assignments_text([("q1", "pi"), ("d2", "1/2")]), "--at")
    [('q1', 'pi'), ('d2', '1/2')]
    """
    items = values.items() if isinstance(values, Mapping) else values
    return ",".join(f"{name}={text}" for name, text in items)


def top_level_parts(text: str) -> list[str]:
    """``text`` split at the commas outside parentheses (``L=Rational(1, 3),q1=0``).

    Example
    -------
    >>> top_level_parts("L=Rational(1, 3),q1=0")
    ['L=Rational(1, 3)', 'q1=0']
    """
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += ch == "("
        depth -= ch == ")"
        if ch == "," and depth <= 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


def _angle(value, where: str) -> ExactAngle:
    """A revolute value as the one exact-angle type: an :class:`ExactAngle` as it is,
    an exact ``(cos, sin)`` pair on the unit circle, or an angle read by the one parser
    (text, or an exact number of radians; a float angle is never exact but 0)."""
    if isinstance(value, ExactAngle):
        return value
    try:
        if isinstance(value, tuple) and len(value) == 2:
            c, s = (parse_number(v, {}, f"{where} (cos, sin)") for v in value)
            if not (c.is_Rational and s.is_Rational) or c**2 + s**2 != 1:
                raise ConfigurationError(f"{where}: (cos, sin) = ({c}, {s}) is not an "
                                         "exact point on the unit circle")
            return ExactAngle.from_cos_sin(c, s)
        if not isinstance(value, str | sp.Basic | int):
            value = sp.sstr(parse_number(value, {}, where))
        return ExactAngle.parse(value, where)
    except NumberError as exc:
        raise ConfigurationError(str(exc)) from None


def _number(value, params, where: str) -> sp.Expr:
    try:
        return parse_number(value, params, where)
    except NumberError as exc:
        raise ConfigurationError(str(exc)) from None
