"""The manipulability ellipsoid as text and JSON (what ``coopkin manipulability``
prints), and its semi-axes as floats for plots and readers (the ellipsoid itself is
exact: :mod:`coopkin_sym.analysis.manipulability`).

Example
-------
>>> from coopkin_sym import load
>>> m = load("five-bar").analyze("L=1").manipulability(["v_x", "v_y"], point=[0, 2, 0])
>>> semi_axes(m)[0]                       # floats: sqrt(1/2) twice
array([0.70710678, 0.70710678])
"""

from __future__ import annotations

import json
from fractions import Fraction

import numpy as np
import sympy as sp

from coopkin_sym.analysis.manipulability import Manipulability
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.errors import ManipulabilityError
from coopkin_sym.exact.angles import ExactAngle


def semi_axes(m: Manipulability) -> tuple[np.ndarray, np.ndarray]:
    """The semi-axes (largest first) and their directions (columns, in the order of
    ``m.controlled``) of the ellipsoid, as floats: the square roots of the eigenvalues
    of the exact ``E``. Only where ``E`` has no symbol left.

    Raises
    ------
    ManipulabilityError
        ``E`` still depends on free variables or parameters.
    """
    free = sorted(str(s) for s in m.shape.free_symbols)
    if free:
        raise ManipulabilityError(f"the semi-axes are numbers only at a point: E still "
                                  f"depends on {', '.join(free)} (give their values)")
    shape = np.array([[float(x) for x in m.shape.row(i)]  # float-ok: semi-axes, shown
                      for i in range(m.shape.rows)], dtype=float)
    lengths, directions = np.linalg.eigh(shape)  # float-ok: semi-axes, shown
    order = np.argsort(lengths)[::-1]
    return np.sqrt(np.clip(lengths[order], 0.0, None)), directions[:, order]


def degeneracy_text(factor: sp.Expr) -> str:
    """A factor of ``det E`` as a condition: an angle where it is linear in one
    ``t_X = tan(X/2)``, else the polynomial equation.

    Example
    -------
    >>> t = sp.Symbol("t_q2")
    >>> degeneracy_text(t - 1), degeneracy_text(3 * t + 1), degeneracy_text(t**2 - 2)
    ('q2 = pi/2', 'q2 = 2*atan(-1/3)', 't_q2**2 - 2 = 0')
    """
    symbols = sorted(factor.free_symbols, key=str)
    if len(symbols) == 1 and str(symbols[0]).startswith("t_"):
        poly = sp.Poly(factor, symbols[0])
        if poly.degree() == 1:
            a, b = poly.all_coeffs()
            value = -b / a
            if value.is_Rational:
                angle = ExactAngle.from_tangent(Fraction(int(value.p), int(value.q)))
                return f"{str(symbols[0])[2:]} = {angle.text}"
    return f"{sp.sstr(factor)} = 0"


def _speed(analysis) -> str:
    return "motor" if analysis.model.passive_joints else "joint"


def manipulability_text(m: Manipulability, analysis: Analysis) -> str:
    """The ellipsoid in a few lines: what it is of, ``E``, ``det E``, the rank, where it
    degenerates, and at a point the float semi-axes.

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("five-bar").analyze("L=1")
    >>> print(manipulability_text(a.manipulability(["v_x", "v_y"], point=[0, 2, 0]), a))
    ... # doctest: +ELLIPSIS
    Manipulability of five-bar linkage with passive elbows (at L=1)
    Object velocities at unit motor speed: v_x, v_y (angular parts x 1)
    ...
    """
    lines = [f"Manipulability of {analysis.model.name} ({analysis.where})",
             f"Object velocities at unit {_speed(analysis)} speed: "
             f"{', '.join(m.controlled)} (angular parts x {sp.sstr(m.length)})",
             f"E = {sp.sstr(m.shape.tolist())}",
             f"det E = {sp.sstr(m.index)}",
             f"rank E = {m.rank} of {len(m.controlled)}"]
    if m.degeneracy:
        lines.append("E loses rank where: "
                     + " or ".join(degeneracy_text(f) for f in m.degeneracy))
        if any(str(s).startswith("t_") for f in m.degeneracy for s in f.free_symbols):
            lines.append("  (t_X = tan(X/2) for a revolute joint X)")
    elif m.shape.free_symbols:
        lines.append("E keeps its rank wherever it is defined")
    if not m.shape.free_symbols:
        axes, directions = semi_axes(m)
        lines.append("Semi-axes (floats): " + ", ".join(f"{x:.6g}" for x in axes))
        for x, d in zip(axes, directions.T, strict=True):
            lines.append(f"  {x:.6g} along (" + ", ".join(f"{c:.4g}" for c in d) + ")")
    return "\n".join(lines)


def manipulability_json(m: Manipulability, analysis: Analysis) -> str:
    """The ellipsoid as JSON: exact entries as strings, the float semi-axes (at a
    point) under ``"semi_axes_float"``.

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("five-bar").analyze("L=1")
    >>> data = json.loads(manipulability_json(a.manipulability(["v_x", "v_y"],
    ...                                                        point=[0, 2, 0]), a))
    >>> data["shape"], data["index"], data["rank"]
    ([['1/2', '0'], ['0', '1/2']], '1/4', 2)
    """
    data = {"system": analysis.model.name, "configuration":
            analysis.configuration.at_text(), "controlled": list(m.controlled),
            "speed": _speed(analysis), "length": sp.sstr(m.length),
            "form": [[sp.sstr(x) for x in m.form.row(i)] for i in range(m.form.rows)],
            "shape": [[sp.sstr(x) for x in m.shape.row(i)] for i in range(m.shape.rows)],
            "index": sp.sstr(m.index), "rank": m.rank,
            "degeneracy": [sp.sstr(f) for f in m.degeneracy],
            "semi_axes_float": None, "directions_float": None}
    if not m.shape.free_symbols:
        axes, directions = semi_axes(m)
        data["semi_axes_float"] = [float(x) for x in axes]  # float-ok: labelled
        data["directions_float"] = directions.T.tolist()
    return json.dumps(data, indent=2)


__all__ = ["degeneracy_text", "manipulability_json", "manipulability_text", "semi_axes"]
