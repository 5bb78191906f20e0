"""Subfields and products of number fields ``Q[x]/(g)``, exactly (linear algebra over
Q with python-flint): the minimal polynomial of an element, an element written in a
basis, two elements whose fields are linearly disjoint and make the whole field, and
the pairs of roots of two polynomials as one field per orbit of conjugate pairs.

Elements are ``fmpq_poly`` in ``x`` reduced modulo ``g`` (``g`` irreducible).

Example
-------
>>> import flint
>>> two, three = flint.fmpq_poly([-2, 0, 1]), flint.fmpq_poly([-3, 0, 1])
>>> c, m, w, _ = compositum(two, three, [])      # the pairs (+-sqrt 2, +-sqrt 3)
>>> str(m), str((w * w) % m)                      # one orbit: Q(sqrt 2 + sqrt 3)
('x^4 + (-10)*x^2 + 1', '2')
"""

from __future__ import annotations

from collections.abc import Sequence

import flint

from coopkin_sym.errors import ArgumentError
from coopkin_sym.exact.deadline import check

Element = flint.fmpq_poly


def _powers(g: flint.fmpq_poly, t: Element, n: int) -> list[Element]:
    """``1, t, ..., t^n`` reduced modulo ``g``."""
    powers = [flint.fmpq_poly([1])]
    for _ in range(n):
        check("the powers of a number field element")
        powers.append((powers[-1] * t) % g)
    return powers


def _columns(g: flint.fmpq_poly, elements: Sequence[Element]) -> flint.fmpq_mat:
    """The ``deg g x len(elements)`` matrix of the coordinates of ``elements`` in the
    basis ``1, x, ..., x^(d-1)``."""
    d = g.degree()
    return flint.fmpq_mat(d, len(elements),
                          [(e % g)[i] for i in range(d) for e in elements])


def minimal_polynomial(g: flint.fmpq_poly, t: Element) -> flint.fmpq_poly:
    """The minimal polynomial over Q of ``t`` in ``Q[x]/(g)`` (``g`` irreducible):
    the first power of ``t`` that depends on the lower ones.

    Example
    -------
    >>> import flint
    >>> g = flint.fmpq_poly([1, 0, -10, 0, 1])       # x = sqrt(2) + sqrt(3)
    >>> minimal_polynomial(g, flint.fmpq_poly([0, -9, 0, 1]) / 2)   # sqrt(2)
    x^2 + (-2)
    """
    powers = _powers(g, t, g.degree())
    for m in range(1, len(powers)):
        relation = express(g, powers[:m], powers[m])
        if relation is not None:
            return flint.fmpq_poly([-c for c in relation.coeffs()]
                                   + [0] * (m - len(relation.coeffs())) + [1])
    raise ArgumentError(f"{g} is not irreducible")  # pragma: no cover


def express(g: flint.fmpq_poly, basis: Sequence[Element], e: Element
            ) -> flint.fmpq_poly | None:
    """``e`` as a combination ``sum c_i basis[i]`` of linearly independent elements of
    ``Q[x]/(g)``, returned as the polynomial ``sum c_i y^i``; None when ``e`` is not in
    their span.

    Example
    -------
    >>> import flint
    >>> g = flint.fmpq_poly([-2, 0, 1])
    >>> one, x = flint.fmpq_poly([1]), flint.fmpq_poly([0, 1])
    >>> express(g, [one, x], flint.fmpq_poly([3, 5])), express(g, [one], x)
    (5*x + 3, None)
    """
    m = len(basis)
    augmented = _columns(g, [*basis, e])
    reduced, rank = augmented.rref()
    if rank > m:
        return None
    solution = [flint.fmpq(0)] * m
    for r in range(rank):
        lead = next(c for c in range(m + 1) if reduced[r, c] != 0)
        solution[lead] = reduced[r, m]
    return flint.fmpq_poly(solution)


def product_generators(g: flint.fmpq_poly, elements: Sequence[Element]):
    """Two of ``elements`` whose fields are linearly disjoint and together make
    ``Q[x]/(g)`` (their degrees multiply to ``deg g``; ``Q(sqrt 2, sqrt 3)`` from
    ``sqrt 2`` and ``sqrt 3``), for when no single element generates it: ``(i, j, m_i,
    m_j, rest)``, ``m`` their minimal polynomials and ``rest`` each other element as
    ``{(p, q): c}``, the element being ``sum c a^p b^q`` (``a, b`` elements ``i, j``,
    ``p < deg m_i``, ``q < deg m_j``); None when there is no such pair.

    Example
    -------
    >>> import flint
    >>> g = flint.fmpq_poly([1, 0, -10, 0, 1])       # x = sqrt(2) + sqrt(3)
    >>> r2 = flint.fmpq_poly([0, -9, 0, 1]) / 2
    >>> r3 = flint.fmpq_poly([0, 11, 0, -1]) / 2
    >>> i, j, mi, mj, rest = product_generators(g, [r2, r3, (r2 * r3) % g])   # sqrt 6
    >>> (i, j, str(mi), str(mj), rest)
    (0, 1, 'x^2 + (-2)', 'x^2 + (-3)', [{(1, 1): 1}])
    """
    d = g.degree()
    minimal = [minimal_polynomial(g, e) for e in elements]
    for i in range(len(elements)):
        for j in range(i + 1, len(elements)):
            di, dj = minimal[i].degree(), minimal[j].degree()
            if di < 2 or dj < 2 or di * dj != d:
                continue
            pi, pj = _powers(g, elements[i], di - 1), _powers(g, elements[j], dj - 1)
            basis = [(a * b) % g for a in pi for b in pj]
            if _columns(g, basis).rank() < d:
                continue   # the same subfield twice, not a product
            rest = []
            for k, e in enumerate(elements):
                if k not in (i, j):
                    c = express(g, basis, e)   # in the span: the basis spans the field
                    rest.append({(n // dj, n % dj): v for n, v in enumerate(c.coeffs())
                                 if v != 0})
            return i, j, minimal[i], minimal[j], rest
    return None

def compositum(h: flint.fmpq_poly, g: flint.fmpq_poly, elements: Sequence[Element],
               tries: Sequence[int] = (1, -1, 2, 3)):
    """The pairs of a root ``w`` of ``h`` and a root ``z`` of ``g`` (both irreducible):
    the algebra ``Q[w, z]/(h, g)`` as ``Q[theta]/(m)``, ``theta = w + c z`` for the
    first ``c`` of ``tries`` whose powers span it (``m`` of degree ``deg h * deg g``,
    squarefree; one irreducible factor of ``m`` per orbit of conjugate pairs, a single
    one when the two fields are linearly disjoint): ``(c, m, w, [e])``, ``w`` and each
    of ``elements`` (elements of ``Q[z]/(g)``) as polynomials in ``theta``, to be read
    modulo each factor of ``m``. None when no ``c`` of ``tries`` spans it.

    Example
    -------
    >>> import flint
    >>> two, three = flint.fmpq_poly([-2, 0, 1]), flint.fmpq_poly([-3, 0, 1])
    >>> c, m, w, (z,) = compositum(two, three, [flint.fmpq_poly([0, 1])])
    >>> c, str(m), str(w), str(z)    # theta = sqrt 2 + sqrt 3
    (1, 'x^4 + (-10)*x^2 + 1', '1/2*x^3 + (-9/2)*x', '(-1/2)*x^3 + 11/2*x')
    """
    d1, d2 = h.degree(), g.degree()
    size = d1 * d2
    h_monic = h / h.coeffs()[-1]

    def times(a: list, b: list) -> list:
        """The product of two elements written ``sum a_i(z) w^i``, reduced."""
        out = [flint.fmpq_poly([])] * (len(a) + len(b) - 1)
        for i, ai in enumerate(a):
            for j, bj in enumerate(b):
                out[i + j] = out[i + j] + ai * bj
        for top in range(len(out) - 1, d1 - 1, -1):   # w^d1 = -(lower terms of h)
            lead, out[top] = out[top], flint.fmpq_poly([])
            for i in range(d1):
                out[top - d1 + i] = out[top - d1 + i] - lead * h_monic[i]
        return [e % g for e in out[:d1]] + [flint.fmpq_poly([])] * (d1 - len(out))

    def vector(a: list) -> list:
        return [a[i][j] for i in range(d1) for j in range(d2)]

    zero = [flint.fmpq_poly([])] * d1
    for c in tries:
        theta = list(zero)
        theta[0] = flint.fmpq_poly([0, c])
        if d1 > 1:
            theta[1] = flint.fmpq_poly([1])
        else:
            theta[0] = theta[0] - h_monic[0]
        powers = [[flint.fmpq_poly([1])] + zero[1:]]
        for _ in range(size):
            check("the powers of a primitive element of a compositum")
            powers.append(times(powers[-1], theta))
        columns = flint.fmpq_mat(size, size, [vector(powers[j])[i] for i in range(size)
                                              for j in range(size)])
        if columns.rank() < size:
            continue
        inverse = columns.inv()

        def in_theta(a: list, inverse=inverse) -> flint.fmpq_poly:
            return flint.fmpq_poly(list((inverse * flint.fmpq_mat(size, 1, vector(a))
                                         ).entries()))

        top = in_theta(powers[size])
        minimal = flint.fmpq_poly([-e for e in top.coeffs()]
                                  + [0] * (size - len(top.coeffs())) + [1])
        w = list(zero)
        if d1 > 1:
            w[1] = flint.fmpq_poly([1])
        else:
            w[0] = -h_monic[0]
        return c, minimal, in_theta(w), [in_theta([e % g] + zero[1:]) for e in elements]
    return None


__all__ = ["compositum", "express", "minimal_polynomial", "product_generators"]
