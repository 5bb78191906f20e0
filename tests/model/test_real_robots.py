"""Real robots at their real sizes: two Franka Panda arms holding a box and an
Allegro-like four-finger hand holding a sphere (the shipped ``panda-two-arm-box`` and
``allegro-hand-sphere``, both given by DH tables). Their numbers, generic and at
exact configurations, are checked against the independent analysis of the same
systems written joint by joint (``independent.py``, the DH frames of ``test_dh``);
both are drawn; a locus on a slice of each (most joints at exact values) has every
component's numbers recomputed independently at its witness."""

from __future__ import annotations

from types import SimpleNamespace

import pytest
import sympy as sp
from independent import at_from_text, reference_analysis, reference_numbers_algebraic
from test_dh import as_joints

import coopkin_sym
from coopkin_sym.model.examples import example_path
from coopkin_sym.model.trees import read_file

GENERIC = {"Nm": 8, "Nc": 6, "Ni": 0, "Nr": 2, "Ng": 6, "Nd": 0, "Nh": 0}
HAND_GENERIC = {"Nm": 6, "Nc": 3, "Ni": 0, "Nr": 3, "Ng": 10, "Nd": 3, "Nh": 0}

#: both arms reaching for the box between them (exact angles near Franka's
#: "ready" pose, the elbows bent)
PANDA_BENT = ("l2=2*atan(1/5),l4=2*atan(-2),l6=2*atan(2),l7=2*atan(2/5),"
              "r2=2*atan(1/5),r4=2*atan(-2),r6=2*atan(2),r7=2*atan(2/5)")
#: the fingers curled round the sphere, the thumb turned to oppose them
HAND_BENT = ("i1=2*atan(1/2),i2=2*atan(1/3),i3=2*atan(1/3),m1=2*atan(1/2),"
             "m2=2*atan(1/3),m3=2*atan(1/3),r1=2*atan(1/2),r2=2*atan(1/3),"
             "r3=2*atan(1/3),t0=pi/2,t2=2*atan(1/3),t3=2*atan(1/3)")


def _joints(name: str) -> dict:
    return as_joints(read_file(example_path(name)))


def _independent(name: str, at: str) -> dict:
    raw = _joints(name)
    reference = reference_analysis(raw, at_from_text(raw, at))
    return {k: reference[k] for k in GENERIC}


def test_two_pandas_have_the_numbers_of_two_redundant_arms_in_a_closed_chain():
    system = coopkin_sym.load("panda-two-arm-box")
    assert [len(arm.joints) for arm in system.model.arms] == [7, 7]
    # 14 joints, 6 object twist components, 2 x 6 constraints: every object twist
    # is reached, and each arm keeps one self-motion (its seventh joint)
    assert system.analyze(generic=True).numbers.as_dict() == GENERIC


@pytest.mark.parametrize("at, numbers", [
    # at home both arms stand straight up: joints 1, 3 and 5 of each arm turn about
    # one vertical line (one more self-motion per arm), the box loses a motion
    ("", {"Nm": 9, "Nc": 5, "Ni": 0, "Nr": 4, "Ng": 6, "Nd": 2, "Nh": 1}),
    (PANDA_BENT, GENERIC),
    # joints 1 and 3 of the left arm in line (l2 = 0): the seventh joint makes up
    # for it, the numbers stay generic
    ("l4=2*atan(-2),l6=2*atan(2),r2=2*atan(1/5),r4=2*atan(-2),r6=2*atan(2)", GENERIC),
    ("l2=2*atan(1/5),l4=2*atan(-2),l6=2*atan(2),r2=2*atan(1/5),r4=2*atan(-2),r6=0",
     GENERIC),
])
def test_two_pandas_at_exact_configurations_agree_with_the_independent_analysis(
        at, numbers):
    ours = coopkin_sym.load("panda-two-arm-box").analyze(at or None).numbers.as_dict()
    assert ours == numbers == _independent("panda-two-arm-box", at)


def test_the_panda_grasp_points_are_the_published_tcp():
    """Frame 7 of Franka's table, 0.107 m flange and 0.1034 m hand: at home the
    left grasp point is at x = 0.088 m, z = 0.333 + 0.316 + 0.384 - 0.2104 m."""
    points = {c["name"]: c["point"] for c in _joints("panda-two-arm-box")["contacts"]}
    assert [sp.Rational(x) for x in points["grip_left"]] == [
        sp.Rational("0.088"), 0, sp.Rational("0.333") + sp.Rational("0.316")
        + sp.Rational("0.384") - sp.Rational("0.2104")]
    # the right arm stands 1 m away, turned by pi: its grasp point mirrors the left's
    assert [sp.Rational(x) for x in points["grip_right"]] == [
        1 - sp.Rational("0.088"), 0, sp.Rational(8226, 10000)]


def test_the_hand_has_four_fingers_of_four_joints():
    system = coopkin_sym.load("allegro-hand-sphere")
    assert [len(arm.joints) for arm in system.model.arms] == [4, 4, 4, 4]
    assert {c.model for c in system.model.contacts} == {"soft"}
    # 16 joints, 4 soft fingers (4 constraints each): Q has full rank 16; the three
    # flexion joints of each long finger move its tip in one plane, so with the
    # fingertip held each rolls it (Nr = 3) and the sphere keeps three motions
    assert system.analyze(generic=True).numbers.as_dict() == HAND_GENERIC


@pytest.mark.parametrize("at, numbers", [
    # straight fingers: the flexion axes of each finger are parallel and its tip on
    # their plane, so almost every joint motion leaves the tips where they are
    ("", {"Nm": 12, "Nc": 1, "Ni": 0, "Nr": 11, "Ng": 10, "Nd": 11, "Nh": 6}),
    (HAND_BENT, HAND_GENERIC),
    (HAND_BENT.replace("t3=2*atan(1/3)", "t1=2*atan(1/5),t3=2*atan(1/3)")
     + ",i0=2*atan(1/7),r0=2*atan(-1/7)", HAND_GENERIC),
    # the index finger straight beyond its first flexion joint: one motion of the
    # sphere less, one rolling of that fingertip more
    (HAND_BENT.replace("i2=2*atan(1/3),i3=2*atan(1/3)", "i2=0,i3=0"),
     {"Nm": 6, "Nc": 2, "Ni": 0, "Nr": 4, "Ng": 10, "Nd": 4, "Nh": 0}),
])
def test_the_hand_at_exact_configurations_agrees_with_the_independent_analysis(
        at, numbers):
    ours = coopkin_sym.load("allegro-hand-sphere").analyze(at or None).numbers.as_dict()
    assert ours == numbers == _independent("allegro-hand-sphere", at)


@pytest.mark.slow          # the hand's whole generic analysis: about 40 s
def test_the_generic_blocks_of_the_hand_over_the_budget_are_refused_before_written():
    """The hand's generic C12 (24,440 terms in an entry) and C22 (a bound of 7,063,244)
    are over the term budget: both are refused with their sizes before anything is
    written out as SymPy (nor expanded); C11 and C23 are kept, and the factored form
    of C22 still gives each finger's small map."""
    a = coopkin_sym.load("allegro-hand-sphere").analyze(generic=True)
    blocks, omitted = a.available_blocks()
    assert sorted(omitted) == ["C12", "C22"]
    assert "C12: the coordinated object motions would have entries of 24,440 terms, " \
        "over the budget of 20,000" in omitted["C12"]
    assert "C22: the coordinated joint motions would have entries of up to about " \
        "7,063,244 terms, over the budget of 20,000" in omitted["C22"]
    assert "_twists" not in a.__dict__ and "_unbounded_coordinated" not in a.__dict__
    assert blocks["C11"].shape == (6, 0) and blocks["C23"].shape == (16, 3)
    assert str(blocks["C23"][1, 0]) == "2848*t_i2**2*t_i3 + 2848*t_i3"
    text = coopkin_sym.analysis_text(a)
    assert "C12: not shown: C12: the coordinated object motions would have entries " \
        "of 24,440 terms" in text
    assert "K_thumb (rows: joints; columns: v_x, v_y, v_z, w_x, w_y, w_z)" in text


@pytest.mark.parametrize("name, at", [("panda-two-arm-box", PANDA_BENT),
                                      ("allegro-hand-sphere", HAND_BENT)])
def test_the_real_robots_are_drawn(name, at, tmp_path):
    """The pictures (two arms reaching for the box between them; four curled
    fingers) are written whole."""
    out = tmp_path / f"{name}.png"
    coopkin_sym.save_picture(coopkin_sym.load(name), out, at=at)
    assert out.stat().st_size > 10_000


def _cos_sin(text: str) -> tuple:
    """Exact cosine and sine (radicals) of a witness's angle text."""
    angle = sp.sympify(text)
    if (angle / sp.pi).is_Rational and (angle / sp.pi) % 2 == 1:
        return sp.Integer(-1), sp.Integer(0)
    t = sp.radsimp(sp.tan(angle / 2))
    return sp.radsimp((1 - t**2) / (1 + t**2)), sp.radsimp(2 * t / (1 + t**2))


def _check_witnesses(name: str, locus) -> None:
    raw = _joints(name)
    for component in locus.components:
        point = (dict(component.witness) if component.witness is not None
                 else component.algebraic_witness["point"])
        at = {k: _cos_sin(v) for k, v in point.items()}
        assert reference_numbers_algebraic(raw, at) == component.numbers, component
        assert component.numbers != locus.generic


PANDA_SLICE = ("l1=0,l2=2*atan(1/5),l3=0,l7=2*atan(2/5),r1=0,r2=2*atan(1/5),r3=0,"
               "r4=2*atan(-2),r5=0,r6=2*atan(2),r7=2*atan(2/5)")
HAND_SLICE = ("i0=0,i3=2*atan(1/3),m0=0,m1=2*atan(1/2),m2=2*atan(1/3),m3=2*atan(1/3),"
              "r0=0,r1=2*atan(1/2),r2=2*atan(1/3),r3=2*atan(1/3),t0=pi/2,t1=0,"
              "t2=2*atan(1/3),t3=2*atan(1/3)")


def _found(locus) -> dict:
    """The components of a locus by their equations: kind and numbers."""
    return {tuple(str(e) for e in c.equations): (c.kind, c.numbers)
            for c in locus.components}


def test_the_locus_of_the_left_panda_elbow_and_wrist_checked_at_its_witnesses():
    system = coopkin_sym.load("panda-two-arm-box")
    locus = system.locus(PANDA_SLICE + ",l5=0", free=["l4", "l6"])
    assert locus.generic == GENERIC
    # a curve of the left arm's elbow angle (any wrist angle) and a point off it where
    # the arm loses a direction: the box loses one motion (Nc 6 -> 5), the arm gains
    # one self-motion
    lost = {"Nm": 8, "Nc": 5, "Ni": 0, "Nr": 3, "Ng": 6, "Nd": 1, "Nh": 0}
    found = _found(locus)
    assert found[("38500*t_l4**2 - 152717*t_l4 - 38500",)] == ("hypersurface", lost)
    assert found[("11*t_l6**2 + 175*t_l6 + 11", "t_l4")] == ("isolated", lost)
    _check_witnesses("panda-two-arm-box", locus)
    # off the locus, on the same slice, the independent analysis finds the generic ones
    at = PANDA_SLICE + ",l5=0,l4=2*atan(1/3),l6=2*atan(1/7)"
    assert system.analyze(at).numbers.as_dict() == GENERIC == _independent(
        "panda-two-arm-box", at)


#: every joint of both arms bent (the left shoulder and elbow l2, l4 free)
PANDA_SHOULDER_SLICE = ("l1=2*atan(1/3),l3=2*atan(-1/2),l5=2*atan(1/5),l6=2*atan(2/3),"
                        "l7=2*atan(1/7),r1=2*atan(-1/3),r2=2*atan(1/4),r3=2*atan(1/2),"
                        "r4=2*atan(-2/3),r5=2*atan(1/6),r6=2*atan(3/4),r7=2*atan(-1/5)")


def test_the_locus_of_the_left_panda_shoulder_and_elbow_is_certified():
    """Its certificate factors polynomials whose factors have coefficients beyond a C
    long (python-flint's own factor fails to sort them): certified complete, the
    components with a rational witness checked there."""
    locus = coopkin_sym.load("panda-two-arm-box").locus(
        PANDA_SHOULDER_SLICE, free=["l2", "l4"], certify=True)
    assert locus.certified
    lost = {"Nm": 8, "Nc": 5, "Ni": 0, "Nr": 3, "Ng": 6, "Nd": 1, "Nh": 0}
    cubic = "236766750*t_l4**3 - 2380112295*t_l4**2 + 5451054946*t_l4 + 1481497600"
    assert _found(locus) == {("s_l2", cubic): ("hypersurface", lost),
                             ("s_l2", "t_l4"): ("isolated", lost),
                             ("t_l2", "t_l4"): ("isolated", lost),
                             (cubic, "t_l2"): ("isolated", lost)}
    rational = [c for c in locus.components if c.witness is not None]
    assert len(rational) == 2
    _check_witnesses("panda-two-arm-box", SimpleNamespace(components=rational,
                                                          generic=locus.generic))


@pytest.mark.slow   # about 10 s
def test_the_locus_of_the_left_panda_elbow_and_wrists_checked_at_its_witnesses():
    locus = coopkin_sym.load("panda-two-arm-box").locus(PANDA_SLICE,
                                                        free=["l4", "l5", "l6"])
    assert len(locus.components) >= 9
    _check_witnesses("panda-two-arm-box", locus)


@pytest.mark.slow
def test_the_locus_of_the_index_finger_checked_at_its_witnesses():
    system = coopkin_sym.load("allegro-hand-sphere")
    locus = system.locus(HAND_SLICE, free=["i1", "i2"])
    assert locus.generic == HAND_GENERIC
    # a curve of the index finger's two flexion angles (and its pieces with one of
    # them at pi) where the sphere gains a motion (Nc 3 -> 4), and two pairs of points
    # where the fingertip rolls once more (Nr 3 -> 4)
    gains = {"Nm": 7, "Nc": 4, "Ni": 0, "Nr": 3, "Ng": 10, "Nd": 3, "Nh": 1}
    rolls = {"Nm": 7, "Nc": 3, "Ni": 0, "Nr": 4, "Ng": 10, "Nd": 4, "Nh": 1}
    found = _found(locus)
    assert found[("s_i1", "10462791*t_i2**2 - 38076776*t_i2 - 18094791")] == (
        "hypersurface", gains)
    assert found[("16*t_i1**2 + 75*t_i1 + 16", "-32*t_i1 + 13*t_i2 - 135")] == (
        "isolated", rolls)
    assert found[("16*t_i1**2 - 75*t_i1 + 16", "-32*t_i1 + 13*t_i2 + 15")] == (
        "isolated", rolls)
    assert sorted(kind for kind, _ in found.values())[:3] == ["hypersurface"] * 3
    _check_witnesses("allegro-hand-sphere", locus)
    at = HAND_SLICE + ",i1=2*atan(1/3),i2=2*atan(1/7)"
    assert system.analyze(at).numbers.as_dict() == HAND_GENERIC == _independent(
        "allegro-hand-sphere", at)


def _readme_runs() -> list[list[str]]:
    """The commands of the README's real-robot example, each with the lines shown."""
    from pathlib import Path

    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text()
    block = readme.split("## Real robots")[1].split("```console\n")[1].split("```")[0]
    return [part.splitlines() for part in block.split("$ coopkin ")[1:]]


def test_the_readme_shows_two_panda_commands():
    assert [run[0] for run in _readme_runs()] == ["analyze panda-two-arm-box --generic",
                                                 "analyze panda-two-arm-box"]


@pytest.mark.parametrize("k", [pytest.param(0, marks=pytest.mark.slow),  # about 10 s
                               1])
def test_the_readme_shows_what_the_commands_print_for_the_pandas(k):
    """The README's real-robot example: the command runs and prints the lines shown."""
    from typer.testing import CliRunner

    from coopkin_sym.cli import app

    command, *shown = _readme_runs()[k]
    shown = [line for line in shown if line != "..."]      # a line "...": lines left out
    result = CliRunner().invoke(app, command.split())
    assert result.exit_code == 0, result.output
    assert shown and all(line in result.stdout.splitlines() for line in shown), (
        command, shown)


def _robot_file(relative: str):
    """A robot file of the optional ``example-robot-data`` package (the ``robots``
    extra); the test is skipped without it."""
    from importlib import metadata

    try:
        files = metadata.distribution("example-robot-data").files or []
    except metadata.PackageNotFoundError:
        pytest.skip("example-robot-data is not installed (pip install coopkin_sym[robots])")
    found = [f for f in files if str(f).endswith(relative)]
    if not found:
        pytest.skip(f"example-robot-data has no {relative}")
    return found[0].locate()


#: the URDF Panda's joints for the DH model's
_URDF_NAMES = {f"{side[0]}{k}": f"{side[0]}_panda_joint{k}" for side in ("left", "right")
               for k in range(1, 8)}


def _urdf_at(at: str) -> str:
    out = []
    for item in filter(None, at.split(",")):
        name, value = item.split("=", 1)
        out.append(f"{_URDF_NAMES[name]}={value}")
    return ",".join(out)


@pytest.mark.parametrize("at", [
    "", PANDA_BENT,
    "l1=2*atan(1/3),l2=2*atan(-1/2),l3=pi/2,l4=2*atan(-3),l5=2*atan(1/4),l6=pi,"
    "r2=2*atan(1/5),r4=-pi/2,r6=2*atan(2)",
    "l4=2*atan(-2),l6=2*atan(2),r2=2*atan(1/5),r4=2*atan(-2),r6=2*atan(2)",
])
@pytest.mark.slow   # run by CI's slow step, which installs the robots extra
def test_the_panda_urdf_of_example_robot_data_gives_the_dh_model(at, tmp_path):
    """The Panda's URDF as example-robot-data ships it, read by ``urdf:`` up to its
    flange (panda_link8) with the grasp point 0.1034 m beyond, gives exactly the
    ``Q`` (and so every number) of the shipped DH model, its frames being Franka's."""
    urdf = _robot_file("panda_description/urdf/panda.urdf")
    path = tmp_path / "pandas.yaml"
    path.write_text(f"""name: two Pandas from URDF
arms:
  - {{name: left, urdf: "{urdf}", tip: panda_link8, prefix: l_}}
  - {{name: right, urdf: "{urdf}", tip: panda_link8, prefix: r_,
     base: {{xyz: [1, 0, 0], rpy: [0, 0, pi]}}}}
contacts:
  - {{name: grip_left, link: left/panda_link8, frame: link, point: [0, 0, 0.1034],
     model: complete}}
  - {{name: grip_right, link: right/panda_link8, frame: link, point: [0, 0, 0.1034],
     model: complete}}
""")
    from_urdf = coopkin_sym.load(str(path))
    from_dh = coopkin_sym.load("panda-two-arm-box")
    assert [j.name for j in from_urdf.model.joints] == list(_URDF_NAMES.values())
    assert from_urdf.model.contacts == from_dh.model.contacts
    ours, theirs = from_dh.analyze(at or None), from_urdf.analyze(_urdf_at(at) or None)
    assert ours.Q == theirs.Q and ours.numbers == theirs.numbers
    if not at:
        assert from_urdf.analyze(generic=True).numbers.as_dict() == GENERIC


#: the Allegro URDF's joints (joint_0.0 .. joint_15.0, made names) for the DH model's
_HAND_NAMES = {f"{f[0]}{k}": f"{f[0]}_joint_{4 * i + k}_0"
               for i, f in enumerate(("index", "middle", "ring", "thumb")) for k in range(4)}


@pytest.mark.parametrize("at, numbers", [
    ("", {"Nm": 12, "Nc": 1, "Ni": 0, "Nr": 11, "Ng": 10, "Nd": 11, "Nh": 6}),
    (HAND_BENT, HAND_GENERIC),
    (HAND_BENT.replace("i2=2*atan(1/3),i3=2*atan(1/3)", "i2=0,i3=0"),
     {"Nm": 6, "Nc": 2, "Ni": 0, "Nr": 4, "Ng": 10, "Nd": 4, "Nh": 0}),
])
@pytest.mark.slow   # run by CI's slow step, which installs the robots extra
def test_the_allegro_urdf_of_example_robot_data_has_the_numbers_of_the_model(
        at, numbers, tmp_path):
    """The Allegro Hand's URDF as example-robot-data ships it (its 5 degree splay and
    the thumb's mounting snapped within 1e-3 rad, where the shipped model takes
    2*atan(1/23)), each finger read to its tip link, the soft contacts' normals on the
    pads' side: the numbers of the shipped model, generic and at exact configurations."""
    urdf = _robot_file("allegro_hand_description/urdf/allegro_right_hand.urdf")
    arms = "".join(
        f"  - {{name: {finger}, urdf: \"{urdf}\", tip: link_{tip}.0_tip, prefix: "
        f"{finger[0]}_, snap: 1e-3}}\n"
        for finger, tip in (("index", 3), ("middle", 7), ("ring", 11), ("thumb", 15)))
    contacts = "".join(
        f"  - {{name: tip_{finger}, link: {finger}/link_{tip}.0_tip, frame: link, "
        f"point: [0, 0, 0], normal: [1, 0, 0], model: soft}}\n"
        for finger, tip in (("index", 3), ("middle", 7), ("ring", 11), ("thumb", 15)))
    path = tmp_path / "hand.yaml"
    path.write_text(f"name: Allegro hand from URDF\narms:\n{arms}contacts:\n{contacts}")
    hand = coopkin_sym.load(str(path))
    assert [j.name for j in hand.model.joints] == list(_HAND_NAMES.values())
    assert len(hand.model.snapped) == 4 and all(s.error < 1e-3 for s in hand.model.snapped)
    names = dict(item.split("=", 1) for item in filter(None, at.split(",")))
    ours = hand.analyze(",".join(f"{_HAND_NAMES[k]}={v}" for k, v in names.items())
                        or None)
    assert ours.numbers.as_dict() == numbers
    assert hand.analyze(generic=True).numbers.as_dict() == HAND_GENERIC
