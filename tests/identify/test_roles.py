"""Each joint's role comes from what it does (plugins, shape, place) before its name, and the
body from the roles: one small description of the project's own per family."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from solver.identify import identify_urdf
from tests.identify import builders
from tests.identify.builders import RobotText

FAMILIES: list[tuple[Callable[[], RobotText], str]] = [
    (builders.surface_vessel, "Surface Vessel"),
    (builders.underwater_vehicle, "Underwater Vehicle"),
    (builders.propellers_fixed, "Aerial Manipulator"),
    (builders.fixed_wing, "UAV"),
    (builders.tilt_rotor, "UAV"),
    (builders.caster_base, "UGV"),
    (builders.parallel_gripper, "Gripper"),
    (builders.wheel_legged_manipulator, "Legged Mobile Manipulator"),
]


@pytest.mark.parametrize(("build", "structure"), FAMILIES, ids=[f[0].__name__ for f in FAMILIES])
def test_each_family_is_read_from_what_its_joints_do(
    build: Callable[[], RobotText], structure: str
) -> None:
    assert identify_urdf(build().text()).structure == structure


def roles(robot: RobotText) -> dict[str, tuple[str, str]]:
    return {r.joint: (r.role, r.evidence) for r in identify_urdf(robot.text()).roles}


def test_a_joint_a_thruster_plugin_names_is_a_thruster_and_says_which_plugin() -> None:
    found = roles(builders.underwater_vehicle())
    assert found["prop_joint"] == (
        "thruster",
        "<jointName> of thruster plugin libthruster_model.so",
    )
    assert found["surface0"][0] == "fin"


def test_thrusters_named_only_by_name_on_a_hull_are_not_wheels() -> None:
    result = identify_urdf(builders.surface_vessel().text())
    assert result.body is not None
    assert not result.body.wheels
    assert {role.role for role in result.roles} == {"thruster"}


def test_a_swivel_carrying_one_wheel_is_a_passive_caster_not_a_leg() -> None:
    found = roles(builders.caster_base())
    assert found["front_swivel"] == (
        "caster",
        "a vertical swivel carrying only the wheel front_roller",
    )
    assert found["front_roller"][0] == "caster"
    assert found["wheel_left_joint"][0] == "wheel"


def test_a_one_motion_linkage_is_a_gripper_not_a_hand() -> None:
    result = identify_urdf(builders.parallel_gripper().text())
    assert result.body is not None
    assert result.body.finger_motions == 1
    assert roles(builders.parallel_gripper())["right_outer_knuckle_joint"][0] == "finger"


def test_a_boat_is_other_under_the_articles_six_types_with_its_reason() -> None:
    result = identify_urdf(builders.surface_vessel().text())
    assert result.kinematic_type is None
    assert any(line.endswith("Other under it, reason: surface vessel") for line in result.evidence)


def test_the_decision_path_names_each_structure_rule_tried_in_order() -> None:
    result = identify_urdf(builders.caster_base().text())
    assert result.decision[0] == "Surface Vessel: no (needs marine, has 0, needs surface, has 0)"
    assert result.decision[-1] == "UGV: yes (mobile_base, arms = 0, legs = 0)"


def thrusters_by_name() -> RobotText:
    """Four joints named as thrusters on a hull; no plugin, no sensor says where it swims."""
    robot = RobotText("hull")
    for i in range(4):
        robot.joint(f"thruster_{i}_joint", "continuous", robot.root, f"thruster_{i}")
    return robot


def test_a_body_in_water_by_thruster_names_alone_is_underwater_with_doubt() -> None:
    result = identify_urdf(thrusters_by_name().text())
    assert result.structure == "Underwater Vehicle"
    assert result.confidence == pytest.approx(0.85 * 0.8, abs=0.01)
    assert (
        "in water by thruster names alone: no buoyancy or hydrodynamics plugin, "
        "no thruster plugin, no DVL or pressure sensor"
    ) in result.evidence
    assert "doubt: a typical Underwater Vehicle has underwater" in result.evidence


@pytest.mark.parametrize(
    "evidence",
    [
        builders.gazebo_sensor("dvl_link", "dvl", "dvl"),
        builders.gazebo_sensor("base_link", "altimeter", "depth", plugin="libsubsea_pressure.so"),
        builders.model_plugin("water", "libunderwater_object.so"),
        builders.model_plugin("hydro", "gz-sim-hydrodynamics-system"),
    ],
    ids=["a DVL", "a pressure sensor", "an underwater plugin", "hydrodynamics"],
)
def test_underwater_evidence_keeps_an_underwater_reading_certain(evidence: str) -> None:
    robot = thrusters_by_name()
    robot.add(evidence)
    result = identify_urdf(robot.text())
    assert (result.structure, result.confidence) == ("Underwater Vehicle", 0.85)
    assert any(line.startswith("below the surface: ") for line in result.evidence)


def test_flight_words_in_a_plugins_parameters_fly_only_a_body_that_cannot_roll_or_walk() -> None:
    # A vehicle plugin of its own that sets a drone's topics: the one sign the body flies.
    plugin = builders.model_plugin(
        "vehicle", "libmy_vehicle.so", "<cmdTopic>drone/cmd_vel</cmdTopic>"
    )
    body = RobotText("shell")
    body.add(plugin)
    assert identify_urdf(body.text()).structure == "UAV"
    # A rover in a world it shares with a drone: the word names the other robot.
    rover = builders.ugv()
    rover.add(plugin)
    assert identify_urdf(rover.text()).structure == "UGV"
    dog = builders.quadruped()
    dog.add(plugin)
    assert identify_urdf(dog.text()).structure == "Quadruped"
