"""Exact facts about the initial forms of the reduced equations: a quadratic form's
diagonal form over Q (its signature and rank), and the real directions of binary forms.

Example
-------
>>> ds, forms = diagonal_form([[0, 1], [1, 0]])     # 2 x y = (x + y)^2 / 2 - (x - y)^2 / 2
>>> [str(d) for d in ds], [[str(c) for c in f] for f in forms]
(['2', '-1/2'], [['1/2', '1/2'], ['1', '-1']])
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

import flint

from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.field_roots import real_root_count, real_roots
from coopkin_sym.exact.realroot import RealRoot


def diagonal_form(matrix: Sequence[Sequence]) -> tuple[list[Fraction], list[list[Fraction]]]:
    """``h(x) = x^T A x`` as ``sum d_i l_i(x)^2``: the nonzero ``d_i`` and the
    coefficient rows of the linear forms ``l_i`` (independent), by symmetric
    elimination over Q. The signature is the signs of the ``d_i``, the rank their count.

    Example
    -------
    >>> ds, forms = diagonal_form([[1, 0], [0, 1]])
    >>> [str(d) for d in ds], [[str(c) for c in f] for f in forms]
    (['1', '1'], [['1', '0'], ['0', '1']])
    """
    n = len(matrix)
    # exact elements of a real number field (with signs) are kept as they are
    a = [[x if hasattr(x, "sign") else Fraction(x) for x in row] for row in matrix]
    ds: list[Fraction] = []
    rows: list[list[Fraction]] = []
    while True:
        # v with v^T A v = d != 0: a unit vector on a nonzero diagonal entry, else the
        # sum of two with a nonzero entry between them; then A -> A - (A v)(A v)^T / d
        k = next((i for i in range(n) if a[i][i] != 0), None)
        if k is not None:
            v = [Fraction(int(i == k)) for i in range(n)]
        else:
            pair = next(((i, j) for i in range(n) for j in range(i + 1, n) if a[i][j] != 0),
                        None)
            if pair is None:
                return ds, rows
            v = [Fraction(int(i in pair)) for i in range(n)]
        w = [sum((a[i][j] * v[j] for j in range(n)), Fraction(0)) for i in range(n)]
        d = sum((v[i] * w[i] for i in range(n)), Fraction(0))
        ds.append(d)
        rows.append([x / d for x in w])
        for i in range(n):
            for j in range(n):
                a[i][j] -= w[i] * w[j] / d


def quadratic_matrix(h, n: int, coefficients: dict | None = None) -> list[list[Fraction]]:
    """The symmetric matrix of a quadratic form (flint polynomial in ``n`` variables),
    or of the form with ``coefficients`` (monomial -> element of a number field)."""
    a = [[Fraction(0)] * n for _ in range(n)]
    items = h.to_dict().items() if coefficients is None else coefficients.items()
    for mono, c in items:
        idx = [i for i, e in enumerate(mono[:n]) for _ in range(e)]
        c = Fraction(int(c.p), int(c.q)) if coefficients is None else c
        if idx[0] == idx[1]:
            a[idx[0]][idx[0]] += c
        else:
            a[idx[0]][idx[1]] += c / 2
            a[idx[1]][idx[0]] += c / 2
    return a


def real_directions(forms: Sequence, n: int) -> list[tuple[object, int]] | None:
    """The common real zeros on the projective line of binary forms (``n == 2``), as
    ``(direction, multiplicity in the first form)``: a direction is ``(1, 0)``, a
    rational ``(x, 1)``, or ``(root, 1)`` with a :class:`RealRoot`. None for ``n != 2``.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "deglex")
    >>> x, y = ctx.gens()
    >>> [(str(d[0]), m) for d, m in real_directions([x * y * (x - 2 * y)], 2)]
    [('1', 1), ('0', 1), ('2', 1)]
    """
    if n != 2:
        return None
    ctx = forms[0].context()
    g = forms[0]
    for h in forms[1:]:
        g = g.gcd(h)
    if g.is_constant():
        return []
    x, y = ctx.gens()[:2]
    out: list[tuple[object, int]] = []
    _, factors = factor(g)
    first = dict((str(f), e) for f, e in factor(forms[0])[1])
    for f, _e in factors:
        mult = first.get(str(f), 1)
        if f.degrees()[0] == 0:                        # a power of y: the direction x
            out.append(((1, 0), mult))
            continue
        coeffs = [0] * (f.degrees()[0] + 1)
        for mono, c in f.to_dict().items():
            coeffs[mono[0]] += c
        if len(coeffs) == 2:
            out.append(((-coeffs[0] / coeffs[1], 1), mult))
            continue
        den = 1
        for c in coeffs:
            den = den * int(flint.fmpq(c).q) // _gcd(den, int(flint.fmpq(c).q))
        ints = [int(flint.fmpq(c) * den) for c in coeffs]
        for root in RealRoot.all_of(ints):
            out.append(((root, 1), mult))
    return out


def _gcd(a: int, b: int) -> int:
    while b:
        a, b = b, a % b
    return a


def algebraic_directions(coefficients: Sequence[dict], field) -> tuple[int, int, bool]:
    """For binary forms over a real number field (each given by ``coefficients``:
    ``(i, j)`` -> coefficient of ``x^i y^j``, as
    :class:`~coopkin_sym.exact.numberfield.Number`), their common real zeros on the
    projective line, counted exactly without computing them: ``(count, multiple,
    first_degree)``, ``multiple`` true when one of them is a multiple root of the first
    form (then the branches are not decided).

    Example
    -------
    >>> import flint
    >>> from coopkin_sym.exact.numberfield import RealNumberField
    >>> from coopkin_sym.exact.realroot import RealRoot
    >>> k = RealNumberField(flint.fmpq_poly([-2, 0, 1]), RealRoot.all_of([-2, 0, 1])[1])
    >>> s = k.number([0, 1])
    >>> # y (x^2 - sqrt(2) y^2): the directions (1, 0) and x = +-2^(1/4) y
    >>> algebraic_directions([{(2, 1): k.number(1), (0, 3): -s}], k)[:2]
    (3, False)
    """
    degree = max(sum(m) for m in coefficients[0])
    polys = []
    at_infinity = True
    infinity_mult = 0
    for k, coeffs in enumerate(coefficients):
        d = max(sum(m) for m in coeffs)
        top = max(i for i, _ in coeffs)
        if top == d:
            at_infinity = False
        if k == 0:
            infinity_mult = d - top
        p = [field.element(0)] * (top + 1)
        for (i, _), c in coeffs.items():
            p[i] = field.element(p[i] + c.value)
        polys.append(p)
    common = field.gcd(polys)
    count = real_root_count(field, common) if len(common) > 1 else 0
    multiple = at_infinity and infinity_mult > 1
    if count:
        first = polys[0]
        derivative = [field.element(c * i) for i, c in enumerate(first)][1:]
        shared = field.gcd([common, derivative])
        multiple = multiple or (len(shared) > 1 and real_root_count(field, shared) > 0)
    return count + int(at_infinity), multiple, degree


def field_directions(coefficients: dict, field) -> tuple[list[tuple[object, int]], bool]:
    """The real directions of one binary form over a real number field (``(i, j)`` ->
    coefficient of ``x^i y^j``, as :class:`~coopkin_sym.exact.numberfield.Number`), as
    :func:`real_directions` gives them over Q: ``((1, 0), m)`` and ``((root, 1), m)``
    with ``root`` a :class:`~coopkin_sym.exact.realroot.RealRoot` over Q (its minimal
    polynomial and an isolating interval, :func:`~coopkin_sym.exact.field_roots.real_roots`);
    ``m`` is 1 for a simple root. The flag says whether some real direction is a
    multiple root (then ``m`` is 2 there: at least).

    Example
    -------
    >>> import flint
    >>> from coopkin_sym.exact.numberfield import RealNumberField
    >>> k = RealNumberField(flint.fmpq_poly([-2, 0, 1]), RealRoot.all_of([-2, 0, 1])[1])
    >>> # y (x^3 - sqrt(2) y^3): the directions (1, 0) and x = 2^(1/6) y
    >>> found, multiple = field_directions({(3, 1): k.number(1), (0, 4): -k.number([0, 1])}, k)
    >>> found[0], found[1][0][0].coeffs, multiple
    (((1, 0), 1), (-2, 0, 0, 0, 0, 0, 1), False)
    """
    degree = max(sum(m) for m in coefficients)
    top = max(i for i, _ in coefficients)
    p = [field.element(0)] * (top + 1)
    for (i, _), c in coefficients.items():
        p[i] = field.element(p[i] + c.value)
    out: list[tuple[object, int]] = []
    multiple = degree - top > 1
    if degree > top:
        out.append(((1, 0), degree - top))
    derivative = [field.element(c * i) for i, c in enumerate(p)][1:]
    shared = field.gcd([p, derivative]) if len(p) > 1 else []
    repeated = real_roots(field, shared) if len(shared) > 1 else []
    multiple = multiple or bool(repeated)
    for root in real_roots(field, p) if len(p) > 1 else []:
        twice = any((root.coeffs, root.index) == (r.coeffs, r.index) for r in repeated)
        out.append(((root, 1), 2 if twice else 1))
    return out, multiple
