"""Where to analyze: exact values for some joint variables and parameters.

A :class:`Configuration` says which joint variables stay symbolic (``free``) and gives
every other joint an exact value: a revolute angle as its exact ``(cos q, sin q)``
pair (rational tangent half-angle, or q = pi), a prismatic displacement as a
rational or a polynomial in the parameters. Parameters without a value stay symbolic.
Unset joints are at home (q = 0).

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> m = load_model("paper-case1-hard")
>>> c = Configuration.parse(m, "q1=pi/2,L=2")
>>> c.revolute["q1"], c.parameters["L"]
((0, 1), 2)
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

import sympy as sp

from coopkin_sym.errors import ConfigurationError
from coopkin_sym.exact.parse import NumberError, angle_text, brief, parse_angle, parse_number
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

    revolute: Mapping[str, tuple[sp.Rational, sp.Rational]] = field(default_factory=dict)
    prismatic: Mapping[str, sp.Expr] = field(default_factory=dict)
    parameters: Mapping[str, sp.Rational] = field(default_factory=dict)
    free: frozenset[str] = frozenset()

    @classmethod
    def parse(
        cls,
        model: Model,
        at: str | Mapping[str, object] | None = None,
        free: Iterable[str] | str | None = None,
    ) -> Configuration:
        """Read ``at`` (``"q1=pi/2,q2=2*atan(1/3),d4=1/2,L=1000"`` or a mapping) and
        the free joints (names, or ``"all"``) for ``model``.

        Revolute values are angles in SymPy syntax, or ``(cos, sin)`` pairs; a joint
        both given a value and declared free is an error.
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
        revolute: dict[str, tuple[sp.Rational, sp.Rational]] = {}
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
        parts = [f"{n}={angle_text(c, s)}" for n, (c, s) in self.revolute.items()]
        parts += [f"{n}={sp.sstr(v)}" for n, v in self.prismatic.items()]
        parts += [f"{n}={sp.sstr(v)}" for n, v in self.parameters.items()]
        return ",".join(parts)


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


def _angle(value, where: str) -> tuple[sp.Rational, sp.Rational]:
    if isinstance(value, tuple) and len(value) == 2:
        try:
            c, s = (parse_number(v, {}, f"{where} (cos, sin)") for v in value)
        except NumberError as exc:
            raise ConfigurationError(str(exc)) from None
        if c**2 + s**2 != 1:
            raise ConfigurationError(f"{where}: (cos, sin) = ({c}, {s}) is not on the unit "
                                     "circle")
        return c, s
    try:
        return parse_angle(value if isinstance(value, str | sp.Basic | int) else
                           _angle_text(value, where), where)
    except NumberError as exc:
        raise ConfigurationError(str(exc)) from None


def _angle_text(value, where: str) -> str:
    """A non-text angle value: exact numbers are read as numbers (radians), anything
    else is refused (a float angle is never exact but 0)."""
    try:
        return sp.sstr(parse_number(value, {}, where))
    except NumberError as exc:
        raise ConfigurationError(str(exc)) from None


def _number(value, params, where: str) -> sp.Expr:
    try:
        return parse_number(value, params, where)
    except NumberError as exc:
        raise ConfigurationError(str(exc)) from None
