"""The parser's fast paths (the commonest angles and rationals, read without the
general parser) agree with the general parser on everything they accept, and leave
everything else to it."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import coopkin_sym.exact.parse as parse
from coopkin_sym.errors import NumberError
from coopkin_sym.exact.parse import angle_reader, values


def _general(monkeypatch, function, *args):
    """``function(*args)`` with both fast paths switched off: the value or the error."""
    with monkeypatch.context() as patch:
        patch.setattr(angle_reader, "_simple_angle", lambda value: None)
        patch.setattr(values, "_simple_rational", lambda value: None)
        try:
            return function(*args)
        except NumberError as exc:
            return ("error", str(exc))


def _texts() -> list[str]:
    out = ["0", "pi", "-pi", "pi/2", "-pi/2", "2*pi", "3*pi/2", "0*pi", "pi/0", "007",
           "2*atan(1/0)", "2*atan(00)", "2*atan(010/3)", " 2 * atan( -3 / 4 ) ",
           "-2*atan(-1/3)", "2*atan(1/3) ", "2*atan(1/3)+0", "2*atan(1/3", "1/0", "-0",
           "3/-4", "+3", "1e3", "0.5", "10/05", "2 *atan(5)", "12*pi/8", "pi/3"]
    for a in range(-7, 8):
        for b in range(0, 6):
            out += [f"2*atan({a}/{b})", f"-2*atan({a}/{b})", f"{a}*pi/{b}", f"{a}/{b}",
                    f"{a}", f"-{abs(a)}*pi/{b}"]
    return out


@pytest.mark.parametrize("text", _texts())
def test_fast_angle_agrees_with_the_general_parser(monkeypatch, text):
    general = _general(monkeypatch, parse.parse_angle, text, "q1")
    try:
        fast = parse.parse_angle(text, "q1")
    except NumberError as exc:
        fast = ("error", str(exc))
    assert fast == general
    if angle_reader._simple_angle(text) is not None:
        assert general[0] != "error"


@pytest.mark.parametrize("text", _texts())
def test_fast_rational_agrees_with_the_general_parser(monkeypatch, text):
    general = _general(monkeypatch, parse.parse_number, text, {}, "x")
    try:
        fast = parse.parse_number(text, {}, "x")
    except NumberError as exc:
        fast = ("error", str(exc))
    assert fast == general
    assert type(fast) is type(general)


@pytest.mark.parametrize("value", [2 * sp.atan(sp.Rational(a, b)) for a in range(-4, 5)
                                   for b in (1, 2, 7)]
                         + [sp.Rational(k, 2) * sp.pi for k in range(-6, 7)]
                         + [sp.pi, sp.Integer(0), sp.pi / 3, sp.atan(sp.Rational(3, 4)),
                            -2 * sp.atan(sp.Rational(1, 3)), sp.Rational(1, 2)])
def test_fast_angle_of_sympy_objects(monkeypatch, value):
    general = _general(monkeypatch, parse.parse_angle, value, "q1")
    try:
        fast = parse.parse_angle(value, "q1")
    except NumberError as exc:
        fast = ("error", str(exc))
    assert fast == general


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="0123456789-+/*() .aitnpe", max_size=16))
def test_fast_paths_on_random_text(text):
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(angle_reader, "_simple_angle", lambda value: None)
        patch.setattr(values, "_simple_rational", lambda value: None)
        expected = {}
        for name, call in (("angle", lambda: parse.parse_angle(text, "q")),
                           ("number", lambda: parse.parse_number(text, {}, "q"))):
            try:
                expected[name] = call()
            except NumberError as exc:
                expected[name] = ("error", str(exc))
    for name, call in (("angle", lambda: parse.parse_angle(text, "q")),
                       ("number", lambda: parse.parse_number(text, {}, "q"))):
        try:
            got = call()
        except NumberError as exc:
            got = ("error", str(exc))
        assert got == expected[name], (name, text)
