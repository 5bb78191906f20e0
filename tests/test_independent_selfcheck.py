"""Self-checks of the independent reference (tests/independent.py) and the strategies.

The reference must be trustworthy before the package is compared with it: here it is
checked against the paper's case studies, hand-derived poses and general identities.
Nothing from ``coopkin_sym`` is imported.
"""

from __future__ import annotations

import copy

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from independent import (
    angle_from_text,
    at_from_text,
    reference_analysis,
    reference_numbers_float,
)
from strategies import (
    exact_angles,
    random_configurations,
    random_systems,
    rational_unit_vectors,
)
from support import same_span

R = sp.Rational
NUMBERS_4 = ("Nm", "Nc", "Ni", "Nr")


def numbers(result, keys=NUMBERS_4):
    return {k: result[k] for k in keys}


# ----------------------------------------------------------------- paper case study 1


def case1(model1: str, model2: str) -> dict:
    return {
        "name": "two one-link arms",
        "parameters": ["L"],
        "arms": [
            {
                "name": "a1",
                "joints": [
                    {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]}
                ],
            },
            {
                "name": "a2",
                "joints": [
                    {"name": "q2", "type": "revolute", "axis": [0, 0, 1], "point": ["L", 0, 0]}
                ],
            },
        ],
        "contacts": [
            {"name": "c1", "link": "a1/1", "point": [0, "L", 0], "normal": [1, 0, 0],
             "model": model1},
            {"name": "c2", "link": "a2/1", "point": ["L", "L", 0], "normal": [-1, 0, 0],
             "model": model2},
        ],
    }  # fmt: skip


@pytest.mark.parametrize("L", [1, 2, R(3, 7)])
def test_case1_hard_hard(L):
    res = reference_analysis(case1("hard", "hard"), {"L": L})
    assert numbers(res) == {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0}
    assert same_span(res["N_GT"], sp.Matrix([0, 0, -L, 1, 0, 0]))
    # the coordinated motion is a translation along x with both joints at equal speed
    assert same_span(res["N_Q"], [sp.Matrix([0, 0, -L, 1, 0, 0, 0, 0]),
                                  sp.Matrix([-L, 0, 0, 0, 0, 0, 1, 1])])  # fmt: skip
    assert res["m"] == 6 and res["Q"].shape == (6, 8)


def test_case1_matrices_by_hand():
    res = reference_analysis(case1("hard", "hard"), {"L": 1})
    G = sp.Matrix(
        [
            [1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0],
            [0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0],
            [0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0],
            [0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0],
            [0, 0, 0, 0, 0, -1, 0, 1, 0, 0, 1, 0],
            [-1, 0, 0, -1, 1, 0, 0, 0, 1, 0, 0, 1],
        ]
    )
    assert res["G"] == G
    D = sp.zeros(12, 2)
    D[0, 0] = -1  # z x (0,1,0) = (-1,0,0)
    D[3, 1] = -1  # z x ((1,1,0)-(1,0,0)) = (-1,0,0)
    D[8, 0] = 1  # angular of contact 1 (rows 6..8)
    D[11, 1] = 1  # angular of contact 2 (rows 9..11)
    assert res["D"] == D
    assert res["H"] == sp.eye(12)[:6, :]


@pytest.mark.parametrize("pair", [("soft", "soft"), ("soft", "hard"), ("hard", "soft")])
def test_case1_soft(pair):
    res = reference_analysis(case1(*pair), {"L": 1})
    assert numbers(res) == {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0}
    assert same_span(res["N_Q"], sp.Matrix([-1, 0, 0, 0, 0, 0, 1, 1]))


def test_case1_soft_H_rows():
    res = reference_analysis(case1("soft", "soft"), {"L": 1})
    H = sp.zeros(8, 12)
    H[:6, :6] = sp.eye(6)
    H[6, 6] = 1  # n1^T on the angular block of contact 1
    H[7, 9] = -1  # n2^T on the angular block of contact 2
    assert res["H"] == H


@pytest.mark.parametrize("pair", [("complete", "hard"), ("hard", "complete"),
                                  ("complete", "complete"), ("complete", "soft")])  # fmt: skip
def test_case1_complete(pair):
    res = reference_analysis(case1(*pair), {"L": 1})
    assert numbers(res) == {"Nm": 0, "Nc": 0, "Ni": 0, "Nr": 0}
    assert res["N_Q"] == []


# ----------------------------------------------------------------- paper case study 2


def case2(model: str) -> dict:
    def rev(name, axis, point):
        return {"name": name, "type": "revolute", "axis": axis, "point": point}

    def pri(name, axis, point):
        return {"name": name, "type": "prismatic", "axis": axis, "point": point}

    z, x = [0, 0, 1], [1, 0, 0]
    return {
        "name": "two SCARA robots",
        "parameters": ["L"],
        "arms": [
            {
                "name": "s1",
                "joints": [
                    rev("q1", z, [0, "2*L", 0]),
                    rev("q2", z, ["L", "2*L", 0]),
                    rev("q3", z, ["L", "L", 0]),
                    pri("q4", z, ["L", "L", 0]),
                ],
            },
            {
                "name": "s2",
                "joints": [
                    pri("q5", x, ["4*L", "L", "L"]),
                    rev("q6", x, ["4*L", "L", "L"]),
                    rev("q7", x, ["4*L", "L", "2*L"]),
                    rev("q8", x, ["4*L", 0, "2*L"]),
                ],
            },
        ],
        "contacts": [
            {"name": "c1", "link": "s1/4", "point": ["L", "L", "L"], "normal": [1, 0, 0],
             "model": model},
            {"name": "c2", "link": "s2/4", "point": ["3*L", "L", "L"], "normal": [-1, 0, 0],
             "model": model},
        ],
    }  # fmt: skip


@pytest.mark.parametrize("L", [1, 5])
def test_case2_complete(L):
    res = reference_analysis(case2("complete"), {"L": L})
    assert numbers(res) == {"Nm": 3, "Nc": 3, "Ni": 0, "Nr": 0}
    # the feasible object motions are exactly the pure translations
    c1 = sp.Matrix.hstack(*[c[:6, 0] for c in res["N_Q"]])
    assert same_span(c1, sp.eye(6)[:, :3])
    # the paper's printed C12 / C22 (section 4.2) span the same coordinated motions
    C12 = sp.Matrix([[L, 0, 0], [0, L, 0], [0, 0, L], [0, 0, 0], [0, 0, 0], [0, 0, 0]])
    C22 = sp.Matrix([[0, 1, 0], [1, -1, 0], [-1, 0, 0], [0, 0, L],
                     [L, 0, 0], [0, -1, 0], [0, 1, -1], [0, 0, 1]])  # fmt: skip
    assert same_span(res["N_Q"], C12.col_join(C22))


@pytest.mark.parametrize("L", [1, 5])
def test_case2_hard(L):
    res = reference_analysis(case2("hard"), {"L": L})
    assert numbers(res) == {"Nm": 8, "Nc": 6, "Ni": 1, "Nr": 2}
    # indeterminacy: rotation about the line through both contacts (x axis at y=z=L)
    w = sp.Matrix([1, 0, 0])
    p = sp.Matrix([L, L, L])
    assert same_span(res["N_GT"], sp.Matrix.vstack(-w.cross(p), w))
    # redundancy: the third (q3) and sixth (q6) joints
    e = sp.eye(8)
    assert same_span(res["N_D"], [e[:, 2], e[:, 5]])


# ------------------------------------------------------------------- hand-made poses


def one_arm(contact_link="a1/2", model="hard") -> dict:
    return {
        "name": "rotate and slide",
        "parameters": [],
        "arms": [
            {
                "name": "a1",
                "joints": [
                    {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [1, 0, 0]},
                    {"name": "q2", "type": "prismatic", "axis": [1, 0, 0]},
                ],
            }
        ],
        "contacts": [
            {"name": "c1", "link": contact_link, "point": [3, 0, 0], "normal": [0, 1, 0],
             "model": model},
        ],
    }  # fmt: skip


def test_rotated_configuration_moves_contact_as_by_hand():
    # q1 = pi/2 about z through (1,0,0), q2 slides 1/2 along the (home) x axis:
    # (3,0,0) -> (7/2,0,0) -> rotated about (1,0,0): (1, 5/2, 0); normal (0,1,0) -> (-1,0,0)
    res = reference_analysis(one_arm(), {"q1": (0, 1), "q2": R(1, 2)})
    assert res["points"]["c1"] == sp.Matrix([1, R(5, 2), 0])
    assert res["normals"]["c1"] == sp.Matrix([-1, 0, 0])
    s2, _ = res["joints"]["q2"]
    assert s2 == sp.Matrix([0, 1, 0])  # the prismatic axis turned with link 1
    D = res["D"]
    # q1: z x (c - o1) = z x (0, 5/2, 0) = (-5/2, 0, 0), angular z; q2: (0,1,0), angular 0
    assert D[:, 0] == sp.Matrix([R(-5, 2), 0, 0, 0, 0, 1])
    assert D[:, 1] == sp.Matrix([0, 1, 0, 0, 0, 0])
    # text angles give the same result
    res_text = reference_analysis(one_arm(), {"q1": "pi/2", "q2": R(1, 2)})
    assert res_text["D"] == D and res_text["G"] == res["G"]


def test_general_angle_and_pi():
    # q1 = 2*atan(1/2): cos = 3/5, sin = 4/5; point (3,0,0) about (1,0,0) -> (1+6/5, 8/5, 0)
    res = reference_analysis(one_arm(), {"q1": (R(3, 5), R(4, 5))})
    assert res["points"]["c1"] == sp.Matrix([R(11, 5), R(8, 5), 0])
    res = reference_analysis(one_arm(), {"q1": "pi"})
    assert res["points"]["c1"] == sp.Matrix([-1, 0, 0])
    assert res["normals"]["c1"] == sp.Matrix([0, -1, 0])


def test_inner_link_base_and_arm_base_contacts():
    at = {"q1": (0, 1), "q2": R(1, 2)}
    inner = reference_analysis(one_arm("a1/1"), at)
    assert inner["points"]["c1"] == sp.Matrix([1, 2, 0])  # q2 does not move link 1
    assert inner["D"][:, 1] == sp.zeros(6, 1)
    assert inner["D"][:, 0] == sp.Matrix([-2, 0, 0, 0, 0, 1])
    for link in ("a1/0", "base"):
        fixed = reference_analysis(one_arm(link), at)
        assert fixed["D"] == sp.zeros(6, 2)
        assert fixed["points"]["c1"] == sp.Matrix([3, 0, 0])
        # the object can only spin about the fixed hard contact; both joints are free
        assert numbers(fixed) == {"Nm": 5, "Nc": 3, "Ni": 3, "Nr": 2}
        assert same_span(fixed["N_GT"], [sp.Matrix([0, 0, 0, 1, 0, 0]),
                                         sp.Matrix([0, 0, 3, 0, 1, 0]),
                                         sp.Matrix([0, -3, 0, 0, 0, 1])])  # fmt: skip


def test_frictionless_and_mixed_rows():
    model = one_arm(model="frictionless")
    res = reference_analysis(model, {"q1": (0, 1)})
    assert res["H"] == sp.Matrix([[-1, 0, 0, 0, 0, 0]])  # current normal (-1,0,0)
    assert res["Ni"] == 5


def test_missing_parameter_value_is_an_error():
    with pytest.raises(ValueError, match="L"):
        reference_analysis(case1("hard", "hard"))


def test_float_numbers_agree_on_paper_cases():
    for model, at in [
        (case1("hard", "hard"), {"L": 1}),
        (case1("soft", "soft"), {"L": 1}),
        (case2("hard"), {"L": 1}),
        (case2("complete"), {"L": 3}),
    ]:
        exact = reference_analysis(model, at)
        assert reference_numbers_float(model, at) == numbers(
            exact, ("Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh")
        )


# ---------------------------------------------------------------------- strategies


@settings(max_examples=100, deadline=None)
@given(rational_unit_vectors())
def test_unit_vectors_are_exactly_unit(v):
    assert len(v) == 3
    assert all(isinstance(x, int) or (isinstance(x, str) and "/" in x) for x in v)
    vec = [sp.Rational(x) for x in v]
    assert sum(x**2 for x in vec) == 1


@settings(max_examples=100, deadline=None)
@given(exact_angles())
def test_angles_text_matches_pair(angle):
    (c, s), text = angle
    assert c**2 + s**2 == 1
    assert angle_from_text(text) == (c, s)
    q = sp.sympify(text)
    assert sp.simplify(sp.cos(q) - c) == 0 and sp.simplify(sp.sin(q) - s) == 0


def _unit(v) -> bool:
    return sum(sp.Rational(x) ** 2 for x in v) == 1


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_strategies_produce_valid_models(data):
    model = data.draw(random_systems(with_parameter=data.draw(st.booleans())))
    arm_names = [a["name"] for a in model["arms"]]
    joints = [j for a in model["arms"] for j in a["joints"]]
    contact_names = [c["name"] for c in model["contacts"]]
    names = arm_names + [j["name"] for j in joints] + contact_names + model["parameters"]
    assert len(names) == len(set(names))
    assert arm_names == [f"a{i}" for i in range(1, len(arm_names) + 1)]
    assert [j["name"] for j in joints] == [f"q{i}" for i in range(1, len(joints) + 1)]
    assert contact_names == [f"c{i}" for i in range(1, len(contact_names) + 1)]
    for j in joints:
        assert _unit(j["axis"])
        assert j["type"] in ("revolute", "prismatic")
        assert j["type"] == "prismatic" or "point" in j
    sizes = {a["name"]: len(a["joints"]) for a in model["arms"]}
    for c in model["contacts"]:
        assert _unit(c["normal"])
        assert c["model"] in ("complete", "soft", "hard", "frictionless")
        if c["link"] != "base":
            arm, _, k = c["link"].partition("/")
            assert 0 <= int(k) <= sizes[arm]
    at, text = data.draw(random_configurations(model))
    assert set(at) == {j["name"] for j in joints} | set(model["parameters"])
    parsed = at_from_text(model, text)
    assert {k: tuple(v) if isinstance(v, tuple) else v for k, v in parsed.items()} == at


# --------------------------------------------------------- identities on random systems


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_identities_on_random_systems(data):
    model = data.draw(
        random_systems(max_arms=3, max_joints=3, max_contacts=3,
                       with_parameter=data.draw(st.booleans()))
    )  # fmt: skip
    at, text = data.draw(random_configurations(model))
    res = reference_analysis(model, at)
    r, m = res["r"], res["m"]
    assert res["Nm"] - res["Nh"] == 6 + r - m
    assert res["Nm"] == res["Nc"] + res["Nr"]
    assert res["Ni"] <= res["Nc"]
    Q = res["Q"]
    assert Q.shape == (m, 6 + r)
    for c in res["N_Q"]:
        assert Q * c == sp.zeros(m, 1)
    for c in res["N_GT"]:
        assert (res["H"] * res["G"].T) * c == sp.zeros(m, 1)
        assert Q * c.col_join(sp.zeros(r, 1)) == sp.zeros(m, 1)
    for c in res["N_D"]:
        assert (res["H"] * res["D"]) * c == sp.zeros(m, 1)
    # the current normals stay exactly unit, the rotations being exact
    for nvec in res["normals"].values():
        assert nvec.dot(nvec) == 1
    # the CLI text describes the same configuration
    again = reference_analysis(model, at_from_text(model, text))
    assert again["Q"] == Q


def test_rigid_motion_invariance():
    # rotating/translating a whole model (at home) by an exact rigid motion keeps numbers
    model = case2("hard")
    moved = copy.deepcopy(model)
    rot = sp.Matrix([[R(3, 5), R(-4, 5), 0], [R(4, 5), R(3, 5), 0], [0, 0, 1]])
    shift = sp.Matrix([1, -2, R(1, 3)])
    L = sp.Symbol("L", positive=True)

    def point(p):
        v = rot * sp.Matrix([sp.sympify(x, locals={"L": L}) for x in p]) + shift
        return [str(x) for x in v]

    def direction(d):
        return [str(x) for x in rot * sp.Matrix(d)]

    for arm in moved["arms"]:
        for j in arm["joints"]:
            j["axis"], j["point"] = direction(j["axis"]), point(j["point"])
    for c in moved["contacts"]:
        c["point"], c["normal"] = point(c["point"]), direction(c["normal"])
    keys = ("Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh")
    at = {"L": 2, "q2": (R(3, 5), R(4, 5)), "q7": (0, -1)}
    assert numbers(reference_analysis(moved, at), keys) == numbers(
        reference_analysis(model, at), keys
    )
