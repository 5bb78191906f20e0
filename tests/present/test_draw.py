"""Pictures: the artists each part of a system gets, motions, files, errors."""

from __future__ import annotations

import math

import pytest

pytest.importorskip("matplotlib")

import matplotlib.image  # noqa: E402
from typer.testing import CliRunner  # noqa: E402

from coopkin_sym import load  # noqa: E402
from coopkin_sym.cli import app  # noqa: E402
from coopkin_sym.present.draw import DrawError, draw_system, parse_motion, save_picture  # noqa: E402

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def gids(fig, prefix: str) -> list[str]:
    """The gids of the figure's artists that start with ``prefix``, sorted."""
    ax = fig.axes[0]
    return sorted(a.get_gid() for a in ax.get_children()
                  if (a.get_gid() or "").startswith(prefix))


def artist(fig, gid: str):
    (found,) = [a for a in fig.axes[0].get_children() if a.get_gid() == gid]
    return found


def points_of(line) -> list[tuple[float, float, float]]:
    """The vertices of a 3D line, without the NaN breaks between segments."""
    xs, ys, zs = line.get_data_3d()
    return [(float(x), float(y), float(z)) for x, y, z in zip(xs, ys, zs, strict=True)
            if not math.isnan(x)]


def texts(fig) -> list[str]:
    return [t.get_text() for t in fig.axes[0].texts]


# --- what is drawn -----------------------------------------------------------------


def test_case1_one_line_per_link_one_marker_per_contact():
    fig = draw_system(load("paper-case1-hard"))
    assert gids(fig, "link:") == ["link:a1/1", "link:a2/1"]
    assert gids(fig, "contact:") == ["contact:c1", "contact:c2"]
    assert gids(fig, "normal:") == ["normal:c1", "normal:c2"]
    assert gids(fig, "joint:") == ["joint:q1", "joint:q2"]
    assert gids(fig, "motion:") == []
    assert gids(fig, "object") == ["object"]
    assert gids(fig, "ground") == ["ground"]


def test_links_run_from_joint_points_to_contacts_drawn_at_l_1():
    fig = draw_system(load("paper-case1-hard"))
    # link 1 of a1: from its joint at the origin to c1 = (0, L, 0), L drawn at 1
    assert points_of(artist(fig, "link:a1/1")) == [(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
    assert points_of(artist(fig, "link:a2/1")) == [(1.0, 0.0, 0.0), (1.0, 1.0, 0.0)]
    assert "L symbolic, drawn at 1" in fig.axes[0].get_title()


def test_configuration_and_parameter_values_are_used():
    fig = draw_system(load("paper-case1-hard"), at="q1=-pi/2,q2=-pi/2,L=2")
    # both links on the contact line (the x axis)
    assert points_of(artist(fig, "link:a1/1")) == [(0.0, 0.0, 0.0), (2.0, 0.0, 0.0)]
    assert points_of(artist(fig, "link:a2/1")) == [(2.0, 0.0, 0.0), (4.0, 0.0, 0.0)]
    title = fig.axes[0].get_title()
    assert "drawn at 1" not in title
    assert "at q1=-pi/2,q2=-pi/2,L=2" in title
    assert "Nm=3 Nc=3 Ni=1 Nr=0" in title


def test_case2_every_link_of_both_scara_robots():
    fig = draw_system(load("paper-case2-hard"))
    assert gids(fig, "link:") == [f"link:s{i}/{k}" for i in (1, 2) for k in (1, 2, 3, 4)]
    assert gids(fig, "joint:") == [f"joint:q{k}" for k in range(1, 9)]
    # link 4 of s1 (moved by the prismatic q4) carries c1 = (L, L, L)
    assert points_of(artist(fig, "link:s1/4")) == [(1.0, 1.0, 0.0), (1.0, 1.0, 1.0)]


def test_contact_models_have_their_own_markers():
    fig = draw_system(load("paper-case1-soft-hard"))
    assert artist(fig, "contact:c1").get_marker() == "D"   # soft finger
    assert artist(fig, "contact:c2").get_marker() == "o"   # hard finger
    fig = draw_system(load("paper-case2-complete"))
    assert artist(fig, "contact:c1").get_marker() == "s"   # complete constraint
    legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert "complete constraint contact" in legend
    assert "arm s1" in legend and "arm s2" in legend
    assert "prismatic joint (axis)" in legend and "revolute joint (axis)" in legend


MIXED = {
    "name": "palm and finger", "parameters": ["L"],
    "arms": [
        {"name": "f", "joints": [
            {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]},
            {"name": "d2", "type": "prismatic", "axis": [1, 0, 0]}]},
    ],
    "contacts": [
        {"name": "tip", "link": "f/2", "point": ["2*L", 0, 0], "normal": [-1, 0, 0],
         "model": "frictionless"},
        {"name": "palm", "link": "f/0", "point": [0, "L", 0], "model": "complete"},
        {"name": "table", "link": "base", "point": ["L", "L", "-L"], "model": "hard"},
    ],
}


def test_base_link_contacts_ground_contacts_and_a_prismatic_joint_without_point():
    fig = draw_system(load(MIXED))
    # the base link of f is drawn because the palm contact is on it
    assert gids(fig, "link:") == ["link:base@table", "link:f/0", "link:f/1", "link:f/2"]
    assert points_of(artist(fig, "link:f/0")) == [(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
    assert gids(fig, "contact:") == ["contact:palm", "contact:table", "contact:tip"]
    assert gids(fig, "normal:") == ["normal:tip"]    # only contacts with a normal
    assert artist(fig, "contact:tip").get_marker() == "^"


# --- motions -----------------------------------------------------------------------


def test_coordinated_motion_arrows_and_exact_rates():
    fig = draw_system(load("paper-case1-hard"), motion=("coordinated", 1))
    assert gids(fig, "motion:") == [
        "motion:rate-head:q1", "motion:rate-head:q2", "motion:rate:q1", "motion:rate:q2",
        "motion:translation", "motion:velocity:c1", "motion:velocity:c2"]
    # C22 = (-1, -1)^T: both joints at the same rate, labelled by their exact ratios
    assert "q1: -1" in texts(fig) and "q2: -1" in texts(fig)
    assert "translate along x" in fig.axes[0].get_title()


def test_indeterminate_motion_is_the_line_through_the_contacts():
    fig = draw_system(load("paper-case1-hard"), motion="indeterminate:1")
    assert gids(fig, "motion:") == ["motion:axis", "motion:spin", "motion:spin-head"]
    axis = points_of(artist(fig, "motion:axis"))
    # C11 = (0, 0, L, -1, 0, 0)^T: rotation about the line y = L, z = 0 through c1, c2
    assert {(y, z) for _, y, z in axis} == {(1.0, 0.0)}
    assert "rotate about the line through c1 and c2" in fig.axes[0].get_title()


def test_redundant_motion_moves_only_its_joint():
    fig = draw_system(load("paper-case2-hard"), motion=("redundant", 1))
    assert gids(fig, "motion:") == ["motion:rate-head:q3", "motion:rate:q3"]
    fig = draw_system(load("paper-case2-hard"), motion=("redundant", 2))
    assert gids(fig, "motion:") == ["motion:rate-head:q6", "motion:rate:q6"]


def test_prismatic_rates_are_straight_arrows():
    a = load("paper-case2-complete").analyze()
    k = next(j for j in range(a.C22.cols) if a.C22[4, j] != 0)   # a column moving q5
    fig = draw_system(a, motion=("coordinated", k + 1))
    rate = artist(fig, "motion:rate:q5")
    assert type(rate).__name__ == "Line3DCollection"             # a quiver arrow
    (label,) = [t for t in texts(fig) if "q5: " in t]
    assert set(label.replace(",", " ").split()) & {"1", "-1", "1/2", "-1/2"} or "/" in label


def test_generic_analysis_is_drawn_at_home_and_says_so():
    a = load("paper-case1-hard").analyze(generic=True)
    fig = draw_system(a, motion="coordinated:1")
    title = fig.axes[0].get_title()
    assert "q1, q2 symbolic, drawn at home (0)" in title
    assert "L symbolic, drawn at 1" in title
    assert "motion:translation" in gids(fig, "motion:")


# --- errors ------------------------------------------------------------------------


@pytest.mark.parametrize("motion, message", [
    (("coordinated", 2), "motion: there is no coordinated motion 2: this system has 1 "
                         "(the columns of C12, C22)"),
    ("coordinated:0", "motion: there is no coordinated motion 0: this system has 1"),
    ("indeterminate:2", "motion: there is no indeterminate motion 2: this system has 1 "
                        "(the columns of C11)"),
    ("redundant:1", "motion: this system has no redundant motion here (C23 empty)"),
    ("sideways:1", "motion: unknown kind 'sideways' (expected coordinated, "
                   "indeterminate, redundant)"),
    ("coordinated:one", "motion: the index must be a whole number, got 'one'"),
    ("coordinated", "motion: expected KIND:K (e.g. coordinated:1), got 'coordinated'"),
    (("coordinated", 1, 2), "motion: expected (kind, k) or 'kind:k'"),
])
def test_bad_motion_is_a_clear_error(motion, message):
    a = load("paper-case1-hard").analyze()
    with pytest.raises(DrawError) as info:
        draw_system(a, motion=motion)
    assert str(info.value).startswith(message)


def test_motion_that_the_system_lacks():
    a = load("paper-case1-soft").analyze()
    with pytest.raises(DrawError, match=r"^motion: this system has no indeterminate motion "
                                        r"here \(C11 empty\)$"):
        parse_motion("indeterminate:1", a)
    assert parse_motion("coordinated:1", a) == ("coordinated", 1)


def test_at_with_an_analysis_and_a_flat_axes_are_errors():
    a = load("paper-case1-hard").analyze()
    with pytest.raises(DrawError, match="^at: this analysis already has its configuration"):
        draw_system(a, at="q1=pi/2")
    from matplotlib.figure import Figure

    flat = Figure().add_subplot()
    with pytest.raises(DrawError, match=r"^ax: a 3D axes is needed"):
        draw_system(a, ax=flat)


def test_draws_into_a_given_3d_axes():
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.add_subplot(1, 2, 2, projection="3d")
    assert draw_system("paper-case1-soft", ax=ax, title="my title") is fig
    assert ax.get_title().splitlines()[0] == "my title"
    assert len([a for a in ax.get_children() if a.get_gid() == "link:a1/1"]) == 1


# --- files -------------------------------------------------------------------------


def test_save_picture_writes_a_valid_png(tmp_path):
    out = save_picture(load("paper-case2-hard"), tmp_path / "case2.png",
                       motion="indeterminate:1", dpi=100)
    assert out == tmp_path / "case2.png"
    assert out.read_bytes()[:8] == PNG_SIGNATURE
    image = matplotlib.image.imread(out)
    assert image.shape == (750, 1050, 4)          # 10.5 x 7.5 inches at 100 dpi
    assert sorted(p.name for p in tmp_path.iterdir()) == ["case2.png"]


def test_save_picture_other_formats(tmp_path):
    save_picture("paper-case1-hard", tmp_path / "a.svg", at="L=3")
    assert (tmp_path / "a.svg").read_text(encoding="utf-8").lstrip().startswith("<?xml")
    save_picture("paper-case1-hard", tmp_path / "a.pdf")
    assert (tmp_path / "a.pdf").read_bytes()[:5] == b"%PDF-"


def test_save_picture_errors_write_nothing(tmp_path):
    with pytest.raises(DrawError, match=r"unknown picture format '\.txt'"):
        save_picture("paper-case1-hard", tmp_path / "a.txt")
    with pytest.raises(DrawError, match="no such directory"):
        save_picture("paper-case1-hard", tmp_path / "missing" / "a.png")
    with pytest.raises(DrawError, match="no coordinated motion 3"):
        save_picture("paper-case1-hard", tmp_path / "a.png", motion="coordinated:3")
    assert list(tmp_path.iterdir()) == []


# --- command -----------------------------------------------------------------------

runner = CliRunner()


def test_cli_draw_writes_the_picture(tmp_path):
    out = tmp_path / "system.png"
    result = runner.invoke(app, ["draw", "paper-case2-hard", "--motion", "coordinated:1",
                                 "--at", "L=2", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert result.stdout == f"wrote {out}\n"
    assert out.read_bytes()[:8] == PNG_SIGNATURE


def test_cli_draw_ellipsoid(tmp_path):
    out = tmp_path / "ellipse.png"
    result = runner.invoke(app, ["draw", "planar-two-fingers", "--ellipsoid", "--at",
                                 "q2=-2*atan(1/2),q4=2*atan(1/2)", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert out.read_bytes()[:8] == PNG_SIGNATURE


@pytest.mark.parametrize("args, message", [
    (["paper-case1-hard", "--motion", "indeterminate:2"],
     "coopkin: error: motion: there is no indeterminate motion 2: this system has 1 "
     "(the columns of C11)\n"),
    (["paper-case1-hard", "--at", "q1=1"], "coopkin: error: --at q1: angle '1' is "
                                           "not exact"),
    (["no-such-model"], "coopkin: error: no-such-model: no such file"),
])
def test_cli_draw_errors(tmp_path, args, message):
    out = tmp_path / "system.png"
    result = runner.invoke(app, ["draw", *args, "-o", str(out)])
    assert result.exit_code == 2
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    assert result.stderr.startswith(message)
    assert list(tmp_path.iterdir()) == []


def test_pictures_get_the_permissions_of_a_plain_file(tmp_path):
    import os
    import stat

    plain = tmp_path / "plain.txt"
    plain.write_text("x")
    out = save_picture(load("paper-case1-hard"), tmp_path / "case1.png")
    assert stat.S_IMODE(os.stat(out).st_mode) == stat.S_IMODE(os.stat(plain).st_mode)


def test_a_legend_of_many_arms_names_twelve_and_counts_the_others():
    from coopkin_sym.model.builders import arm_cell
    from coopkin_sym.present.draw import LEGEND_ARMS

    fig = draw_system(load(arm_cell(30, 2)), labels=False)
    texts = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    arms = [t for t in texts if t.startswith("arm a")]
    assert arms == [f"arm a{k}" for k in range(1, LEGEND_ARMS)]
    assert "19 more arms" in texts
    small = draw_system(load(arm_cell(12, 2)), labels=False)
    assert sum(t.get_text().startswith("arm a") for t in
               small.axes[0].get_legend().get_texts()) == 12


def test_too_many_names_are_left_out_and_said():
    """Over MAX_NAME_LABELS names (joints and contacts) the labels would cover the
    picture: none is drawn, and a note says how many there were."""
    from coopkin_sym.errors import OutputSkipped
    from coopkin_sym.model.builders import arm_cell

    with pytest.warns(OutputSkipped, match="name labels left out: 240 names"):
        fig = draw_system(load(arm_cell(60, 3)))
    assert not [t for t in fig.axes[0].texts if (t.get_gid() or "").startswith("label:")]
    fig = draw_system(load(arm_cell(10, 3)))           # 40 names: drawn
    assert len([t for t in fig.axes[0].texts
                if (t.get_gid() or "").startswith("label:")]) > 20


def test_an_irrational_angle_is_named_rounded_in_the_title_when_long():
    """q1 = -pi/6 (tan(q1/2) = -2 + sqrt(3)) is short: written as given. A root of a
    quartic is written rounded, and the title says so."""
    from coopkin_sym import load
    from coopkin_sym.analysis.numbers import Numbers
    from coopkin_sym.present.draw import draw_system
    from coopkin_sym.present.draw_inputs import at_algebraic_witness

    system = load("paper-case1-hard")
    fig = draw_system(system, at="q1=-pi/6,q2=pi/6,L=1")
    title = fig.axes[0].get_title()
    n = system.analyze("q1=-pi/6,q2=pi/6,L=1").numbers
    assert f"at q1=-pi/6,q2=pi/6,L=1   Nm={n.Nm} Nc={n.Nc} Ni={n.Ni} Nr={n.Nr}" in title
    assert "tan(q1/2), tan(q2/2) irrational: numbers exact" in title
    root = "2*atan(CRootOf(x**4 - 10*x**2 + 1, 2))"          # tan(q1/2) = sqrt3 - sqrt2
    drawn = at_algebraic_witness(system.model, {"q1": root, "q2": "0", "L": "1"},
                                 {"q1": "0.636476277"}, Numbers(2, 2, 1, 0, 1, 4, 0))
    title = draw_system(drawn).axes[0].get_title()
    assert "at q1\u22480.636476,q2=0,L=1   Nm=2 Nc=2 Ni=1 Nr=0" in title
    assert "tan(q1/2) irrational (shown rounded)" in title
