"""The one exact-expression parser: exact values, budgets, bounded work, exact angles."""

from __future__ import annotations

import time
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from coopkin_sym import limits, load
from coopkin_sym.errors import CoopkinError
from coopkin_sym.exact.parse import (
    NumberError,
    algebraic_half_angle,
    exact_expr,
    parse_angle,
    parse_expression,
    parse_number,
)
from coopkin_sym.model.configuration import ConfigurationError

L, M, N = (sp.Symbol(n, positive=True) for n in "LMN")
PARAMS = {"L": L, "M": M, "N": N}
R = sp.Rational


def quick(call, seconds: float = 2.0):
    """``call()`` (returning its result or NumberError), timed."""
    start = time.monotonic()
    try:
        out = call()
    except NumberError as exc:
        out = exc
    assert time.monotonic() - start < seconds, "took too long"
    return out


# ------------------------------------------------------------------ the parser


def test_parse_expression_reads_polynomials_and_rational_functions():
    t = sp.Symbol("t_q1")
    assert parse_expression("3*t_q1**2 - 2*t_q1 + 1/2", ["t_q1"], "eq") == \
        3 * t**2 - 2 * t + R(1, 2)
    assert parse_expression("(t_q1**2 - 1)/(t_q1 - 1)", ["t_q1"], "eq") == t + 1
    assert parse_expression("1/(t_q1 + 1)", ["t_q1"], "eq") == 1 / (t + 1)
    assert parse_expression("2^3 - -1", [], "x") == 9
    assert parse_expression("-2**2", [], "x") == -4          # Python's precedence
    assert parse_expression("pi/2 + atan(1)", [], "x") == 3 * sp.pi / 4


def test_parse_expression_uses_the_given_symbols():
    result = parse_expression("2*L", PARAMS, "x", kind="parameters")
    assert result == 2 * L and next(iter(result.free_symbols)).is_positive


def test_parse_expression_roots_of_polynomials():
    root = parse_expression("CRootOf(x**3 - x - 1, 0)", [], "w")
    assert root == sp.CRootOf(sp.Symbol("x") ** 3 - sp.Symbol("x") - 1, 0)
    with pytest.raises(NumberError, match="degree over 32"):
        parse_expression("CRootOf(x**100 - 2, 0)", [], "w")
    start = time.monotonic()          # a complex root would need a slow isolation
    with pytest.raises(NumberError, match="names a real root: its index is an integer "
                                          "from 0 to 1"):
        parse_expression("CRootOf(x**30 - 3*x - 1, 3)", [], "w")
    assert time.monotonic() - start < 1
    assert algebraic_half_angle("2*atan(CRootOf(x**3 - x - 1, 0))", "q1") == root
    with pytest.raises(NumberError, match="one variable"):
        parse_expression("CRootOf(x*y - 2, 0)", [], "w")


@pytest.mark.parametrize(("text", "expected"), [
    ("Integer(4)", 4), ("Rational(1, 3)", R(1, 3)), ("Rational(0.5)", R(1, 2)),
    ("Rational(3, 6)*2", 1), ("Integer(-7)", -7)])
def test_integer_and_rational_are_exact(text, expected):
    assert parse_number(text, {}, "x") == expected


@pytest.mark.parametrize(("text", "message"), [
    ("Integer(0.9999)", "Integer of 9999/10000, which is not an integer"),
    ("Integer(1/2)", "not an integer"),
    ("Rational(1,2,3)", "Rational takes one or two numbers"),
    ("Rational(1, 0)", "not a finite number"),
    ("Rational(L, 2)", "Rational takes rational numbers"),
    ("Integer(pi)", "Integer takes rational numbers"),
    ("Integer()", "cannot be parsed"),
])
def test_integer_and_rational_never_round(text, message):
    with pytest.raises(NumberError, match=message):
        parse_number(text, PARAMS, "x")


def test_leading_zero_is_ambiguous():
    with pytest.raises(NumberError, match="leading zero"):
        parse_number("010", {}, "x")
    assert parse_number("0.5", {}, "x") == R(1, 2)
    assert parse_number("0", {}, "x") == 0


# ------------------------------------------------------------------ budgets


@pytest.mark.parametrize(("text", "message"), [
    ("(L+M+N+1)**1000", "too large: a product of"),
    ("((L+1)**1000)**2", "too large: degree over 1000"),
    ("1e1000*1e1000*1e1000*1e1000*1e1000", "more than 1000 digits"),
    ("1e1000", "more than 1000 digits"),
    ("(10**999)**2", "more than 1000 digits"),
    ("9" * 500 + "**3", "more than 1000 digits"),
    ("1e100000", "decimal exponent over 1000"),
    ("2**1001", "exponent over 1000"),
    ("(" * 60 + "1" + ")" * 60, "parentheses nested more than 50 deep"),
    ("L" + "+L" * 600, "too long"),
    ("(sqrt(2)*10**500)**3", "more than 1000 digits"),
])
def test_budgets_refuse_at_once(text, message):
    err = quick(lambda: parse_number(text, PARAMS, "x"), 3.0)
    assert isinstance(err, NumberError), err
    assert message in str(err)
    assert "\n" not in str(err)


def test_honest_sizes_are_within_the_budgets():
    assert parse_number("(L+1)**100", PARAMS, "x") == sp.expand((L + 1) ** 100)
    assert parse_number("9" * 1000, {}, "x") == int("9" * 1000)
    assert parse_number("1e999", {}, "x") == 10**999
    long_sum = " + ".join(f"{k}*L**{k}" for k in range(1, 300))
    assert parse_expression(long_sum, PARAMS, "x", kind="parameters") == sum(
        k * L**k for k in range(1, 300))


def test_sympy_and_python_inputs_get_the_same_budgets():
    with pytest.raises(NumberError, match="more than 1000 digits"):
        parse_number(10**1500, {}, "x")
    with pytest.raises(NumberError, match="more than 1000 digits"):
        parse_number(Fraction(1, 10**1500), {}, "x")
    with pytest.raises(NumberError, match="exponent over 1000"):
        parse_number(sp.Pow(L + 1, 5000, evaluate=False), PARAMS, "x")
    with pytest.raises(NumberError, match="too large"):
        parse_number(sp.Integer(10) ** 5000, {}, "x")


def test_numpy_values():
    assert parse_number(np.int64(7), {}, "x") == 7
    assert parse_number(np.float64(0.1), {}, "x") == R(1, 10)      # as a Python float
    with pytest.raises(NumberError, match="numpy float32, which is not exact"):
        parse_number(np.float32(0.1), {}, "x")
    with pytest.raises(NumberError, match="truth value"):
        parse_number(np.bool_(True), {}, "x")


def test_exact_expr_keeps_sympy_and_reads_text():
    assert exact_expr(sp.sqrt(2)) == sp.sqrt(2)
    assert exact_expr("t + 1/2", ["t"]) == sp.Symbol("t") + R(1, 2)
    with pytest.raises(NumberError, match="undeclared symbol t"):
        exact_expr("t", None)
    with pytest.raises(NumberError, match="not a number"):
        exact_expr([1, 2], None)


# ------------------------------------------------------------------ angles


@pytest.mark.parametrize(("text", "expected"), [
    ("atan(3/4)", (R(4, 5), R(3, 5))),                  # = 2*atan(1/3)
    ("atan(1/2) + atan(1/3) + pi/4", (0, 1)),            # = pi/2
    ("atan(1/2) + atan(1/3)", None),                     # = pi/4: irrational tan(pi/8)
    ("atan(4/3) - atan(3/4)", (R(24, 25), R(7, 25))),      # = atan(7/24)
    ("2*atan(4/3) - 2*atan(3/4)", (R(527, 625), R(336, 625))),
    ("3*atan(3/4)", (R(-44, 125), R(117, 125))),
    ("atan(3/4)/2", None),                                # atan(1/3): tan(q/2) irrational
    ("4*atan(1/5) - atan(1/239)", None),                 # Machin: pi/4
    ("8*atan(1/5) - 2*atan(1/239)", (0, 1)),              # 2 * Machin = pi/2
])
def test_angles_decided_exactly(text, expected):
    if expected is None:
        with pytest.raises(NumberError, match="is irrational"):
            parse_angle(text, "q1")
    else:
        assert parse_angle(text, "q1") == (R(expected[0]), R(expected[1]))


@settings(max_examples=60, deadline=2000)
@given(st.fractions(max_denominator=50).filter(lambda r: r != 0),
       st.integers(-6, 6), st.integers(-3, 3))
def test_angle_decision_matches_the_exact_rotation(r, k, m):
    """``2k atan(r) + m pi/2`` is always exact; its point is the product of exact
    rotations (computed here with SymPy's rational arithmetic)."""
    text = f"{2 * k}*atan({r}) + {m}*pi/2"
    c, s = parse_angle(text, "q")
    rot = (1 + sp.I * R(r.numerator, r.denominator)) ** 2 / (1 + R(r.numerator,
                                                                   r.denominator) ** 2)
    z = sp.expand(rot ** k * sp.I ** m)
    assert (c, s) == (sp.re(z), sp.im(z))


def test_large_denominators_of_pi_are_refused_quickly():
    err = quick(lambda: algebraic_half_angle("pi/99991", "q1"), 1.0)
    assert isinstance(err, NumberError)
    assert "degree up to" in str(err) and "over the limit of 16" in str(err)
    err = quick(lambda: parse_angle("pi/99991", "q1"), 1.0)
    assert "is irrational" in str(err)
    assert algebraic_half_angle("-pi/6", "q1") == -2 + sp.sqrt(3)


def test_sums_of_atan_are_bounded():
    many = "+".join(f"atan(1/{k})" for k in range(2, 14))
    err = quick(lambda: parse_angle(many, "q1"), 1.0)
    assert "cannot be decided: more than 8 terms" in str(err)
    four = "+".join(f"atan(1/{k})" for k in range(2, 6))
    err = quick(lambda: algebraic_half_angle(four, "q1"), 2.0)
    assert isinstance(err, NumberError)


def test_rational_radians_are_never_exact():
    with pytest.raises(NumberError, match="is irrational"):
        parse_angle("1 + 2*atan(1/3)", "q1")
    with pytest.raises(NumberError, match="not an algebraic number"):
        algebraic_half_angle("1 + 2*atan(1/3)", "q1")


def test_the_field_of_a_configuration_is_bounded():
    system = load("paper-case2-hard")
    with pytest.raises(ConfigurationError, match="over the limit of 64"):
        from coopkin_sym.analysis.irrational import analyze_irrational
        analyze_irrational(system.model, "q1=pi/17,q2=pi/13,q3=pi/11")


def test_limits_are_read_at_use(monkeypatch):
    monkeypatch.setattr(limits, "MAX_TERMS", 10)
    with pytest.raises(NumberError, match="more than 10 terms"):
        parse_number("(L+M+1)**4", PARAMS, "x")


def test_every_refusal_is_the_package_error():
    for text in ["1/0", "(", "x", "sqrt(L)", "atan(L)", "L**L", "2L", "a.b", "1,2"]:
        with pytest.raises(CoopkinError):
            parse_number(text, PARAMS, "x")


# ------------------------------------------------------------------ the commands


@pytest.mark.parametrize(("args", "message"), [
    (["analyze", "paper-case1-hard", "--at", "L=" + "*".join(["1e1000"] * 5)],
     "more than 1000 digits"),
    (["analyze", "paper-case1-hard", "--at", "L=1e999*1e999*1e999*1e999*1e999"],
     "more than 1000 digits"),
    (["analyze", "paper-case1-hard", "--at", "L=Rational(1,2,3)"],
     "Rational takes one or two numbers"),
    (["analyze", "paper-case1-hard", "--at", "L=Integer(0.9999)"], "not an integer"),
    (["analyze", "paper-case1-hard", "--at", "L=" + "9" * 5000], "too long"),
    (["analyze", "paper-case1-hard", "--at", "q1=pi/99991"], "is irrational"),
    (["analyze", "paper-case1-hard", "--at", "q1=" + "+".join(
        f"atan(1/{k})" for k in range(2, 14))], "more than 8 terms"),
    (["sweep", "paper-case1-hard", "--grid", "q1=0..1:1000000000"],
     "over the limit of 1,000,000 per joint"),
    (["sweep", "paper-case1-hard", "--grid", "q1=0..1:2000,q2=0..1:2000"],
     "over the limit of 2,000,000"),
    (["sweep", "paper-case1-hard", "--grid", "q1=0..1:" + "9" * 5000],
     "over the limit of 1,000,000 points per joint"),
    (["sweep", "paper-case1-hard", "--grid", "q2=0..1e1000:3"], "more than 1000 digits"),
    (["sweep", "paper-case1-hard", "--grid", "q2=0..1e999:3"], "beyond 1,000,000 radians"),
    (["draw", "paper-case2-hard", "-o", "/tmp/coopkin-never.png", "--at", "L=1e999"],
     "beyond what a picture can show"),
    (["draw", "paper-case2-hard", "-o", "/tmp/coopkin-never.png", "--at", "q4=1e300"],
     "beyond what a picture can show"),
])
def test_issue_commands_are_one_line_errors(args, message):
    from typer.testing import CliRunner

    from coopkin_sym.cli import app

    start = time.monotonic()
    result = CliRunner().invoke(app, args)
    assert time.monotonic() - start < 10
    assert result.exit_code == 2, result.output
    assert result.stderr.startswith("coopkin: error: ")
    assert result.stderr.count("\n") == 1
    assert message in result.stderr, result.stderr
