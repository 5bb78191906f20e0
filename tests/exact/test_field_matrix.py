"""Matrices of rational functions computed with python-flint give exactly what
SymPy's DomainMatrix gives over the same fraction field, entry for entry."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.polys.matrices import DomainMatrix

from coopkin_sym.errors import NumberError
from coopkin_sym.exact.field_matrix import FieldMatrix

X, Y, L = sp.symbols("x y L")
_atoms = st.sampled_from([X, Y, L, X * Y - 1, X**2 + L, Y - 2 * X, sp.Integer(3)])
_entries = st.builds(lambda a, b, c, k: (a * b + k) / (c + 1), _atoms, _atoms, _atoms,
                     st.integers(-3, 3))


def _matrix(entries, n):
    return DomainMatrix.from_Matrix(sp.Matrix(n, n, entries)).to_field()


def _same(f: FieldMatrix, dm: DomainMatrix) -> bool:
    """Entry for entry, as SymPy writes them."""
    return f.to_domain_matrix().to_Matrix() == dm.to_Matrix()


@settings(max_examples=12, deadline=None, derandomize=True)
@given(st.lists(_entries, min_size=4, max_size=4), st.lists(_entries, min_size=4,
                                                            max_size=4))
def test_products_inverses_and_determinants_agree_with_sympy(a, b):
    dm_a, dm_b = _matrix(a, 2), _matrix(b, 2)
    field = dm_a.domain.unify(dm_b.domain)
    dm_a, dm_b = dm_a.convert_to(field), dm_b.convert_to(field)
    fa, fb = FieldMatrix.of(dm_a), FieldMatrix.of(dm_b)
    assert _same(fa * fb, dm_a * dm_b)
    assert _same(fa - fb, dm_a - dm_b)
    assert _same(fa.transpose(), dm_a.transpose())
    assert fa.det_element() == dm_a.det()
    if dm_a.det() == field.zero:
        with pytest.raises(NumberError, match="not invertible"):
            fa.inv()
    else:
        assert _same(fa.inv(), dm_a.inv())
        assert _same(fa * fa.inv(), DomainMatrix.eye(2, field))


def test_a_singular_matrix_has_no_inverse_and_determinant_zero():
    dm = _matrix([X, Y, 2 * X, 2 * Y], 2)
    with pytest.raises(NumberError, match="not invertible"):
        FieldMatrix.of(dm).inv()
    assert FieldMatrix.of(dm).det_element() == dm.domain.zero


def test_entries_come_back_as_sympy_writes_them():
    dm = _matrix([X / (2 * X + 2 * Y), sp.Rational(1, 3), 0, (X**2 - 1) / (X - 1)], 2)
    back = FieldMatrix.of(dm).to_domain_matrix()
    assert back.to_Matrix() == dm.to_Matrix() == sp.Matrix(
        [[X / (2 * X + 2 * Y), sp.Rational(1, 3)], [0, X + 1]])


def test_rationals_of_sympys_pure_python_ground_types_are_read():
    from fractions import Fraction

    from sympy.external.pythonmpq import PythonMPQ

    from coopkin_sym.exact.rationals import to_fraction

    assert to_fraction(PythonMPQ(-3, 6)) == Fraction(-1, 2)
