"""Contract test of the one rational-function type,
:class:`~coopkin_sym.exact.ratfunc.RatFunc`, in both its forms.

Random values over the known factors ``1 + t**2``, ``1 + u**2`` of a ring and random
reduced values of the same ring (drawn by hypothesis) are combined with ``+ - * /``,
with each other and with Python numbers; every result is checked against SymPy's exact
arithmetic, and its form: two values over the known factors of one ring stay in that
form (no gcd taken), every other result is reduced (coprime, positive leading
coefficient of the denominator). Equality compares values across the forms; both
forms pickle and come back equal and in their form.
"""

from __future__ import annotations

import operator
import pickle
from fractions import Fraction

import flint
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.exact.ring import Ring
from coopkin_sym.exact.sympy_bridge import ratfunc_to_sympy

RING = Ring(["t", "u", "L"], ["t", "u"])
SYMS = {n: sp.Symbol(n) for n in RING.names}
T, U, L = (SYMS[n] for n in RING.names)
SETTINGS = settings(max_examples=40, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])

_MONOMIAL = st.tuples(st.integers(0, 2), st.integers(0, 2), st.integers(0, 1))
_RATIONAL = st.builds(Fraction, st.integers(-3, 3), st.integers(1, 3))


def _qpoly(terms: dict) -> flint.fmpq_mpoly:
    return RING.qctx.from_dict({m: flint.fmpq(c.numerator, c.denominator)
                                for m, c in terms.items() if c})


def _zpoly(terms: dict) -> flint.fmpz_mpoly:
    return RING.zctx.from_dict({m: c for m, c in terms.items() if c})


@st.composite
def known(draw) -> RatFunc:
    """A value over the known factors: a random numerator, random powers (the
    numerator sometimes a multiple of a factor, so the form is not lowest terms)."""
    num = _qpoly(draw(st.dictionaries(_MONOMIAL, _RATIONAL, max_size=4)))
    if draw(st.booleans()):
        num = num * RING.den_factors[draw(st.integers(0, 1))]
    powers = (draw(st.integers(0, 2)), draw(st.integers(0, 2)))
    return RING.ratfunc(num, powers)


@st.composite
def reduced(draw) -> RatFunc:
    num = _zpoly(draw(st.dictionaries(_MONOMIAL, st.integers(-3, 3), max_size=3)))
    den = _zpoly(draw(st.dictionaries(_MONOMIAL, st.integers(-3, 3), min_size=1,
                                      max_size=3)))
    if den.is_zero():
        den = RING.zctx.constant(-2)
    return RatFunc.make(num, den)


VALUES = st.one_of(known(), reduced())
NUMBERS = st.one_of(st.integers(-4, 4), _RATIONAL)


def _sympy(f) -> sp.Expr:
    if isinstance(f, RatFunc):
        return ratfunc_to_sympy(f, SYMS, RING)
    return sp.Rational(f.numerator, f.denominator) if isinstance(f, Fraction) else \
        sp.Integer(f)


def _same_value(ours: RatFunc, expected: sp.Expr) -> bool:
    return sp.cancel(sp.together(_sympy(ours) - expected)) == 0


def _is_canonical(f: RatFunc) -> bool:
    return (f.ring is None and f.powers is None
            and (f.num.gcd(f.den).is_one() or f.num.is_zero() and f.den.is_one())
            and int(f.den.leading_coefficient()) > 0)


OPERATIONS = [operator.add, operator.sub, operator.mul, operator.truediv]


@pytest.mark.parametrize("op", OPERATIONS, ids=lambda o: o.__name__)
@SETTINGS
@given(a=VALUES, b=VALUES)
def test_arithmetic_is_exact_in_both_forms(op, a, b):
    if op is operator.truediv and b.is_zero():
        with pytest.raises(ZeroDivisionError):
            op(a, b)
        return
    result = op(a, b)
    assert _same_value(result, op(_sympy(a), _sympy(b)))
    stays_known = a.known and b.known and (op is not operator.truediv or b.is_constant())
    if stays_known:
        assert result.ring is RING and len(result.powers) == 2
    else:
        assert _is_canonical(result)


@pytest.mark.parametrize("op", OPERATIONS, ids=lambda o: o.__name__)
@SETTINGS
@given(a=VALUES, x=NUMBERS)
def test_arithmetic_with_numbers_keeps_the_form(op, a, x):
    for left, right in ((a, x), (x, a)):
        if op is operator.truediv and (right == 0 or isinstance(right, RatFunc)
                                       and right.is_zero()):
            with pytest.raises(ZeroDivisionError):
                op(left, right)
            continue
        result = op(left, right)
        assert _same_value(result, op(_sympy(left), _sympy(right)))
        if a.known and (op is not operator.truediv or right is x):
            assert result.known
        elif not a.known:
            assert _is_canonical(result)


@SETTINGS
@given(a=VALUES, b=VALUES)
def test_equality_compares_values_across_the_forms(a, b):
    assert a == a.reduced() and a.reduced() == a
    assert (a == b) == (sp.cancel(sp.together(_sympy(a) - _sympy(b))) == 0)
    assert a != a + 1
    if a.known:      # the same value written with one more factor 1 + t^2
        widened = RING.ratfunc(a.num * RING.den_factors[0], (a.powers[0] + 1, a.powers[1]))
        assert widened == a and widened.reduced() == a.reduced()


@SETTINGS
@given(a=VALUES)
def test_reduced_form_is_canonical_and_keeps_the_value(a):
    r = a.reduced()
    assert _is_canonical(r)
    assert _same_value(r, _sympy(a))
    assert r.reduced() is r
    assert a.is_constant() == (r.num.is_constant() and r.den.is_constant())
    if a.is_constant():
        assert sp.Rational(a.rational().numerator, a.rational().denominator) == \
            sp.cancel(_sympy(a))
    assert a.terms() == len(r.num) + len(r.den)


@SETTINGS
@given(a=VALUES)
def test_both_forms_pickle(a):
    back = pickle.loads(pickle.dumps(a))
    assert back == a
    assert back.known == a.known and back.powers == a.powers
    if a.known:
        assert back.ring == RING and str(back.num) == str(a.num)
        assert back * a == a * a and (back * a).known   # the ring comes back equal
    else:
        assert str(back.num) == str(a.num) and str(back.den) == str(a.den)


def test_the_known_form_takes_no_gcd():
    """Sums and products over the known factors keep a common factor of numerator and
    denominator (no gcd is taken); the reduced form cancels it."""
    c = RING.cos_of(0)
    w = c * (RING.one() + RING.gens()[0] * RING.gens()[0])     # (1 - t^2), written over 1 + t^2
    assert w.powers == (1, 0) and str(w.num) == "-t^4 + 1"
    assert str(w.reduced().num) == "-t^2 + 1" and w.reduced().den.is_one()
    assert w == 1 - RING.gens()[0] * RING.gens()[0]


def test_zero_denominators_are_refused():
    with pytest.raises(ZeroDivisionError):
        RatFunc.make(RING.zctx.constant(1), RING.zctx.constant(0))
    with pytest.raises(ZeroDivisionError):
        RING.cos_of(0) / RING.zero()
    with pytest.raises(ZeroDivisionError):
        RatFunc.poly(RING.zctx.constant(3)) / 0
