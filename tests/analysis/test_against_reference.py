"""The package against an independent computation on systems it has never seen.

``independent.reference_analysis`` builds G, D, H, Q with explicit 4x4 transforms and
decides everything with SymPy's exact ``Matrix`` routines; it imports nothing from
``coopkin_sym``. Random systems (``strategies.random_systems``) have inner-link, arm
base and ground (palm) contacts, several contacts on a link, mixed contact models and
revolute and prismatic joints; configurations include singular-looking ones.
"""

from __future__ import annotations

import json

import numpy as np
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from independent import reference_analysis
from strategies import random_configurations, random_systems
from support import rank, same_span
from typer.testing import CliRunner

import coopkin_sym
from coopkin_sym.cli import app

SETTINGS = settings(max_examples=40, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


def a_r(model) -> int:
    return sum(len(arm["joints"]) for arm in model["arms"])


def columns(vectors, nrows: int) -> sp.Matrix:
    return sp.Matrix.hstack(*vectors) if vectors else sp.zeros(nrows, 0)


@st.composite
def system_and_configuration(draw):
    model = draw(random_systems(with_parameter=draw(st.booleans())))
    at, text = draw(random_configurations(model))
    return model, at, text


@SETTINGS
@given(system_and_configuration())
def test_matrices_numbers_and_subspaces_agree(case):
    model, at, text = case
    ref = reference_analysis(model, at)
    a = coopkin_sym.load(model).analyze(text)
    # the kinematics, entry by entry
    assert a.G == ref["G"]
    assert a.D == ref["D"]
    assert a.H == ref["H"]
    assert a.Q == ref["Q"]
    numbers = a.numbers.as_dict()
    assert numbers == {k: ref[k] for k in numbers}
    # the subspaces
    assert same_span(a.C11, columns(ref["N_GT"], 6))
    assert same_span(a.C23, columns(ref["N_D"], a.r))
    assert same_span(a.C, columns(ref["N_Q"], 6 + a.r))
    assert (a.Q * a.C) == sp.zeros(a.m, a.C.cols)
    # invariants
    n = a.numbers
    assert n.Nm == n.Nc + n.Nr and n.Nm - n.Nh == 6 + a.r - a.m
    assert rank(a.C[:6, :]) == n.Nc


@SETTINGS
@given(system_and_configuration())
def test_cli_json_agrees_with_reference(tmp_path_factory, case):
    model, at, text = case
    path = tmp_path_factory.mktemp("m") / "system.json"
    path.write_text(json.dumps(model))
    result = CliRunner().invoke(app, ["analyze", str(path), "--at", text, "--json"])
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    ref = reference_analysis(model, at)
    assert out["numbers"] == {k: ref[k] for k in out["numbers"]}
    rows = out["blocks"]["C11"]
    c11 = sp.Matrix(6, len(rows[0]), [sp.Rational(e) for row in rows for e in row])
    assert same_span(c11, columns(ref["N_GT"], 6))
    assert out["shapes"]["C23"] == [a_r(model), ref["Nr"]]


@SETTINGS
@given(system_and_configuration())
def test_ranks_agree_with_float_svd_where_well_conditioned(case):
    model, _at, text = case
    a = coopkin_sym.load(model).analyze(text)
    q = np.array(a.Q.evalf(), dtype=float)  # float-ok: comparison with float rank tests
    s = np.linalg.svd(q, compute_uv=False)  # float-ok
    exact_rank = 6 + a.r - a.numbers.Nm
    gap_ok = (exact_rank == 0 or s[exact_rank - 1] > 1e-6 * s[0]) and (
        exact_rank >= len(s) or s[exact_rank] < 1e-9 * s[0])
    if gap_ok:
        assert np.linalg.matrix_rank(q) == exact_rank  # float-ok


def test_generic_numbers_equal_numbers_at_random_points():
    # Schwartz-Zippel on every shipped example: the generic rank is the rank at almost
    # every point; random rational points away from the examples' special values
    for name in ["paper-case1-hard", "paper-case1-soft", "paper-case2-complete",
                 "paper-case2-hard"]:
        system = coopkin_sym.load(name)
        generic = system.analyze(generic=True).numbers
        parts = []
        for k, j in enumerate(system.model.joints):
            value = f"2*atan({3 + 2 * k}/{17 + 5 * k})" if j.type == "revolute" else (
                f"{k + 2}/{k + 9}")
            parts.append(f"{j.name}={value}")
        parts.append("L=23/19")
        assert system.analyze(",".join(parts)).numbers == generic, name
