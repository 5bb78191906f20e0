"""A certificate that a singularity locus is complete, or the reason it is not.

The numbers of a system change exactly where ``rank Gt^T`` (the first six columns of
``Q``), ``rank Dt`` (block diagonal by arm) or ``rank Q`` fall below their values. For a
polynomial matrix ``M`` of rank ``rho`` (generic, or on a component), the points where
its rank falls below ``rho`` are the common zeros ``V(I)`` of ``I = I_rho(M)``, the ideal
of its ``rho x rho`` minors. A locus is complete when each such set lies in the union of
the reported components; by the Nullstellensatz that is a statement about ideals, decided
exactly by Gröbner bases (:func:`coopkin_sym.exact.groebner.covers`).

What is checked
---------------
* **Charts.** ``t = tan(q/2)`` misses ``q = pi``. Every subset ``S`` of the free revolute
  joints gives a slice ``q_S = pi`` (those joints fixed at pi, the others free in the t
  chart); the slices, from ``S`` empty (the t chart) to all joints, hold every
  configuration once. A component lies in ``q_j = pi`` when its equations include
  ``s_<j>`` (``s = cot(q/2) = 1/t``). On the slice ``S`` a component applies when its
  equations, read strictly there (``s_j = 0`` for ``j`` in ``S``; an equation in ``t_j``
  for ``j`` in ``S``, or in ``s_k`` for ``k`` not in ``S``, cannot hold), define a subset
  of the slice; the others have no point on it.
* **Depth 0.** On every slice, for ``Gt^T``, each arm's block of ``Dt`` and ``Q`` at their
  generic ranks (computed here exactly and compared with the locus's generic numbers):
  the drop set lies in the components that apply.
* **Inside a component** of depth ``k`` (its equations added to the ideal), two tests per
  matrix, reported at depths ``k`` and ``k + 1``: its numbers hold everywhere on it as
  upper bounds (every ``(rho + 1)``-minor vanishes there), and the points where a rank
  falls below its value lie in components later in a total order (smaller ranks
  later, then greater depth, more equations, the listing order). ``rank Dt`` is taken
  as a total over the arms, through the ideal
  ``sum over k_1 + ... + k_A = R of prod_a I_(k_a)(Dt_a)``.

* **Components with denominators.** A component found through a parametrization is
  the set where its equations hold and none of its ``outside`` polynomials vanishes;
  its closure is the zero set of the saturation ``(equations) : o^oo``
  (:func:`coopkin_sym.exact.saturation.saturate`), which the tests use in its place.
  When a saturation is not computed within its bound, the component is the equations'
  zero set minus ``V(o)``: the tests inside it leave ``V(o)`` out, and a covering that
  uses it also proves the points of its equations where ``o`` vanishes covered by the
  other components (unless the components without such polynomials cover alone).

* **Real points only.** A test that fails over C may hold at the real points, and a
  component without a real witness may have no real point on a chart
  (:mod:`~coopkin_sym.analysis.locus.certify_real`).

Together: **every real configuration has the generic numbers or the numbers of some
reported component that contains it.** (A point with other numbers lies in a component
by the depth-0 tests; the last such component in the order has exactly its numbers, by
its two tests.) That is what
"complete (certified)" means. Parameter values on the locus's parameter conditions
are left out (they are reported apart).

Only real points matter, and the polynomials ``1 + t_j^2`` (denominators of the
kinematics) never vanish there. So rows and pivots are handled *at real points*: a row
may be divided by a factor without real zeros, a pivot without real zeros eliminates its
column (the rank falls by one at every real point), factors of minors with no real
zeros (``1 + t^2``, univariate factors with no real root by Sturm's theorem, sums of even
monomials of one sign, a length parameter) are removed, squares too (``V(g^2) = V(g)``),
and the sets ``1 + t_j^2 = 0`` may take part in the covering. This leaves small ideals:
for paper case 2 with hard contacts, the 6 x 14 ``Q`` becomes one row of 9 polynomials.
When a matrix has more than :data:`MAX_MINORS` minors, random integer combinations
``det(A M B)`` (Cauchy-Binet) replace them: they lie in the ideal, so their zero set
contains the drop set and a proof with them is a proof.

Backends and measurements
-------------------------
One covering test is an ideal that must be the unit ideal. Measured on this 2-core
machine (``benchmarks/bench_certify.py``) on one test of paper case 2 with hard contacts
(t chart, ``rank Gt^T``, whose drop set ``c1 = c2`` is 5-dimensional in 8 variables),
cap 60 s:

================================  =========  =======  =======  ==================
covering system                   Singular   flint    SymPy    msolve (modulo p)
================================  =========  =======  =======  ==================
true, one z (10 vars, 273k terms)  3.6 s      3.6 s    > 60 s   20 s
true, z per component (17 vars)    0.03 s     > 60 s   0.43 s   > 60 s
false, whole space (either form)   > 60 s     > 60 s   > 60 s   > 60 s
false, random 3-dim subspace       > 60 s     > 60 s   > 60 s   0.36 s
================================  =========  =======  =======  ==================

So Singular proves (exact ``std`` over Q; both forms of the covering system are tried,
sharing the time), flint proves the small systems (no process to start: paper case 1
certifies in 0.05 s on flint alone, 0.3 s through Singular), msolve finds what is
missing on random subspaces (a screen: it never certifies), SymPy is a last exact
fallback. Singular and msolve come with the ``certify`` extra
(``pip install coopkin_sym[certify]``); without them flint does everything, and the
large tests time out (the certificate then says so).

Whole certificates of the shipped examples' loci are timed in
``benchmarks/bench_certify.py``. What makes paper case 2 (64 charts) feasible is the
structure: per-arm blocks and the six object columns, pivots without real zeros (which
leave one row of 9 polynomials of ``Q``), hypersurface components divided out of the
generators, components that miss the drop set left out, and random subspaces that
expose a missing family in 3 variables. There are ``2^r`` charts for ``r`` free
revolute joints.

What the certificate takes from the locus: the components' equations and numbers, and
the parameter conditions. It needs no witness and trusts no claim: a wrong number on a
component makes its tests fail.

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.locus.types import Component, Locus
>>> system = load("paper-case1-hard")
>>> generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
>>> links = {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 1}
>>> meet = {"Nm": 3, "Nc": 3, "Ni": 3, "Nr": 0, "Ng": 3, "Nd": 4, "Nh": 1}
>>> comps = [Component([f"t_q1 - ({a})", f"t_q2 - ({b})"], links, None, True)
...          for a in (1, -1) for b in (1, -1)]
>>> comps.append(Component(["t_q1**2 + 4*t_q1 + 1", "t_q1 + t_q2"], meet, None, True))
>>> locus = Locus("paper case 1", ["t_q1", "t_q2"], "L=1", generic, comps)
>>> certify_locus(system, locus, timeout=60).certified
True
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import random
import time
from functools import partial

import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.locus import certify_real as at_reals
from coopkin_sym.analysis.locus.drops import (
    Poly,
    _Chart,
    _drop_generators,
    _dt_generators,
    _Everywhere,
    _primitive,
    _RealZeros,
    _Setup,
    _TooLarge,
)
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import Certificate, Check, Locus
from coopkin_sym.analysis.numbers import NUMBER_NAMES, numbers_from_ranks, ranks_from_numbers
from coopkin_sym.errors import CertifyError, TimeLimitReached
from coopkin_sym.exact import deadline
from coopkin_sym.exact.angles import ExactAngle, cotangent_name
from coopkin_sym.exact.groebner import (
    EXTRA_HINT,
    Verdict,
    covers,
    is_unit_ideal,
    msolve_path,
    singular_path,
)
from coopkin_sym.exact.matrix import POLYNOMIALS, rank
from coopkin_sym.exact.parse import NumberError
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.exact.saturation import saturate
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model, model_of


# --- the certificate ---------------------------------------------------------------------
def certify_locus(system, locus: Locus, *, at=None, timeout: float = 30.0,
                  backend: str = "auto", budget: float | None = None,
                  first_failure: bool = False, max_depth: int | None = None
                  ) -> Certificate:
    """Prove that ``locus`` lists every configuration where the numbers change, with
    the right numbers, or say why that is not proved, chart by chart and depth by depth.

    Parameters
    ----------
    system
        The :class:`~coopkin_sym.system.System` the locus was computed for.
    locus
        The locus (:func:`coopkin_sym.analysis.locus.search.compute_locus`, or read back from JSON).
    at
        The values the locus was computed with (``--at`` syntax); default: the locus's
        own ``fixed`` text.
    timeout
        Seconds for each Gröbner-basis test; a test over it is not certified ("timed
        out after N s").
    backend
        ``"auto"`` (Singular to prove and msolve to screen when installed, else flint),
        ``"singular"``, ``"flint"``, ``"sympy"``; ``"msolve"`` alone never certifies
        (it works modulo a prime).
    budget
        Seconds for the whole certificate (inside a caller's bound of
        :mod:`coopkin_sym.exact.deadline` the tighter one applies); the tests after it
        are not run, and the certificate says so.
    first_failure
        Stop at the first test that is not certified (the answer is then only "not
        certified" and why; the tests after it are not run).
    max_depth
        Test only depths up to this one (``0``: the generic drop sets alone); the
        certificate then says that the deeper ones were not tested.

    Returns
    -------
    Certificate

    Raises
    ------
    CertifyError
        When the locus's variables are not those of the system with ``at`` fixed.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> generic = {"Nm": 0, "Nc": 0, "Ni": 0, "Nr": 0, "Ng": 3, "Nd": 7, "Nh": 1}
    >>> nothing = Locus("paper case 1", ["t_q1", "t_q2"], "L=1", generic)
    >>> cert = certify_locus(load("paper-case1-complete-hard"), nothing, timeout=60)
    >>> first = cert.failures()[0]  # q2 = pi/2 for every q1 is missing (q1 = pi too)
    >>> first.where(), first.why.kind
    ('t chart, depth 0, rank of Q', 'cert_drops_elsewhere')
    >>> [c.chart for c in cert.checks if not c.certified]
    ['t chart', 'q1 = pi']
    """
    started = time.monotonic()
    with deadline.time_limit(budget, "certificate"):
        try:
            return _certify(system, locus, at, timeout, backend, first_failure, max_depth,
                            started)
        except TimeLimitReached as exc:   # before any test could run
            why = Remark.of("cert_time_before_tests", seconds=exc.seconds, where=exc.where)
            return Certificate(system=model_of(system).name, refused=why,
                               depths={0: {"certified": False, "why": why, "tests": 0,
                                           "failed": 0}},
                               seconds=round(time.monotonic() - started, 3))


def _certify(system, locus: Locus, at, timeout: float, backend: str, first_failure: bool,
             max_depth: int | None, started: float) -> Certificate:
    """:func:`certify_locus` inside its time bound."""
    model: Model = model_of(system).in_base_frame()  # numbers only
    config = _configuration(model, locus.fixed if at is None else at)
    revolute = [j.name for j in model.joints if j.name in config.free
                and j.type == "revolute"]
    parameters = {p.name for p in model.parameters if p.name not in config.parameters}
    setup = _Setup(model, config, revolute, (), {}, [], [], parameters)
    base = _chart(setup, ())
    if list(base.names) != list(locus.variables):
        raise CertifyError(f"the locus has variables {', '.join(locus.variables) or 'none'}"
                           f" but the system with {config.at_text() or 'nothing'} fixed has "
                           f"{', '.join(base.names) or 'none'}: certify with the values "
                           "the locus was computed with")
    setup.full_names = tuple(base.names) + tuple(cotangent_name(j) for j in revolute)
    cert = Certificate(system=model.name)
    setup.components = _read_components(locus, setup.full_names, cert.notes)
    setup.conditions = _read_conditions(locus, setup.full_names, cert.notes)
    ranks = {name: _rank(rows) for name, rows in base.matrices.items()}
    ranks["HD"] = sum(v for k, v in ranks.items() if k.startswith("HD["))
    setup.generic_ranks = ranks
    r, m = len(model.joints), len(base.matrices["Q"])
    generic = _numbers(m, r, ranks["Q"], ranks["HG^T"], ranks["HD"], model.object_dim)
    if generic != {k: locus.generic.get(k) for k in NUMBER_NAMES}:
        why = Remark.of("cert_generic_differs", given=_numbers_of(locus.generic),
                        exact=_numbers_of(generic))
        cert.refused = why
        cert.depths = {0: {"certified": False, "why": why, "tests": 0, "failed": 0}}
        cert.seconds = round(time.monotonic() - started, 3)
        return cert
    _refuse_inconsistent_numbers(setup, locus, m, r, cert.notes)
    runner = _Runner(cert, setup, locus, timeout, backend, first_failure, max_depth)
    slices = [pi for size in range(len(revolute) + 1)
              for pi in itertools.combinations(revolute, size)]
    for k, pi_joints in enumerate(slices):
        if runner.stopped:
            break
        try:
            chart = base if not pi_joints else _chart(setup, pi_joints)
            runner.chart(chart)
        except TimeLimitReached as exc:
            name = "t chart" if not pi_joints else " = ".join(pi_joints) + " = pi"
            left = len(slices) - k - 1
            cert.checks.append(Check(name, 0, None, "Q", "drops", why=Remark.of(
                "cert_chart_not_run", seconds=exc.seconds, where=exc.where, left=left)))
            break
    real_only = sum(c.why == Remark.of("cert_real_points_only") for c in cert.checks)
    if real_only:
        cert.notes.append(Remark.of("cert_real_points_tests", count=real_only))
    if runner.stopped:
        cert.notes.append(Remark.of("cert_stopped_early"))
    if runner.skipped_depth:
        cert.notes.append(Remark.of("cert_depth_limited", depth=max_depth))
    _summarize(cert, locus, max_depth if runner.skipped_depth else None)
    if backend == "auto" and singular_path() is None:
        cert.notes.append(Remark.of("cert_no_singular", hint=EXTRA_HINT))
    if backend == "auto" and msolve_path() is None:
        cert.notes.append(Remark.of("cert_no_msolve", hint=EXTRA_HINT))
    cert.seconds = round(time.monotonic() - started, 3)
    return cert


def _refuse_inconsistent_numbers(setup: _Setup, locus: Locus, m: int, r: int,
                                 notes: list[Remark]) -> None:
    """Components whose seven numbers do not follow from their Nm, Ni, Nr are not
    used (and a note says so)."""
    for i, comp in enumerate(setup.components):
        if comp is None:
            continue
        given = {k: locus.components[i].numbers.get(k) for k in NUMBER_NAMES}
        dim = setup.model.object_dim
        implied = _numbers(m, r, *ranks_from_numbers(comp[1], r, dim=dim), dim)
        if given != implied:
            notes.append(Remark.of("cert_numbers_inconsistent", component=i,
                                   given=_numbers_of(given), implied=_numbers_of(implied)))
            setup.components[i] = None


# --- setting up --------------------------------------------------------------------------
def _configuration(model: Model, at) -> Configuration:
    fixed = Configuration.parse(model, at)
    params = dict(fixed.parameters)
    free_params = [p for p in model.parameters if p.name not in params]
    if len(free_params) == 1 and len(model.parameters) == 1:
        params[free_params[0].name] = sp.Integer(1)   # the locus's scaling rule
    free = [j.name for j in model.joints
            if j.name not in fixed.revolute and j.name not in fixed.prismatic]
    return Configuration(fixed.revolute, fixed.prismatic, params, frozenset(free))


def _chart(setup: _Setup, pi_joints: tuple[str, ...]) -> _Chart:
    """The matrices on the slice where ``pi_joints`` are at pi, rows cleared of
    denominators."""
    model, config = setup.model, setup.config
    revolute = dict(config.revolute)
    for j in pi_joints:
        revolute[j] = ExactAngle(1, 0)
    conf = Configuration(revolute, config.prismatic, config.parameters,
                         config.free - set(pi_joints))
    kin = kinematics.build(model, conf)
    ring = kin.ring
    gens = ring.zctx.gens()
    units = [1 + gens[ring.names.index(n)] ** 2 for n in ring.den_names]
    rows = [ring.clear_row(r) for r in kin.Q]
    owners = [model.contacts[c].arm for c in kin.row_contacts]
    dim = model.object_dim
    matrices: dict[str, list] = {"HG^T": [r[:dim] for r in rows]}
    blocks = []
    for a, arm in enumerate(model.arms):
        off = dim + model.joint_offset(a)
        block = [[rows[i][off + k] for k in range(len(arm.joints))]
                 for i, o in enumerate(owners) if o == a]
        if block:
            matrices[f"HD[{arm.name}]"] = block
            blocks.append((arm.name, block))
    matrices["Q"] = rows
    name = "t chart" if not pi_joints else " = ".join(pi_joints) + " = pi"
    return _Chart(name, pi_joints, tuple(ring.names), ring.zctx, units, matrices, blocks)


def _rank(rows) -> int:
    rows = [r for r in rows if not all(e.is_zero() for e in r)]
    return rank(rows, len(rows[0]), POLYNOMIALS) if rows else 0


def _numbers(m: int, r: int, rank_q: int, rank_gt: int, rank_dt: int,
             dim: int) -> dict[str, int]:
    return numbers_from_ranks(m, r, rank_q, rank_gt, rank_dt, dim=dim).as_dict()


def _numbers_of(numbers) -> tuple[tuple[str, object], ...]:
    """The seven numbers as facts of a remark (name, value), in the usual order."""
    return tuple((k, numbers.get(k)) for k in NUMBER_NAMES)


# --- reading the locus -------------------------------------------------------------------
#: Seconds for one saturation of a component's equations by an outside polynomial.
SATURATION_SECONDS = 10.0

#: How deep the coverings of the points where a parametrization's denominator vanishes
#: go (those points may lie in a component that has such points of its own).
MAX_RESIDUAL_DEPTH = 3

#: The share of a test's time for the covering without the components that keep a
#: denominator of their parametrization (0: not tried; their residual tests decide).
WITHOUT_DENOMINATORS_SHARE = 0.25


def _integer_terms(poly: NamedPolynomial, names: tuple[str, ...]) -> dict:
    """An exact polynomial as a primitive integer exponent map over ``names`` (rational
    coefficients are scaled to integers)."""
    terms = poly.exponents(names)
    scale = 1
    for c in terms.values():
        scale = math.lcm(scale, c.denominator)
    return {monom: int(c * scale) for monom, c in terms.items()}


def _integer_polynomial(text: str, names: tuple[str, ...], where: str) -> dict:
    """A polynomial written in the locus (a parameter condition), read by the one
    parser, as :func:`_integer_terms`."""
    return _integer_terms(NamedPolynomial.parse(text, names, where), names)


def _read_components(locus: Locus, names: tuple[str, ...], notes: list[Remark]
                     ) -> list[tuple[list[dict], dict[str, int], list[dict]] | None]:
    """Each component's equations (exponent maps over ``names``), ranks and the
    outside polynomials that may vanish on its equations, or None when it cannot be
    read (a note says why)."""
    out = []
    for i, comp in enumerate(locus.components):
        try:
            where = f"component #{i + 1}, "
            eqs = [_integer_terms(poly, names)
                   for poly in comp.equation_polynomials(names, where)]
            outs = [_integer_terms(poly, names)
                    for poly in comp.outside_polynomials_of(names, where)]
            # the component holds V(equations) minus V(outside); an outside polynomial
            # that vanishes nowhere on V(equations) (a unit ideal with them) takes
            # nothing away; where another may vanish, a covering that uses the
            # component also proves those points covered by the others (_Runner.cover)
            outs = [o for o in outs if not is_unit_ideal([*eqs, o], timeout=10.0,
                                                         nvars=len(names)).proved]
            eqs, outs = _closure(eqs, outs, len(names))
            numbers = {k: int(comp.numbers[k]) for k in ("Nm", "Ni", "Nr")}
        except NumberError as exc:
            notes.append(Remark.of("cert_component_unreadable", error=str(exc)))
            out.append(None)
            continue
        except (KeyError, TypeError, ValueError):
            notes.append(Remark.of("cert_numbers_unreadable", component=i))
            out.append(None)
            continue
        out.append((eqs, numbers, outs))
    return out


def _closure(eqs: list[dict], outs: list[dict], nvars: int) -> tuple[list[dict], list]:
    """The equations of the closure of ``V(eqs)`` minus the zeros of ``outs``: the
    saturation by each outside polynomial in turn (:func:`saturate`, bounded); the
    outside polynomials whose saturation was not computed are kept (a covering that
    uses the component then covers their zeros apart)."""
    kept = []
    for o in outs:
        sat = saturate(eqs, o, nvars, timeout=SATURATION_SECONDS)
        if sat is None:
            kept.append(o)
        else:
            eqs = sat
    return eqs, kept


def _read_conditions(locus: Locus, names: tuple[str, ...], notes: list[Remark]
                     ) -> list[dict]:
    out = []
    for k, condition in enumerate(locus.parameter_conditions):
        if isinstance(condition, Remark):  # computed: its polynomial vanishes
            left, right = condition["polynomial"], "0"
        else:                              # read back from a report: "lhs = rhs"
            left, _, right = condition.partition("=")
        try:
            lhs = _integer_polynomial(left, names, f"parameter condition {k + 1}")
            rhs = _integer_polynomial(right or "0", names, f"parameter condition {k + 1}")
        except NumberError as exc:
            notes.append(Remark.of("cert_condition_unreadable", error=str(exc)))
            continue
        diff = dict(lhs)
        for key, c in rhs.items():
            diff[key] = diff.get(key, 0) - c
        out.append({key: c for key, c in diff.items() if c})
    if out:
        notes.append(Remark.of("cert_conditions_left_out"))
    return out


def _in_chart(setup: _Setup, equations: list[dict], chart: _Chart) -> list[Poly] | None:
    """Equations on the slice ``chart``, or None when they have no point there (read
    strictly, see the module docstring)."""
    index = {n: i for i, n in enumerate(chart.names)}
    pi = set(chart.pi_joints)
    out = []
    for eq in equations:
        terms: dict[tuple[int, ...], int] = {}
        for monom, c in eq.items():
            vanishes = False
            key = [0] * len(chart.names)
            for name, e in zip(setup.full_names, monom, strict=True):
                if not e:
                    continue
                if name.startswith("s_") and name[2:] in setup.revolute:
                    if name[2:] not in pi:
                        return None      # q = pi for a joint that is not at pi here
                    vanishes = True      # s_j = 0 on this slice
                elif name.startswith("t_") and name[2:] in pi:
                    return None          # an equation in t_j cannot hold at q_j = pi
                else:
                    key[index[name]] = e
            if not vanishes:
                terms[tuple(key)] = terms.get(tuple(key), 0) + c
        terms = {k: c for k, c in terms.items() if c}
        if not terms:
            continue
        if len(terms) == 1 and not any(next(iter(terms))):
            return None                  # a nonzero constant: no point here
        out.append(_primitive(chart.zctx.from_dict(terms)))
    return out


# --- running the tests ---------------------------------------------------------------------
def _order(index: int, component, ranks: dict[str, int]) -> tuple[int, int, int, int]:
    """A total order of the components: inside one, the components later in it may hold
    its deeper drops. Smaller ranks (larger numbers) come later, then greater depth,
    then more equations, then the listing order. Any total order makes the induction
    of the module docstring work (take the last component that holds a point); this
    one puts every component with the numbers of a drop point after the components
    the point drops from."""
    return (-sum(ranks.values()), component.depth, len(component.equations), index)


class _Runner:
    def __init__(self, cert: Certificate, setup: _Setup, locus: Locus, timeout: float,
                 backend: str, first_failure: bool, max_depth: int | None):
        self.cert, self.setup, self.locus = cert, setup, locus
        self.max_depth = max_depth
        self.first_failure, self.stopped = first_failure, False
        self.skipped_depth = False
        self.timeout, self.backend = timeout, backend
        self.rng = random.Random(1992)
        r = len(setup.model.joints)
        self.component_ranks = [
            None if c is None else dict(zip(("Q", "HG^T", "HD"),
                                            ranks_from_numbers(
                                                c[1], r, dim=setup.model.object_dim),
                                            strict=True))
            for c in setup.components]

    def chart(self, chart: _Chart) -> None:
        setup = self.setup
        real = _RealZeros(chart, setup.parameters)
        cache: dict = {}
        here = {}
        self.outs = {}
        for i, comp in enumerate(setup.components):
            if comp is not None:
                eqs = _in_chart(setup, comp[0], chart)
                if eqs is None:
                    continue
                outs = [_in_chart(setup, [o], chart) for o in comp[2]]
                if any(o == [] for o in outs):
                    continue      # an outside polynomial vanishes on the whole slice
                here[i] = eqs
                self.outs[i] = [o[0] for o in outs if o]
        conditions = [p for p in (_in_chart(setup, [c], chart) for c in setup.conditions)
                      if p]
        everything = list(here.items())
        for name in chart.matrices:
            if self.stopped:
                return
            gens = partial(self.generators, chart, real, cache, name,
                           setup.generic_ranks[name])
            self.run(Check(chart.name, 0, None, name, "drops"), chart, [], gens,
                     everything, conditions)
        for i in sorted(here):
            comp = self.locus.components[i]
            if self.max_depth is not None and comp.depth > self.max_depth:
                self.skipped_depth = True
                continue
            if not comp.real and self._not_real(chart, i, here[i], conditions):
                continue
            key = _order(i, comp, self.component_ranks[i])
            later = [(j, p) for j, p in here.items()
                     if _order(j, self.locus.components[j], self.component_ranks[j]) > key]
            ranks = self.component_ranks[i]
            for name in ("HG^T", "HD", "Q"):
                for kind, target in (("numbers", ranks[name] + 1), ("drops", ranks[name])):
                    if self.stopped:
                        return
                    depth = comp.depth + (1 if kind == "drops" else 0)
                    if self.max_depth is not None and depth > self.max_depth:
                        self.skipped_depth = True
                        continue
                    gens = partial(self.generators, chart, real, cache, name, target)
                    check = Check(chart.name, depth, i, name, kind)
                    if kind == "numbers":
                        self.bound(check, chart, here[i], gens, conditions)
                    else:
                        self.run(check, chart, here[i], gens, later, conditions)

    def _not_real(self, chart: _Chart, index: int, own: list[Poly], conditions) -> bool:
        """Whether component ``index`` (``own``: its equations on the chart) is proved
        to have no real point on the chart (:func:`over_reals`); its tests are then
        recorded as certified (only real configurations matter)."""
        comp = self.locus.components[index]
        seconds = self._test_timeout(Check(chart.name, comp.depth, index, "Q", "numbers"))
        started = time.monotonic()
        allowed = [[u] for u in chart.units] + conditions + [[o] for o in self.outs.get(index, ())]
        if not at_reals.no_real_point_outside(own, [], allowed, len(chart.names),
                                              seconds * at_reals.REAL_SHARE):
            return False
        spent = round(time.monotonic() - started, 3)
        for name, kind in itertools.product(("HG^T", "HD", "Q"), ("numbers", "drops")):
            depth = comp.depth + (1 if kind == "drops" else 0)
            if self.max_depth is not None and depth > self.max_depth:
                self.skipped_depth = True
                continue
            self._add(Check(chart.name, depth, index, name, kind, certified=True, seconds=spent,
                            backend="flint", why=Remark.of("cert_component_not_real")))
        return True

    def generators(self, chart: _Chart, real: _RealZeros, cache: dict, name: str,
                   target: int):
        """The drop ideal of matrix ``name`` below rank ``target`` (cached)."""
        key = (name, target)
        if key not in cache:
            if name == "HD":
                cache[key] = _dt_generators(chart, target, self.setup, real, self.rng,
                                            cache)
            else:
                cache[key] = _drop_generators(chart.matrices[name], target, chart, real,
                                              self.rng)
        return cache[key]

    def _test_timeout(self, check: Check) -> float:
        """Seconds for one test: its own bound, within what is left of the whole
        certificate's (past that, :class:`TimeLimitReached`)."""
        deadline.check(f"the test at {check.where()}")
        left = deadline.remaining()
        return self.timeout if left is None else max(min(self.timeout, left), 0.01)

    def _prepare(self, check: Check, gens):
        """``(seconds, generators)`` for one test; generators None when they are too
        large to write (the check is then recorded as not certified, with why)."""
        seconds = self._test_timeout(check)
        made = gens()
        if isinstance(made, _TooLarge):
            check.why = made.why
            self._add(check)
            return seconds, None
        return seconds, made

    def bound(self, check: Check, chart: _Chart, own: list[Poly], gens, conditions
              ) -> None:
        """The rank on the component never exceeds its value: the ``(rho + 1)``-minors
        vanish on it. ``gens`` makes their generators."""
        seconds, gens = self._prepare(check, gens)
        if gens is None:
            return
        if gens == []:
            check.certified, check.backend = True, "none"
            check.why = Remark.of("cert_no_larger_rank")
            self._add(check)
            return
        if gens is _Everywhere:
            check.why = Remark.of("cert_larger_everywhere")
            self._add(check)
            return
        allowed = [[u] for u in chart.units] + conditions + self._outside(check)
        verdict = covers(own, [gens], timeout=seconds, backend=self.backend,
                         nvars=len(chart.names), allowed=allowed)
        verdict = at_reals.over_reals(verdict, own, [gens], allowed, len(chart.names),
                                      seconds, slopes_backend=self.backend)
        self._record(check, verdict, "cert_larger_somewhere")

    def _outside(self, check: Check) -> list[list]:
        """The sets a test inside a component leaves out: where an outside polynomial
        of the component vanishes (the component is the set where its equations hold
        and none of them vanishes)."""
        return [[o] for o in self.outs.get(check.inside, ())] if check.inside is not None \
            else []

    def run(self, check: Check, chart: _Chart, own: list[Poly], gens, covering,
            conditions) -> None:
        """The drop set (within ``own``) lies in the ``covering`` components. ``gens``
        makes the generators of the drop ideal."""
        seconds, gens = self._prepare(check, gens)
        if gens is None:
            return
        if gens is _Everywhere:
            check.certified, check.backend = True, "none"
            check.why = Remark.of("cert_never_drops")
            self._add(check)
            return
        whole = next((i for i, p in covering if not p and not self.outs.get(i)), None)
        if whole is not None:
            check.certified, check.backend = True, "none"
            check.why = Remark.of("cert_whole_slice", component=whole)
            self._add(check)
            return
        ideal, allowed = list(own) + list(gens), conditions + self._outside(check)
        started = time.monotonic()
        verdict, residual = self.cover(ideal, list(covering), seconds, chart, allowed)
        verdict = dataclasses.replace(verdict, seconds=time.monotonic() - started)
        if residual is not None and not verdict.proved:
            self._residual_failed(check, verdict, residual)
            return
        if not any(self.outs.get(i) for i, _ in covering):
            verdict = at_reals.over_reals(verdict, ideal, [p for _, p in covering],
                                          [[u] for u in chart.units] + allowed,
                                          len(chart.names), seconds)
        self._record(check, verdict, "cert_drops_elsewhere")

    def cover(self, ideal: list, pieces: list, seconds: float, chart: _Chart,
              conditions, depth: int = 0, until: float | None = None
              ) -> tuple[Verdict, tuple | None]:
        """Whether ``V(ideal)`` lies in the ``pieces`` ``(index, equations)``. A piece
        is ``V(equations)`` minus where an outside polynomial ``o`` of its component
        vanishes: the covering of ``V(equations)`` is proved, then that the pieces
        without such polynomials cover ``V(ideal)`` alone (in
        :data:`WITHOUT_DENOMINATORS_SHARE` of the time), else
        for each such ``o`` that ``V(ideal + equations + o)`` lies in the other pieces
        (the same way, up to :data:`MAX_RESIDUAL_DEPTH` deep), all by ``until`` (default:
        ``seconds`` from now). The verdict, and ``(component index, o)`` when a
        residual test failed."""
        until = time.monotonic() + seconds if until is None else until
        if (left := until - time.monotonic()) <= 0:
            return Verdict(None, False, "none", seconds, f"timed out after {seconds:.3g} s"), None
        allowed = [[u] for u in chart.units] + conditions
        verdict = covers(ideal, [p for _, p in pieces], timeout=left,
                         backend=self.backend, nvars=len(chart.names), allowed=allowed)
        if not verdict.proved:
            return verdict, None
        closed = [(i, p) for i, p in pieces if not self.outs.get(i)]
        if len(closed) < len(pieces):
            # the pieces with an outside polynomial may not be needed at all: then
            # no residual test is (its polynomial can be far larger than the rest)
            share = min(seconds * WITHOUT_DENOMINATORS_SHARE, until - time.monotonic())
            without = covers(ideal, [p for _, p in closed], timeout=share,
                             backend=self.backend, nvars=len(chart.names),
                             allowed=allowed) if closed and share > 0 else None
            if without is not None and without.proved:
                return without, None
        for i, eqs in pieces:
            for o in self.outs.get(i, ()):
                if depth >= MAX_RESIDUAL_DEPTH:
                    return Verdict(None, False, verdict.backend, verdict.seconds,
                                   "residual depth bound"), (i, o)
                deadline.check("a covering of the points outside a parametrization")
                rest = [(j, q) for j, q in pieces if j != i]
                inner, _ = self.cover([*ideal, *eqs, o], rest, seconds, chart,
                                      conditions, depth + 1, until)
                if not inner.proved:
                    return inner, (i, o)
        return verdict, None

    def _residual_failed(self, check: Check, verdict: Verdict, residual: tuple) -> None:
        """A covering proved but for the points of a component where a denominator of
        its parametrization vanishes."""
        index, o = residual
        check.backend, check.seconds = verdict.backend, round(verdict.seconds, 3)
        check.why = Remark.of("cert_denominator_residual", component=index,
                              polynomial=NamedPolynomial.from_flint(o, o.context().names()
                                                                    ).text,
                              undecided=verdict.holds is None)
        self._add(check)

    def _record(self, check: Check, verdict: Verdict, failure: str) -> None:
        """Record a backend's verdict; ``failure`` is the kind of remark saying what
        fails when it does not hold."""
        check.backend, check.seconds = verdict.backend, round(verdict.seconds, 3)
        if verdict.proved:
            check.certified = True
            if verdict.detail == at_reals.REAL_DETAIL:
                check.why = Remark.of("cert_real_points_only")
        elif verdict.holds is False:
            check.why = Remark.of(failure, depth=check.depth, modular=not verdict.exact)
        elif verdict.holds is True:
            check.why = Remark.of("cert_modular_only", backend=verdict.backend)
        else:
            hint = (EXTRA_HINT if verdict.detail.startswith("timed out")
                    and singular_path() is None else "")
            check.why = Remark.of("cert_undecided", detail=verdict.detail, hint=hint)
        self._add(check)

    def _add(self, check: Check) -> None:
        self.cert.checks.append(check)
        if self.first_failure and not check.certified:
            self.stopped = True


def _summarize(cert: Certificate, locus: Locus, max_depth: int | None) -> None:
    def tally(table: dict, key, check: Check) -> None:
        entry = table.setdefault(key, {"certified": True, "why": None, "tests": 0,
                                       "failed": 0})
        entry["tests"] += 1
        if not check.certified:
            entry["failed"] += 1
            if entry["certified"]:
                entry["certified"], entry["why"] = False, check

    depths: dict[int, dict] = {}
    charts: dict[str, dict] = {}
    for c in cert.checks:
        tally(depths, c.depth, c)
        tally(charts, c.chart, c)
    top = max((c.depth for c in locus.components), default=-1) + 1
    for d in range(top + 1):
        untested = max_depth is not None and d > max_depth
        depths.setdefault(d, {"certified": not untested,
                              "why": Remark.of("cert_not_tested" if untested
                                               else "cert_nothing_to_test"),
                              "tests": 0, "failed": 0})
    cert.depths = dict(sorted(depths.items()))
    cert.charts = charts
    cert.untested_beyond = max_depth
    cert.certified = not cert.failures()


__all__ = ["Certificate", "CertifyError", "Check", "certify_locus"]
