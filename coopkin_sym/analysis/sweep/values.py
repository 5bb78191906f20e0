"""Exact values of swept joints: tangent half-angles and displacements, snapped.

A swept revolute joint takes values whose ``tan(q/2)`` is rational (or ``q = pi``); a
grid angle that is not is snapped to a nearby one within a stated bound (floats only
choose the rational). See :mod:`coopkin_sym.analysis.sweep`.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from coopkin_sym.exact.angles import ExactAngle

#: Largest angle change allowed when a grid angle is snapped to a rational tan(q/2).
SNAP_BOUND = 1e-9  # float-ok: a tolerance for choosing snapped angles, never for ranks


# --- exact values ---------------------------------------------------------------------
@dataclass(frozen=True)
class Value:
    """One exact value of a swept joint, in homogeneous coordinates.

    A revolute angle has ``tan(q/2) = num/den`` (``(1, 0)`` is ``q = pi``); a prismatic
    displacement is ``num/den``. ``text`` is exact (``"pi/2"``, ``"2*atan(1/3)"``,
    ``"3/4"``). A snapped grid angle keeps the angle that was asked for
    (``requested``) and how far the exact one lies from it (``error``, radians).

    Example
    -------
    >>> v = Value.from_tangent(Fraction(1, 3))
    >>> v.text, v.num, v.den
    ('2*atan(1/3)', 1, 3)
    >>> Value.from_angle(ExactAngle(1, 0)).text
    'pi'
    """

    text: str
    num: int
    den: int
    requested: str | None = None
    error: float | None = None  # float-ok: reported distance of a snapped angle

    @classmethod
    def from_angle(cls, angle: ExactAngle) -> Value:
        """The value of an exact angle."""
        return cls(angle.text, angle.num, angle.den)

    @classmethod
    def from_tangent(cls, t: Fraction | int | None) -> Value:
        """The angle with ``tan(q/2) = t`` (``None``: ``q = pi``)."""
        return cls.from_angle(ExactAngle.from_tangent(t))

    @property
    def snapped(self) -> bool:
        return self.requested is not None


def _tangent_of(ratio: Fraction) -> Fraction | None | bool:
    """``tan(pi * ratio / 2)`` when rational (``None`` for infinity), else ``False``.

    Niven: for rational ``ratio`` the half-angle tangent is rational only at multiples
    of ``pi/2``.
    """
    r = ratio % 2
    table = {Fraction(0): Fraction(0), Fraction(1, 2): Fraction(1), Fraction(1): None,
             Fraction(3, 2): Fraction(-1)}
    return table.get(r, False)


def _pi_text(ratio: Fraction) -> str:
    """``ratio * pi`` as SymPy prints it (``"-89*pi/90"``, ``"pi/6"``, ``"0"``)."""
    if ratio == 0:
        return "0"
    num, den = abs(ratio.numerator), ratio.denominator
    text = ("-" if ratio < 0 else "") + ("pi" if num == 1 else f"{num}*pi")
    return text + (f"/{den}" if den != 1 else "")
