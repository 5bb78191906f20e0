"""The kinematics with joints at q = pi as limits of the chart's (t = oo), against the
kinematics built at those configurations; and the rank test that proves a slice's
numbers."""

from __future__ import annotations

import itertools

import flint
import pytest

import coopkin_sym
from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.decomposition import attains, decompose
from coopkin_sym.exact.angles import ExactAngle, tangent_name
from coopkin_sym.exact.elimination import ranks_at_random_point
from coopkin_sym.exact.ring import Ring
from coopkin_sym.model.builders import planar_hand
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import load_model

MODELS = ["paper-case1-hard", "paper-case2-hard", "five-bar", "bennett-linkage",
          "underactuated-finger", "dh-three-finger-hand", "planar-hand-2x2"]


def _model(name: str):
    if name == "planar-hand-2x2":
        return coopkin_sym.load(planar_hand(2, 2)).model
    return load_model(name)


def _revolute(model) -> list[str]:
    return [j.name for j in model.joints if j.type == "revolute"]


def _at_pi(model, config: Configuration, joints) -> Configuration:
    revolute = dict(config.revolute)
    for n in joints:
        revolute[n] = ExactAngle(1, 0)
    return Configuration(revolute, config.prismatic, config.parameters,
                         config.free - set(joints))


@pytest.mark.parametrize("source", MODELS)
def test_the_limits_at_pi_are_the_kinematics_built_there(source):
    model = _model(source)
    free = [j.name for j in model.joints]
    config = Configuration.parse(model, None, free=free)
    full = kinematics.build(model, config)
    rev = _revolute(model)
    subsets = [s for k in (1, 2, len(rev)) for s in itertools.combinations(rev, k)][:12]
    assert subsets
    for joints in subsets:
        built = kinematics.build(model, _at_pi(model, config, joints))
        ring, symbols, q = kinematics.q_at_pi(full, joints)
        assert ring == built.ring and symbols == built.symbols and q == built.Q
        # the same limits give every other matrix and vector of the kinematics
        _, limit = full.ring.at_infinity([tangent_name(j) for j in joints])
        for name in ("GT", "D", "H", "points", "normals", "axes", "origins"):
            got = [None if v is None else [limit(f) for f in v] for v in getattr(full, name)]
            assert got == getattr(built, name), (joints, name)


def test_a_value_without_a_limit_at_infinity_is_refused():
    ring = Ring(["t_q1", "L"], ["t_q1"])
    t, L = ring.gens()
    smaller, limit = ring.at_infinity(["t_q1"])
    assert limit(t * ring.cos_of(0)) is None              # t cos q grows without bound
    assert limit(ring.sin_of(0) * L).is_zero()             # sin(pi) L = 0
    assert limit(ring.cos_of(0) * ring.cos_of(0)).rational() == 1
    assert limit(L + 3) == smaller.gens()[0] + 3


def test_ranks_at_a_point_bound_the_generic_ranks_from_below():
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    rows = [[x, y, x * y], [x**2, x * y, x**2 * y], [ctx.constant(1), ctx.constant(0), y]]
    # rank 2: the second row is x times the first
    assert ranks_at_random_point(rows, [range(3), [0, 1], [2]]) == [2, 2, 1]


@pytest.mark.parametrize("source", ["paper-case1-hard", "five-bar", "planar-hand-2x2"])
def test_a_slice_reaching_the_generic_ranks_has_the_generic_numbers(source):
    model = _model(source)
    config = Configuration.parse(model, None, free=[j.name for j in model.joints])
    full = kinematics.build(model, config)
    rows = [full.ring.clear_row(r) for r in full.Q]
    generic = decompose(rows, model, full.row_contacts, full.ring.zctx).numbers
    assert attains(rows, model, generic)
    seen = set()
    for joints in itertools.combinations(_revolute(model), 2):
        ring, _, q = kinematics.q_at_pi(full, joints)
        slice_rows = [ring.clear_row(r) for r in q]
        exact = decompose(slice_rows, model, full.row_contacts, ring.zctx).numbers
        proved = attains(slice_rows, model, generic)
        seen.add(proved)
        # True is a proof; False where the slice is generic would need a random point
        # on a minor's zero set (a chance of about degree / 2^20)
        assert proved == (exact == generic), joints
    assert True in seen


@pytest.mark.parametrize("source", [
    "paper-case1-hard",
    # two whole searches each (about 11 s): with the slow tests
    pytest.param("five-bar", marks=pytest.mark.slow),
    pytest.param("planar-hand-2x2", marks=pytest.mark.slow)])
def test_the_rank_proofs_at_a_point_change_no_locus(source, monkeypatch):
    """The search proves numbers by ranks at a point where it can (slices at q = pi,
    candidates whose numbers are the enclosing ones); without those proofs, every
    number decided over the function field, the locus is the same."""
    from coopkin_sym.analysis.locus.search import charts, compute_locus, recursion

    system = coopkin_sym.load(planar_hand(2, 2) if source == "planar-hand-2x2" else source)

    def described(locus):
        return [(tuple(c.equations), tuple(sorted(c.numbers.items())), c.kind)
                for c in locus.components]
    fast = compute_locus(system, max_depth=2)
    monkeypatch.setattr(charts, "attains", lambda *args: False)
    monkeypatch.setattr(recursion, "attains", lambda *args: False)
    slow = compute_locus(system, max_depth=2)
    assert described(fast) == described(slow)
    assert len(fast.unexplored) == len(slow.unexplored)
