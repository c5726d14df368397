"""Motion controls from a description alone: declared controllers first, then what the joints'
roles show; a guess says it is one."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from solver.files.yamlio import parse_document
from solver.identify import identify_urdf
from solver.identify.profile import parse_profile
from solver.identify.readers.urdf import parse_urdf
from tests.conftest import RULES
from tests.identify import builders
from tests.identify.builders import RobotText

SHIPPED = (RULES / "identification.yaml").read_text(encoding="utf-8")


def controls(robot: RobotText) -> dict[str, str]:
    return {c.motion_control: c.source for c in identify_urdf(robot.text()).motion_controls}


@pytest.mark.parametrize(
    ("build", "expected"),
    [
        (builders.caster_base, {"Driving"}),
        (builders.surface_vessel, {"Driving"}),
        (builders.underwater_vehicle, {"Driving"}),
        (builders.manipulator, {"Joint", "End Effector"}),
        (builders.quadrotor, {"Flight"}),
        (builders.tilt_rotor, {"Flight"}),
        (builders.hand, {"Joint"}),
    ],
    ids=[
        "wheels",
        "thrusters on a hull",
        "thrusters",
        "arm with gripper",
        "rotors",
        "tilt rotors",
        "hand",
    ],
)
def test_motion_controls_come_from_the_roles_a_description_declares(
    build: Callable[[], RobotText], expected: set[str]
) -> None:
    assert set(controls(build())) == expected


def test_a_declared_drive_plugin_is_the_evidence_not_the_wheels_it_drives() -> None:
    robot = builders.ugv()
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    assert controls(robot) == {"Driving": "urdf: drive plugin libgazebo_ros_diff_drive.so"}


def test_wheels_no_controller_drives_are_named_as_the_evidence() -> None:
    assert controls(builders.ugv()) == {"Driving": "urdf: 4 wheel joint(s) that turn"}


def test_end_effector_goals_read_from_an_arm_say_they_are_a_guess() -> None:
    found = controls(builders.manipulator())
    assert found["Joint"] == "urdf: 1 arm(s) of actuated joints"
    assert found["End Effector"] == (
        "urdf: likely, not declared: an arm of 6 joints or more ending in a gripper"
    )


def test_an_arm_of_five_joints_with_a_gripper_shows_joint_goals_only() -> None:
    robot = RobotText("arm5")
    builders.arm(robot, robot.root, joints=5)
    assert set(controls(robot)) == {"Joint"}


def test_a_pan_tilt_unit_alone_is_aimed_by_its_joints() -> None:
    assert controls(builders.pan_tilt_only()) == {
        "Joint": "urdf: likely, not declared: a pan/tilt unit alone, aimed on command"
    }
    # A gimbal under a drone, or a pan/tilt unit beside a gripper, aims for something else.
    drone = builders.quadrotor()
    tip = drone.chain(drone.root, ["gimbal_pan", "gimbal_tilt"])
    drone.fixed(tip, "camera_link")
    assert "Joint" not in controls(drone)
    rig = builders.pan_tilt_only()
    rig.chain(rig.root, ["gripper_finger_joint"], "prismatic")
    assert all("pan/tilt" not in source for source in controls(rig).values())
    # Nor a sensor mast on a hull in water, or a head beside a limb of no name.
    mast = builders.underwater_vehicle()
    mast.chain(mast.root, ["pan_joint", "tilt_joint"])
    assert all("pan/tilt" not in source for source in controls(mast).values())
    beside = builders.pan_tilt_only()
    beside.chain(beside.root, ["j1"])
    assert all("pan/tilt" not in source for source in controls(beside).values())


def test_a_pan_tilt_head_on_a_floating_base_is_not_aimed_alone() -> None:
    # A gimbal on a body a simulator floats (a drone's, its rotors trimmed): no pan/tilt unit.
    robot = RobotText("floating_gimbal", root="world")
    base = robot.joint("world_joint", "floating", "world", "base_link")
    robot.fixed(base, "imu_link")
    robot.chain(base, ["gimbal_pan", "gimbal_tilt"])
    assert "Joint" not in controls(robot)


def test_a_pan_tilt_head_with_transmissions_is_not_joint_control() -> None:
    # A camera's pan/tilt points a sensor; it is not a motion control of the robot.
    robot = builders.ugv()
    robot.chain(robot.root, ["camera_pan_joint", "camera_tilt_joint"])
    robot.add(builders.transmission("camera_pan_joint"))
    robot.add(builders.transmission("camera_tilt_joint"))
    assert set(controls(robot)) == {"Driving"}


def test_arm_joints_with_transmissions_are_the_evidence_for_joint_control() -> None:
    robot = builders.mobile_manipulator()
    for name in ("shoulder_pan", "shoulder_lift", "elbow", "head_pan", "head_tilt"):
        robot.add(builders.transmission(name))
    # The head's two transmissions are not counted; the arm's three are.
    assert controls(robot)["Joint"] == "urdf: 3 limb joint(s) a controller drives"


def test_transmissions_on_the_legs_of_a_walker_carry_its_gait_not_joint_commands() -> None:
    robot = builders.quadruped()
    for corner in ("FL", "FR", "RL", "RR"):
        for joint in ("hip", "thigh", "calf"):
            robot.add(builders.transmission(f"{corner}_{joint}"))
    assert controls(robot) == {"Walking": "urdf: likely, not declared: 4 legs to walk on"}


def test_an_arm_on_a_walker_with_transmissions_is_joint_control_and_its_legs_are_not() -> None:
    robot = builders.legged_manipulator()
    for joint in ("FL_hip", "FR_hip", "RL_hip", "RR_hip", "shoulder_pan", "elbow"):
        robot.add(builders.transmission(joint))
    assert controls(robot)["Joint"] == "urdf: 2 limb joint(s) a controller drives"


def test_one_leg_with_transmissions_walks_nowhere_and_its_joints_take_commands() -> None:
    robot = RobotText("leg_rig")
    builders.leg(robot, robot.root, "test", ("hip", "knee", "ankle"))
    for joint in ("test_hip", "test_knee", "test_ankle"):
        robot.add(builders.transmission(joint))
    assert controls(robot) == {"Joint": "urdf: 3 limb joint(s) a controller drives"}


def transformable_multirotor() -> RobotText:
    """Three modules joined by driven hinges, each carrying a tilting rotor (a gimbal)."""
    robot = RobotText("modules")
    link = robot.root
    for i in range(3):
        gimbal = robot.chain(link, [f"gimbal{i}"])
        robot.joint(f"rotor{i}", "continuous", gimbal, f"rotor{i}_link")
        if i < 2:
            link = robot.chain(link, [f"hinge{i}"])
            robot.add(builders.transmission(f"hinge{i}"))
        robot.add(builders.transmission(f"gimbal{i}"))
    return robot


def test_driven_joints_that_only_carry_rotors_are_flight_not_joint_control() -> None:
    result = identify_urdf(transformable_multirotor().text())
    assert result.structure == "UAV"
    assert {role.joint: role.role for role in result.roles}["hinge0"] == "trunk"
    assert {c.motion_control for c in result.motion_controls} == {"Flight"}


def tracked_with_flippers() -> RobotText:
    """A tracked base with a driven flipper at each corner of its hull."""
    robot = RobotText("crawler")
    robot.add(builders.model_plugin("tracks", "libSimpleTrackedVehiclePlugin.so"))
    for corner in ("fl", "fr", "rl", "rr"):
        robot.chain(robot.root, [f"flipper_{corner}_j", f"flipper_{corner}_motor_j"])
        robot.add(builders.transmission(f"flipper_{corner}_j"))
    return robot


def test_a_tracked_bases_flippers_are_driven_limbs_not_the_fingers_of_a_hand() -> None:
    result = identify_urdf(tracked_with_flippers().text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert result.body.fingers == ()
    assert {role.role for role in result.roles} == {"other"}
    assert controls(tracked_with_flippers()) == {
        "Driving": "urdf: drive plugin libSimpleTrackedVehiclePlugin.so",
        "Joint": "urdf: 4 limb joint(s) a controller drives",
    }


LIDAR = builders.gazebo_sensor("laser", "ray", "front_laser")
GUESS = "urdf: likely, not declared: {} and a {} sensor, what navigation needs"


def test_a_driven_base_with_a_lidar_could_take_waypoints_and_says_it_is_a_guess() -> None:
    robot = builders.ugv()
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    robot.add(LIDAR)
    assert controls(robot)["Waypoint"] == GUESS.format("Driving", "lidar")


def test_a_driven_base_with_a_camera_only_shows_no_waypoints() -> None:
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("cam", "camera", "front_camera"))
    assert set(controls(robot)) == {"Driving"}


def test_a_lidar_on_an_arm_is_no_navigation() -> None:
    robot = builders.manipulator()
    robot.add(LIDAR)
    assert "Waypoint" not in controls(robot)


def test_a_multirotor_with_odometry_could_fly_to_waypoints() -> None:
    robot = builders.quadrotor()
    robot.add(builders.model_plugin("odometry_sensor", "librotors_gazebo_odometry_plugin.so"))
    assert controls(robot)["Waypoint"] == GUESS.format("Flight", "odometry")


def test_a_vehicle_in_water_with_a_doppler_velocity_log_could_follow_waypoints() -> None:
    robot = builders.underwater_vehicle()
    robot.add(builders.model_plugin("dvl", "libuuv_gazebo_ros_dvl_plugin.so"))
    found = controls(robot)
    assert found["Driving"] == "urdf: 1 thruster(s)"
    assert found["Waypoint"] == GUESS.format("Driving", "dvl")
    assert "Waypoint" not in controls(builders.underwater_vehicle())


LIMIT = '<limit lower="-10" upper="10" effort="1" velocity="1"/>'
GPS = builders.gazebo_sensor("gps_link", "gps", "gps")


def test_a_driven_base_with_a_gps_could_follow_waypoints_outdoors() -> None:
    robot = builders.ugv()
    robot.add(GPS)
    assert controls(robot)["Waypoint"] == GUESS.format("Driving", "gps")


@pytest.mark.parametrize(
    "build",
    [builders.surface_vessel, builders.underwater_vehicle],
    ids=["vessel", "underwater"],
)
def test_a_gps_on_a_vessel_shows_no_waypoints(
    build: Callable[[], RobotText],
) -> None:
    # A GPS fixes a vessel only at the surface: by itself it is no sign of navigation software.
    robot = build()
    robot.add(GPS)
    assert "Waypoint" not in controls(robot)


def test_a_multirotor_with_a_gps_could_fly_missions_of_waypoints() -> None:
    robot = builders.quadrotor()
    robot.add(GPS)
    assert controls(robot)["Waypoint"] == GUESS.format("Flight", "gps")


def test_a_multirotor_with_neither_odometry_nor_a_gps_shows_no_waypoints() -> None:
    robot = builders.quadrotor()
    robot.add(builders.gazebo_sensor("camera_link", "camera", "camera"))
    assert "Waypoint" not in controls(robot)


def test_a_navigation_need_named_by_a_control_holds_for_every_source_of_it() -> None:
    text = SHIPPED.replace("      thrusters: [lidar, dvl]\n", "      Driving: [gps]\n")
    profile = parse_profile(parse_document(text, "mine.yaml"))
    robot = builders.surface_vessel()
    robot.add(GPS)
    found = identify_urdf(robot.text(), profile=profile).motion_controls
    assert {c.motion_control: c.source for c in found}["Waypoint"] == GUESS.format("Driving", "gps")


@pytest.mark.parametrize(
    ("build", "legs"),
    [(builders.quadruped, 4), (builders.biped, 2), (builders.humanoid, 2)],
    ids=["quadruped", "biped", "humanoid"],
)
def test_legs_show_the_body_walks_and_say_it_is_a_guess(
    build: Callable[[], RobotText], legs: int
) -> None:
    assert controls(build())["Walking"] == f"urdf: likely, not declared: {legs} legs to walk on"


def sprawled_walker(legs: int, hip_axis: str = "0 0 1") -> str:
    """``legs`` legs of three joints around a body, each swung first about ``hip_axis`` (the
    vertical: a coxa, as a hexapod's or a spider's is) then lifted about level axes, its foot
    further out than its hip."""

    def places(x: float, y: float) -> tuple[tuple[str, str], ...]:
        level = f"{-y:.3f} {x:.3f} 0"
        return (
            (f"{0.1 * x} {0.1 * y} 0", hip_axis),
            (f"{0.05 * x} {0.05 * y} 0", level),
            (f"{0.1 * x} {0.1 * y} -0.05", level),
        )

    return builders.ring_of_legs("crawler", legs, places)


@pytest.mark.parametrize("legs", [6, 4])
def test_sprawled_legs_swung_about_the_vertical_first_take_joint_commands_beside_the_gait(
    legs: int,
) -> None:
    found = identify_urdf(sprawled_walker(legs)).motion_controls
    assert {c.motion_control: c.source for c in found} == {
        "Walking": f"urdf: likely, not declared: {legs} legs to walk on",
        "Joint": f"urdf: likely, not declared: {legs} sprawled legs, each swung about the "
        "vertical first, commanded joint by joint",
    }


def test_legs_under_a_body_lifted_about_a_level_axis_first_only_walk() -> None:
    # A mammal's hip rolls its leg out first (about the body's long axis): no sprawl.
    found = identify_urdf(sprawled_walker(4, hip_axis="1 0 0")).motion_controls
    assert [c.motion_control for c in found] == ["Walking"]


def test_two_legs_whose_hips_yaw_first_stand_under_a_biped_and_only_walk() -> None:
    found = identify_urdf(sprawled_walker(2)).motion_controls
    assert [c.motion_control for c in found] == ["Walking"]


def test_one_leg_walks_nowhere() -> None:
    robot = RobotText("leg_rig")
    builders.leg(robot, robot.root, "rig", ("hip", "thigh", "calf"))
    assert "Walking" not in controls(robot)


def test_casters_and_wheels_are_no_legs_to_walk_on() -> None:
    assert "Walking" not in controls(builders.caster_base())


def test_a_grippers_driven_joint_takes_joint_goals() -> None:
    robot = builders.one_motion_gripper()
    robot.add(builders.transmission("r1"))
    assert "Joint" in controls(robot)


def test_a_short_chain_on_a_flying_body_is_the_vehicles_not_joint_control() -> None:
    # A 1-joint gimbal or control surface with a transmission on a multirotor.
    robot = builders.quadrotor()
    robot.chain(robot.root, ["gimbal_motor"])
    robot.add(builders.transmission("gimbal_motor"))
    assert "Joint" not in controls(robot)


def test_legs_and_a_lidar_are_no_guess_of_waypoints_wheels_and_a_lidar_are() -> None:
    walker = builders.quadruped()
    walker.add(builders.gazebo_sensor("base_link", "ray", "laser"))
    found = controls(walker)
    assert "Walking" in found
    assert "Waypoint" not in found
    rover = builders.ugv()
    rover.add(builders.gazebo_sensor("base_link", "ray", "laser"))
    assert controls(rover)["Waypoint"] == (
        "urdf: likely, not declared: Driving and a lidar sensor, what navigation needs"
    )


@pytest.mark.parametrize(
    ("plugin", "control"),
    [
        ("gz-sim-velocity-control-system", "Driving"),
        ("gz-sim-diff-drive-system", "Driving"),
        ("gz-sim-multicopter-velocity-control-system", "Flight"),
    ],
)
def test_gazebo_sim_spellings_of_drive_and_flight_plugins_are_read(
    plugin: str, control: str
) -> None:
    robot = RobotText("sim")
    robot.add(builders.model_plugin("system", plugin))
    found = controls(robot)
    assert control in found
    assert ({"Driving", "Flight"} - {control}).isdisjoint(found)


def test_a_plugin_listing_thruster_entries_drives_a_vessel_whatever_it_is_called() -> None:
    # Named for no vessel: a vessel's name alone is driven (its propulsion not drawn).
    robot = builders.RobotText("platform")
    robot.joint("fwd_joint", "revolute", robot.root, "fwd", '<limit lower="-0.5" upper="0.5"/>')
    robot.fixed(robot.root, "aft")
    robot.add(
        builders.model_plugin(
            "body_control",
            "libfloating_body_control.so",
            "<thruster><name>fwd</name></thruster><thruster><name>aft</name></thruster>",
        )
    )
    found = identify_urdf(robot.text())
    assert found.structure in ("Surface Vessel", "Underwater Vehicle")
    assert found.body is not None
    assert found.body.thrusters
    assert "Driving" in {c.motion_control for c in found.motion_controls}
    # The same plugin with a list of anything else drives nothing.
    other = robot.text().replace("thruster>", "light>")
    assert "Driving" not in {c.motion_control for c in identify_urdf(other).motion_controls}


def planar_base() -> builders.RobotText:
    """A base the model moves in the plane: root joints along x and y and about z."""
    robot = builders.RobotText("omni", root="world")
    link = robot.joint("base_x", "prismatic", "world", "x_link", '<axis xyz="1 0 0"/>' + LIMIT)
    link = robot.joint("base_y", "prismatic", link, "y_link", '<axis xyz="0 1 0"/>' + LIMIT)
    link = robot.joint("base_yaw", "continuous", link, "base_link", '<axis xyz="0 0 1"/>')
    robot.fixed(link, "front_left_wheel")
    return robot


def test_a_base_the_model_moves_in_the_plane_is_mobile_but_commanded_by_nothing() -> None:
    # A planner's convention (Drake's, a whole-body MoveIt model's), as an SRDF's planar
    # virtual joint is: no command reaches the base through it (measured, the journal).
    result = identify_urdf(planar_base().text())
    assert result.body is not None
    assert result.body.planar_base
    assert controls(planar_base()) == {}


def test_a_profile_may_take_a_base_moved_in_the_plane_for_a_driven_one() -> None:
    text = SHIPPED.replace("planar_base: []", "planar_base: Driving")
    profile = parse_profile(parse_document(text, "mine.yaml"))
    found = identify_urdf(planar_base().text(), profile=profile)
    assert {c.motion_control: c.source for c in found.motion_controls} == {
        "Driving": "urdf: a base moved in the plane"
    }


FOOT_EFFECTORS = (
    '<end_effector name="l_foot" parent_link="l_leg_foot" group="l_leg"/>'
    '<end_effector name="r_foot" parent_link="r_leg_foot" group="r_leg"/>'
)


def long_armed_humanoid() -> RobotText:
    """Two 6-joint legs, two 6-joint arms ending in grippers, a 2-joint head."""
    robot = RobotText("long_arms")
    for side in ("l", "r"):
        builders.leg(
            robot,
            robot.root,
            f"{side}_leg",
            ("hip_yaw", "hip_roll", "hip_pitch", "knee", "ankle_pitch", "ankle_roll"),
        )
        builders.arm(robot, robot.root, f"{side}_", 6)
    robot.chain(robot.root, ["neck_yaw", "head_pitch"])
    return robot


def walker_srdf(effectors: str) -> str:
    """A whole-body SRDF of :func:`long_armed_humanoid`: leg and arm groups, ``effectors``."""
    groups = "".join(
        f'<group name="{side}_arm"><chain base_link="base_link" tip_link="{side}_wrist_3_link"/>'
        f'</group><group name="{side}_leg"><chain base_link="base_link" '
        f'tip_link="{side}_leg_ankle_roll_link"/></group>'
        for side in ("l", "r")
    )
    return f'<robot name="long_arms">{groups}{effectors}</robot>'


def test_srdf_groups_each_on_a_leg_say_a_walkers_joints_take_goals() -> None:
    # A walker's MoveIt configuration plans its legs one by one: no arm, no end effector.
    text = builders.quadruped().text()
    groups = "".join(
        f'<group name="{c}_leg"><joint name="{c}_hip"/><joint name="{c}_thigh"/>'
        f'<joint name="{c}_calf"/></group>'
        for c in ("FL", "FR", "RL", "RR")
    )
    srdf = f'<robot name="dog">{groups}</robot>'
    found = identify_urdf(text, srdf_text=srdf, srdf_file="dog.srdf")
    shown = {c.motion_control: c.source for c in found.motion_controls}
    planned = "dog.srdf: planning group(s) FL_leg, FR_leg, RL_leg, RR_leg (each on a leg)"
    assert planned in shown["Joint"]
    assert "End Effector" not in shown
    # Read alone, its legs walk under a gait: no joint goals.
    assert "Joint" not in {c.motion_control for c in identify_urdf(text).motion_controls}
    # A group of one ankle joint plans no leg.
    ankle = (
        '<robot name="dog"><group name="ankle">'
        '<chain base_link="FL_thigh_link" tip_link="FL_calf_link"/></group></robot>'
    )
    alone = identify_urdf(text, srdf_text=ankle, srdf_file="dog.srdf")
    assert "Joint" not in {c.motion_control for c in alone.motion_controls}


def test_an_srdf_whose_end_effectors_are_all_feet_plans_joints_not_cartesian_goals() -> None:
    # A walker's whole-body model (for its balance controller) names where it stands; its arm
    # groups are joint groups, and no end effector is guessed for its arms ending in grippers.
    text = long_armed_humanoid().text()
    found = identify_urdf(text, srdf_text=walker_srdf(FOOT_EFFECTORS), srdf_file="w.srdf")
    shown = {c.motion_control: c.source for c in found.motion_controls}
    assert "End Effector" not in shown
    planned = "w.srdf: planning group(s) l_arm, r_arm (its end effectors are feet only)"
    assert planned in shown["Joint"]
    # An end effector on a hand says the arms take Cartesian goals.
    hand = '<end_effector name="l_hand" parent_link="l_wrist_3_link" group="l_arm"/>'
    with_hand = identify_urdf(text, srdf_text=walker_srdf(FOOT_EFFECTORS + hand))
    assert "End Effector" in {c.motion_control for c in with_hand.motion_controls}


def test_a_bipeds_arms_take_cartesian_goals_only_where_an_srdf_end_effector_is_on_a_hand() -> None:
    # Two legs: the arms move inside the balance of the whole body. Neither 6-joint arms ending
    # in grippers nor SRDF arm groups without a hand end effector say Cartesian goals are offered.
    text = long_armed_humanoid().text()
    alone = {c.motion_control for c in identify_urdf(text).motion_controls}
    assert alone == {"Joint", "Walking"}
    plain = identify_urdf(text, srdf_text=walker_srdf(""), srdf_file="w.srdf")
    shown = {c.motion_control: c.source for c in plain.motion_controls}
    assert "End Effector" not in shown
    assert (
        "w.srdf: planning group(s) l_arm, r_arm (on two legs, no hand end effector)"
        in (shown["Joint"])
    )
    hand = '<end_effector name="l_hand" parent_link="l_wrist_3_link" group="l_arm"/>'
    with_hand = identify_urdf(text, srdf_text=walker_srdf(hand))
    assert "End Effector" in {c.motion_control for c in with_hand.motion_controls}
    # The same arms on four legs (a legged manipulator) are guessed as before.
    robot = builders.quadruped()
    builders.arm(robot, robot.root, "", 6)
    four = {c.motion_control for c in identify_urdf(robot.text()).motion_controls}
    assert "End Effector" in four


def test_an_srdf_naming_only_feet_drops_the_arm_guess_even_without_arm_groups() -> None:
    # A legged manipulator whose SRDF plans no arm group and names only its feet: the guess
    # from the arm's shape (End Effector) is dropped; a hand end effector says it is offered.
    robot = builders.quadruped()
    builders.arm(robot, robot.root, "", 6)
    feet = "".join(
        f'<group name="{c}_leg"><chain base_link="base_link" tip_link="{c}_foot"/></group>'
        f'<end_effector name="{c}_foot" parent_link="{c}_foot" group="{c}_leg"/>'
        for c in ("FL", "FR", "RL", "RR")
    )
    only_feet = identify_urdf(robot.text(), srdf_text=f'<robot name="dog">{feet}</robot>')
    assert "End Effector" not in {c.motion_control for c in only_feet.motion_controls}
    hand = (
        '<group name="arm"><chain base_link="base_link" tip_link="wrist_3_link"/></group>'
        '<end_effector name="hand" parent_link="wrist_3_link" group="arm"/>'
    )
    with_hand = identify_urdf(robot.text(), srdf_text=f'<robot name="dog">{feet}{hand}</robot>')
    shown = {c.motion_control: c.source for c in with_hand.motion_controls}
    assert "<srdf>: end effector(s) hand" in shown["End Effector"]


def telescoping_arm(segments: int, turned: bool = False) -> RobotText:
    """A mobile base with a lift, an arm of ``segments`` prismatic segments sliding along one
    axis (``turned``: each turned a quarter on the last, so each slides another way), a wrist
    and a two-finger gripper."""
    robot = builders.ugv()
    robot.fixed(robot.root, "mast")
    robot.add(
        '<joint name="lift" type="prismatic"><parent link="mast"/><child link="lift_link"/>'
        '<axis xyz="0 0 1"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint>'
        '<link name="lift_link"/>'
    )
    parent = "lift_link"
    for index in range(segments):
        child = f"arm_l{index}"
        rpy = '<origin rpy="1.5708 0 0"/>' if index == 0 or turned else '<origin xyz="0 0 0.01"/>'
        robot.add(
            f'<joint name="arm_joint_{index}" type="prismatic"><parent link="{parent}"/>'
            f'<child link="{child}"/>{rpy}<axis xyz="0 0 1"/>'
            '<limit lower="0" upper="0.1" effort="1" velocity="1"/></joint>'
            f'<link name="{child}"/>'
        )
        parent = child
    robot.add(
        f'<joint name="wrist_yaw" type="revolute"><parent link="{parent}"/>'
        '<child link="wrist_link"/><axis xyz="0 0 1"/>'
        '<limit lower="-3" upper="3" effort="1" velocity="1"/></joint><link name="wrist_link"/>'
    )
    for side in ("left", "right"):
        robot.add(
            f'<joint name="gripper_finger_{side}" type="revolute"><parent link="wrist_link"/>'
            f'<child link="finger_{side}"/><axis xyz="0 0 1"/>'
            '<limit lower="0" upper="1" effort="1" velocity="1"/></joint>'
            f'<link name="finger_{side}"/>'
        )
    return robot


def test_a_telescopes_segments_sliding_along_one_axis_are_one_motion_of_an_arm() -> None:
    # Lift, four segments of one telescope, a wrist: six joints, three motions. No pose of the
    # gripper is reachable in every direction: no Cartesian goal is guessed.
    found = identify_urdf(telescoping_arm(4).text())
    assert found.structure == "Mobile Manipulator"
    assert "End Effector" not in {c.motion_control for c in found.motion_controls}
    # Segments each turned on the last slide in other directions: six motions, a guess.
    turned = identify_urdf(telescoping_arm(4, turned=True).text())
    assert "End Effector" in {c.motion_control for c in turned.motion_controls}


def swivel_modules(*, drive_wheels: int = 0) -> RobotText:
    """A base whose four wheels each hang under a vertical swivel (no transmission, no plugin),
    with ``drive_wheels`` more wheels on the base itself."""
    robot = RobotText("modules")
    for corner in ("front_left", "front_right", "back_left", "back_right"):
        swivel = robot.joint(
            f"caster_{corner}_joint", "continuous", robot.root, f"caster_{corner}_link",
            '<axis xyz="0 0 1"/>',
        )  # fmt: skip
        robot.joint(f"wheel_{corner}_joint", "continuous", swivel, f"wheel_{corner}_link")
    if drive_wheels:
        builders.wheeled_base(robot, drive_wheels)
    return robot


def test_wheels_that_all_hang_under_swivels_are_steered_drive_modules() -> None:
    found = controls(swivel_modules())
    assert set(found) == {"Driving"}
    assert "no other wheel" in found["Driving"]


def test_swivels_beside_wheels_of_their_own_are_casters_and_the_wheels_drive() -> None:
    found = controls(swivel_modules(drive_wheels=2))
    assert "no other wheel" not in found["Driving"]


def climber(interface: str | None) -> RobotText:
    """A ring of four wheels, each on a slide that presses it to a pole; ``interface``: how a
    ``<ros2_control>`` block commands the slides (None: it does not)."""
    robot = RobotText("climber")
    blocks = []
    for corner in ("ne", "nw", "sw", "se"):
        slide = robot.joint(
            f"{corner}_actuator", "prismatic", robot.root, f"{corner}_carriage",
            '<axis xyz="1 0 0"/><limit lower="0" upper="0.04" effort="1" velocity="1"/>',
        )  # fmt: skip
        robot.joint(f"{corner}_wheel_joint", "continuous", slide, f"{corner}_wheel")
        wheel = '<command_interface name="velocity"/>'
        blocks.append(f'<joint name="{corner}_wheel_joint">{wheel}</joint>')
        if interface is not None:
            command = f'<command_interface name="{interface}"/>'
            blocks.append(f'<joint name="{corner}_actuator">{command}</joint>')
    robot.add(f'<ros2_control name="hw" type="system">{"".join(blocks)}</ros2_control>')
    return robot


def test_slides_that_carry_wheels_set_to_a_position_are_joint_control() -> None:
    # A climber's arms press its wheels to the pole: each set to a place, one by one.
    assert set(controls(climber("position"))) == {"Driving", "Joint"}
    # A slide moved by velocity, or not commanded, carries its wheel as a steering mount does.
    assert set(controls(climber("velocity"))) == {"Driving"}
    assert set(controls(climber(None))) == {"Driving"}
    # A rocker set to an angle carries its wheels over the ground: the vehicle's own motion.
    rover = RobotText("rocker_rover")
    rockers = ""
    for side in ("left", "right"):
        rocker = rover.joint(
            f"{side}_rocker_joint", "revolute", rover.root, f"{side}_rocker",
            '<axis xyz="0 1 0"/><limit lower="-0.3" upper="0.3" effort="1" velocity="1"/>',
        )  # fmt: skip
        for end in ("front", "rear"):
            rover.joint(f"{side}_{end}_wheel_joint", "continuous", rocker, f"{side}_{end}_wheel")
        rockers += f'<joint name="{side}_rocker_joint"><command_interface name="position"/></joint>'
    rover.add(f'<ros2_control name="hw" type="system">{rockers}</ros2_control>')
    assert set(controls(rover)) == {"Driving"}


def swinging(wheels_at: tuple[str, ...], driven: bool = True) -> RobotText:
    """A base on four drive wheels with a hinge on each side about its width (y) carrying
    wheels at ``wheels_at`` (their places along x from the hinge), a transmission on each hinge
    when ``driven``."""
    robot = RobotText("crawler")
    for corner, y in (("fl", "0.2"), ("fr", "-0.2"), ("rl", "0.2"), ("rr", "-0.2")):
        x = "0.3" if corner[0] == "f" else "-0.3"
        robot.add(builders.joint_xml(f"{corner}_wheel_joint", "continuous", robot.root,
                                     f"{corner}_wheel", f"{x} {y} 0", "0 1 0"))  # fmt: skip
        robot.links.append(f"{corner}_wheel")
    for side, y in (("left", "0.25"), ("right", "-0.25")):
        robot.add(builders.joint_xml(f"{side}_hinge", "revolute", robot.root, f"{side}_arm",
                                     f"0.3 {y} 0", "0 1 0"))  # fmt: skip
        robot.links.append(f"{side}_arm")
        for i, x in enumerate(wheels_at):
            robot.add(builders.joint_xml(f"{side}_end_wheel_{i}_joint", "continuous",
                                         f"{side}_arm", f"{side}_end_wheel_{i}", f"{x} 0 0",
                                         "0 1 0"))  # fmt: skip
            robot.links.append(f"{side}_end_wheel_{i}")
        if driven:
            robot.add(builders.transmission(f"{side}_hinge"))
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    return robot


def test_driven_hinges_that_swing_a_wheel_at_their_end_are_joint_control() -> None:
    # A flipper raising the wheel at its end, each set one by one.
    assert set(controls(swinging(("0.3",)))) == {"Driving", "Joint"}
    assert controls(swinging(("0.3",)))["Joint"] == "urdf: 2 limb joint(s) a controller drives"
    # No controller on them: nothing commands them (a suspension's arm).
    assert set(controls(swinging(("0.3",), driven=False))) == {"Driving"}
    # A rocker's pivot between its wheels carries them over the ground: the vehicle's motion.
    assert set(controls(swinging(("0.3", "-0.3")))) == {"Driving"}
    # A hinge on the wheel's own line spins with it.
    assert set(controls(swinging(("0",)))) == {"Driving"}


def carried(
    places: tuple[str, ...],
    *,
    axis: str = "0 1 0",
    kind: str = "revolute",
    base: str = "drive",
    rpy: str = "",
    wheel_axis: str = "0 1 0",
) -> RobotText:
    """A base on four drive wheels (``base`` ``drive``: a drive plugin; ``flying``: four rotors
    instead) with one driven joint of ``kind`` about ``axis`` (its frame turned by ``rpy``; a
    position transmission) carrying a wheel (axis ``wheel_axis`` in the joint's frame) at each of
    ``places`` (xyz from the joint)."""
    robot = RobotText("carrier")
    if base == "flying":
        for i in range(4):
            robot.joint(f"rotor_{i}_joint", "continuous", robot.root, f"rotor_{i}")
    else:
        builders.wheeled_base(robot, 4)
        robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    robot.add(builders.joint_xml("hinge", kind, robot.root, "arm", "0.3 0.25 0", axis))
    if rpy:  # the hinge's frame turned on the base: its axis is written in the turned frame
        turned = f'<origin xyz="0.3 0.25 0" rpy="{rpy}"/>'
        robot.extra[-1] = robot.extra[-1].replace('<origin xyz="0.3 0.25 0"/>', turned)
    robot.links.append("arm")
    for i, place in enumerate(places):
        robot.add(builders.joint_xml(f"end_wheel_{i}_joint", "continuous", "arm",
                                     f"end_wheel_{i}", place, wheel_axis))  # fmt: skip
        robot.links.append(f"end_wheel_{i}")
    robot.add(builders.transmission("hinge"))
    return robot


def test_a_hinge_swings_wheels_only_about_their_axis_away_from_it_and_on_one_side() -> None:
    assert set(controls(carried(("0.3 0 0",)))) == {"Driving", "Joint"}
    # A wheel 5 mm off the hinge's line turns with it, as one on the line does.
    assert set(controls(carried(("0.005 0 0",)))) == {"Driving"}
    # A steering hinge turns its wheel about an axis across the wheel's, and so does a hinge
    # rolling a wheel hung below it.
    assert set(controls(carried(("0.3 0 0",), axis="0 0 1"))) == {"Driving"}
    assert set(controls(carried(("0 0 -0.3",), axis="1 0 0"))) == {"Driving"}
    # A hinge whose frame is turned a quarter about x, its axis written along z: its axis is
    # the wheel's (y), not upright; it swings the wheel, it is no steering swivel.
    turned = carried(("0.3 0 0",), axis="0 0 1", rpy="-1.5707963 0 0", wheel_axis="0 0 1")
    assert set(controls(turned)) == {"Driving", "Joint"}
    # Wheels at 0 and 80 degrees either way round the hinge: not all on one side of it.
    spread = ("0.3 0 0", "0.052 0 0.295", "0.052 0 -0.295")
    assert set(controls(carried(spread))) == {"Driving"}
    # A body that flies moves its own parts so (a swinging landing wheel).
    assert "Joint" not in controls(carried(("0.3 0 0",), base="flying"))


def test_a_slide_carrying_a_wheel_is_set_to_a_position_not_swung() -> None:
    # Set one by one (the slide's rule), not swung (a hinge's): listed once.
    robot = carried(("0.3 0 0",), kind="prismatic")
    assert controls(robot)["Joint"] == "urdf: 1 limb joint(s) a controller drives"
    # Moved by velocity, it carries its wheel as a steering mount does.
    robot.extra[-1] = builders.transmission("hinge", "VelocityJointInterface")
    assert set(controls(robot)) == {"Driving"}


def test_the_knees_of_legs_on_wheeled_feet_are_the_gaits_not_swinging_hinges() -> None:
    # Each calf swings the wheel at its foot about a parallel axis, one side: a leg's knee, which
    # the walker's gait drives, not a mount's hinge.
    robot = RobotText("wheel_dog")
    for corner, x, y in (
        ("FL", 0.3, 0.2),
        ("FR", 0.3, -0.2),
        ("RL", -0.3, 0.2),
        ("RR", -0.3, -0.2),
    ):
        links = [f"{corner}_{part}" for part in ("hip", "thigh", "calf", "wheel")]
        places = (f"{x} {y} 0", "0 0 0", "0 0 -0.25", "0 0 -0.25")
        axes = ("1 0 0", "0 1 0", "0 1 0", "0 1 0")
        kinds = ("revolute", "revolute", "revolute", "continuous")
        parent = robot.root
        for link, place, axis, kind in zip(links, places, axes, kinds, strict=True):
            robot.add(builders.joint_xml(f"{link}_joint", kind, parent, link, place, axis))
            robot.add(builders.transmission(f"{link}_joint"))
            robot.links.append(link)
            parent = link
    result = identify_urdf(robot.text())
    assert result.structure == "Quadruped"
    assert "Joint" not in {c.motion_control for c in result.motion_controls}


def rocker_bogie(*, driven_bogies: bool) -> RobotText:
    """A six-wheeled rover whose rocker on each side carries its front wheel and a bogie that
    carries the middle and rear wheels, each rocker driven (and each bogie when
    ``driven_bogies``)."""
    robot = RobotText("rover")
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    for side, y in (("left", "0.3"), ("right", "-0.3")):
        robot.add(builders.joint_xml(f"{side}_rocker_joint", "revolute", robot.root,
                                     f"{side}_rocker", f"0 {y} 0", "0 1 0"))  # fmt: skip
        robot.add(builders.joint_xml(f"{side}_front_wheel_joint", "continuous",
                                     f"{side}_rocker", f"{side}_front_wheel", "0.4 0 -0.2",
                                     "0 1 0"))  # fmt: skip
        robot.add(builders.joint_xml(f"{side}_bogie_joint", "revolute", f"{side}_rocker",
                                     f"{side}_bogie", "-0.2 0 -0.1", "0 1 0"))  # fmt: skip
        for end, x in (("middle", "0.2"), ("rear", "-0.2")):
            robot.add(builders.joint_xml(f"{side}_{end}_wheel_joint", "continuous",
                                         f"{side}_bogie", f"{side}_{end}_wheel", f"{x} 0 -0.1",
                                         "0 1 0"))  # fmt: skip
        parts = ("rocker", "front_wheel", "bogie", "middle_wheel", "rear_wheel")
        robot.links += [f"{side}_{part}" for part in parts]
        robot.add(builders.transmission(f"{side}_rocker_joint"))
        if driven_bogies:
            robot.add(builders.transmission(f"{side}_bogie_joint"))
    return robot


def test_a_rockers_pivot_between_its_front_wheel_and_its_bogie_swings_nothing() -> None:
    # A passive bogie is looked through: the rocker carries three wheels on both sides of it.
    assert set(controls(rocker_bogie(driven_bogies=False))) == {"Driving"}
    # A driven bogie is a point the rocker carries, behind its pivot; the bogie carries a wheel
    # either side of its own.
    assert set(controls(rocker_bogie(driven_bogies=True))) == {"Driving"}


def test_a_flippers_wheel_on_a_spring_is_still_the_flippers() -> None:
    robot = carried(())
    robot.add(builders.joint_xml("tensioner", "revolute", "arm", "tension_arm", "0.25 0 0",
                                 "0 1 0"))  # fmt: skip
    robot.add(builders.joint_xml("end_wheel_joint", "continuous", "tension_arm", "end_wheel",
                                 "0.05 0 0", "0 1 0"))  # fmt: skip
    robot.links += ["tension_arm", "end_wheel"]
    assert controls(robot)["Joint"] == "urdf: 1 limb joint(s) a controller drives"


def test_slides_that_hold_wheels_up_or_move_rotors_are_the_vehicles_own() -> None:
    # Each wheel on an upright slide (a suspension, even one held to a position).
    rover = RobotText("sprung")
    blocks = ""
    for corner in ("fl", "fr", "rl", "rr"):
        slide = rover.joint(
            f"{corner}_suspension", "prismatic", rover.root, f"{corner}_strut",
            '<axis xyz="0 0 1"/><limit lower="-0.05" upper="0.05" effort="1" velocity="1"/>',
        )  # fmt: skip
        rover.joint(f"{corner}_wheel_joint", "continuous", slide, f"{corner}_wheel")
        blocks += f'<joint name="{corner}_suspension"><command_interface name="position"/></joint>'
    rover.add(f'<ros2_control name="hw" type="system">{blocks}</ros2_control>')
    assert set(controls(rover)) == {"Driving"}
    # A quadrotor whose rotor arms slide out.
    drone = RobotText("morphing")
    for i in range(4):
        arm = drone.joint(
            f"arm_{i}", "prismatic", drone.root, f"arm_{i}_link",
            '<axis xyz="1 0 0"/><limit lower="0" upper="0.1" effort="1" velocity="1"/>',
        )  # fmt: skip
        drone.joint(f"rotor_{i}_joint", "continuous", arm, f"rotor_{i}", '<axis xyz="0 0 1"/>')
        drone.add(builders.transmission(f"arm_{i}"))
    assert "Joint" not in controls(drone)
    # A mast lifting a pan/tilt camera, commanded to a position, points a sensor: a head.
    mast = builders.ugv()
    tip = mast.chain(mast.root, ["j1"], "prismatic")
    tip = mast.chain(tip, ["j2", "j3"])
    mast.fixed(tip, "cam_frame")
    mast.add(builders.gazebo_sensor("cam_frame", "camera", "cam"))
    for name in ("j1", "j2", "j3"):
        mast.add(builders.transmission(name))
    assert set(controls(mast)) == {"Driving"}


def forklift(*plugins: tuple[str, str]) -> RobotText:
    """A rover with a fork carriage on a slide; ``plugins``: (file name, joint) of Gazebo
    plugins naming a joint in ``<joint_name>``."""
    robot = builders.ugv()
    robot.joint(
        "fork_joint", "prismatic", robot.root, "fork",
        '<axis xyz="0 0 1"/><limit lower="0" upper="1" effort="1" velocity="1"/>',
    )  # fmt: skip
    for filename, joint in plugins:
        robot.add(builders.model_plugin(filename, filename, f"<joint_name>{joint}</joint_name>"))
    return robot


@pytest.mark.parametrize(
    "filename",
    [
        "gz-sim-joint-controller-system",
        "gz-sim-joint-position-controller-system",
        "libignition-gazebo-joint-position-controller-system.so",
    ],
)
def test_a_joint_a_simulators_joint_controller_commands_is_joint_control(filename: str) -> None:
    assert "Joint" in controls(forklift((filename, "fork_joint")))


def test_a_joint_a_plugin_commands_is_no_lock_whatever_its_limits() -> None:
    robot = forklift(("gz-sim-joint-position-controller-system", "fork_joint"))
    text = robot.text().replace('lower="0" upper="1"', 'lower="0" upper="0"')
    assert parse_urdf(text).joint("fork_joint").movable  # type: ignore[union-attr]
    # A force-commanded controller commands an effort.
    forced = forklift(("gz-sim-joint-controller-system", "fork_joint"))
    forced.add(
        builders.model_plugin(
            "gz-sim-joint-controller-system",
            "gz-sim-joint-controller-system",
            "<joint_name>wheel_left_joint</joint_name><use_force_commands>true</use_force_commands>",
        )
    )
    assert parse_urdf(forced.text()).interfaces("wheel_left_joint") == ("effort",)


def test_an_aircrafts_propeller_a_plugin_spins_is_its_flight_not_joint_control() -> None:
    plane = RobotText("plane")
    for side in ("left", "right"):
        plane.joint(
            f"{side}_aileron_joint", "revolute", plane.root, f"{side}_aileron",
            '<axis xyz="0 1 0"/><limit lower="-0.5" upper="0.5" effort="1" velocity="1"/>',
        )  # fmt: skip
    plane.joint("prop_joint", "continuous", plane.root, "propeller", '<axis xyz="1 0 0"/>')
    plane.add(
        builders.model_plugin(
            "gz-sim-joint-controller-system",
            "gz-sim-joint-controller-system",
            "<joint_name>prop_joint</joint_name>",
        )
    )
    assert "Joint" not in controls(plane)


def test_a_joint_only_a_state_publisher_names_is_commanded_by_nothing() -> None:
    robot = forklift(("gz-sim-joint-state-publisher-system", "fork_joint"))
    assert "Joint" not in controls(robot)
    # What the plugin commands: a position controller to a position, the other by velocity.
    urdf = parse_urdf(
        forklift(
            ("gz-sim-joint-position-controller-system", "fork_joint"),
            ("gz-sim-joint-controller-system", "wheel_left_joint"),
        ).text()
    )
    assert urdf.interfaces("fork_joint") == ("position",)
    assert urdf.interfaces("wheel_left_joint") == ("velocity",)


def test_a_thrust_plugin_that_names_only_the_hull_drives_the_vessel() -> None:
    robot = RobotText("hull")
    robot.add(builders.model_plugin("dyn", "libusv_gazebo_dynamics_plugin.so"))
    robot.add(
        builders.model_plugin(
            "thrust", "libusv_gazebo_thrust_plugin.so", "<bodyName>base_link</bodyName>"
        )
    )
    result = identify_urdf(robot.text())
    assert result.structure == "Surface Vessel"
    assert {c.motion_control for c in result.motion_controls} == {"Driving"}


def test_an_aircrafts_landing_wheels_are_no_driving() -> None:
    plane = builders.tilt_rotor()
    builders.wheeled_base(plane, 3)
    assert set(controls(plane)) == {"Flight"}


def test_a_plugin_moving_an_aircraft_in_the_simulator_is_no_driving() -> None:
    for mover in ("libgazebo_ros_planar_move.so", "gz-sim-velocity-control-system"):
        copter = builders.quadrotor()
        copter.add(builders.model_plugin("mover", mover))
        assert set(controls(copter)) == {"Flight"}


def test_an_aircraft_the_model_moves_in_the_plane_is_flown_not_driven() -> None:
    robot = builders.RobotText("hover", root="odom")
    robot.joint("base_planar", "planar", "odom", "base_link")
    for i in range(4):
        robot.joint(f"rotor_{i}_joint", "continuous", "base_link", f"rotor_{i}")
    assert set(controls(robot)) == {"Flight"}


def test_a_robot_that_flies_and_rolls_on_a_declared_drive_is_driven_and_flown() -> None:
    rolling = builders.quadrotor()
    builders.wheeled_base(rolling, 2)
    rolling.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    assert set(controls(rolling)) == {"Flight", "Driving"}
    geared = builders.quadrotor()
    builders.wheeled_base(geared, 2)
    for side in ("left", "right"):
        geared.add(builders.transmission(f"wheel_{side}_joint", "VelocityJointInterface"))
    assert set(controls(geared)) == {"Flight", "Driving"}


def test_a_force_based_move_plugin_drives_a_base_with_no_wheel_joint() -> None:
    """A holonomic base pushed in the plane by a force plugin on cmd_vel, two arms on it: a
    mobile manipulator, driven (an SRDF's planar virtual joint would be no evidence)."""
    robot = builders.torso()
    robot.add(
        builders.model_plugin(
            "mover", "libgazebo_ros_force_based_move.so", "<commandTopic>cmd_vel</commandTopic>"
        )
    )
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    assert "Driving" in {c.motion_control for c in result.motion_controls}


def test_wheels_all_written_on_fixed_joints_show_no_motion_control() -> None:
    # A trimmed model: the base is a mobile base, with doubt, but nothing in the file moves
    # it (the live tests use it as the base that shows no motion control).
    robot = RobotText("trimmed")
    for side in ("left", "right"):
        robot.joint(f"wheel_{side}_joint", "fixed", robot.root, f"wheel_{side}_link")
    assert "Driving" not in controls(robot)


def test_wheels_written_fixed_beside_a_swivel_caster_show_no_motion_control() -> None:
    text = (
        '<robot name="r"><link name="base_link"/><link name="lw"/><link name="rw"/>'
        '<link name="cs"/><link name="cw"/>'
        + builders.joint_xml("left_wheel_joint", "fixed", "base_link", "lw", "0 0.2 0", "0 1 0")
        + builders.joint_xml("right_wheel_joint", "fixed", "base_link", "rw", "0 -0.2 0", "0 1 0")
        + builders.joint_xml(
            "caster_swivel_joint", "continuous", "base_link", "cs", "-0.3 0 0", "0 0 1"
        )
        + builders.joint_xml(
            "caster_wheel_joint", "continuous", "cs", "cw", "-0.03 0 -0.05", "0 1 0"
        )
        + "</robot>"
    )
    assert "Driving" not in {c.motion_control for c in identify_urdf(text).motion_controls}


def sailboat(*, driven_rudder: bool = True) -> RobotText:
    """A hull at the surface (a sail plugin), no thruster, a rudder and a sail on hinges."""
    robot = RobotText("sloop")
    robot.chain(robot.root, ["rudder_joint"])
    robot.chain(robot.root, ["main_sail_joint"])
    robot.add(builders.model_plugin("sail", "libSailPlugin.so"))
    if driven_rudder:
        robot.add(builders.transmission("rudder_joint"))
    return robot


def test_a_vessel_with_no_thruster_steered_by_a_driven_rudder_is_driven() -> None:
    result = identify_urdf(sailboat().text())
    assert result.structure == "Surface Vessel"
    assert {c.motion_control for c in result.motion_controls} == {"Driving"}
    assert "rudder joint(s) a controller drives" in result.motion_controls[0].source
    # A rudder no controller drives steers nothing an operator commands.
    assert controls(sailboat(driven_rudder=False)) == {}


def test_a_gripper_alone_is_opened_and_closed_on_command_a_guess_said_so() -> None:
    result = identify_urdf(builders.parallel_gripper().text())
    assert result.structure == "Gripper"
    (control,) = result.motion_controls
    assert control.motion_control == "Joint"
    assert "likely, not declared: a gripper or hand alone" in control.source
    # On an arm the arm's joints say Joint; the guess for a lone end effector is not made.
    sources = " ".join(
        c.source for c in identify_urdf(builders.manipulator().text()).motion_controls
    )
    assert "gripper or hand alone" not in sources


def test_a_hand_alone_on_its_wrist_is_opened_and_closed_on_command_a_guess_said_so() -> None:
    result = identify_urdf(builders.forearm_hand().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["wrist"]
    (control,) = result.motion_controls
    assert control.motion_control == "Joint"
    assert "likely, not declared: a gripper or hand alone" in control.source


def test_a_gripper_turned_by_one_joint_of_no_limbs_kind_is_still_a_gripper_alone() -> None:
    # A surgical forceps: a pitch, and two jaws on it.
    robot = RobotText("forceps")
    pitch = robot.chain(robot.root, ["pitch_joint"])
    robot.chain(pitch, ["finger_left_joint"])
    robot.chain(pitch, ["finger_right_joint"])
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [(limb.kind, limb.gripper) for limb in result.body.limbs] == [("other", True)]
    (control,) = result.motion_controls
    assert control.motion_control == "Joint"
    assert "likely, not declared: a gripper or hand alone" in control.source


def test_a_vessel_whose_propulsion_is_not_drawn_is_driven() -> None:
    # A hull, a GPS and an IMU frame, and the buoyancy plugin that floats it: the thrusters are
    # a driver's, not the description's.
    robot = RobotText("hull")
    robot.fixed(robot.root, "gps_link")
    robot.fixed(robot.root, "imu_link")
    robot.add(builders.model_plugin("float", "libbuoyancy_gazebo_plugin.so"))
    result = identify_urdf(robot.text())
    assert result.structure in {"Surface Vessel", "Underwater Vehicle"}
    assert controls(robot) == {"Driving": "urdf: a vessel with no thruster or fin drawn"}
    # A fin drawn (a sailboat's rudder no controller drives) steers nothing: no control.
    robot.chain(robot.root, ["rudder_joint"])
    assert controls(robot) == {}


def tracked_base(*, sprocket: str = "continuous", command: str = "velocity") -> RobotText:
    """Two track-named joints a ros2_control block drives, sprockets too high to be wheels."""
    robot = RobotText("crawler")
    limits = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
    for side in ("left", "right"):
        robot.joint(
            f"{side}_track_joint",
            sprocket,
            robot.root,
            f"{side}_drive_sprocket",
            limits if sprocket == "revolute" else "",
        )
    interfaces = "".join(
        f'<joint name="{side}_track_joint"><command_interface name="{command}"/></joint>'
        for side in ("left", "right")
    )
    robot.add(f'<ros2_control name="base" type="system">{interfaces}</ros2_control>')
    return robot


def test_a_tracks_spinning_sprockets_drive_the_vehicle_not_joint_goals() -> None:
    assert "Joint" not in controls(tracked_base())
    # A track-named joint with limits (a flipper on its hinge) is a limb a person commands;
    # so is one drawn continuous that a controller turns to a position.
    assert "Joint" in controls(tracked_base(sprocket="revolute"))
    assert "Joint" in controls(tracked_base(command="position"))
