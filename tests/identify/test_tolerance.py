"""Real descriptions are imperfect: what can be read is read, each flaw is a located warning.

Exit 2 is kept for a main description that cannot be read at all (not XML, no links, hostile
XML); ``--strict`` turns warnings back into errors for people who want validation.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from solver.errors import InputError
from solver.identify import identify_urdf
from solver.identify.readers.srdf import parse_srdf
from solver.identify.readers.urdf import parse_urdf
from tests.conftest import run_cli
from tests.identify import builders

ARM_SRDF = """<?xml version="1.0"?>
<robot name="arm6">
  <virtual_joint name="world_joint" type="fixed" parent_frame="world" child_link="base_link"/>
  <group name="arm">
    <joint name="world_joint"/>
    <joint name="shoulder_pan"/><joint name="shoulder_lift"/><joint name="elbow"/>
    {extra}
  </group>
  {groups}
</robot>
"""


def warnings_of(text: str) -> list[str]:
    return [str(w) for w in parse_urdf(text, "r.urdf", strict=False).warnings]


def attachment() -> str:
    """A gripper described alone: its joint names the arm's flange, which is not here."""
    return (
        '<robot name="r">\n<link name="finger"/>\n'
        '<joint name="j" type="prismatic">\n<parent link="flange"/>\n'
        '<child link="finger"/>\n<limit lower="0" upper="1"/>\n</joint>\n</robot>\n'
    )


def two_links(joint_type: str = "revolute", parent: str = "a", child: str = "b") -> str:
    return (
        '<robot name="r">\n<link name="a"/>\n<link name="b"/>\n'
        f'<joint name="j" type="{joint_type}">\n<parent link="{parent}"/>\n'
        f'<child link="{child}"/>\n</joint>\n</robot>\n'
    )


def test_an_srdf_group_may_list_the_srdfs_own_virtual_joint() -> None:
    urdf = parse_urdf(builders.manipulator().text())
    srdf = parse_srdf(ARM_SRDF.format(extra="", groups=""), "arm.srdf", urdf)
    assert srdf.group("arm") is not None
    assert "world_joint" in srdf.group("arm").joints  # type: ignore[union-attr]  # asserted above


def test_srdf_items_the_urdf_lacks_are_dropped_with_a_warning_and_the_rest_kept() -> None:
    urdf = parse_urdf(builders.manipulator().text())
    text = ARM_SRDF.format(
        extra='<joint name="other_variant_joint"/>\n'
        '    <link name="other_variant_link"/>\n'
        '    <group name="no_such_group"/>',
        groups='<group name="tool"><link name="prefix_tool0"/></group>',
    )
    srdf = parse_srdf(text, "arm.srdf", urdf, strict=False)
    arm = srdf.group("arm")
    assert arm is not None
    assert arm.joints == ("world_joint", "shoulder_pan", "shoulder_lift", "elbow")
    assert arm.links == ()
    assert arm.subgroups == ()
    found = [str(w) for w in srdf.warnings]
    assert any(w.startswith("arm.srdf:7:") and "'other_variant_joint'" in w for w in found)
    assert any("'other_variant_link'" in w for w in found)
    assert any("subgroup 'no_such_group'" in w for w in found)
    assert any("'prefix_tool0'" in w for w in found)


def test_an_srdf_of_another_variant_still_identifies_the_robot_with_warnings() -> None:
    text = ARM_SRDF.format(extra='<joint name="other_variant_joint"/>', groups="")
    result = identify_urdf(builders.manipulator().text(), srdf_text=text, srdf_file="arm.srdf")
    assert result.structure == "Manipulator"
    assert [w.location.line for w in result.warnings] == [7]


def test_a_joint_whose_parent_link_is_missing_is_read_as_an_attachment() -> None:
    found = warnings_of(attachment())
    assert found == [
        "r.urdf:4: joint[j].parent: joint 'j' names parent link 'flange', which does not exist"
    ]
    urdf = parse_urdf(attachment(), "r.urdf", strict=False)
    assert urdf.root == "flange"
    assert [j.name for j in urdf.joints] == ["j"]


def test_a_duplicate_link_is_a_warning_and_the_first_is_kept() -> None:
    text = two_links().replace('<link name="b"/>', '<link name="b"/>\n<link name="a"/>')
    assert warnings_of(text) == ["r.urdf:4: link[a]: duplicate link 'a' (first at line 2)"]


def test_a_link_with_two_parents_keeps_the_first_joint() -> None:
    text = (
        '<robot name="r">\n<link name="a"/>\n<link name="b"/>\n<link name="c"/>\n'
        '<joint name="j1" type="fixed"><parent link="a"/><child link="c"/></joint>\n'
        '<joint name="j2" type="fixed"><parent link="b"/><child link="c"/></joint>\n'
        '<joint name="j3" type="fixed"><parent link="a"/><child link="b"/></joint>\n'
        "</robot>"
    )
    urdf = parse_urdf(text, "r.urdf", strict=False)
    assert [j.name for j in urdf.joints] == ["j1", "j3"]
    assert [w.location.line for w in urdf.warnings] == [6]
    assert "two parent joints" in urdf.warnings[0].message


def test_an_undeclared_namespace_prefix_is_read_with_a_warning() -> None:
    text = (
        '<?xml version="1.0"?>\n<robot name="r">\n<xacro:property name="x" value="1"/>\n'
        '<link name="a"/>\n</robot>\n'
    )
    urdf = parse_urdf(text, "r.urdf", strict=False)
    assert urdf.root == "a"
    assert (3, "xml-namespace") in [(w.location.line, w.code) for w in urdf.warnings]


def test_an_xml_version_0_0_is_read_as_xml_1_0() -> None:
    text = "<?xml version='0.0'?>\n" + two_links()
    assert warnings_of(text) == ["r.urdf:1: XML version '0.0' declared; read as XML 1.0"]


@pytest.mark.parametrize(
    ("before", "why"),
    [
        ("\n\n\n", "blank lines before it"),
        ("<!-- licence\n  banner -->\n\n", "a comment before it"),
    ],
)
def test_an_xml_declaration_out_of_place_keeps_every_line_number(before: str, why: str) -> None:
    text = before + '<?xml version="1.0"?>\n' + two_links(parent="ghost")
    found = warnings_of(text)
    assert found[0] == (
        f"r.urdf:4: the XML declaration is not at the start of the document ({why}); read anyway"
    )
    assert found[1].startswith("r.urdf:9: joint[j].parent:")
    with pytest.raises(InputError, match="XML declaration allowed only at the start"):
        parse_urdf(text, "r.urdf")


def test_a_second_xml_declaration_a_generator_wrote_after_its_banner_is_ignored() -> None:
    text = '<?xml version="1.0"?>\n<!-- generated -->\n<?xml version="1.0" ?>\n' + two_links()
    assert warnings_of(text) == ["r.urdf:3: 1 more XML declaration(s) after the first; read anyway"]


def test_a_declaration_after_a_byte_order_mark_is_at_the_start() -> None:
    assert warnings_of("\ufeff<?xml version='1.0'?>\n<!-- c -->\n" + two_links()) == []
    assert warnings_of("\ufeff<!-- c -->\n<?xml version='1.0'?>\n" + two_links()) == [
        "r.urdf:2: the XML declaration is not at the start of the document "
        "(a comment before it); read anyway"
    ]


@pytest.mark.parametrize(
    "prologue",
    [
        '<!-- <?xml version="1.0"?> -->\n',  # in a comment
        '<?pi data <?xml version="1.0"?>\n',  # in another instruction's data
        "<!DOCTYPE robot SYSTEM \"<?xml version='1.0'?>\">\n",  # in the document type
    ],
)
def test_a_declaration_written_inside_other_markup_is_that_markup(prologue: str) -> None:
    assert warnings_of(prologue + two_links()) == []
    assert parse_urdf(prologue + two_links(), "r.urdf").root == "a"  # as strict reads it


def test_a_prologue_of_instructions_full_of_declarations_is_read_in_one_pass() -> None:
    # Each declaration-like text inside the instruction's data was searched from the last one
    # (quadratic: minutes for a megabyte); the prologue scan reads each instruction once.
    many = "<?pi " + '<?xml version="1.0" ' * 40_000 + " ?>\n" + two_links()
    assert parse_urdf(many, "r.urdf", strict=False).root == "a"


def test_a_urdf_in_drakes_namespace_is_read_by_its_local_names() -> None:
    text = two_links().replace(
        '<robot name="r">',
        '<robot name="r" xmlns="http://drake.mit.edu" xmlns:xacro="http://ros.org/wiki/xacro">',
    )
    text = text.replace("</joint>", '<xacro:x/></joint>\n<loop_joint name="loop"/>')
    urdf = parse_urdf(text, "r.urdf", strict=False)
    assert (urdf.root, [j.name for j in urdf.joints]) == ("a", ["j"])
    assert [str(w).split(":")[:3] for w in urdf.warnings] == [
        ["r.urdf", "1", " the document's elements are in the namespace 'http"],
        ["r.urdf", "7", " xacro"],  # a prefixed element keeps its namespace: still xacro's
    ]
    assert "read by their local names, as ROS's parsers read them" in str(urdf.warnings[0])
    with pytest.raises(InputError, match="expected <robot>"):
        parse_urdf(text, "r.urdf")
    undeclared = text.replace(' xmlns:xacro="http://ros.org/wiki/xacro"', "")
    assert parse_urdf(undeclared, "r.urdf", strict=False).root == "a"  # both flaws read


def test_a_trailing_nul_byte_is_ignored_with_a_warning() -> None:
    assert warnings_of(two_links() + "\x00") == [
        "r.urdf:9: NUL byte(s) after the end of the document ignored"
    ]


def test_a_spherical_joint_is_read_as_a_ball_joint_with_a_warning() -> None:
    robot = builders.RobotText("ragdoll")
    for side in ("left", "right"):
        builders.leg(robot, robot.root, f"{side}_leg", ("hip", "knee", "ankle"))
        shoulder = robot.chain(robot.root, [f"{side}_shoulder"], "spherical")
        robot.chain(shoulder, [f"{side}_elbow"])
    robot.chain(robot.root, ["neck"], "spherical")
    result = identify_urdf(robot.text(), file="h.urdf")
    # A ball-joint shoulder and an elbow: an arm of four degrees of freedom.
    assert result.body is not None
    assert (result.structure, result.body.count("arm")) == ("Humanoid", 2)
    assert {w.message.split(";")[0] for w in result.warnings} == {"unknown joint type 'spherical'"}


def test_a_non_finite_scan_sample_count_is_a_warning_not_a_crash() -> None:
    for value in ("inf", "1e999", "nan"):
        robot = builders.ugv()
        robot.add(
            builders.gazebo_sensor(
                "base_link",
                "ray",
                "laser",
                f"<ray><scan><horizontal><samples>{value}</samples></horizontal></scan></ray>",
            )
        )
        result = identify_urdf(robot.text(), file="rover.urdf")
        assert [s.kind for s in result.sensors] == ["lidar"]
        assert [w.code for w in result.warnings] == ["urdf-number"]
        assert repr(value) in result.warnings[0].message


def test_json_and_text_output_carry_the_warnings(tmp_path: Path) -> None:
    path = tmp_path / "r.urdf"
    path.write_text(attachment(), encoding="utf-8")
    shown = json.loads(run_cli("identify", path, "--format", "json").stdout)
    assert shown["warnings"] == [
        {
            "file": str(path),
            "line": 4,
            "message": "joint[j].parent: joint 'j' names parent link 'flange', "
            "which does not exist",
        }
    ]
    text = run_cli("identify", path).stdout
    assert f"  warning: {path}:4: joint[j].parent: joint 'j' names parent link 'flange'" in text


def test_strict_turns_warnings_into_errors_with_exit_2(tmp_path: Path) -> None:
    path = tmp_path / "r.urdf"
    path.write_text(two_links(joint_type="spherical"), encoding="utf-8")
    assert run_cli("identify", path).returncode == 0
    result = run_cli("identify", path, "--strict")
    assert result.returncode == 2
    assert f"{path}:4: joint[j].type: unknown joint type 'spherical'" in result.stderr
    assert "Traceback" not in result.stderr


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("this is not XML", "malformed XML"),
        ('<robot name="e"/>', "no links"),
        (
            '<!DOCTYPE r [<!ENTITY a "aaaa">]><robot name="r"><link name="&a;"/></robot>',
            "entity declarations are refused",
        ),
        (
            '<robot name="r"><link name="a"/><link name="b"/>'
            '<joint name="j1" type="fixed"><parent link="a"/><child link="b"/></joint>'
            '<joint name="j2" type="fixed"><parent link="b"/><child link="a"/></joint></robot>',
            "no root link",
        ),
    ],
)
def test_only_a_description_that_cannot_be_read_at_all_exits_2(
    tmp_path: Path, text: str, expected: str
) -> None:
    path = tmp_path / "bad.urdf"
    path.write_text(text, encoding="utf-8")
    result = run_cli("identify", path)
    assert result.returncode == 2
    assert expected in result.stderr
    assert "Traceback" not in result.stderr


def test_a_description_past_the_size_cap_is_refused_at_the_first_element_beyond(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from solver.identify.readers import urdf as module

    monkeypatch.setattr(module, "MAX_PARTS", 3)
    links = "".join(f'<link name="l{i}"/>\n' for i in range(5))
    with pytest.raises(InputError) as caught:
        parse_urdf(f'<robot name="r">\n{links}</robot>', "big.urdf", strict=False)
    assert str(caught.value).startswith("big.urdf:5: link: 5 links and 0 joints: more than 3")


def test_a_non_ascii_digit_is_not_read_as_a_number() -> None:
    text = two_links().replace('<parent link="a"/>', '<parent link="a"/><limit lower="٣"/>')
    urdf = parse_urdf(text, "r.urdf", strict=False)
    assert urdf.joints[0].lower is None
    assert [w.message for w in urdf.warnings] == ["limit lower is not a finite number: '٣'"]
