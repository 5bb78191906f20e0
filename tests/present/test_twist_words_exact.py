"""Twists in words computed in one exact field agree with the expression arithmetic.

``twist_words`` and ``object_motions_words`` take the entries and the contact points
into one field SymPy builds for them (rational functions over the rationals or a
number field). The old way, simplifying SymPy expressions, is kept for entries outside
such a field; here it is the independent reference on random twists with rational,
symbolic and quadratic-irrational entries, with contacts put on the axis on purpose.
The phrases agree word for word; over a number field the field writes the values in
lowest terms, so there the values are compared exactly instead of as text.
"""

from __future__ import annotations

import random

import pytest
import sympy as sp

from coopkin_sym import load
from coopkin_sym.exact.entry_field import (
    EntryField,
    ExprArithmetic,
    FlintEntryField,
    field_of,
    is_zero_expr,
)
from coopkin_sym.exact.parse import exact_expr
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.present import sentences as sentences_module
from coopkin_sym.present.sentences import (
    joint_motion_words,
    object_motions_words,
    sentences,
    twist_words,
)

L, t = sp.symbols("L t_q1")
SQ3 = sp.sqrt(3)


def _entry(rng: random.Random, kind: str) -> sp.Expr:
    c = sp.Rational(rng.randint(-3, 3), rng.randint(1, 3))
    if kind == "rational" or rng.random() < 0.3:
        return c
    if kind == "symbolic":
        return c * L + rng.randint(-2, 2) * t + rng.randint(-1, 1) * L * t
    return c + rng.randint(-2, 2) * SQ3 + rng.randint(0, 1) * L


def _twist_and_contacts(rng: random.Random, kind: str):
    w = [_entry(rng, kind) for _ in range(3)]
    if rng.random() < 0.15:
        w = [0, 0, 0]
    v = [_entry(rng, kind) for _ in range(3)]
    contacts = []
    wv = sp.Matrix(w)
    ww = wv.dot(wv)
    for k in range(rng.randint(0, 3)):
        if ww != 0 and rng.random() < 0.6:
            # a point on the axis: p + s w
            p = wv.cross(sp.Matrix(v)) / ww
            s = sp.Rational(rng.randint(-2, 2), rng.randint(1, 2))
            point = [sp.radsimp(sp.cancel(p[i] + s * w[i])) for i in range(3)]
        else:
            point = [_entry(rng, kind) for _ in range(3)]
        contacts.append((f"c{k + 1}", point))
    return v + w, contacts


def _tuple_end(text: str, start: int) -> tuple[int, list[str]]:
    """The end of the parenthesized tuple opening at ``start`` and its entries."""
    depth, parts, last = 0, [], start + 1
    for i in range(start, len(text)):
        if text[i] == "(":
            depth += 1
        elif text[i] == ")":
            depth -= 1
            if depth == 0:
                return i + 1, parts + [text[last:i]]
        elif text[i] == "," and depth == 1:
            parts.append(text[last:i])
            last = i + 2
    raise AssertionError(f"unbalanced: {text}")


def _skeleton(text: str) -> tuple[str, list[sp.Expr]]:
    """The words of a twist phrase with each written value (points, directions, the
    pitch) taken out as an exact expression, read back by the package's parser."""
    words, values, i = [], [], 0
    while i < len(text):
        if text.startswith("pitch ", i):
            words.append("pitch #")
            values.append(text[i + 6:])
            break
        if text[i] == "(" and text[:i].endswith(("along ", "through ")):
            i, parts = _tuple_end(text, i)
            words.append("(#)")
            values += parts
            continue
        words.append(text[i])
        i += 1
    names = {"L": L, "t_q1": t}
    return "".join(words), [exact_expr(v, names, "written value") for v in values]


def _same_phrase(a: str, b: str) -> bool:
    (wa, va), (wb, vb) = _skeleton(a), _skeleton(b)
    return wa == wb and len(va) == len(vb) and all(
        is_zero_expr(x - y) for x, y in zip(va, vb, strict=True))


def _same_ratio(a: str, b: str) -> bool:
    """Two "joints in the ratio q1: e1, q2: e2" phrases name the same joints with
    exactly equal values."""
    head = "joints in the ratio "
    if not (a.startswith(head) and b.startswith(head)):
        return False
    pa = [x.split(": ") for x in a[len(head):].split(", ")]
    pb = [x.split(": ") for x in b[len(head):].split(", ")]
    names = {"L": L, "t_q1": t}
    return [n for n, _ in pa] == [n for n, _ in pb] and all(
        is_zero_expr(exact_expr(x, names, "value") - exact_expr(y, names, "value"))
        for (_, x), (_, y) in zip(pa, pb, strict=True))


def _with_expressions(fn, *args):
    old = EntryField.of_entries
    try:
        EntryField.of_entries = staticmethod(lambda exprs: ExprArithmetic())
        return fn(*args)
    finally:
        EntryField.of_entries = old


# the symbolic and quadratic campaigns take 15 to 45 s each: run by .ci/run (-m slow)
@pytest.mark.parametrize("kind", ["rational", pytest.param("symbolic", marks=pytest.mark.slow),
                                  pytest.param("quadratic", marks=pytest.mark.slow)])
def test_twist_words_agree_with_the_expression_arithmetic(kind, monkeypatch):
    # every value written out, however long: the values themselves are compared
    monkeypatch.setattr(sentences_module, "_MAX_VALUE", 10**9)
    rng = random.Random(f"twist words {kind}")
    lines = 0
    for _ in range(40):
        u, contacts = _twist_and_contacts(rng, kind)
        fast = twist_words(u, contacts)
        slow = _with_expressions(twist_words, u, contacts)
        assert fast == slow or (kind == "quadratic" and _same_phrase(fast, slow)), \
            (u, contacts, fast, slow)
        lines += " through c" in fast
    assert lines >= 5        # the contacts on the axis were found


def test_the_field_is_exact_for_each_kind():
    assert isinstance(field_of([[1, sp.Rational(1, 2)]]), EntryField)
    assert isinstance(field_of([[L * t, 1 / (1 + t)]]), EntryField)
    field = field_of([[SQ3 * L, 3 * L**2]])
    assert isinstance(field, EntryField)
    # (sqrt(3) L)^2 - 3 L^2 is zero in the number field: sqrt(3) is not a new symbol
    assert field.is_zero(field.of(SQ3 * L) * field.of(SQ3 * L) - field.of(3 * L**2))
    # outside a field of rational functions: the expression arithmetic
    assert type(field_of([[sp.cos(L), 1]])) is ExprArithmetic
    assert type(field_of([[sp.sqrt(L), 1]])) is ExprArithmetic


def test_three_rotations_about_a_symbolic_point_turn_freely():
    c = [L, 2 * t, 1 - L]
    cross = sp.Matrix(c)
    rotations = []
    for axis in ([1, t, 0], [0, 1, L], [t, 0, 1]):
        w = sp.Matrix(axis)
        v = -w.cross(cross)                       # v + w x c = 0
        rotations.append([*v, *w])
    contacts = [("c1", c), ("c2", [0, 0, 0])]
    assert object_motions_words(rotations, contacts) == \
        "turn freely about c1, in every direction"
    assert _with_expressions(object_motions_words, rotations, contacts) == \
        "turn freely about c1, in every direction"


def test_generic_sentences_of_a_shipped_example_are_unchanged(monkeypatch):
    a = load("paper-case1-hard").analyze(generic=True)
    fast = sentences(a)
    monkeypatch.setattr(EntryField, "of_entries",
                        staticmethod(lambda exprs: ExprArithmetic()))
    assert fast == sentences(load("paper-case1-hard").analyze(generic=True))


def test_the_phrase_comparison_tells_different_values_apart():
    a = "screw about the line through (1, sqrt(3), L) along x with pitch 2*L"
    assert _same_phrase(a, "screw about the line through (1, 3/sqrt(3), L) along x with "
                           "pitch L + L")
    assert not _same_phrase(a, "screw about the line through (1, sqrt(3), L) along x with pitch L")
    assert not _same_phrase(a, "rotate about the line through (1, sqrt(3), L) along x")


@pytest.mark.parametrize("kind", ["rational", "symbolic", "quadratic"])
def test_joint_motion_words_agree_with_the_expression_arithmetic(kind, monkeypatch):
    monkeypatch.setattr(sentences_module, "_MAX_VALUE", 10**9)
    rng = random.Random(f"joint words {kind}")
    names = ["q1", "q2", "q3", "q4"]
    said = set()
    for _ in range(60):
        qdot = [_entry(rng, kind) if rng.random() < 0.6 else 0 for _ in names]
        if rng.random() < 0.4:                  # a pair at equal or opposite speeds
            e = _entry(rng, kind)
            qdot = [0, e * (1 + L - L), 0, rng.choice([1, -1]) * e]
        fast = joint_motion_words(qdot, names)
        slow = _with_expressions(joint_motion_words, qdot, names)
        assert fast == slow or (kind == "quadratic" and _same_ratio(fast, slow)), \
            (qdot, fast, slow)
        said.add(fast.split(" ")[0] + " " + fast.split(" ")[-1])
    assert len(said) >= 3


def test_flint_entries_read_term_by_term_equal_sympy_fractions():
    rng = random.Random("flint entries")
    exprs = []
    for _ in range(60):
        a, b = _entry(rng, "symbolic"), _entry(rng, "symbolic")
        exprs += [a, a * b, sp.expand(a * b) / (1 + t**2), (a + 1) / (b * L + 2),
                  sp.Rational(rng.randint(-9, 9), rng.randint(1, 9))]
    field = EntryField.of_entries(exprs)
    assert isinstance(field, FlintEntryField)
    domain = sp.ZZ.frac_field(*field.symbols)
    for e in dict.fromkeys(exprs):
        x = domain.from_sympy(e)
        assert field.of(e) == RatFunc.make(field._poly(x.numer), field._poly(x.denom)), e
        assert sp.cancel(field.to_sympy(field.of(e)) - e) == 0


def test_values_too_long_to_read_are_named_not_written():
    big = sum(sp.Rational(k + 1, k + 2) * L**k * t ** (12 - k) for k in range(12))
    # a rotation about an axis along a long direction, through the origin
    assert twist_words([0, 0, 0, big, 1, 0]) == \
        "rotate about the line through (0, 0, 0) along a direction too large to write here"
    # the same axis through a contact: the contact names the line
    assert twist_words([0, 0, 0, big, 1, 0], [("c1", [0, 0, 0])]) == \
        "rotate about the line through c1 along a direction too large to write here"
    words = twist_words([big, 0, 0, 0, 0, 1])           # v = (big, 0, 0), w = z
    assert words.startswith("rotate about the line through a point too large to write")
    assert words.endswith(" along z")
    assert twist_words([0, 0, big, 0, 0, 1]) == \
        "screw about the line through (0, 0, 0) along z with a pitch too large to write here"
    assert joint_motion_words([big, 1, 0], ["q1", "q2", "q3"]) == "joints q1, q2 together"
