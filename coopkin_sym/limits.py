"""Budgets on everything read from outside: files, numbers, expressions, grids.

Each limit keeps a tiny input from taking minutes or gigabytes; each is far above what
an honest model needs (a 200-arm, 2000-contact system is about 0.3 MB and 40,000
entries). Going over one is an error naming the entry and the limit, never a hang or
a traceback. The values are documented in ``docs/model-format.md`` (section
"Limits"); code reads them from here, so a test can lower one.

Example
-------
>>> MAX_DIGITS, MAX_EXPONENT
(1000, 1000)
"""

from __future__ import annotations

import functools
import math

#: Bytes in a model file, a URDF file or a report read back.
MAX_FILE_BYTES = 8 * 1024 * 1024
#: Entries (mappings, lists, scalars) in one file or tree, counting every use of a
#: YAML alias as a copy.
MAX_NODES = 1_000_000
#: Nesting of mappings and lists in one file or tree, and of the elements of a URDF
#: file.
MAX_DEPTH = 32
#: Links of one URDF file (large robots have a few hundred).
MAX_URDF_LINKS = 4000
#: Joints of one URDF file.
MAX_URDF_JOINTS = 4000
#: XML elements of one URDF file (links, joints and everything inside them); their
#: nesting is bounded by :data:`MAX_DEPTH`.
MAX_URDF_ELEMENTS = 100_000
#: Joints (moving and fixed) on the chain of one arm read from a URDF file.
MAX_URDF_CHAIN = 256
#: Characters in one number or angle (model values, ``--at``, ``--grid`` ends).
MAX_NUMBER_TEXT = 1000
#: Characters in one equation or condition (reports read back, the API).
MAX_EXPRESSION_TEXT = 1_000_000
#: Decimal digits of an integer, or of a numerator or denominator, anywhere.
MAX_DIGITS = 1000
#: Largest integer exponent (``x**n``) and decimal exponent (``1e-n``).
MAX_EXPONENT = 1000
#: Total degree of a polynomial built from text.
MAX_DEGREE = 1000
#: Terms of a polynomial built from text.
MAX_TERMS = 100_000
#: Terms times terms of one product while building a polynomial (its cost).
MAX_PRODUCT = 4_000_000
#: Nesting of parentheses in one expression.
MAX_PARENTHESES = 50
#: Size (nodes) of an irrational constant (pi, atan, sqrt) while it is built.
MAX_CONSTANT_NODES = 2000
#: Multiples of pi and of atan(x) added up in one angle.
MAX_ANGLE_TERMS = 8
#: ``n`` such that ``exp(i q)`` is an ``n``-th root of a rational point of the
#: circle: bounds the work of deciding an angle (``pi/99991`` needs n = 199982).
MAX_ANGLE_ORDER = 360
#: Degree over Q that an angle with an irrational ``tan(q/2)`` may bring (``pi/6``
#: brings 2, ``pi/12`` brings 4).
MAX_ANGLE_DEGREE = 16
#: Degree of a polynomial whose real root ``CRootOf(p, k)`` names (witnesses).
MAX_ROOT_DEGREE = 32
#: Degree of the number field of one configuration with irrational coordinates.
MAX_FIELD_DEGREE = 64
#: Largest end of a range of angles in a sweep grid (radians).
MAX_ANGLE_RADIANS = 10**6
#: Values on one axis of a sweep grid.
MAX_GRID_COUNT = 1_000_000
#: Points of a sweep (all axes together, or a list of points).
MAX_GRID_POINTS = 2_000_000
#: Largest coordinate (in length units) a picture draws.
MAX_DRAWN_COORDINATE = 1e12  # float-ok: a bound on what is drawn, not a decision


@functools.lru_cache(maxsize=4)
def _power_of_ten(n: int) -> int:
    return 10**n


def integer_bound() -> int:
    """``10**MAX_DIGITS``: every integer read must be below it in absolute value."""
    return _power_of_ten(MAX_DIGITS)


def max_bits() -> int:
    """Bits of the largest integer of at most :data:`MAX_DIGITS` digits, plus one."""
    return math.ceil(MAX_DIGITS * math.log2(10)) + 1
