"""MJCF arms: the kinematic subset read exactly, checked against the same arm in URDF."""

from __future__ import annotations

import pytest
import sympy as sp

from coopkin_sym.errors import MjcfError
from coopkin_sym.model.mjcf import read_mjcf_text
from coopkin_sym.model.urdf import read_urdf_text

# A seven-joint arm with the Panda's published kinematics (offsets in metres, the
# quarter turns between its joints), once in MJCF (with a default class, degrees and
# quaternions, as robot files write them) and once in URDF (rpy in radians).
PANDA_MJCF = """<mujoco model="arm7">
  <default><default class="arm"><joint axis="0 0 1"/></default></default>
  <worldbody>
    <body name="link0" childclass="arm">
      <body name="link1" pos="0 0 0.333"><joint name="j1"/>
        <body name="link2" quat="0.7071068 -0.7071068 0 0"><joint name="j2"/>
          <body name="link3" pos="0 -0.316 0" quat="0.7071068 0.7071068 0 0">
            <joint name="j3"/>
            <body name="link4" pos="0.0825 0 0" axisangle="1 0 0 90"><joint name="j4"/>
              <body name="link5" pos="-0.0825 0.384 0" euler="-90 0 0">
                <joint name="j5"/>
                <body name="link6" quat="0.7071068 0.7071068 0 0"><joint name="j6"/>
                  <body name="link7" pos="0.088 0 0" quat="0.7071068 0.7071068 0 0">
                    <joint name="j7"/><site name="flange" pos="0 0 0.107"/>
                  </body></body></body></body></body></body></body>
    </body>
    <body name="box" pos="0.5 0 0.2"><joint type="free"/></body>
  </worldbody>
</mujoco>"""

_R = "1.5707963"
PANDA_URDF = f"""<robot name="arm7">
  <link name="link0"/><link name="link1"/><link name="link2"/><link name="link3"/>
  <link name="link4"/><link name="link5"/><link name="link6"/><link name="link7"/>
  <joint name="j1" type="revolute"><parent link="link0"/><child link="link1"/>
    <origin xyz="0 0 0.333" rpy="0 0 0"/><axis xyz="0 0 1"/></joint>
  <joint name="j2" type="revolute"><parent link="link1"/><child link="link2"/>
    <origin xyz="0 0 0" rpy="-{_R} 0 0"/><axis xyz="0 0 1"/></joint>
  <joint name="j3" type="revolute"><parent link="link2"/><child link="link3"/>
    <origin xyz="0 -0.316 0" rpy="{_R} 0 0"/><axis xyz="0 0 1"/></joint>
  <joint name="j4" type="revolute"><parent link="link3"/><child link="link4"/>
    <origin xyz="0.0825 0 0" rpy="{_R} 0 0"/><axis xyz="0 0 1"/></joint>
  <joint name="j5" type="revolute"><parent link="link4"/><child link="link5"/>
    <origin xyz="-0.0825 0.384 0" rpy="-{_R} 0 0"/><axis xyz="0 0 1"/></joint>
  <joint name="j6" type="revolute"><parent link="link5"/><child link="link6"/>
    <origin xyz="0 0 0" rpy="{_R} 0 0"/><axis xyz="0 0 1"/></joint>
  <joint name="j7" type="revolute"><parent link="link6"/><child link="link7"/>
    <origin xyz="0.088 0 0" rpy="{_R} 0 0"/><axis xyz="0 0 1"/></joint>
</robot>"""


def test_a_seven_joint_arm_reads_the_same_from_mjcf_and_urdf():
    """Defaults, degrees, quaternions, axis-angle and Euler angles give, exactly, the
    joints the URDF of the same arm gives."""
    mjcf = read_mjcf_text(PANDA_MJCF, "arm7.xml", tip="link7")
    urdf = read_urdf_text(PANDA_URDF, "arm7.urdf")
    assert [j.name for j in mjcf.joints] == [f"j{k}" for k in range(1, 8)]
    assert [(j.axis, j.point) for j in mjcf.joints] == [(j.axis, j.point)
                                                       for j in urdf.joints]
    assert mjcf.joints[6].axis == (0, 0, -1)
    assert mjcf.joints[3].point == (sp.Rational(33, 400), 0, sp.Rational(333 + 316, 1000))
    name, links, place = mjcf.sites[0]
    assert (name, links) == ("flange", 7)
    assert place == (sp.Rational(88, 1000), 0, sp.Rational(333 + 316 + 384 - 107, 1000))
    assert [(i.joint, i.type) for i in mjcf.ignored] == [("box_joint1", "free")]
    kinds = {s.where.split(" orientation")[0] for s in mjcf.snapped}
    assert kinds == {"body 'link2'", "body 'link3'", "body 'link4'", "body 'link5'",
                     "body 'link6'", "body 'link7'"}
    assert all(s.error < 1e-6 for s in mjcf.snapped)


def test_angles_are_radians_when_the_compiler_says_so():
    text = ('<mujoco><compiler angle="radian"/><worldbody><body name="a" '
            'axisangle="0 0 1 1.5707963"><joint name="q" axis="1 0 0"/></body>'
            '</worldbody></mujoco>')
    assert read_mjcf_text(text, "m.xml").joints[0].axis == (0, 1, 0)


@pytest.mark.parametrize(("text", "message"), [
    ('<mujoco><include file="other.xml"/><worldbody/></mujoco>',
     "m.xml: <include> reads another file"),
    ('<mujoco><worldbody><body name="a"><joint type="free"/></body></worldbody></mujoco>',
     "m.xml: body 'a': a free joint is not supported on the arm's chain"),
    ('<mujoco><worldbody><body name="a"/><body name="b"/></worldbody></mujoco>',
     "m.xml: the bodies branch (2 leaves): name the arm's last body with tip"),
    ('<mujoco><worldbody><body name="a"><joint class="x"/></body></worldbody></mujoco>',
     "m.xml: joint 'a_joint1': unknown default class 'x'"),
    ('<robot/>', "m.xml: the root element is <robot>, expected <mujoco>"),
    ('<mujoco><worldbody><body name="a" quat="1 0 0"/></worldbody></mujoco>',
     "m.xml: body 'a': quat '1 0 0': expected 4 numbers"),
    ('<mujoco><!DOCTYPE x [<!ENTITY e "e">]><worldbody/></mujoco>', "m.xml: not a"),
])
def test_what_an_arm_cannot_have_is_refused_with_the_element(text, message):
    with pytest.raises(MjcfError) as info:
        read_mjcf_text(text, "m.xml")
    assert str(info.value).startswith(message), str(info.value)


def test_a_model_file_reads_arms_from_mjcf_as_from_urdf(tmp_path):
    """``mjcf:`` takes the keys of ``urdf:`` (tip, base, prefix, snap, passive): two
    seven-joint arms holding a box give the same Q read either way."""
    from coopkin_sym import load

    (tmp_path / "arm7.xml").write_text(PANDA_MJCF)
    (tmp_path / "arm7.urdf").write_text(PANDA_URDF)

    def model(kind: str) -> str:
        path = tmp_path / f"cell-{kind}.yaml"
        path.write_text(f"""name: two arms, {kind}
arms:
  - {{name: left, {kind}: arm7.{'xml' if kind == 'mjcf' else 'urdf'}, tip: link7, prefix: l_}}
  - {{name: right, {kind}: arm7.{'xml' if kind == 'mjcf' else 'urdf'}, tip: link7,
     prefix: r_, base: {{xyz: [1, 0, 0]}}}}
contacts:
  - {{name: c1, link: left/link7, point: [0.088, 0, 0.926], model: complete}}
  - {{name: c2, link: right/link7, point: [1.088, 0, 0.926], model: hard}}
""")
        return str(path)

    at = "l_j2=2*atan(1/3),l_j4=-pi/2,r_j2=2*atan(1/2),r_j4=-pi/2,r_j6=pi/2"
    from_mjcf, from_urdf = load(model("mjcf")), load(model("urdf"))
    assert [j.name for j in from_mjcf.model.joints][:3] == ["l_j1", "l_j2", "l_j3"]
    a, b = from_mjcf.analyze(at), from_urdf.analyze(at)
    assert a.Q == b.Q and a.numbers == b.numbers
    assert (a.numbers.Nm, a.numbers.Nr) == (11, 5)      # 14 joints, 9 rows of rank 9


def test_an_arm_reads_one_robot_file(tmp_path):
    from coopkin_sym import load
    from coopkin_sym.errors import ModelError

    (tmp_path / "a.xml").write_text(PANDA_MJCF)
    (tmp_path / "m.yaml").write_text("arms:\n  - {name: a, mjcf: a.xml, urdf: a.urdf, "
                                     "tip: link7}\ncontacts: []\n")
    with pytest.raises(ModelError, match="arms\\[0\\]: an arm is read from one robot "
                                         "file: urdf or mjcf"):
        load(str(tmp_path / "m.yaml"))


def _cell(tmp_path, contacts: str) -> str:
    """Two arms from the MJCF Panda holding an object, with the given contacts."""
    (tmp_path / "arm7.xml").write_text(PANDA_MJCF)
    (tmp_path / "arm7.urdf").write_text(PANDA_URDF)
    path = tmp_path / "cell.yaml"
    path.write_text(f"""name: two arms on sites
arms:
  - {{name: left, mjcf: arm7.xml, tip: link7, prefix: l_}}
  - {{name: right, mjcf: arm7.xml, tip: link7, prefix: r_,
     base: {{xyz: [1, 0, 0], rpy: [0, 0, pi]}}}}
  - {{name: other, urdf: arm7.urdf, prefix: u_}}
contacts:
{contacts}""")
    return str(path)


def test_a_contact_on_an_mjcf_site_is_the_contact_at_the_site_written_out(tmp_path):
    """``site: ARM/SITE`` gives the contact its link (the site's body) and its point
    (the site's position), exactly as writing them out; ``frame: link`` gives the
    normal in the frame of the site's body."""
    from coopkin_sym import load

    on_sites = load(_cell(tmp_path, """\
  - {name: c1, site: left/flange, model: complete}
  - {name: c2, site: right/flange, frame: link, normal: ["3/5", 0, "4/5"], model: soft}
  - {name: c3, link: other/link7, point: [0, 0, 0], model: hard}
"""))
    written = load(_cell(tmp_path, """\
  - {name: c1, link: left/link7, point: [0.088, 0, 0.926], model: complete}
  - {name: c2, link: right/link7, frame: link, point: [0, 0, 0.107],
     normal: ["3/5", 0, "4/5"], model: soft}
  - {name: c3, link: other/link7, point: [0, 0, 0], model: hard}
"""))
    assert on_sites.model.contacts == written.model.contacts
    c1, c2 = on_sites.model.contacts[:2]
    assert (c1.arm, c1.link, c1.point) == (0, 7, (sp.Rational(88, 1000), 0,
                                                   sp.Rational(926, 1000)))
    # the right arm is turned by pi about z: its flange mirrors the left one; link 7
    # points its z axis down at home (x kept, y and z reversed), then the arm's turn
    assert c2.point == (1 - sp.Rational(88, 1000), 0, sp.Rational(926, 1000))
    assert c2.normal == (sp.Rational(-3, 5), 0, sp.Rational(-4, 5))
    at = "l_j2=2*atan(1/3),l_j4=-pi/2,r_j2=2*atan(1/2),r_j4=-pi/2,r_j6=pi/2"
    a, b = on_sites.analyze(at), written.analyze(at)
    assert a.Q == b.Q and a.numbers == b.numbers


@pytest.mark.parametrize("contact, message", [
    ("{name: c, site: left/wrist, model: hard}",
     "contacts[0].site: arm 'left' has no site 'wrist' on its chain (sites: flange)"),
    ("{name: c, site: other/flange, model: hard}",
     "contacts[0].site: sites exist only on an arm read from an MJCF file (mjcf:); "
     "arm 'other' is not"),
    ("{name: c, site: hand/flange, model: hard}",
     "contacts[0].site: unknown arm 'hand' (arms: left, right, other)"),
    ("{name: c, site: flange, model: hard}",
     "contacts[0].site: expected ARM/SITE (a site of an arm read from an MJCF file), "
     "got 'flange'"),
    ("{name: c, site: left/flange, point: [0, 0, 0], model: hard}",
     "contacts[0].site: a contact on a site takes its link and point from the site; "
     "remove point"),
    ("{name: c, model: hard}",
     "contacts[0]: missing key 'link'\n"),
])
def test_a_contact_on_a_site_that_cannot_be_is_one_clear_error(tmp_path, contact, message):
    from coopkin_sym import load
    from coopkin_sym.errors import ModelError

    with pytest.raises(ModelError) as info:
        load(_cell(tmp_path, f"  - {contact}\n"))
    text = str(info.value) + "\n"
    assert f": {message}" in text, text
