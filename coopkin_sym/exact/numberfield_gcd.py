"""The monic gcd over a number field ``Q(alpha) = Q[x]/(g)`` from its images modulo
primes, certified by exact division.

Euclid's algorithm over ``Q(alpha)`` inverts a leading coefficient at every step, and
the rationals of those inverses grow fast: polynomials of degree 111 in ``y`` over a
field of degree 8 took a minute for a linear gcd. Here the gcd is computed in
``(F_p[x]/(g_p))[y]`` for word-size primes ``p``, its coefficients are lifted by the
Chinese remainder theorem and rational reconstruction, and the candidate ``h`` is
accepted only with a proof that it is the gcd ``d``:

* a prime is used only when ``p`` divides neither the leading coefficient of ``g`` nor
  its discriminant, and the leading coefficient of the first polynomial is a unit
  modulo ``(p, g)``: the denominators of the coefficients of ``d`` divide those
  numbers, so ``d`` has an image ``d_p``, monic of the same degree;
* Euclid modulo ``p`` runs only through unit leading coefficients (a prime meeting a
  zero divisor is dropped), so its result ``r_p`` lies in the ideal of the images and
  ``d_p`` divides it: ``deg d <= deg r_p``;
* ``h`` (monic, of degree ``deg r_p``) divides every polynomial exactly over
  ``Q(alpha)``, so it divides ``d``: ``deg h <= deg d``. Hence ``h = d``.

A degree 0 modulo one such prime proves the gcd is 1 at once.

Example
-------
>>> import flint
>>> g = flint.fmpq_poly([-2, 0, 1])                       # alpha = sqrt(2)
>>> x = flint.fmpq_poly([0, 1])
>>> # (y - alpha)(y + 1) and (y - alpha)(y - 3)
>>> h = modular_gcd(g, [[-x, 1 - x, 1], [3 * x, -3 - x, 1]])
>>> [str(c) for c in h]
['(-1)*x', '1']
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import flint

from coopkin_sym.exact.deadline import check

#: The first prime tried is the largest below this bound (primes go down from it).
PRIME_BOUND = 2**62
#: Primes tried before giving the work back to Euclid over ``Q(alpha)`` (about 62 bits
#: of every lifted coefficient per prime).
MAX_PRIMES = 400

Element = flint.fmpq_poly


def modular_gcd(g: flint.fmpq_poly, polys: Sequence[Sequence[Element]],
                max_primes: int = MAX_PRIMES) -> list[Element] | None:
    """The monic gcd over ``Q[x]/(g)`` (``g`` irreducible) of polynomials in ``y``
    (lists of ``fmpq_poly`` in ``x``, lowest degree first, each with a nonzero leading
    coefficient modulo ``g``), certified; ``None`` when ``max_primes`` primes did not
    give it (the caller then computes it another way).

    Example
    -------
    >>> import flint
    >>> g = flint.fmpq_poly([1, 0, 1])                    # alpha = i
    >>> [str(c) for c in modular_gcd(g, [[1, 0, 1], [flint.fmpq_poly([0, -1]), 1]])]
    ['(-1)*x', '1']
    """
    big_g = _integral(g)
    ints = [_integral_coefficients(p, g) for p in polys]
    best: int | None = None
    moduli, residues = 1, []
    candidate = None
    p = PRIME_BOUND
    for _ in range(max_primes):
        check("a gcd over a number field modulo primes")
        p = _previous_prime(p)
        image = _image_gcd(big_g, ints, p)
        if image is None:
            continue
        degree = len(image) - 1
        if degree == 0:
            return [Element(1)]
        if best is not None and degree > best:
            continue                                    # an unlucky prime
        flat = [int(c) for coeff in image[:-1] for c in _padded(coeff, big_g.degree())]
        if best is None or degree < best:
            best, moduli, residues, candidate = degree, p, flat, None
            continue
        residues = [_crt(r, moduli, c, p) for r, c in zip(residues, flat, strict=True)]
        moduli *= p
        lifted = _reconstruct_all(residues, moduli)
        if lifted is None:
            continue
        if lifted == candidate:
            h = _as_polynomial(lifted, best, big_g.degree())
            if all(_divides(h, poly, g) for poly in polys):
                return h
        candidate = lifted
    return None


def _integral(p: flint.fmpq_poly) -> flint.fmpz_poly:
    return p.numer()


def _integral_coefficients(poly: Sequence[Element], g: Element) -> list[flint.fmpz_poly]:
    """The coefficients times one common integer (the gcd is the same), as integer
    polynomials reduced modulo ``g``."""
    reduced = [Element(c) % g for c in poly]
    scale = 1
    for c in reduced:
        d = int(c.denom())
        scale = scale * d // _int_gcd(scale, d)
    return [(c * scale).numer() for c in reduced]


def _int_gcd(a: int, b: int) -> int:
    while b:
        a, b = b, a % b
    return a


def _previous_prime(n: int) -> int:
    n -= 1
    while not flint.fmpz(n).is_prime():
        n -= 1
    return n


def _image_gcd(big_g: flint.fmpz_poly, polys: list[list[flint.fmpz_poly]], p: int):
    """The monic gcd modulo ``p`` (a list of ``nmod_poly``), or ``None`` when ``p``
    is not usable (see the module's conditions)."""
    gp = flint.nmod_poly(big_g.coeffs(), p)
    if gp.degree() != big_g.degree() or gp.discriminant() == 0:
        return None
    images = [_trim([flint.nmod_poly(c.coeffs(), p) % gp for c in poly]) for poly in polys]
    first = images[0]
    if len(first) != len(polys[0]) or _inverse(first[-1], gp) is None:
        return None
    g_now: list = []
    for b in images:
        while b:
            if not g_now:
                g_now, b = b, []
                continue
            r = _remainder(g_now, b, gp)
            if r is None:
                return None
            g_now, b = b, r
    inv = _inverse(g_now[-1], gp)
    if inv is None:
        return None
    return [c * inv % gp for c in g_now]


def _trim(p: list) -> list:
    while p and p[-1].is_zero():
        p.pop()
    return p


def _inverse(a, gp):
    """``1/a`` modulo ``gp``, or ``None`` when ``a`` is a zero divisor."""
    if a.is_zero():
        return None
    d, s, _ = a.xgcd(gp)                                 # d monic
    return s if d.is_one() else None


def _remainder(a: list, b: list, gp):
    inv = _inverse(b[-1], gp)
    if inv is None:
        return None
    a = list(a)
    while len(a) >= len(b):
        factor = a[-1] * inv % gp
        shift = len(a) - len(b)
        for i, c in enumerate(b):
            a[shift + i] = (a[shift + i] - factor * c) % gp
        a = _trim(a)
    return a


def _padded(c, degree: int) -> list:
    coeffs = c.coeffs()
    return coeffs + [0] * (degree - len(coeffs))


def _crt(r: int, m: int, c: int, p: int) -> int:
    """The residue modulo ``m p`` that is ``r`` modulo ``m`` and ``c`` modulo ``p``."""
    return r + m * ((c - r) * pow(m, -1, p) % p)


def _reconstruct_all(residues: list[int], m: int) -> list[tuple[int, int]] | None:
    out = []
    for r in residues:
        fraction = _rational(r, m)
        if fraction is None:
            return None
        out.append(fraction)
    return out


def _rational(r: int, m: int) -> tuple[int, int] | None:
    """``n/d`` with ``n = r d`` modulo ``m`` and ``|n|, d <= sqrt(m/2)``, or ``None``."""
    bound = math.isqrt(m // 2)
    r0, r1, t0, t1 = m, r % m, 0, 1
    while r1 > bound:
        q = r0 // r1
        r0, r1 = r1, r0 - q * r1
        t0, t1 = t1, t0 - q * t1
    if t1 == 0 or abs(t1) > bound or _int_gcd(r1, abs(t1)) != 1:
        return None
    return (r1, t1) if t1 > 0 else (-r1, -t1)


def _as_polynomial(lifted: list[tuple[int, int]], degree: int, field_degree: int
                   ) -> list[Element]:
    out = []
    for i in range(degree):
        row = lifted[i * field_degree:(i + 1) * field_degree]
        out.append(Element([flint.fmpq(n, d) for n, d in row]))
    return [*out, Element(1)]


def _divides(h: list[Element], poly: Sequence[Element], g: Element) -> bool:
    """Whether the monic ``h`` divides ``poly`` over ``Q[x]/(g)``, exactly (the
    division by a monic polynomial needs no inverse)."""
    a = [Element(c) % g for c in poly]
    while len(a) >= len(h):
        check("a division over a number field")
        factor = a[-1]
        shift = len(a) - len(h)
        if not factor.is_zero():
            for i, c in enumerate(h):
                a[shift + i] = (a[shift + i] - factor * c) % g
        a.pop()
    return all(c.is_zero() for c in a)


__all__ = ["modular_gcd"]
