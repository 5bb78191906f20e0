"""Exact numbers at many configurations, fast.

The matrix ``Q`` of a system is built once with the swept joints symbolic and every
other joint at its value (:class:`Compiled`); each row is cleared to integer
polynomials and *homogenized*: a swept revolute joint enters through
``tan(q/2) = a/b`` and a swept prismatic one through ``d = a/b``, so a row becomes a
polynomial in the integers ``(a, b)`` that is a nonzero multiple of the row of ``Q``
at every point, ``q = pi`` included (``(a, b) = (1, 0)``). Evaluating those integer
polynomials gives a matrix with the ranks of ``Q``, ``H G^T`` and ``H D`` at the
point, hence all seven numbers. That expansion grows about fivefold per swept joint
of a chain: with more than four on one chain, and for the exact rechecks, ``Q`` is
instead evaluated at each point from the home data by the product of exponentials
(:mod:`coopkin_sym.analysis.sweep.chains`).

:func:`sweep` evaluates a whole batch modulo the prime ``p = 2**31 - 1`` and
eliminates it with numpy (:mod:`coopkin_sym.exact.modular`). A rank modulo ``p``
never exceeds the rank over Q, which never exceeds the generic rank (computed once,
exactly, over ``Q(t, L)``), so every point whose three modular ranks equal the generic
ones is *certified*; every other point (candidate singular) is *rechecked* exactly
over Q with flint. No rank is ever decided in floating point.

:func:`grid` builds the exact points of a grid. A grid angle whose ``tan(q/2)`` is
irrational is snapped to a nearby angle with a rational ``tan(q/2)`` within
``|dq| <= bound`` (floats are used only to choose that rational) and the result says so.

:class:`SweepResult` writes a plain CSV (each swept joint's exact value followed by the
same value as a float, ``q1_rad`` in radians or ``d1_float`` for a prismatic joint:
labelled extras for plotting, never used in a decision) with its metadata in
``<name>.csv.json``, JSON (exact values only) and, with pandas and pyarrow, Parquet;
it reads the CSV and the JSON back (:meth:`SweepResult.read`), and gives a pandas
DataFrame (:meth:`SweepResult.to_pandas`) when pandas is installed
(``docs/sweep-files.md``).

Example
-------
>>> from coopkin_sym import load
>>> system = load("paper-case1-hard")
>>> result = sweep(system, grid(system, "q1=-pi/2..pi/2:3,q2=-pi/2..pi/2:3"))
>>> [r["Nm"] for r in result.rows()]
[3, 2, 3, 2, 2, 2, 3, 2, 3]
>>> result.rows()[0]["q1"], result.rows()[0]["exact_recheck"]
('-pi/2', True)
"""

from coopkin_sym.analysis.sweep.compiled import Compiled, compile_system
from coopkin_sym.analysis.sweep.grid import Grid, grid, parse_grid
from coopkin_sym.analysis.sweep.result import SweepResult
from coopkin_sym.analysis.sweep.run import sweep
from coopkin_sym.analysis.sweep.values import Value
from coopkin_sym.errors import SweepError

__all__ = ["Compiled", "Grid", "SweepError", "SweepResult", "Value", "compile_system",
           "grid", "parse_grid", "sweep"]
