"""URDF text is read into a checked tree; every structural problem is located."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver.errors import InputError
from solver.identify.readers.urdf import Cylinder, Inertia, Link, parse_urdf
from tests.conftest import run_cli
from tests.identify import builders


def faults(text: str) -> list[str]:
    with pytest.raises(InputError) as caught:
        parse_urdf(text, "r.urdf")
    return [str(fault) for fault in caught.value.faults]


def test_parse_urdf_reads_links_joints_sensors_and_plugins() -> None:
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("base_link", "ray", "laser"))
    robot.add(
        builders.model_plugin(
            "imu", "libhector_gazebo_ros_imu.so", "<bodyName>base_link</bodyName>"
        )
    )
    urdf = parse_urdf(robot.text(), "rover.urdf")
    assert urdf.root == "base_link"
    assert urdf.name == "rover"
    assert len(urdf.joints) == 4
    assert len(urdf.links) == 5
    assert urdf.sensors[0].type == "ray"
    assert urdf.sensors[0].link == "base_link"
    assert urdf.plugins[0].param("bodyname") == "base_link"


def test_a_joint_naming_a_missing_link_is_located_at_that_element() -> None:
    text = (
        '<robot name="r">\n<link name="a"/>\n<joint name="j" type="fixed">\n'
        '<parent link="a"/>\n<child link="ghost"/>\n</joint>\n</robot>'
    )
    assert faults(text) == [
        "r.urdf:5: joint[j].child: joint 'j' names child link 'ghost', which does not exist"
    ]


def test_a_link_a_joint_names_but_no_element_declares_is_read_as_undeclared() -> None:
    text = (
        '<robot name="kit">\n<link name="kit_link"/>\n<joint name="j" type="fixed">\n'
        '<parent link="base_link"/>\n<child link="kit_link"/>\n</joint>\n</robot>'
    )
    urdf = parse_urdf(text, "kit.urdf", strict=False)
    assert urdf.root == "base_link"
    assert [(link.name, link.declared) for link in urdf.links] == [
        ("kit_link", True),
        ("base_link", False),
    ]


def test_every_problem_of_a_file_is_reported_at_once() -> None:
    text = (
        '<robot name="r">\n<link name="a"/>\n<link name="a"/>\n'
        '<joint name="j1" type="hinge"><parent link="a"/><child link="b"/></joint>\n'
        '<joint name="j2" type="fixed"><parent link="x"/><child link="a"/></joint>\n'
        "</robot>"
    )
    found = faults(text)
    assert len(found) == 4
    assert any("duplicate link 'a'" in f for f in found)
    assert any("unknown joint type 'hinge'" in f and f.startswith("r.urdf:4:") for f in found)
    assert any("child link 'b'" in f for f in found)
    assert any("parent link 'x'" in f and f.startswith("r.urdf:5:") for f in found)


def test_a_cycle_is_reported() -> None:
    text = (
        '<robot name="r"><link name="root"/><link name="a"/><link name="b"/>\n'
        '<joint name="j1" type="fixed"><parent link="a"/><child link="b"/></joint>\n'
        '<joint name="j2" type="fixed"><parent link="b"/><child link="a"/></joint>\n'
        "</robot>"
    )
    assert any("cycle" in f for f in faults(text))


def test_a_link_with_two_parents_is_reported() -> None:
    text = (
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>\n'
        '<joint name="j1" type="fixed"><parent link="a"/><child link="c"/></joint>\n'
        '<joint name="j2" type="fixed"><parent link="b"/><child link="c"/></joint>\n'
        "</robot>"
    )
    assert any("two parent joints" in f for f in faults(text))


def test_several_roots_and_an_empty_robot_are_reported() -> None:
    assert "2 root links" in faults('<robot name="r"><link name="a"/><link name="b"/></robot>')[0]
    assert "no links" in faults('<robot name="e"/>')[0]


def test_a_document_that_is_not_a_robot_is_refused() -> None:
    assert "expected <robot>" in faults("<sdf/>")[0]


def test_a_self_joint_and_a_bad_limit_are_reported() -> None:
    text = (
        '<robot name="r"><link name="a"/>\n'
        '<joint name="j" type="revolute"><parent link="a"/><child link="a"/>'
        '<limit lower="x"/></joint></robot>'
    )
    assert any("to itself" in f for f in faults(text))


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            '<robot name="r"><link name="a"/><link name="b"/>'
            '<joint name="j" type="ball"><parent link="a"/><child link="b"/></joint></robot>',
            "unknown joint type 'ball'",
        ),
        ('<robot name="r"><link name="a"/><link name="b"/></robot>', "2 root links"),
        ('<robot name="e"/>', "empty robot"),
        ('<robot name="r"><link name="a"></robot>', "malformed XML"),
    ],
)
def test_the_cli_with_strict_reports_flawed_urdfs_with_exit_2(
    tmp_path: Path, text: str, expected: str
) -> None:
    path = tmp_path / "bad.urdf"
    path.write_text(text, encoding="utf-8")
    result = run_cli("identify", path, "--format", "json", "--strict")
    assert result.returncode == 2
    assert expected in result.stderr
    assert str(path) in result.stderr
    assert "Traceback" not in result.stderr
    assert result.stdout == ""


def test_a_plugins_entries_are_named_once_each_and_bounded() -> None:
    robot = builders.ugv()
    entries = "".join(f"<entry_{k}><empty/></entry_{k}>" for k in range(1000))
    robot.add(
        builders.model_plugin(
            "control",
            "libcontrol.so",
            "<thruster><name>a</name></thruster><thruster><name>b</name></thruster>" + entries,
        )
    )
    plugin = parse_urdf(robot.text(), "rover.urdf").plugins[0]
    assert plugin.groups[:2] == ("thruster", "entry_0")
    assert len(plugin.groups) == 400  # the reader keeps at most this many
    assert ("name", "a") in plugin.params


def test_included_models_are_read_with_the_link_they_are_fixed_to_and_bounded() -> None:
    robot = builders.ugv()
    robot.add(
        "<gazebo><include><uri>model://gps/</uri><name>fix</name></include>"
        '<joint name="j" type="fixed"><child>fix::link</child><parent>base_link</parent></joint>'
        "<include><uri>model://camera</uri></include>"
        "<include><uri>http://example.com/model</uri></include></gazebo>"
    )
    robot.add("<gazebo>" + "<include><uri>model://x</uri></include>" * 1000 + "</gazebo>")
    urdf = parse_urdf(robot.text(), "many.urdf", strict=False)
    assert [(m.model, m.name, m.link) for m in urdf.models[:2]] == [
        ("gps", "fix", "base_link"),
        ("camera", "camera", None),
    ]
    assert len(urdf.models) == 400  # the hostile thousand are cut where plugin parameters are
    # ... and the cut is said, once, where it falls (the 399th of the thousand).
    cut = [w for w in urdf.warnings if w.code == "too-large"]
    assert [(w.location.file, w.location.path, w.message) for w in cut] == [
        ("many.urdf", "gazebo/include", "more than 400 model includes: the rest are not read")
    ]
    assert cut[0].location.line == robot.text().splitlines().index(robot.extra[-1]) + 1
    with pytest.raises(InputError, match="more than 400 model includes"):
        parse_urdf(robot.text())  # strict: every problem is an error


def test_an_included_model_with_a_blank_name_is_named_by_its_model() -> None:
    robot = builders.ugv()
    robot.add("<gazebo><include><uri>model://gps</uri><name>   </name></include></gazebo>")
    assert [(m.model, m.name) for m in parse_urdf(robot.text()).models] == [("gps", "gps")]


def test_the_links_fixed_below_a_link_stop_at_every_joint_that_moves() -> None:
    robot = builders.RobotText("r")
    hub = robot.fixed(robot.root, "hub")
    robot.fixed(hub, "tyre")
    spoke = robot.chain(hub, ["spin"])
    robot.fixed(spoke, "cap")
    urdf = parse_urdf(robot.text())
    assert sorted(urdf.fixed_below(robot.root)) == ["hub", "tyre"]
    assert list(urdf.fixed_below(spoke)) == ["cap"]
    assert list(urdf.fixed_below("tyre")) == []


@pytest.mark.parametrize(
    ("block", "off"),
    [
        ("<turnGravityOff>true</turnGravityOff>", True),
        ("<gravity>0</gravity>", True),
        ("<gravity>false</gravity>", True),
        ("<turnGravityOff>false</turnGravityOff>", False),
        ("<gravity>true</gravity>", False),
    ],
)
def test_a_gazebo_block_that_turns_gravity_off_is_read(block: str, off: bool) -> None:
    text = f'<robot name="r"><link name="a"/><gazebo reference="a">{block}</gazebo></robot>'
    assert parse_urdf(text, "r.urdf").gravity_off is off


def base_link(inner: str) -> Link:
    """The link ``base`` of a one-link robot whose ``<link>`` holds ``inner``."""
    link = parse_urdf(f'<robot name="r"><link name="base">{inner}</link></robot>', "r.urdf").link(
        "base"
    )
    assert link is not None
    return link


@pytest.mark.parametrize(
    ("visual", "expected"),
    [
        (
            '<visual><origin xyz="0.1 0 0" rpy="0 1.5 0"/><geometry>'
            '<cylinder radius="0.2" length="0.03"/></geometry></visual>',
            Cylinder(0.2, 0.03, (0.0, 1.5, 0.0), (0.1, 0.0, 0.0)),
        ),
        (
            '<visual><geometry><cylinder radius="0.2" length="0.03"/></geometry></visual>',
            Cylinder(0.2, 0.03),
        ),
        ('<visual><geometry><cylinder radius="nan" length="0.03"/></geometry></visual>', None),
        ('<visual><geometry><cylinder radius="-1" length="0.03"/></geometry></visual>', None),
        ('<visual><geometry><box size="1 1 1"/></geometry></visual>', None),
        (
            '<visual><geometry><mesh filename="prop.dae"/></geometry></visual>'
            '<visual><geometry><cylinder radius="0.2" length="0.03"/></geometry></visual>',
            None,
        ),
        ('<visual><geometry><cylinder radius="0.2"/></geometry></visual>', None),
        ("", None),
    ],
    ids=[
        "placed and turned",
        "at the link",
        "not a number",
        "negative",
        "a box",
        "a mesh first",
        "no length",
        "no visual",
    ],
)
def test_a_links_first_visual_is_kept_when_it_is_a_readable_cylinder(
    visual: str, expected: Cylinder | None
) -> None:
    link = base_link(visual)
    assert link.cylinder == expected


@pytest.mark.parametrize(
    ("inertial", "expected"),
    [
        ('<inertial><mass value="2.5"/></inertial>', 2.5),
        ('<inertial><mass value="0"/></inertial>', None),
        ('<inertial><mass value="-1"/></inertial>', None),
        ('<inertial><mass value="nan"/></inertial>', None),
        ("<inertial/>", None),
        ("", None),
    ],
    ids=["positive", "zero", "negative", "not a number", "no mass", "no inertial"],
)
def test_a_links_mass_is_its_inertials_positive_mass(inertial: str, expected: float | None) -> None:
    link = base_link(inertial)
    assert link.mass == expected


@pytest.mark.parametrize(
    ("inertial", "expected"),
    [
        ('<inertial><origin xyz="0 0 -0.08"/><mass value="1"/></inertial>', (0.0, 0.0, -0.08)),
        ('<inertial><mass value="1"/></inertial>', None),  # a macro's default, not a place
        ('<inertial><origin rpy="0 1 0"/><mass value="1"/></inertial>', None),
        ('<inertial><origin xyz="0 nan 1"/><mass value="1"/></inertial>', None),
        ('<inertial><origin xyz="0 1"/><mass value="1"/></inertial>', None),
        # A CAD export's frame: a mass of 0 and an origin anywhere (fresh set 1527's claw tips).
        ('<inertial><origin xyz="-0.2 0 0"/><mass value="0"/></inertial>', None),
        ('<inertial><origin xyz="-0.2 0 0"/></inertial>', None),
        ("", None),
    ],
    ids=[
        "placed",
        "no origin",
        "turned only",
        "not a number",
        "two numbers",
        "no mass",
        "mass unwritten",
        "no inertial",
    ],
)
def test_a_links_mass_centre_is_where_its_inertial_puts_it_and_unknown_when_unreadable(
    inertial: str, expected: tuple[float, float, float] | None
) -> None:
    link = base_link(inertial)
    assert link.mass_centre == expected


@pytest.mark.parametrize(
    ("inertia", "expected"),
    [
        (
            '<origin rpy="0 0 1"/><inertia ixx="1" ixy="0.1" ixz="0" iyy="2" iyz="0" izz="3"/>',
            Inertia((1.0, 0.1, 0.0, 2.0, 0.0, 3.0), (0.0, 0.0, 1.0)),
        ),
        ('<inertia ixx="1" ixy="0" ixz="0" iyy="2" iyz="0"/>', None),
        ('<inertia ixx="1" ixy="0" ixz="0" iyy="0" iyz="0" izz="3"/>', None),
        ('<inertia ixx="1" ixy="x" ixz="0" iyy="2" iyz="0" izz="3"/>', None),
        ("", None),
    ],
    ids=["turned by its origin", "a term missing", "a moment of zero", "a term unreadable", "none"],
)
def test_a_links_inertia_is_its_inertials_six_terms_when_all_are_readable(
    inertia: str, expected: Inertia | None
) -> None:
    link = base_link(f'<inertial><mass value="1"/>{inertia}</inertial>')
    assert link.inertia == expected


def stiffness_arm(*, dummy: str = "", effort: str = "0") -> str:
    """An arm of three joints, each with a pseudo-joint beside it (a joint's stiffness, as the
    Pisa/IIT LWR writes it): ``effort`` and a ``<link/>`` with ``dummy`` in it."""
    robot = builders.RobotText("lwr")
    link = robot.root
    for i in range(1, 4):
        robot.joint(
            f"a{i}_stiffness",
            "revolute",
            link,
            f"link_{i}_dummy",
            f'<limit effort="{effort}" lower="0" upper="5000" velocity="20000"/>',
        )
        link = robot.chain(link, [f"a{i}"])
    text = robot.text()
    return text.replace('<link name="link_1_dummy"/>', f'<link name="link_1_dummy">{dummy}</link>')


def test_a_joint_that_moves_nothing_and_exerts_nothing_is_no_joint_of_the_body() -> None:
    urdf = parse_urdf(stiffness_arm(), "lwr.urdf")
    assert [j.name for j in urdf.joints if j.movable] == ["a1", "a2", "a3"]
    assert all(j.phantom for j in urdf.joints if j.name.endswith("_stiffness"))


@pytest.mark.parametrize(
    ("text", "moving"),
    [
        # A link with something in it is a body the joint moves.
        (stiffness_arm(dummy='<inertial><mass value="0.1"/></inertial>'), "a1_stiffness"),
        # A joint that may exert a force moves its link, whatever the link holds.
        (stiffness_arm(effort="2"), "a1_stiffness"),
        # A link something hangs from is no leaf: the joint carries it.
        (
            stiffness_arm().replace(
                "</robot>",
                '<link name="below"/><joint name="below_j" type="fixed">'
                '<parent link="link_2_dummy"/><child link="below"/></joint>\n</robot>',
            ),
            "a2_stiffness",
        ),
        # Commanded or coupled, it is a joint.
        (
            stiffness_arm().replace(
                "</robot>", builders.transmission("a2_stiffness") + "\n</robot>"
            ),
            "a2_stiffness",
        ),
        (
            stiffness_arm().replace(
                '<child link="link_3_dummy"/>', '<child link="link_3_dummy"/><mimic joint="a3"/>'
            ),
            "a3_stiffness",
        ),
    ],
)
def test_a_joint_to_an_empty_leaf_moves_when_it_may_exert_or_carry_or_is_driven(
    text: str, moving: str
) -> None:
    urdf = parse_urdf(text, "lwr.urdf")
    assert next(j for j in urdf.joints if j.name == moving).movable


def wrist_helpers(*, mass: str = "0.002", inside: str = "") -> str:
    """A drawn three-joint arm whose last link carries a simulator's helper chain: two
    revolute joints to links of ``mass`` with ``inside`` in them (Velma's keep-upright chain at
    each wrist)."""
    drawn = '<visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual>'
    robot = builders.RobotText("velma")
    tip = robot.chain(robot.root, ["a1", "a2", "a3"])
    helper = robot.chain(tip, ["upright0", "upright1"])
    text = robot.text()
    for link in (robot.root, "a1_link", "a2_link", tip):
        text = text.replace(f'<link name="{link}"/>', f'<link name="{link}">{drawn}</link>')
    point = f'<inertial><mass value="{mass}"/></inertial>{inside}'
    for link in ("upright0_link", helper):
        text = text.replace(f'<link name="{link}"/>', f'<link name="{link}">{point}</link>')
    return text


def test_a_chain_of_undrawn_mass_points_is_no_part_of_the_body() -> None:
    urdf = parse_urdf(wrist_helpers(), "velma.urdf")
    assert [j.name for j in urdf.joints if j.movable] == ["a1", "a2", "a3"]


@pytest.mark.parametrize(
    "text",
    [
        wrist_helpers(mass="0.05"),  # fifty grams is a part
        wrist_helpers(inside='<visual><geometry><sphere radius="0.01"/></geometry></visual>'),
        wrist_helpers().replace(  # a sensor rides it
            "</robot>", builders.gazebo_sensor("upright1_link", "camera", "cam") + "\n</robot>"
        ),
        wrist_helpers().replace("<visual>", "<inertial>").replace("</visual>", "</inertial>"),
    ],
    ids=["heavy", "drawn", "sensing", "nothing drawn in the file"],
)
def test_a_chain_below_a_part_a_sensor_or_in_an_undrawn_file_still_moves(text: str) -> None:
    urdf = parse_urdf(text, "velma.urdf")
    assert all(j.movable for j in urdf.joints)


def test_efforts_all_zero_are_placeholders_that_lock_nothing() -> None:
    text = stiffness_arm().replace('effort="1"', 'effort="0"')
    urdf = parse_urdf(text, "lwr.urdf")
    assert all(j.movable for j in urdf.joints)


@pytest.mark.parametrize("shape", ["row", "under_a_fixed_mast"])
def test_blank_joints_are_read_in_one_walk_however_many(shape: str) -> None:
    # 20,000 joints written 0..0 with zero effort, in one row, or each a leaf at the foot of a
    # mast of 10,000 fixed joints with three in a row beside them: each link is walked up once,
    # not once per joint below it, and every blank joint moves (an export that wrote no limits).
    blank = '<limit lower="0" upper="0" effort="0" velocity="0"/>'
    parts = ['<robot name="r"><link name="l0"/>']
    if shape == "row":
        for i in range(1, 20_001):
            parts.append(
                f'<link name="l{i}"/><joint name="j{i}" type="revolute"><parent link="l{i - 1}"/>'
                f'<child link="l{i}"/>{blank}</joint>'
            )
    else:
        for i in range(1, 10_001):
            parts.append(
                f'<link name="l{i}"/><joint name="f{i}" type="fixed"><parent link="l{i - 1}"/>'
                f'<child link="l{i}"/></joint>'
            )
        for i in range(10_000):
            parts.append(
                f'<link name="leaf{i}"/><joint name="b{i}" type="revolute">'
                f'<parent link="l10000"/><child link="leaf{i}"/>{blank}</joint>'
            )
        for i in range(3):
            parent = "l0" if i == 0 else f"arm{i - 1}"
            parts.append(
                f'<link name="arm{i}"/><joint name="a{i}" type="revolute">'
                f'<parent link="{parent}"/><child link="arm{i}"/>{blank}</joint>'
            )
    urdf = parse_urdf("".join(parts) + "</robot>")
    assert all(joint.movable for joint in urdf.joints if joint.type == "revolute")


def test_a_file_whose_every_moving_joint_is_written_blank_gave_no_limits_and_all_move() -> None:
    # A CAD export of a rover: its four wheels, leaves on the body, none carrying another, are
    # its only joints, each written 0..0 with zero effort. Nobody locks every joint of a robot:
    # they move (how far, the export did not say).
    blank = '<axis xyz="0 0 1"/><limit lower="0" upper="0" effort="0" velocity="0"/>'
    wheels = "".join(
        f'<link name="w{i}"/><joint name="j{i}" type="revolute"><parent link="base"/>'
        f'<child link="w{i}"/>{blank}</joint>'
        for i in range(4)
    )
    urdf = parse_urdf(f'<robot name="r"><link name="base"/>{wheels}</robot>')
    assert all(joint.movable for joint in urdf.joints)
    # Two such joints alone are a camera's mount, and three beside a joint with real limits
    # are mounts a robot locked: they stay locked.
    two = "".join(
        f'<link name="m{i}"/><joint name="m{i}" type="revolute"><parent link="base"/>'
        f'<child link="m{i}"/>{blank}</joint>'
        for i in range(2)
    )
    urdf = parse_urdf(f'<robot name="r"><link name="base"/>{two}</robot>')
    assert not any(joint.movable for joint in urdf.joints)
    arm = (
        '<link name="arm"/><joint name="shoulder" type="revolute"><parent link="base"/>'
        '<child link="arm"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="5" velocity="1"/></joint>'
    )
    urdf = parse_urdf(f'<robot name="r"><link name="base"/>{wheels}{arm}</robot>')
    assert [joint.movable for joint in urdf.joints] == [False] * 4 + [True]
