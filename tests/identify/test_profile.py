"""The identification profile is data; a malformed one is reported whole, located."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from solver.errors import Fault, SolverError
from solver.files.yamlio import parse_document
from solver.identify.profile import ProfileError, load_profile, parse_profile
from tests.conftest import RULES

SHIPPED = (RULES / "identification.yaml").read_text(encoding="utf-8")


def test_the_shipped_profile_loads_with_its_structures_in_order() -> None:
    profile = load_profile()
    assert profile.structure_names[-1] == "Other"
    assert {"Quadruped", "Biped", "Hand", "Aerial Manipulator", "Legged Mobile Manipulator"} <= set(
        profile.structure_names
    )
    assert profile.role("sensor_type") == "sensor_type"


def with_wheel(pattern: str) -> str:
    """The shipped profile with its wheel pattern replaced by ``pattern`` (YAML text)."""
    line = next(line for line in SHIPPED.splitlines() if line.startswith("  wheel: "))
    return SHIPPED.replace(line, f"  wheel: {pattern}")


def test_every_problem_of_a_profile_is_reported_with_its_location() -> None:
    text = (
        with_wheel("'(unclosed'")
        .replace(
            "when: {legs: {min: 4}, serial_legs: {max: 7}, arms: 0}", "when: {paws: 4, arms: 0}"
        )
        .replace("doubt_factor: 0.8", "doubt_factor: 3")
        .replace(
            "{kind: imu, types: [sensor_msgs/Imu]}",
            "{kind: imu, types: [sensor_msgs/Imu], direction: sideways}",
        )
    )
    with pytest.raises(ProfileError) as caught:
        parse_profile(parse_document(text, "mine.yaml"))
    found = {f.location.path: f for f in caught.value.faults}
    assert "invalid regular expression" in found["patterns.wheel"].message
    assert "unknown feature 'paws'" in found["structures[8].when.paws"].message
    assert "doubt_factor" in found["doubt_factor"].message
    assert any("direction must be one of" in f.message for f in caught.value.faults)
    assert all(f.location.file == "mine.yaml" and f.location.line for f in caught.value.faults)
    assert len(caught.value.faults) == 4


def test_unknown_keys_and_unknown_structures_are_named() -> None:
    text = SHIPPED.replace("doubt_factor: 0.8", "doubt_factor: 0.8\nthreshold: 3").replace(
        "      Quadruped: Walking", "      Quadropod: Walking"
    )
    with pytest.raises(ProfileError) as caught:
        parse_profile(parse_document(text, "p.yaml"))
    messages = [f.message for f in caught.value.faults]
    assert any("unknown profile field 'threshold'" in m for m in messages)
    assert any("unknown structure 'Quadropod' (did you mean 'Quadruped'?)" in m for m in messages)


def frames_block() -> str:
    """The shipped profile's ``sensors.frames`` block (its comment lines and rules)."""
    start = SHIPPED.index("  # A link the description only draws")
    return SHIPPED[start : SHIPPED.index("  # Plugins publishing simulation ground truth")]


def test_a_profile_without_frame_rules_reads_no_frame_and_a_bad_rule_is_located() -> None:
    without = parse_profile(parse_document(SHIPPED.replace(frames_block(), ""), "p.yaml"))
    assert without.frame_rules == ()
    bad = SHIPPED.replace(frames_block(), "  frames:\n    - {kind: imu, match: '(?=imu)'}\n")
    with pytest.raises(ProfileError) as caught:
        parse_profile(parse_document(bad, "p.yaml"))
    (fault,) = caught.value.faults
    assert fault.location.path == "sensors.frames[0].match"
    assert "invalid regular expression" in fault.message


def test_a_profile_that_is_not_a_mapping_is_refused() -> None:
    with pytest.raises(ProfileError):
        parse_profile(parse_document("- a\n- b\n", "list.yaml"))


def test_a_catastrophic_user_pattern_runs_without_backtracking() -> None:
    # ^(a+)+$ takes Python's re some 13 s on 29 letters and a '!'; RE2 answers at once.
    text = with_wheel("'^(a+)+$'")
    profile = parse_profile(parse_document(text, "mine.yaml"))
    pattern = profile.pattern("wheel")
    assert pattern is not None
    assert not pattern.search("a" * 29 + "!")
    assert pattern.search("a" * 29)


def test_a_pattern_needing_backtracking_is_refused_with_its_location() -> None:
    text = with_wheel("'(?<=left_)wheel'")
    with pytest.raises(ProfileError) as caught:
        parse_profile(parse_document(text, "mine.yaml"))
    fault = next(f for f in caught.value.faults if f.location.path == "patterns.wheel")
    assert fault.location.file == "mine.yaml"
    assert "no lookaround or backreferences" in fault.message


def the_fault(text: str) -> Fault:
    """The one located fault of a profile written as ``text``."""
    with pytest.raises(ProfileError) as caught:
        parse_profile(parse_document(text, "p.yaml"))
    [fault] = caught.value.faults
    return fault


def test_the_navigation_guess_is_optional_and_its_fields_are_checked() -> None:
    start = SHIPPED.index("  navigation:")
    without = parse_profile(parse_document(SHIPPED[:start], "plain.yaml"))
    assert without.navigation is None
    shipped = load_profile().navigation
    assert shipped is not None
    assert shipped.control == "Waypoint"
    assert dict(shipped.needs)["flight"] == ("odometry", "gps")
    assert dict(shipped.needs)["wheels"] == ("lidar", "gps")
    text = SHIPPED.replace("    control: Waypoint\n", "    control: Waypoint\n    guess: yes\n")
    fault = the_fault(text)
    assert fault.location.path == "motion.navigation.guess"
    assert "unknown navigation field 'guess'" in fault.message


@pytest.mark.parametrize("degrees", [-1, 360])
def test_a_field_of_view_no_camera_can_have_is_a_located_fault(degrees: int) -> None:
    text = SHIPPED.replace("wider_than: 180}", f"wider_than: {degrees}}}")
    fault = the_fault(text)
    assert fault.location.path.endswith(".wider_than")
    assert f"0 to 359 degrees, got {degrees}" in fault.message


def test_a_range_no_ranger_can_have_is_a_located_fault() -> None:
    text = SHIPPED.replace("max_range: 1}", "max_range: 0}")
    fault = the_fault(text)
    assert fault.location.path.endswith(".max_range")
    assert "max_range must be 1 metre or more, got 0" in fault.message


def test_a_navigation_need_for_nothing_that_moves_a_body_is_a_located_fault() -> None:
    text = SHIPPED.replace("      wheels: [lidar, gps]\n", "      wheel: [lidar, gps]\n")
    fault = the_fault(text)
    assert fault.location.path == "motion.navigation.needs.wheel"
    assert "unknown navigation source 'wheel'" in fault.message
    assert "wheels" in fault.message


@pytest.mark.parametrize(
    ("written", "path"),
    [
        ("unless: 'compute_?cartesian", "motion.packages[1].unless"),
        ("per_joint: '", "motion.gait.per_joint"),
    ],
)
def test_a_pattern_re2_cannot_run_in_the_new_keys_is_a_located_fault(
    written: str, path: str
) -> None:
    fault = the_fault(SHIPPED.replace(written, written.replace("'", "'(?<=x)", 1), 1))
    assert fault.location.path == path
    assert fault.location.line is not None
    assert "invalid regular expression" in fault.message


def test_a_gait_may_name_the_controllers_of_a_joints_own_and_a_flight_need_not() -> None:
    gait, flight = load_profile().gait, load_profile().flight
    assert gait is not None
    assert gait.per_joint is not None
    assert gait.per_joint.search("type: effort_controllers/JointPositionController")
    assert not gait.per_joint.search("type: effort_controllers/JointGroupPositionController")
    assert flight is not None
    assert flight.per_joint is None


@pytest.mark.parametrize(
    ("key", "software", "controllers", "field"),
    [
        (
            "gait",
            "ros2 launch dog walking.launch.py",
            "type: forward_command_controller/X",
            "stance",
        ),
        (
            "flight",
            "rosrun mavros mavros_node",
            "type: velocity_controllers/JointVelocityController",
            "autopilot",
        ),
    ],
)
def test_each_software_rule_is_optional_and_its_fields_are_checked(
    key: str, software: str, controllers: str, field: str
) -> None:
    start = SHIPPED.index(f"  {key}:\n")
    found = re.search(r"\n  \S", SHIPPED[start + 1 :])
    assert found is not None
    end = start + 1 + found.start() + 1  # up to the next key or comment of `motion`
    assert (
        getattr(parse_profile(parse_document(SHIPPED[:start] + SHIPPED[end:], "p.yaml")), key)
        is None
    )
    shipped = getattr(load_profile(), key)
    assert shipped.shipped.find(software) is not None
    assert shipped.controllers.find(controllers) is not None
    fault = the_fault(SHIPPED.replace(f"  {key}:\n", f"  {key}:\n    {field}: yes\n"))
    assert fault.location.path == f"motion.{key}.{field}"
    assert f"unknown {key} field '{field}'" in fault.message


def test_package_rules_are_optional_and_their_structures_are_checked() -> None:
    start = SHIPPED.index("  packages:")
    assert parse_profile(parse_document(SHIPPED[:start], "plain.yaml")).package_controls == ()
    shipped = load_profile().package_controls
    assert [rule.control for rule in shipped] == [
        "Waypoint",
        "Waypoint",
        "Waypoint",
        "Waypoint",
        "Waypoint",
        "velocity",
        "velocity",
        "navigation velocity",
        "End Effector",
        "End Effector",
        "End Effector",
        "End Effector",
    ]
    assert "Manipulator" in shipped[0].not_for
    # A rule may leave out the files another pattern finds text in.
    assert shipped[1].unless is not None
    assert shipped[1].unless.search("import moveit_commander")
    assert shipped[5].unless is None
    text = SHIPPED.replace(
        "      not_for: [Manipulator, Pan/Tilt Unit, Gripper, Hand, Torso]\n",
        "      not_for: [Manipulater, Pan/Tilt Unit, Gripper, Hand, Torso]\n",
        1,
    )
    fault = the_fault(text)
    assert fault.location.path == "motion.packages[0].not_for[0]"
    assert "unknown structure 'Manipulater' (did you mean 'Manipulator'?)" in fault.message
    # The structures a rule is read for only are checked as well.
    listed = "      only_for: [UGV, Mobile Manipulator, Other]\n"
    only = SHIPPED.replace(listed, "      only_for: [UVG]\n", 1)
    assert only != SHIPPED
    fault = the_fault(only)
    assert fault.location.path.endswith("].only_for[0]")
    assert "unknown structure 'UVG'" in fault.message


def test_body_package_words_are_optional_and_name_only_known_media() -> None:
    start = SHIPPED.index("body_packages:")
    assert parse_profile(parse_document(SHIPPED[:start], "plain.yaml")).body_packages == ()
    assert [medium for medium, _ in load_profile().body_packages] == [
        "flight",
        "underwater",
        "surface",
        "ground",
    ]
    text = SHIPPED.replace("  surface: '(^|[^a-z])(usvs", "  surfce: '(^|[^a-z])(usvs", 1)
    assert text != SHIPPED
    fault = the_fault(text)
    assert fault.location is not None
    assert fault.location.path == "body_packages.surfce"
    assert fault.location.line is not None


# ---- a file that is no profile is named, never quoted (issue 36.13) ---------------------------

PASSWD = "root:x:0:0:the-secret-line:/root:/bin/bash\ndaemon:x:1:1::/:/bin/false\n"


@pytest.mark.parametrize(
    ("text", "got"),
    [
        (PASSWD, "a single value"),
        ("the-secret-password\n", "a single value"),
        ("- the-secret-one\n- the-secret-two\n", "a list"),
    ],
    ids=["/etc/passwd", "a scalar", "a list"],
)
def test_a_file_that_is_no_mapping_is_no_profile_and_quoted_nowhere(text: str, got: str) -> None:
    with pytest.raises(ProfileError) as caught:
        parse_profile(parse_document(text, "secret"))
    assert str(caught.value) == (
        "secret:1:1: not an identification profile: expected a mapping of fields at the top "
        f"level, got {got}"
    )


def test_a_profile_extending_a_file_that_is_no_profile_quotes_nothing_of_it(tmp_path: Path) -> None:
    # /etc/shadow's lines end in ':': a mapping whose keys are the secrets.
    (tmp_path / "shadow").write_text("root:$6$the-secret-hash:19000:0:99999:7:::\n")
    own = tmp_path / "own.yaml"
    own.write_text("extends: shadow\ncharacteristics: {}\n")
    with pytest.raises(SolverError) as caught:
        load_profile(own)
    assert str(caught.value) == (
        f"{own}:1:10: extends: cannot read the profile it extends ('shadow'): "
        f"{tmp_path / 'shadow'}:1:1: not an identification profile: it has no "
        "'characteristics:' field"
    )


def test_a_pattern_that_reads_past_the_word_it_reports_shows_its_shown_group() -> None:
    from solver.identify.profile import Pattern

    pattern = Pattern(r"key_teleop|(?P<shown>joy_teleop)[\s\S]{0,1000}?cmd_vel")
    assert pattern.find("joy_teleop:\n  topic_name: /cmd_vel\n") == "joy_teleop"
    assert pattern.find("Node(package='key_teleop')") == "key_teleop"
    assert pattern.find("joy_teleop:\n  topic_name: /pan/commands\n") is None


@pytest.mark.parametrize(
    ("name", "wing"),
    [
        ("main_wing_joint", True),
        ("rwing_joint", True),
        ("fixedwing/base_link", True),
        ("left_aileron", True),
        ("boom_swing_joint", False),
        ("rr_swing_link", False),
        ("state_following_offset", False),
        ("mowing_blade_joint", False),
    ],
)
def test_the_default_profile_names_a_wing_not_a_swing_nor_a_word_ending_in_wing(
    name: str, wing: bool
) -> None:
    from solver.identify.profile import PartMatcher

    parts_of = PartMatcher(load_profile().patterns)
    assert ("wing" in parts_of(name)) is wing
