"""The exact layer, below everything: exact arithmetic and nothing about robots.

:mod:`~coopkin_sym.exact.matrix` is the one exact-matrix type (rank, nullspace,
determinant over ``Q(x)``, ``Z[x]/(f)`` and towers of number fields; integer matrices;
batches modulo a prime), on the kernels :mod:`~coopkin_sym.exact.elimination`,
:mod:`~coopkin_sym.exact.quotient` and :mod:`~coopkin_sym.exact.modular`.
:mod:`~coopkin_sym.exact.parse` is the package's one parser of text into exact numbers
and expressions; :mod:`~coopkin_sym.exact.angles` the exact angle;
:mod:`~coopkin_sym.exact.polynomial` polynomials over named variables;
:mod:`~coopkin_sym.exact.rationals` the conversions between rational types;
:mod:`~coopkin_sym.exact.realroot` and :mod:`~coopkin_sym.exact.numberfield` real
algebraic numbers; :mod:`~coopkin_sym.exact.groebner` ideal tests (on
:mod:`~coopkin_sym.exact.binaries`, the external Singular and msolve);
:mod:`~coopkin_sym.exact.sympy_bridge` the way to and from SymPy;
:mod:`~coopkin_sym.exact.entry_field` one exact field for a few SymPy entries. This layer imports
only the package's errors and limits.

Example
-------
>>> from coopkin_sym.exact.matrix import PolyMatrix
>>> PolyMatrix.from_integers(2, 2, [1, 2, 2, 4]).rank()
1
"""
