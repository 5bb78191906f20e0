"""The name labels of pictures: ``labels=True`` (legible: long names shortened, moved
apart), ``"short"`` (joint numbers) and ``False`` (none), on every public picture
function."""

from __future__ import annotations

import shutil
from pathlib import Path
from unittest import mock

import pytest

pytest.importorskip("matplotlib")

from coopkin_sym import load  # noqa: E402
from coopkin_sym.present import draw  # noqa: E402
from coopkin_sym.present.draw import DrawError, draw_system, save_picture  # noqa: E402
from coopkin_sym.present.draw_labels import label_boxes  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[2] / "coopkin_sym" / "model" / "examples"


def labels_of(fig) -> list[tuple[str, str]]:
    return [(t.get_gid(), t.get_text()) for t in fig.axes[0].texts
            if (t.get_gid() or "").startswith("label:")]


def overlapping(fig) -> int:
    boxes = label_boxes(fig.axes[0])
    return sum(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1:])


@pytest.fixture(scope="module")
def long_names(tmp_path_factory) -> Path:
    """The URDF example with long joint and contact names (as URDF robots have)."""
    folder = tmp_path_factory.mktemp("urdf")
    shutil.copy(EXAMPLES / "planar-2r-finger.urdf", folder)
    text = (EXAMPLES / "urdf-two-fingers.yaml").read_text()
    for old, new in (("prefix: l_", "prefix: left_hand_index_finger_"),
                     ("prefix: r_", "prefix: right_hand_index_finger_"),
                     ("name: c1,", "name: left_fingertip_contact,"),
                     ("name: c2,", "name: right_fingertip_contact,")):
        assert old in text
        text = text.replace(old, new)
    (folder / "fingers.yaml").write_text(text)
    return folder / "fingers.yaml"


def test_long_names_are_shortened_and_do_not_overlap(long_names):
    system = load(long_names)
    fig = system.draw()
    assert labels_of(fig) == [
        ("label:joint:left_hand_index_finger_mcp", "…mcp"),
        ("label:joint:left_hand_index_finger_pip", "…pip"),
        ("label:joint:right_hand_index_finger_mcp", "…mcp"),
        ("label:joint:right_hand_index_finger_pip", "…pip"),
        ("label:contact:left_fingertip_contact", "left_fin…_contact"),
        ("label:contact:right_fingertip_contact", "right_fi…_contact")]
    assert overlapping(fig) == 0
    short = system.draw(labels="short")
    assert [text for _, text in labels_of(short)] == ["1", "2", "1", "2", "lef…act",
                                                      "rig…act"]


def test_labels_false_draws_no_name_label_and_keeps_the_rest():
    system = load("urdf-two-fingers")
    fig = system.draw(labels=False)
    assert list(fig.axes[0].texts) == []
    named = system.draw()
    assert [text for _, text in labels_of(named)] == ["l_mcp", "l_pip", "r_mcp", "r_pip",
                                                      "c1", "c2"]
    # the rates of a motion are its content: they stay
    moving = load("paper-case1-hard").draw("q1=pi/2,q2=pi/2", motion="coordinated:1",
                                           labels=False)
    assert labels_of(moving) == []
    assert sorted(t.get_text() for t in moving.axes[0].texts) == ["q1: -1", "q2: -1"]


@pytest.mark.parametrize("example", ["five-bar", "quadruped-standing", "shaky-pinned-bars"])
def test_labels_that_would_cover_one_another_are_moved_apart(example):
    system = load(example)
    with mock.patch.object(draw, "spread_labels", lambda ax: 0):
        assert overlapping(system.draw()) > 0           # as they were drawn before
    assert overlapping(system.draw()) == 0


def test_coincident_joints_share_one_label():
    fig = load("dh-two-puma560-box").draw(labels=True)
    assert ("label:joint:p1_1,p1_2", "p1_1, p1_2") in labels_of(fig)
    short = load("dh-two-puma560-box").draw(labels="short")
    assert [t for g, t in labels_of(short) if g.startswith("label:joint:p1_")] == [
        "1, 2", "3", "4", "5, 6"]


def test_every_picture_function_takes_labels(tmp_path):
    system = load("paper-case1-hard")
    assert list(draw_system(system, labels=False).axes[0].texts) == []
    out = save_picture(system, tmp_path / "p.png", labels="short")
    assert out.read_bytes()[:4] == b"\x89PNG"
    for bad in ("long", 1, None):
        with pytest.raises(DrawError, match="labels: True, False or 'short'"):
            system.draw(labels=bad)


def test_the_draw_command_takes_labels(tmp_path):
    from typer.testing import CliRunner

    from coopkin_sym.cli import app

    out = tmp_path / "p.png"
    result = CliRunner().invoke(app, ["draw", "five-bar", "-o", str(out), "--labels", "none"])
    assert result.exit_code == 0 and result.stdout == f"wrote {out}\n"
    bad = CliRunner().invoke(app, ["draw", "five-bar", "-o", str(out), "--labels", "all"])
    assert bad.exit_code == 2
    assert bad.stderr == "coopkin: error: --labels: names, short or none (not 'all')\n"
