"""How the body travels: tracks and drive plugins on the ground; wings, rotor-named leaves too
few to fly and flight words in plugins in the air; a hull's thrusters and hints in water; and
what a model trimmed of its moving parts still shows."""

from __future__ import annotations

import math

import pytest

from solver.identify import identify_urdf, load_profile
from solver.identify.actuation import joint_roles
from solver.identify.readers.urdf import parse_urdf
from solver.identify.roles import Role
from solver.identify.tree import JointTree
from solver.identify.vehicle import (
    fixed_wheels,
    grounded,
    listed_thrusters,
    not_rotors,
    surface_hints,
    tracks,
    underwater_hints,
    wings,
)
from tests.identify import builders
from tests.identify.builders import RobotText


def tree_of(robot: RobotText) -> JointTree:
    return JointTree(parse_urdf(robot.text(), strict=False), load_profile())


def test_fixed_wheels_still_make_a_mobile_base_with_doubt() -> None:
    robot = RobotText("trimmed")
    robot.fixed("base_link", "left_wheel")
    robot.fixed("base_link", "right_wheel")
    result = identify_urdf(robot.text())
    assert result.structure == "UGV"
    assert result.confidence == pytest.approx(0.95 * 0.8, abs=0.01)


def test_fixed_propellers_on_a_body_that_cannot_move_are_a_uav_with_doubt() -> None:
    trimmed = RobotText("trimmed quadrotor")
    for i in range(4):
        trimmed.fixed("base_link", f"prop{i}_link")
    result = identify_urdf(trimmed.text())
    assert (result.structure, result.kinematic_type) == ("UAV", "UAV")
    assert result.confidence == pytest.approx(0.95 * 0.8, abs=0.01)


def motor_arms(moving_joint: bool = False, word: str = "motor") -> RobotText:
    """A body of four arms each ending in a link named ``arm<i>_<word>_link``, all fixed (a
    quadcopter a force plugin moves); ``moving_joint`` adds a pan joint somewhere."""
    robot = RobotText("simple_body")
    for i in range(4):
        arm = robot.fixed(robot.root, f"arm{i}_link")
        robot.fixed(arm, f"arm{i}_{word}_link")
    if moving_joint:
        robot.chain(robot.root, ["pan"])
    return robot


def test_motors_fixed_at_the_leaves_of_a_body_where_nothing_moves_fly_it_with_doubt() -> None:
    result = identify_urdf(motor_arms().text())
    assert (result.structure, result.kinematic_type) == ("UAV", "UAV")
    assert result.confidence == pytest.approx(0.95 * 0.8, abs=0.01)
    assert "Flight" in {c.motion_control for c in result.motion_controls}
    # A joint that moves: the motors may turn it, or wheels the model left out; no flight. A
    # word that only begins with motor (a motorcycle's part) is no motor.
    assert identify_urdf(motor_arms(moving_joint=True).text()).structure != "UAV"
    assert identify_urdf(motor_arms(word="motorcycle").text()).structure == "Other"


def test_propellers_fixed_to_every_module_of_a_chain_are_no_trimmed_multirotor() -> None:
    # A screw-driven snake: five units turning one after another, each carrying two fixed
    # `propeller` screws (fresh set 1862). Those on the moving units outnumber those on the
    # hull: the units' parts, not a multirotor's rotors, which all sit on its hull.
    snake = RobotText("snake")
    link = snake.root
    for i in range(5):
        for side in ("left", "right"):
            snake.fixed(link, f"propeller_{i}_{side}")
        if i < 4:
            link = snake.joint(f"unit_{i}", "continuous", link, f"unit_{i}_link",
                               '<axis xyz="0 0 1"/>')  # fmt: skip
    result = identify_urdf(snake.text())
    assert result.body is not None
    assert result.body.fixed_rotors == ()
    assert result.structure != "UAV"
    # A trimmed quadrotor with a one-joint camera tilt keeps its four rotors on the hull.
    tilted = RobotText("trimmed quadrotor")
    for i in range(4):
        tilted.fixed("base_link", f"prop{i}_link")
    tilted.chain("base_link", ["camera_tilt"])
    tilted.fixed("camera_tilt_link", "camera_prop_guard")
    assert len(identify_urdf(tilted.text()).body.fixed_rotors) == 4  # type: ignore[union-attr]


def test_fixed_rotor_links_beside_moving_joints_are_motors_not_flight() -> None:
    legged = RobotText("legged")
    for corner in ("front_left", "front_right", "rear_left", "rear_right"):
        legged.chain("base_link", [f"{corner}_hip", f"{corner}_knee"])
        legged.fixed("base_link", f"{corner}_hip_rotor")
    result = identify_urdf(legged.text())
    assert result.structure == "Quadruped"
    assert result.body is not None
    assert result.body.fixed_rotors == ()


def test_wheels_fixed_below_motor_links_on_a_still_body_are_a_trimmed_base_not_rotors() -> None:
    # Each wheel's joint is named for both links (``fl_motor_link_to_fl_wheel_link_joint``), as
    # an exporter names them; a planar-move plugin slides the base: a ground robot.
    robot = RobotText("omni", root="base_link")
    for corner in ("front_left", "front_right", "back_left", "back_right"):
        motor = robot.fixed("base_link", f"{corner}_motor_link")
        wheel = f"{corner}_wheel_link"
        robot.joint(f"{motor}_to_{wheel}_joint", "fixed", motor, wheel)
    robot.add(builders.model_plugin("mover", "libgazebo_ros_planar_move.so"))
    result = identify_urdf(robot.text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert result.body.fixed_rotors == ()
    assert [c.motion_control for c in result.motion_controls] == ["Driving"]


def thrusters_by_name(count: int = 4) -> RobotText:
    """``count`` joints named as thrusters on a hull; no plugin, no sensor says where it swims."""
    robot = RobotText("hull")
    for i in range(count):
        robot.joint(f"thruster_{i}_joint", "continuous", robot.root, f"thruster_{i}")
    return robot


@pytest.mark.parametrize("count", [5, 8])
def test_more_thrusters_than_a_surface_craft_has_dive_the_body(count: int) -> None:
    """A surface craft has two to four; six or eight push a submersible up and down too."""
    result = identify_urdf(thrusters_by_name(count).text())
    assert result.structure == "Underwater Vehicle"
    fixed = RobotText("sub")
    for i in range(count):
        fixed.fixed(fixed.root, f"vertical{i}_thruster")  # a RoboSub team's, trimmed of joints
    assert identify_urdf(fixed.text()).structure == "Underwater Vehicle"


def test_a_body_in_water_by_thruster_names_alone_floats() -> None:
    """Nothing makes it dive (no water plugin, no DVL or depth gauge, no submersible's name):
    a hull with thrusters, as every such labelled row of the development part is."""
    result = identify_urdf(thrusters_by_name().text())
    assert result.structure == "Surface Vessel"
    assert (
        "floats at the surface: thrusters alone (no water plugin, DVL or depth gauge)"
        in result.evidence
    )
    assert result.confidence == pytest.approx(0.9 * 0.8, abs=0.01)  # with doubt: weak_water
    diver = thrusters_by_name()
    diver.fixed(diver.root, "dvl_link")
    assert identify_urdf(diver.text()).structure == "Underwater Vehicle"
    # A pressure sensor is a diver's depth gauge (or an autopilot's barometer): it may dive.
    gauged = thrusters_by_name()
    gauged.add(builders.gazebo_sensor(gauged.root, "air_pressure", "baro"))
    assert identify_urdf(gauged.text()).structure == "Underwater Vehicle"
    rov = thrusters_by_name()
    rov.name = "rov"
    assert identify_urdf(rov.text()).structure == "Underwater Vehicle"


def hull_of_fixed_thrusters(count: int = 6, *, under_a_joint: bool = False) -> RobotText:
    """A hull whose thrusters are leaf links fixed to it (the propellers left out), pushed by a
    velocity plugin on cmd_vel; ``under_a_joint`` hangs them from a turning link instead."""
    robot = RobotText("hull")
    parent = robot.root
    if under_a_joint:
        parent = robot.chain(robot.root, ["turret"])
    for i in range(count):
        robot.fixed(parent, f"thruster_{i}")
    robot.add(builders.model_plugin("velocity", "libgazebo_ros_velocity_controller.so"))
    return robot


def test_thruster_links_fixed_to_a_pushed_hull_put_it_in_water() -> None:
    result = identify_urdf(hull_of_fixed_thrusters(4).text())
    assert result.structure == "Surface Vessel"  # nothing makes it dive
    assert any("thruster_0 (fixed)" in line for line in result.evidence)
    assert "Driving" in {c.motion_control for c in result.motion_controls}


def test_a_gps_frame_fixed_to_a_hull_of_fixed_thrusters_floats_it_unless_a_dvl_frame_dives_it() -> (
    None
):
    boat = hull_of_fixed_thrusters(2)
    boat.fixed(boat.root, "gps_frame")
    result = identify_urdf(boat.text())
    assert result.structure == "Surface Vessel"
    assert result.body is not None
    assert result.body.surface_hints == ("gps_frame (a GPS frame: heard above water)",)
    boat.fixed(boat.root, "dvl")  # an AUV's GPS, heard when it comes up
    assert identify_urdf(boat.text()).structure == "Underwater Vehicle"


def test_a_water_plugins_surface_of_numbers_is_where_the_water_lies_not_a_floating_hull() -> None:
    # freefloating_gazebo's buoyancy plugin sets the water's surface at z = 40 for any body.
    diver = hull_of_fixed_thrusters(2)
    diver.add(
        builders.model_plugin(
            "freebuoyancy_gazebo", "libfreebuoyancy_gazebo.so", "<surface>0 0 40</surface>"
        )
    )
    result = identify_urdf(diver.text())
    assert result.body is not None
    assert (result.structure, result.body.surface_hints) == ("Underwater Vehicle", ())
    # A <surface> that names no place (a switch for a hull's surface model) still says it.
    hull = hull_of_fixed_thrusters(2)
    hull.add(builders.model_plugin("hull", "libusv_dynamics.so", "<surface>hull</surface>"))
    assert identify_urdf(hull.text()).structure == "Surface Vessel"


def test_a_gps_frame_a_joint_moves_says_nothing_of_the_surface() -> None:
    boat = hull_of_fixed_thrusters(2)
    boat.fixed(boat.chain(boat.root, ["mast"]), "gps_frame")
    result = identify_urdf(boat.text())
    assert result.body is not None
    assert not any("gps_frame" in hint for hint in result.body.surface_hints)


def test_one_fixed_thruster_link_or_ones_a_joint_moves_say_nothing_of_water() -> None:
    assert identify_urdf(hull_of_fixed_thrusters(1).text()).structure == "UGV"
    assert identify_urdf(hull_of_fixed_thrusters(under_a_joint=True).text()).structure == "UGV"


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


def test_a_uuv_plugin_puts_a_body_its_propellers_spin_below_the_surface() -> None:
    # PX4's simulation spins a submarine's propellers with the multicopters' motor model; the
    # unmanned underwater vehicle's (UUV's) plugin gives it buoyancy and drag.
    robot = builders.quadrotor()
    for i in range(4):
        robot.add(
            builders.model_plugin(
                f"motor_{i}", "libgazebo_motor_model.so", f"<jointName>rotor_{i}_joint</jointName>"
            )
        )
    assert identify_urdf(robot.text()).structure == "UAV"
    robot.add(builders.model_plugin("uuv_forces", "libgazebo_uuv_plugin.so"))
    result = identify_urdf(robot.text())
    assert result.structure == "Underwater Vehicle"
    assert "below the surface: libgazebo_uuv_plugin.so" in result.evidence


def test_wings_that_turn_without_limits_on_a_wheeled_base_are_no_control_surfaces() -> None:
    # A toy's two wings flapping on endless joints beside its wheels; an aileron deflects within
    # limits.
    def base_with_wings(kind: str) -> str:
        robot = builders.ugv()
        for side in ("left", "right"):
            limits = '<limit lower="-0.5" upper="0.5" effort="1" velocity="1"/>'
            robot.joint(f"wing_{side}_joint", kind, robot.root, f"wing_{side}", limits)
        return identify_urdf(robot.text()).structure

    assert base_with_wings("continuous") == "UGV"
    assert base_with_wings("revolute") == "UAV"


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


def car_of_tyres() -> RobotText:
    """A CAD export's car: front rims spinning on steered axles and a rear axle spinning two
    rims, each rim's tyre fixed to it, no joint named for a wheel (links named by corner; the
    rear axle's own link by nothing: it stays an axle)."""
    robot = RobotText("car")
    robot.joint("joint_rear_axle", "continuous", "base_link", "link_rear_axle")
    for side in ("left", "right"):
        robot.fixed("link_rear_axle", f"link_rear_{side}_rim")
        robot.fixed(f"link_rear_{side}_rim", f"link_rear_{side}_tyre")
        robot.joint(f"joint_front_{side}_axle", "revolute", "base_link", f"link_front_{side}_axle")
        robot.joint(
            f"joint_front_{side}_rim",
            "continuous",
            f"link_front_{side}_axle",
            f"link_front_{side}_rim",
        )
        robot.fixed(f"link_front_{side}_rim", f"link_front_{side}_tyre")
    return robot


def test_a_rim_turning_the_tyre_fixed_to_it_is_a_wheel() -> None:
    robot = car_of_tyres()
    assert identify_urdf(robot.text()).structure == "UGV"
    roles = {name: role.role for name, role in joint_roles(tree_of(robot)).items()}
    assert roles["joint_front_left_rim"] == roles["joint_front_right_rim"] == "wheel"
    assert roles.get("joint_rear_axle") != "wheel"
    assert "leg" not in roles.values()


def test_a_spinning_joint_carrying_a_tyre_and_a_gripper_turns_no_wheel() -> None:
    robot = car_of_tyres()
    robot.fixed("link_front_left_rim", "link_front_left_gripper")
    roles = {name: role.role for name, role in joint_roles(tree_of(robot)).items()}
    assert roles.get("joint_front_left_rim") != "wheel"


def test_tracks_are_a_track_plugin_and_track_named_joints_each_once() -> None:
    robot = builders.tracked()
    robot.joint("left_track_joint", "continuous", robot.root, "left_track")
    robot.add(builders.model_plugin("tracks2", "libSimpleTrackedVehiclePlugin.so"))
    tree = tree_of(robot)
    assert tracks(tree) == ("libSimpleTrackedVehiclePlugin.so", "left_track_joint")
    assert grounded(tree, {})


def test_a_carriage_sliding_on_a_linear_track_is_no_tread() -> None:
    """Two pushers each carried by a slide along a track and a slide across it (a table
    game's gantries): the slides are no tracks, so the body is no tracked vehicle."""
    robot = RobotText("table")
    for side in ("1", "2"):
        robot.chain(robot.root, [f"base_to_track_{side}", f"track_{side}_to_pusher"], "prismatic")
    tree = tree_of(robot)
    assert tracks(tree) == ()
    assert identify_urdf(robot.text()).structure != "UGV"


def test_a_body_with_casters_alone_is_grounded_and_a_bare_one_is_not() -> None:
    tree = tree_of(RobotText("bare"))
    assert not grounded(tree, {})
    assert grounded(tree, {"c": Role("c", "caster", "a swivel")})


def test_a_lone_rotor_named_leaf_is_said_not_to_fly() -> None:
    robot = builders.manipulator()
    robot.joint("prop_joint", "continuous", "wrist_3_link", "prop_link")
    tree = tree_of(robot)
    assert not_rotors(tree, joint_roles(tree)) == ["prop_joint"]


def test_fixed_wheel_joints_count_only_while_no_wheel_turns() -> None:
    robot = RobotText("trimmed")
    robot.fixed("base_link", "left_wheel")
    tree = tree_of(robot)
    assert fixed_wheels(tree, {}) == ["left_wheel_fixed"]
    assert fixed_wheels(tree, {"w": Role("w", "wheel", "named")}) == []


def test_fixed_wheels_under_a_body_bolted_to_the_world_make_no_mobile_base() -> None:
    # A cart's casters under a table the model fixes in place: nothing of it travels.
    table = RobotText("table", root="world")
    table.fixed("world", "base_link")
    table.fixed("base_link", "front_caster_wheel")
    table.fixed("base_link", "rear_caster_wheel")
    assert fixed_wheels(tree_of(table), {}) == []
    hung = RobotText("hung", root="world")
    hung.joint("float", "floating", "world", "base_link")
    hung.fixed("base_link", "left_wheel")
    assert fixed_wheels(tree_of(hung), {}) == ["left_wheel_fixed"]


def test_wings_are_wing_links_with_the_control_surfaces_beside_them() -> None:
    tree = tree_of(builders.fixed_wing())
    assert wings(tree, {}) == ["main_wing", "aileron_left", "aileron_right", "horizontal_tail"]
    tail_only = RobotText("tail")
    tail_only.fixed("base_link", "horizontal_tail")
    assert wings(tree_of(tail_only), {}) == []


def landing_plane(*, board: str = "0.3 1.4 0.02", turned: str = "0 0 0") -> str:
    """A plane of unnamed parts: a body, a board fixed on it (``board``, its box's size, turned
    by ``turned``), an endless leaf at its nose turning about the body's long axis, and two
    wheels below it about axles across it (landing gear)."""
    spin = '<axis xyz="1 0 0"/>'
    return f"""<robot name="p">
  <link name="l0"/>
  <link name="l1"><visual><origin rpy="{turned}"/><geometry><box size="{board}"/></geometry>
  </visual></link>
  <link name="l2"/><link name="l3"/><link name="l4"/>
  <joint name="j0" type="fixed"><parent link="l0"/><child link="l1"/>
    <origin xyz="-0.7 0 0.05"/></joint>
  <joint name="j1" type="continuous"><parent link="l0"/><child link="l2"/>
    <origin xyz="0.6 0 0"/>{spin}</joint>
  <joint name="j2" type="continuous"><parent link="l0"/><child link="l3"/>
    <origin xyz="0.2 0.2 -0.1"/><axis xyz="0 1 0"/></joint>
  <joint name="j3" type="continuous"><parent link="l0"/><child link="l4"/>
    <origin xyz="0.2 -0.2 -0.1"/><axis xyz="0 1 0"/></joint>
</robot>"""


def test_a_board_across_the_body_beside_a_propeller_pulling_along_it_is_a_wing() -> None:
    result = identify_urdf(landing_plane())
    assert result.body is not None
    assert (result.body.wings, result.body.propellers) == (("l1",), ("j1",))
    assert result.body.wheels == ("j2", "j3")  # its landing gear
    assert result.structure == "UAV"
    # A board standing upright is a fin, one along the body a deck, one as thick as it is
    # long a bar: no wing, and the wheels drive the body on the ground.
    for board, turned in (("0.3 1.4 0.02", "1.5708 0 0"), ("1.4 0.3 0.02", "0 0 0")):
        rover = identify_urdf(landing_plane(board=board, turned=turned))
        assert rover.body is not None
        assert (rover.body.wings, rover.body.propellers) == ((), ())
        assert rover.structure == "UGV"
    assert identify_urdf(landing_plane(board="0.02 1.4 0.02")).structure == "UGV"


def test_an_aileron_misspelled_as_cad_exports_write_it_is_a_wing() -> None:
    # A fuselage mesh carrying its wings, with ailerons spelt `airelon` and a tail.
    plane = RobotText("iha")
    for link in ("airelon1", "airelon2", "rudder", "elevator1"):
        plane.fixed("base_link", link)
    assert wings(tree_of(plane), {}) == ["airelon1", "airelon2", "rudder", "elevator1"]
    assert identify_urdf(plane.text()).structure == "UAV"


def test_a_thruster_plugin_listing_a_fixed_link_names_a_thruster() -> None:
    robot = RobotText("hull")
    robot.fixed("base_link", "stern_thruster")
    robot.add(
        builders.model_plugin(
            "t", "libthruster_model.so", "<linkName>stern_thruster</linkName><gain>2</gain>"
        )
    )
    assert listed_thrusters(tree_of(robot), {}) == ["stern_thruster (libthruster_model.so)"]


def test_a_hull_is_at_the_surface_by_its_waterline_and_below_it_by_its_plugins() -> None:
    vessel = tree_of(builders.surface_vessel())
    assert surface_hints(vessel) == ("robot name catamaran", "metacentric_width")
    torpedo = tree_of(builders.underwater_vehicle())
    assert underwater_hints(torpedo) == ("libthruster_model.so", "libunderwater_object.so")
    assert surface_hints(tree_of(builders.quadrotor())) == ()


def test_a_buoyancy_plugin_says_in_water_not_below_it() -> None:
    robot = thrusters_by_name()
    robot.add(builders.model_plugin("float", "libbuoyancy_gazebo_plugin.so"))
    tree = tree_of(robot)
    assert underwater_hints(tree) == ()


def test_a_word_in_a_sensors_settings_says_nothing_of_the_hull() -> None:
    # An underwater vehicle's barometer with an offset to the water surface.
    robot = thrusters_by_name()
    robot.add(builders.model_plugin("water", "libunderwater_object.so"))
    robot.add(
        builders.gazebo_sensor(
            "base_link", "altimeter", "baro", "<water_surface_offset>0</water_surface_offset>"
        )
    )
    robot.add(
        builders.model_plugin(
            "baro", "libbarometer.so", "<water_surface_offset>0</water_surface_offset>"
        )
    )
    assert surface_hints(tree_of(robot)) == ()
    assert identify_urdf(robot.text()).structure == "Underwater Vehicle"


def test_a_gps_on_a_hull_that_shows_nothing_of_diving_says_it_floats() -> None:
    robot = thrusters_by_name()
    robot.add(builders.model_plugin("float", "libbuoyancy_gazebo_plugin.so"))
    robot.add(builders.gazebo_sensor("base_link", "gps", "gps"))
    assert identify_urdf(robot.text()).structure == "Surface Vessel"
    diving = thrusters_by_name()
    diving.add(builders.gazebo_sensor("base_link", "gps", "gps"))
    diving.add(builders.gazebo_sensor("dvl_link", "dvl", "dvl"))
    assert identify_urdf(diving.text()).structure == "Underwater Vehicle"


SCAN = (
    "<ray><scan><horizontal><samples>360</samples><min_angle>-3.14</min_angle>"
    "<max_angle>3.14</max_angle></horizontal></scan><range><min>0.1</min><max>30</max></range>"
    "</ray>"
)


def test_a_lidar_on_a_hull_that_shows_nothing_of_diving_says_it_floats() -> None:
    robot = thrusters_by_name()
    robot.add(builders.model_plugin("float", "libbuoyancy_gazebo_plugin.so"))
    robot.add(builders.gazebo_sensor("base_link", "ray", "scanner", SCAN))
    result = identify_urdf(robot.text())
    assert result.structure == "Surface Vessel"
    assert "floats at the surface: scanner (lidar: scans in air)" in result.evidence
    # Below the surface a ray sensor is something else (a sonar's beams): a DVL says it dives.
    robot.add(builders.gazebo_sensor("dvl_link", "dvl", "dvl"))
    assert identify_urdf(robot.text()).structure == "Underwater Vehicle"


def test_a_gps_and_a_lidar_float_a_hull_simulated_with_a_submersibles_plugin() -> None:
    robot = thrusters_by_name()
    robot.add(builders.model_plugin("hull", "libuuv_underwater_object_ros_plugin.so"))
    robot.add(builders.gazebo_sensor("base_link", "ray", "scanner", SCAN))
    # One of them is not enough against the plugin: a diver may carry either.
    assert identify_urdf(robot.text()).structure == "Underwater Vehicle"
    robot.add(builders.gazebo_sensor("base_link", "gps", "gps"))
    result = identify_urdf(robot.text())
    assert result.structure == "Surface Vessel"
    assert (
        "floats at the surface: gps (GPS: heard above water), scanner (lidar: scans in air)"
        in result.evidence
    )
    # Over a DVL they say nothing: an AUV surfaces for a fix and may scan its sea floor.
    robot.add(builders.gazebo_sensor("dvl_link", "dvl", "dvl"))
    assert identify_urdf(robot.text()).structure == "Underwater Vehicle"


def test_a_one_ray_range_finder_on_a_hull_says_nothing_of_the_surface() -> None:
    robot = thrusters_by_name()
    robot.add(builders.model_plugin("float", "libbuoyancy_gazebo_plugin.so"))
    one_ray = SCAN.replace("<samples>360</samples>", "<samples>1</samples>")
    robot.add(builders.gazebo_sensor("base_link", "ray", "echo", one_ray))
    assert surface_hints(tree_of(robot)) == ()


def thrust_model(entry: str, *extra: str) -> RobotText:
    """Four spinning ``rotor_N`` links on a body, pushed by a plugin of the robot's own
    (``libthrust_plugin.so``) that lists one ``entry`` per link (``{}`` its link's name);
    ``extra`` more plugins."""
    robot = RobotText("drone")
    entries = ""
    for i in range(4):
        robot.joint(f"rotor{i}_joint", "continuous", "base_link", f"rotor_{i}")
        entries += entry.format(f"rotor_{i}")
    robot.add(builders.model_plugin("thrust", "libthrust_plugin.so", entries))
    for plugin in extra:
        robot.add(plugin)
    return robot


ROTORS = "<rotors><linkName>{}</linkName><maxForce>30</maxForce></rotors>"


def test_a_thrust_plugin_listing_rotor_entries_flies_the_body_it_does_not_float_it() -> None:
    result = identify_urdf(thrust_model(ROTORS).text())
    assert result.structure == "UAV"
    assert "flight plugin(s): libthrust_plugin.so" in result.evidence


@pytest.mark.parametrize(
    ("entry", "why"),
    [
        ("<thruster><linkName>{}</linkName></thruster>", "thruster entries"),
        ("<propeller><linkName>{}</linkName></propeller>", "a boat's propeller entries"),
        ("<thruster><rotor><linkName>{}</linkName></rotor></thruster>", "rotors in thrusters"),
    ],
)
def test_a_thrust_plugin_listing_thrusters_or_propellers_flies_nothing(
    entry: str, why: str
) -> None:
    result = identify_urdf(thrust_model(entry).text())
    assert not any(line.startswith("flight plugin") for line in result.evidence), why
    assert result.structure in ("Surface Vessel", "Underwater Vehicle"), why


def test_rotor_entries_beside_a_water_plugin_fly_nothing() -> None:
    buoyancy = builders.model_plugin("float", "libbuoyancy_gazebo_plugin.so")
    result = identify_urdf(thrust_model(ROTORS, buoyancy).text())
    assert not any(line.startswith("flight plugin") for line in result.evidence)
    assert result.structure in ("Surface Vessel", "Underwater Vehicle")


def hull_with_compensation(hull: str, thrusters: str = "0.6") -> str:
    """A hull whose link gives ``<buoyancy><compensation>`` (buoyancy over weight) under a
    thruster plugin of a floating-body simulator; each thruster link gives ``thrusters``."""
    robot = RobotText("hull", root="hull")
    for i in range(2):
        robot.joint(f"t{i}", "revolute", "hull", f"t{i}_link", '<axis xyz="0 1 0"/>')
    robot.add(
        builders.model_plugin(
            "floating", "libfloating_control.so", "<thruster><map>1 0 0 0 0 0</map></thruster>"
        )
    )
    text = robot.text()
    for link, value in (("hull", hull), ("t0_link", thrusters), ("t1_link", thrusters)):
        text = text.replace(
            f'<link name="{link}"/>',
            f'<link name="{link}"><buoyancy><compensation>{value}</compensation></buoyancy></link>',
        )
    return text


def test_a_hull_whose_buoyancy_is_above_its_weight_floats_at_the_surface() -> None:
    result = identify_urdf(hull_with_compensation("1.2"))
    assert result.structure == "Surface Vessel"
    assert "floats at the surface: hull buoyancy 1.2 x weight (floats)" in result.evidence


@pytest.mark.parametrize("hull", ["0.98", "1", "nan", "", "1e999"])
def test_a_hull_that_does_not_float_by_its_compensation_stays_underwater(hull: str) -> None:
    result = identify_urdf(hull_with_compensation(hull, thrusters="5"))
    assert result.structure == "Underwater Vehicle"  # a sinking hull; its thrusters' buoyancy
    assert not any("floats" in line for line in result.evidence)  # is not the body's


def hull_with_volume(volume: str, mass: str, *, neutral: str = "0", density: str = "") -> str:
    """A hull of ``mass`` kg under the UUV simulator's hydrodynamics plugin, which lists it
    with the ``volume`` (m3) it displaces, in water of ``density`` (none written: sea water),
    its thrusters named so."""
    robot = RobotText("craft", root="hull")
    for i in range(2):
        robot.joint(f"thruster_{i}_joint", "continuous", "hull", f"thruster_{i}")
    fluid = f"<fluid_density>{density}</fluid_density>" if density else ""
    entry = (
        f'{fluid}<link name="hull"><neutrally_buoyant>{neutral}</neutrally_buoyant>'
        f"<volume>{volume}</volume></link>"
    )
    robot.add(builders.model_plugin("uuv", "libuuv_underwater_object_ros_plugin.so", entry))
    inertia = '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>'
    hull = f'<link name="hull"><inertial><mass value="{mass}"/>{inertia}</inertial></link>'
    return robot.text().replace('<link name="hull"/>', hull)


def test_a_hull_displacing_three_times_its_weight_of_water_floats_at_the_surface() -> None:
    # 1.776 m3 of sea water (1,826 kg) under a 600 kg hull: it floats, whatever plugin moves it.
    result = identify_urdf(hull_with_volume("1.776", "600"))
    assert result.structure == "Surface Vessel"
    assert any(
        line.startswith("floats at the surface: hull buoyancy 3.04") for line in result.evidence
    )
    # In fresh water of half the density, the same hull floats too (1.52 x its weight).
    assert identify_urdf(hull_with_volume("1.776", "600", density="500")).structure == (
        "Surface Vessel"
    )


def test_a_hulls_reserve_that_the_arm_it_carries_takes_up_floats_nothing() -> None:
    # 1.167 m3 of sea water (1,200 kg) under a 1,000 kg hull: 1.2 times its weight. An arm of
    # 190 kg that displaces nothing trims the whole to neutral: it dives; one of 10 kg does not.
    def with_arm(kg: str) -> str:
        text = hull_with_volume("1.167", "1000")
        inertia = '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>'
        arm = (
            '<joint name="shoulder" type="revolute"><parent link="hull"/><child link="arm"/>'
            '<axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            f'<link name="arm"><inertial><mass value="{kg}"/>{inertia}</inertial></link>'
        )
        return text.replace("</robot>", arm + "</robot>")

    assert identify_urdf(with_arm("10")).structure == "Surface Vessel"
    result = identify_urdf(with_arm("190"))
    assert result.structure == "Underwater Vehicle"
    assert not any("floats" in line for line in result.evidence)
    # The same arm that the hydrodynamics plugin makes neutrally buoyant weighs nothing.
    neutral = "<link name='arm'><neutrally_buoyant>1</neutrally_buoyant></link></plugin>"
    assert identify_urdf(with_arm("190").replace("</plugin>", neutral, 1)).structure == (
        "Surface Vessel"
    )


@pytest.mark.parametrize(
    ("volume", "mass", "neutral"),
    [
        ("1.838", "1862.87", "0"),  # a work-class ROV trimmed 1.4 % light: it dives
        ("0.068", "80", "0"),  # a glider heavier than its water
        ("1.776", "600", "1"),  # made neutrally buoyant by the plugin, whatever the volume
        ("1e999", "600", "0"),  # no finite volume
        ("-2", "600", "0"),
    ],
)
def test_a_hull_trimmed_near_neutral_or_made_neutral_stays_underwater(
    volume: str, mass: str, neutral: str
) -> None:
    result = identify_urdf(hull_with_volume(volume, mass, neutral=neutral))
    assert result.structure == "Underwater Vehicle"
    assert not any("floats" in line for line in result.evidence)


def test_a_buoyancy_plugin_with_no_depth_cue_is_said_in_water_without_denying_the_plugin() -> None:
    robot = thrusters_by_name()
    robot.add(builders.model_plugin("float", "libbuoyancy_gazebo_plugin.so"))
    # A frame publisher whose name was copied from the buoyancy plugin above it: not water.
    robot.add(builders.model_plugin("simple_buoyancy", "libworld_frame_publisher.so"))
    result = identify_urdf(robot.text())
    assert "water plugin(s): libbuoyancy_gazebo_plugin.so" in result.evidence
    assert not any("no buoyancy" in line for line in result.evidence)
    assert (
        "in water, nothing says below or at the surface: no hydrodynamics or thruster plugin, "
        "no DVL or pressure sensor, no surface cue"
    ) in result.evidence


def bare_body(name: str) -> RobotText:
    """One body link and its visual part on a fixed joint: nothing moves, no plugin, no sensor
    (an aircraft exported from CAD as one mesh)."""
    robot = RobotText(name, root="body")
    robot.fixed(robot.root, "body_viz")
    return robot


def test_a_bare_body_named_as_a_multirotor_flies_with_doubt() -> None:
    for name in ("quadrotor", "swarm_hexarotor", "octorotor_3"):
        assert identify_urdf(bare_body(name).text()).structure == "UAV", name


def test_a_bare_body_named_as_an_aircraft_flies_with_doubt() -> None:
    result = identify_urdf(bare_body("Fixed_Wing_UAV").text())
    assert result.structure == "UAV"
    assert result.confidence == pytest.approx(0.95 * 0.8, abs=0.01)
    assert "flight named in: robot name Fixed_Wing_UAV" in result.evidence
    flight = {c.motion_control: c.source for c in result.motion_controls}["Flight"]
    assert flight == "urdf: flight named in robot name Fixed_Wing_UAV"


def test_a_bare_body_named_as_a_lighter_than_air_craft_flies_with_doubt() -> None:
    # A competition blimp exported from CAD: its body on a zero-axis joint, a camera frame.
    for name in ("burn_cream_blimp", "airship", "Dirigible_2", "zeppelin"):
        robot = RobotText(name, root="world")
        robot.joint("IMU", "continuous", "world", "envelope", '<axis xyz="0 0 0"/>')
        robot.fixed("envelope", "camera_link")
        assert identify_urdf(robot.text()).structure == "UAV", name
    # A plugin named for a blimp (a tracker following one) flies no wheeled rover.
    rover = builders.ugv()
    rover.add(builders.model_plugin("tracker", "libblimp_tracker.so"))
    assert identify_urdf(rover.text()).structure == "UGV"


def test_a_robot_name_says_nothing_when_the_body_has_limbs_or_a_plugin_that_moves_it() -> None:
    assert identify_urdf(bare_body("display_stand").text()).structure == "Other"
    armed = bare_body("drone_arm_rig")
    builders.arm(armed, armed.root, joints=6, gripper=False)
    assert identify_urdf(armed.text()).structure == "Manipulator"
    driven = bare_body("drone_carrier")
    driven.add(builders.model_plugin("drive", "libgazebo_ros_planar_move.so"))
    assert identify_urdf(driven.text()).structure == "UGV"


def test_a_long_fixed_chain_of_floating_links_under_a_moving_joint_is_read_once() -> None:
    # A sinking hull, a thruster joint, then 20,000 links fixed one under the next, each
    # declaring it floats: none is the body, so no floating hull (each link's walk up to the
    # thruster joint is remembered, not repeated).
    text = hull_with_compensation("0.98", thrusters="5")
    chain = RobotText("chain", root="t0_link")
    parent = "t0_link"
    for i in range(20_000):
        parent = chain.fixed(parent, f"c{i}")
    links = "".join(
        f'<link name="c{i}"><buoyancy><compensation>1.5</compensation></buoyancy></link>'
        for i in range(20_000)
    )
    text = text.replace("</robot>", links + "\n".join(chain.joints) + "</robot>")
    result = identify_urdf(text)
    assert result.structure == "Underwater Vehicle"
    assert not any("floats" in line for line in result.evidence)


def test_thruster_leaves_under_a_deep_fixed_chain_are_placed_in_one_walk() -> None:
    # 20,000 links fixed one under the next, then 20,000 thruster-named leaves on the last:
    # whether each leaf's link is still is known from one walk of the tree, not a walk up
    # from every leaf (which took minutes).
    robot = RobotText("deep_hull")
    parent = robot.root
    for i in range(20_000):
        parent = robot.fixed(parent, f"c{i}")
    for i in range(20_000):
        robot.fixed(parent, f"thruster_{i}")
    result = identify_urdf(robot.text())
    assert result.structure == "Underwater Vehicle"  # more thrusters than a surface craft's


def dvl_arm(frame: str = "dvl_link") -> RobotText:
    """A body with fixed sensor frames and no plugin, carrying a 2-joint arm with a gripper."""
    robot = RobotText("drone_with_arm")
    robot.joint(f"{frame}_joint", "fixed", robot.root, frame)
    robot.joint("camera_joint", "fixed", robot.root, "front_camera_link")
    tip = robot.chain(robot.root, ["shoulder_joint", "arm_joint"])
    robot.chain(tip, ["finger_joint1"], "prismatic")
    robot.joint("finger_joint2", "prismatic", tip, "finger2", '<mimic joint="finger_joint1"/>')
    return robot


def test_a_body_with_a_dvl_frame_carrying_a_small_arm_is_an_underwater_vehicle() -> None:
    result = identify_urdf(dvl_arm().text())
    assert result.structure == "Underwater Vehicle"
    assert result.body is not None
    assert result.body.water_frames == ("dvl_link",)


def test_a_dvl_frame_moved_by_a_joint_is_no_evidence_of_water() -> None:
    robot = dvl_arm("camera_mount")
    robot.joint("dvl_tilt", "revolute", "front_camera_link", "dvl_link", "")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.water_frames == ()
    assert result.structure == "Manipulator"


@pytest.mark.parametrize("hull", ["1.01", "1.05"])
def test_a_body_trimmed_just_above_neutral_is_a_submersible_not_a_floating_hull(hull: str) -> None:
    """A submersible is trimmed a hair buoyant (it rises when its thrusters stop); a hull that
    floats carries a reserve of a tenth of its weight or more."""
    result = identify_urdf(hull_with_compensation(hull, thrusters="1"))
    assert result.structure == "Underwater Vehicle"
    assert not any("floats" in line for line in result.evidence)
    assert identify_urdf(hull_with_compensation("1.1", thrusters="1")).structure == "Surface Vessel"


def test_a_buoyancy_engine_puts_the_body_below_the_surface_it_names() -> None:
    # A submersible's variable-buoyancy engine fills and empties a volume to dive and rise; its
    # <surface> parameter is the height it rises to, not the word of a hull floating there.
    robot = thrusters_by_name()
    robot.add(
        builders.model_plugin(
            "engine",
            "gz-sim-buoyancy-engine-system",
            "<link_name>base_link</link_name><neutral_volume>4.7</neutral_volume>"
            "<surface>100.0</surface>",
        )
    )
    tree = tree_of(robot)
    assert surface_hints(tree) == ()
    assert underwater_hints(tree) == ("gz-sim-buoyancy-engine-system",)
    result = identify_urdf(robot.text())
    assert result.structure == "Underwater Vehicle"
    assert result.confidence == pytest.approx(0.85, abs=0.01)  # no doubt left


def test_a_cameras_depth_sensor_frame_puts_no_wheeled_base_under_water() -> None:
    for frame in ("depth_sensor_link", "dvl_link"):
        text = (
            f'<robot name="r"><link name="base_link"/><link name="lw"/><link name="rw"/>'
            f'<link name="{frame}"/>'
            + builders.joint_xml(
                "left_wheel_joint", "continuous", "base_link", "lw", "0 0.2 0", "0 1 0"
            )
            + builders.joint_xml(
                "right_wheel_joint", "continuous", "base_link", "rw", "0 -0.2 0", "0 1 0"
            )
            + builders.joint_xml("frame_joint", "fixed", "base_link", frame, "0.2 0 0.3", "1 0 0")
            + "</robot>"
        )
        expected = "UGV" if frame == "depth_sensor_link" else "Underwater Vehicle"
        assert identify_urdf(text).structure == expected, frame


def test_a_collisions_contact_settings_say_nothing_of_a_hull_at_the_surface() -> None:
    # Gazebo's <surface> (friction) and <contact_surface_layer> are on every simulated body:
    # a submersible with thrusters and a DVL frame that carries them still dives.
    robot = thrusters_by_name()
    robot.joint("dvl_joint", "fixed", robot.root, "dvl_link")
    robot.add(
        '<gazebo reference="base_link"><collision><surface><friction><ode><mu>1</mu></ode>'
        "</friction></surface></collision><contact_surface_layer>0.001</contact_surface_layer>"
        "</gazebo>"
    )
    result = identify_urdf(robot.text())
    assert result.structure == "Underwater Vehicle"
    assert not any(line.startswith("floats at the surface") for line in result.evidence)


def named_hull(name: str) -> RobotText:
    """A hull described as a few frames and a rudder and a sail on endless joints (no plugin,
    no sensor), called ``name``."""
    robot = RobotText(name)
    robot.fixed(robot.root, "gps_link")
    robot.fixed(robot.root, "imu_link")
    robot.joint("hull_to_rudder", "continuous", robot.root, "rudder")
    robot.joint("hull_to_mast", "continuous", robot.root, "mast")
    return robot


def test_a_robot_named_as_a_boat_that_shows_no_other_way_of_travelling_floats_with_doubt() -> None:
    for name in ("sailboat001", "boat", "harbour_usv", "BlueBoat"):
        result = identify_urdf(named_hull(name).text())
        assert result.structure == "Surface Vessel", name
        assert result.confidence == pytest.approx(0.9 * 0.8, abs=0.01)
        assert f"a vessel by its name alone: robot name {name}" in result.evidence
    # Nothing of water in the name: no vessel.
    assert identify_urdf(named_hull("weather_station").text()).structure == "Other"


def test_a_boat_name_says_nothing_of_a_body_its_joints_move_otherwise() -> None:
    rover = named_hull("boat_trailer")
    builders.wheeled_base(rover)
    assert identify_urdf(rover.text()).structure == "UGV"
    arm = named_hull("boat_crane")
    builders.arm(arm, arm.root)
    assert identify_urdf(arm.text()).structure == "Manipulator"


def hull_with_hydrodynamics(name: str) -> RobotText:
    """Four thrusters a thruster plugin drives and a hydrodynamics plugin (used for hulls
    afloat and for vehicles below alike), called ``name``."""
    robot = RobotText(name)
    for i in range(4):
        robot.joint(f"t{i}_joint", "continuous", robot.root, f"t{i}")
        robot.add(
            builders.model_plugin(
                f"t{i}", "libuuv_thruster_ros_plugin.so", f"<linkName>t{i}</linkName>"
            )
        )
    robot.add(builders.model_plugin("hydro", "libHydrodynamicsPlugin.so"))
    return robot


def test_a_robot_named_as_a_surface_craft_floats_whatever_its_water_plugins_say() -> None:
    for name in ("asv", "harbour_asv", "catamaran", "stinger_tug", "river_barge", "canoe2"):
        result = identify_urdf(hull_with_hydrodynamics(name).text())
        assert result.structure == "Surface Vessel", name
        assert f"robot name {name}" in "\n".join(result.evidence)
    # An ASV word inside another word is none; a submersible's name says nothing of a surface.
    for name in ("vasvik", "auv", "tugger"):
        assert identify_urdf(hull_with_hydrodynamics(name).text()).structure == (
            "Underwater Vehicle"
        ), name


def test_propellers_of_a_craft_named_for_the_surface_push_it_in_water() -> None:
    boat = RobotText("boat")
    for side in ("left", "right"):
        boat.joint(f"{side}_prop_joint", "continuous", boat.root, f"{side}_prop")
    result = identify_urdf(boat.text())
    assert result.structure == "Surface Vessel"
    assert {role.role for role in result.roles} == {"thruster"}
    ship = thrusters_by_name()
    ship.name = "research_ship"
    assert identify_urdf(ship.text()).structure == "Surface Vessel"
    # Named for nothing in water, the same propellers fly.
    copter = RobotText("bicopter")
    for side in ("left", "right"):
        copter.joint(f"{side}_prop_joint", "continuous", copter.root, f"{side}_prop")
    assert identify_urdf(copter.text()).structure == "UAV"


def test_a_robot_named_as_a_drone_that_shows_no_way_of_travelling_flies_with_doubt() -> None:
    # A drone a simulator moves by setting its pose: sensors, no rotor.
    scout = RobotText("drone")
    scout.fixed(scout.root, "lidar_link")
    scout.add(builders.gazebo_sensor("lidar_link", "ray", "lidar"))
    result = identify_urdf(scout.text())
    assert result.structure == "UAV"
    assert result.confidence == pytest.approx(0.95 * 0.8, abs=0.01)
    assert "flight named in: robot name drone" in result.evidence
    # Wheels say how it travels: the name is no evidence then.
    builders.wheeled_base(scout)
    assert identify_urdf(scout.text()).structure == "UGV"


def quad(name: str) -> RobotText:
    """Four unnamed-by-role propeller joints on upright axes all round a body, called ``name``."""
    robot = RobotText(name)
    for i, (x, y) in enumerate(((0.2, 0.2), (0.2, -0.2), (-0.2, 0.2), (-0.2, -0.2))):
        builders.placed(
            robot, f"prop{i}_joint", "continuous", robot.root, f"prop{i}", xyz=f"{x} {y} 0.05"
        )
    return robot


def test_a_water_word_inside_another_word_or_a_tag_floats_nothing() -> None:
    for name in ("airship", "mothership_drone", "surface_survey_quad", "spaceship"):
        assert identify_urdf(quad(name).text()).structure == "UAV", name
    auv = hull_with_hydrodynamics("auv")
    auv.add("<gazebo><relationship>none</relationship><ownership/></gazebo>")
    assert identify_urdf(auv.text()).structure == "Underwater Vehicle"


def test_a_boat_name_floats_a_hull_its_hydrodynamics_plugin_moves() -> None:
    # A hydrodynamics plugin moves hulls at the surface too (Gazebo's, a BlueBoat's).
    assert identify_urdf(hull_with_hydrodynamics("blueboat").text()).structure == ("Surface Vessel")
    assert identify_urdf(hull_with_hydrodynamics("boathouse").text()).structure == (
        "Underwater Vehicle"
    )


def test_a_boat_name_does_not_float_a_body_with_a_dvl() -> None:
    sub = hull_with_hydrodynamics("u_boat")
    sub.fixed(sub.root, "dvl_link")
    sub.add(builders.gazebo_sensor("dvl_link", "dvl", "dvl"))
    assert identify_urdf(sub.text()).structure == "Underwater Vehicle"


def test_a_gripper_named_for_boats_is_a_gripper() -> None:
    robot = builders.parallel_gripper()
    robot.name = "boat_gripper"
    assert identify_urdf(robot.text()).structure == "Gripper"


def test_a_drone_a_velocity_plugin_pushes_flies_by_its_name_and_a_wheeled_one_rolls() -> None:
    drone = RobotText("drone")
    drone.add(
        builders.model_plugin(
            "ignition::gazebo::systems::VelocityControl", "ignition-gazebo-velocity-control-system"
        )
    )
    assert identify_urdf(drone.text()).structure == "UAV"
    builders.wheeled_base(drone)
    assert identify_urdf(drone.text()).structure == "UGV"


def test_a_drone_named_so_that_a_planar_move_plugin_holds_with_gravity_off_flies() -> None:
    """A simulator's kinematic drone: gravity off, a planar-move plugin on cmd_vel."""
    drone = RobotText("uav")
    drone.fixed(drone.root, "camera_link")
    drone.add(builders.model_plugin("move", "libgazebo_ros_planar_move.so"))
    assert identify_urdf(drone.text()).structure == "UGV"  # gravity pulls it: it rolls
    drone.add("<gazebo><turnGravityOff>true</turnGravityOff></gazebo>")
    assert identify_urdf(drone.text()).structure == "UAV"
    drone.name = "carrier"
    assert identify_urdf(drone.text()).structure == "UGV"


def test_propellers_named_in_spanish_or_portuguese_are_an_rovs_thrusters() -> None:
    """``hélice`` is a propeller: six of them spinning on a body named as an ROV dive it."""
    rov = RobotText("rov_simulation")
    for i in range(6):
        housing = rov.fixed(rov.root, f"truster_{i}")
        rov.joint(f"truster_{i}_to_helice", "continuous", housing, f"helice_{i}")
    result = identify_urdf(rov.text())
    assert result.structure == "Underwater Vehicle"
    assert result.body is not None
    assert not result.body.wheels


@pytest.mark.parametrize("name", ["AROV", "bluerov2", "openrov_v1", "mini_auv"])
def test_an_rov_or_auv_compound_name_dives_a_hull_of_thrusters(name: str) -> None:
    robot = thrusters_by_name()
    robot.name = name
    assert identify_urdf(robot.text()).structure == "Underwater Vehicle"


@pytest.mark.parametrize("name", ["rover", "provant_vant4", "improver", "petrov_bot", "improv"])
def test_a_word_that_only_holds_rov_is_no_submersibles_name(name: str) -> None:
    robot = thrusters_by_name()
    robot.name = name
    assert identify_urdf(robot.text()).structure == "Surface Vessel"


def test_a_robot_named_as_a_submersible_that_shows_no_way_of_travelling_dives_with_doubt() -> None:
    rov = RobotText("rov_model_urdf")
    rov.fixed(rov.root, "camera_link")
    rov.add(builders.gazebo_sensor("camera_link", "camera", "camera_front"))
    result = identify_urdf(rov.text())
    assert result.structure == "Underwater Vehicle"
    assert result.confidence < 0.85
    # Its name says it dives: a scanner on it floats it no more than a DVL would.
    rov.fixed(rov.root, "scan_link")
    rov.add(builders.gazebo_sensor("scan_link", "ray", "lidar"))
    assert identify_urdf(rov.text()).structure == "Underwater Vehicle"
    # Its propellers push it in water; a rover's name is no submersible's.
    auv = RobotText("my_auv")
    for side in ("left", "right"):
        auv.joint(f"{side}_prop_joint", "continuous", auv.root, f"{side}_prop")
    assert {role.role for role in identify_urdf(auv.text()).roles} == {"thruster"}
    assert identify_urdf(named_hull("rover").text()).structure == "Other"


def test_a_box_a_planar_move_pushes_that_carries_a_subsea_pressure_gauge_is_underwater() -> None:
    robot = RobotText("sub")
    robot.add(builders.model_plugin("move", "libgazebo_ros_planar_move.so"))
    robot.add(builders.model_plugin("depth", "libuuv_gazebo_ros_subsea_pressure_plugin.so"))
    result = identify_urdf(robot.text())
    assert result.structure == "Underwater Vehicle"
    assert result.body is not None
    assert result.body.marine_plugins == ("libuuv_gazebo_ros_subsea_pressure_plugin.so",)


def test_the_same_box_with_a_camera_plugin_stays_a_ground_base() -> None:
    robot = RobotText("rover")
    robot.add(builders.model_plugin("move", "libgazebo_ros_planar_move.so"))
    robot.add(builders.model_plugin("cam", "libgazebo_ros_camera.so"))
    assert identify_urdf(robot.text()).structure == "UGV"


def disc_body(
    places: list[str], *, rpy: str = "0 0 0", radius: float = 0.12, extra: str = ""
) -> str:
    """A body where nothing moves, with leaf links drawn as cylinders 2 cm thick ``radius``
    wide, placed by their visuals at ``places`` and turned by ``rpy``; no part named but by
    ``extra`` (more of the description)."""
    leaves = "".join(
        f'<link name="l{i}"><visual><origin xyz="{xyz}" rpy="{rpy}"/><geometry>'
        f'<cylinder radius="{radius}" length="0.02"/></geometry></visual></link>'
        f'<joint name="j{i}" type="fixed"><parent link="l0"/><child link="l{i}"/></joint>'
        for i, xyz in enumerate(places, start=1)
    )
    return f'<robot name="robot"><link name="l0"/>{leaves}{extra}</robot>'


CORNERS = ["0.2 0.2 0.05", "0.2 -0.2 0.05", "-0.2 0.2 0.05", "-0.2 -0.2 0.05"]
FIXED_WHEEL = (
    '<link name="left_wheel"/><joint name="left_wheel_joint" type="fixed"><parent link="l0"/>'
    '<child link="left_wheel"/></joint>'
)


def test_discs_side_by_side_on_a_body_where_nothing_moves_are_propellers_whatever_their_names() -> (
    None
):
    result = identify_urdf(disc_body(CORNERS))
    assert result.structure == "UAV"
    assert result.body is not None
    assert result.body.fixed_rotors == ("j1", "j2", "j3", "j4")


def test_discs_a_body_collides_as_under_propellers_drawn_as_meshes_are_propellers() -> None:
    # A simulator's model converted to URDF: each propeller drawn as a mesh, colliding as a
    # disc (its first <collision> a cylinder), the visual's shape saying nothing.
    meshes = (
        disc_body(CORNERS).replace("<visual>", "<collision>").replace("</visual>", "</collision>")
    )
    mesh = '<visual><geometry><mesh filename="prop.dae"/></geometry></visual>'
    text = meshes
    for i in range(1, 5):
        text = text.replace(
            f'<link name="l{i}"><collision>', f'<link name="l{i}">{mesh}<collision>'
        )
    result = identify_urdf(text)
    assert result.structure == "UAV"
    assert result.body is not None
    assert result.body.fixed_rotors == ("j1", "j2", "j3", "j4")


@pytest.mark.parametrize(
    ("places", "rpy", "radius", "extra"),
    [
        (CORNERS, "1.5708 0 0", 0.12, ""),
        (["0 0 0.05", "0 0 0.1", "0 0 0.15"], "0 0 0", 0.12, ""),
        (CORNERS, "0 0 0", 0.03, ""),
        (CORNERS[:2], "0 0 0", 0.12, ""),
        (["0.4 0 0.1", "0 0 0.1", "-0.4 0 0.1"], "0 0 0", 0.12, ""),
        ([c.replace("0.05", "-0.5") for c in CORNERS], "0 0 0", 0.12, ""),
        (CORNERS, "0 0 0", 0.12, FIXED_WHEEL),
        (
            CORNERS[:3],
            "0 0 0",
            0.12,
            "".join(builders.gazebo_sensor(f"l{i}", "gpu_ray", f"scan{i}") for i in (1, 2, 3)),
        ),
    ],
    ids=[
        "wheels standing on edge",
        "plates stacked on one axis",
        "posts thicker than wide",
        "two antennas",
        "plates in a row",
        "pads under a table",
        "round brushes beside a fixed wheel",
        "lidar pucks",
    ],
)
def test_cylinders_that_are_no_propeller_discs_do_not_fly(
    places: list[str], rpy: str, radius: float, extra: str
) -> None:
    text = disc_body(places, rpy=rpy, radius=radius, extra=extra)
    assert identify_urdf(text).structure != "UAV"


def spacecraft(*plugins: tuple[str, str]) -> RobotText:
    """A box four thruster plugins push (each names the hull), with ``plugins`` beside them."""
    robot = RobotText("craft")
    for i in range(4):
        robot.add(
            builders.model_plugin(
                f"t{i}", "libbang_bang_thruster.so", "<body_link>base_link</body_link>"
            )
        )
    for name, filename in plugins:
        robot.add(builders.model_plugin(name, filename))
    return robot


@pytest.mark.parametrize(
    "plugin",
    [("wheel", "libcontinuous_reaction_wheel.so"), ("air", "libair_thruster_ros_plugin.so")],
)
def test_thrusters_beside_a_reaction_wheel_or_air_thrusters_fly_the_craft(
    plugin: tuple[str, str],
) -> None:
    # A free-flyer on an air table or in orbit: its thrusters do not put it in water.
    result = identify_urdf(spacecraft(plugin).text())
    assert result.structure == "UAV"
    assert [c.motion_control for c in result.motion_controls] == ["Flight"]


def test_thrusters_with_a_reaction_wheel_and_a_water_plugin_or_name_stay_in_water() -> None:
    craft = spacecraft(("wheel", "libreaction_wheel.so"), ("water", "libunderwater_object.so"))
    assert identify_urdf(craft.text()).structure == "Underwater Vehicle"
    assert identify_urdf(spacecraft().text()).structure == "Underwater Vehicle"
    # A gyro stabiliser on a craft named for the water does not lift it out.
    auv = spacecraft(("gyro", "libreaction_wheel.so"))
    auv.name = "auv"
    assert identify_urdf(auv.text()).structure == "Underwater Vehicle"


def densities(thrusters: str, *others: tuple[str, str]) -> RobotText:
    """Three thruster plugins on joints of their own, each given ``thrusters`` as the density of
    its medium, a hydrodynamics plugin damping the body, and ``others`` (file, parameters)."""
    craft = RobotText("craft")
    for i in range(3):
        craft.joint(f"t{i}_joint", "continuous", "base_link", f"t{i}", '<axis xyz="0 1 0"/>')
        params = f"<joint_name>t{i}_joint</joint_name><fluid_density>{thrusters}</fluid_density>"
        craft.add(builders.model_plugin(f"t{i}", "libgz-sim8-thruster-system.so", params))
    damping = "<link_name>base_link</link_name><xU>-6.0</xU>"
    craft.add(builders.model_plugin("drag", "libgz-sim8-hydrodynamics-system.so", damping))
    for i, (filename, params) in enumerate(others):
        craft.add(builders.model_plugin(f"other{i}", filename, params))
    return craft


def test_thrusters_given_airs_density_fly_the_craft_whatever_plugin_damps_it() -> None:
    # A fixed-wing aircraft a maker pushes with Gazebo Sim's thruster plugin in air (1.204 kg/m³),
    # its drag a hydrodynamics plugin's, its wings' lift given air's density too.
    lift = ("gz-sim-advanced-lift-drag-system", "<air_density>1.225</air_density>")
    result = identify_urdf(densities("1.204", lift).text())
    assert result.structure == "UAV"
    assert [c.motion_control for c in result.motion_controls][:1] == ["Flight"]
    assert not any("surface" in line for line in result.evidence)


def test_thrusters_given_waters_density_or_air_and_water_stay_in_water() -> None:
    assert identify_urdf(densities("1000").text()).structure == "Underwater Vehicle"
    # A submersible's fins given water's density in a lift plugin's air tag (LRAUV-style).
    fins = ("gz-sim-lift-drag-system", "<air_density>1000</air_density>")
    assert identify_urdf(densities("1.2", fins).text()).structure == "Underwater Vehicle"
    # An unexpanded density is none: the plugins' words decide.
    assert identify_urdf(densities("${rho}").text()).structure == "Underwater Vehicle"
    # Thrusters that give no density of their own are not flown by a sail's lift in the air.
    sail = ("gz-sim-lift-drag-system", "<air_density>1.2</air_density>")
    assert identify_urdf(densities("${rho}", sail).text()).structure == "Underwater Vehicle"
    # Air for the thrusters, water for the hull's buoyancy: in water.
    hull = ("gz-sim-buoyancy-system", "<uniform_fluid_density>1025</uniform_fluid_density>")
    assert identify_urdf(densities("1.2", hull).text()).structure != "UAV"


def test_a_reaction_wheel_with_no_thruster_says_nothing_of_flight() -> None:
    rover = builders.ugv()
    rover.add(builders.model_plugin("wheel", "libreaction_wheel.so"))
    result = identify_urdf(rover.text())
    assert result.structure == "UGV"
    assert not any("air or space" in line for line in result.evidence)


def test_links_named_for_a_thrusters_model_fixed_to_a_hull_are_its_thrusters() -> None:
    # A student ROV: six BlueRobotics T200 frames fixed to a body of no mass, nothing else.
    rov = RobotText("rov", root="base_link")
    for i in range(1, 7):
        rov.fixed(rov.root, f"t200_link_t{i}")
    result = identify_urdf(rov.text())
    assert result.structure == "Underwater Vehicle"
    assert any("t200_link_t1 (fixed)" in line for line in result.evidence)


def outboards(*, spin: str = "1 0 0", wheels: bool = False) -> RobotText:
    """A hull with two outboard engines at its stern, each swivelling about the upright on its
    mount and turning a propeller about ``spin`` (a WAM-V's azimuthing outboards)."""
    robot = RobotText("craft")
    limit = '<limit lower="-3.14" upper="3.14" effort="10" velocity="10"/>'
    for side, y in (("left", 1.0), ("right", -1.0)):
        mount = f'<origin xyz="-2.4 {y} 0.3"/><axis xyz="0 0 1"/>{limit}'
        engine = robot.joint(
            f"{side}_engine_joint", "revolute", "base_link", f"{side}_engine", mount
        )
        spin_at = f'<origin xyz="-0.3 0 -0.5"/><axis xyz="{spin}"/>'
        robot.joint(f"{side}_propeller_joint", "continuous", engine, f"{side}_propeller", spin_at)
    if wheels:
        builders.wheeled_base(robot)
    return robot


def test_propellers_turning_about_a_level_axis_on_a_wingless_body_push_it_as_a_boats_do() -> None:
    result = identify_urdf(outboards().text())
    assert result.structure == "Surface Vessel"
    assert result.body is not None
    assert result.body.thrusters == ("left_propeller_joint", "right_propeller_joint")
    # About the upright they lift (a multirotor's); over wheels they are a plane's on its gear;
    # on an aircraft's name, an aircraft's.
    named = outboards()
    named.name = "twin_engine_aircraft"
    for robot in (outboards(spin="0 0 1"), outboards(wheels=True), named):
        other = identify_urdf(robot.text())
        assert other.body is not None
        assert other.body.thrusters == ()


def tub(*, turned: tuple[float, ...] = (0.0, 1.5708, 3.1416, -1.5708)) -> RobotText:
    """A round hull with a propeller on a fixed guard at each side, each turning about its
    guard's y axis, the guards turned about the upright by ``turned`` (tangent to the hull)."""
    robot = RobotText("tub")
    for index, yaw in enumerate(turned):
        x, y = 0.1 * math.cos(yaw - 1.5708), 0.1 * math.sin(yaw - 1.5708)
        place = f'<origin xyz="{x} {y} -0.1" rpy="0 0 {yaw}"/>'
        guard = robot.joint(f"guard_{index}_joint", "fixed", "base_link", f"guard_{index}", place)
        spin = '<origin xyz="0 0 0"/><axis xyz="0 1 0"/>'
        robot.joint(f"propeller_{index}_joint", "continuous", guard, f"propeller_{index}", spin)
    return robot


def test_level_propellers_square_to_each_other_push_a_hull_every_way_as_a_vessels_do() -> None:
    result = identify_urdf(tub().text())
    assert result.structure == "Surface Vessel"
    assert result.body is not None
    assert len(result.body.thrusters) == 4
    assert result.body.rotors == ()
    # All along one line (a multirotor drawn with y up), they stay rotors; so they do on an
    # aircraft's name.
    parallel = identify_urdf(tub(turned=(0.0, 0.0, 3.1416, 3.1416)).text())
    assert parallel.body is not None
    assert parallel.body.thrusters == ()
    named = tub()
    named.name = "tub_drone"
    flown = identify_urdf(named.text())
    assert flown.body is not None
    assert flown.body.thrusters == ()


def test_more_level_propellers_than_a_hull_carries_are_no_thrusters() -> None:
    # Sixteen set around a tub are its thrusters; a stranger's seventeen or more are no hull's
    # (compared pair by pair, thousands would cost minutes).
    around = [index * 2 * math.pi / 16 for index in range(16)]
    sixteen = identify_urdf(tub(turned=tuple(around)).text())
    assert sixteen.body is not None
    assert len(sixteen.body.thrusters) == 16
    more = identify_urdf(tub(turned=(*around, 0.0)).text())
    assert more.body is not None
    assert more.body.thrusters == ()


def rotors_at(*places: tuple[str, str], vectored: bool = False) -> RobotText:
    """A body with a rotor at each (place, axis), on the body itself, or on a mount that
    swings it (``vectored``)."""
    robot = RobotText("craft")
    for index, (place, axis) in enumerate(places):
        parent, xyz = robot.root, place
        if vectored:
            swing = f'<origin xyz="{xyz}"/><axis xyz="0 1 0"/>'
            limit = '<limit lower="-1.57" upper="1.57" effort="1" velocity="1"/>'
            parent = robot.joint(
                f"mount_{index}_joint", "revolute", parent, f"mount_{index}", swing + limit
            )
            xyz = "0 0 0"
        spin = f'<origin xyz="{xyz}"/><axis xyz="{axis}"/>'
        robot.joint(f"propeller_{index}_joint", "continuous", parent, f"propeller_{index}", spin)
    return robot


@pytest.mark.parametrize(
    "craft",
    [
        # A quadplane drawn with y up: four lift rotors about y, a pusher about x behind them;
        # the lift rotors spread over what reads as the upright (the drawing's sides).
        rotors_at(
            ("0.4 0 0.4", "0 1 0"),
            ("-0.4 0 0.4", "0 1 0"),
            ("0.4 0 -0.4", "0 1 0"),
            ("-0.4 0 -0.4", "0 1 0"),
            ("-0.8 0 0", "1 0 0"),
        ),
        # An airship's propellers swung by vectoring mounts.
        rotors_at(("0 1 0", "1 0 0"), ("0 -1 0", "1 0 0"), ("-2 0 0", "0 1 0"), vectored=True),
        # Two fans square to each other: fans, not a hull's thrusters.
        rotors_at(("0.2 0 0", "1 0 0"), ("0 0.2 0", "0 1 0")),
    ],
)
def test_level_rotors_square_to_each_other_stay_rotors_off_one_height_on_mounts_or_two(
    craft: RobotText,
) -> None:
    result = identify_urdf(craft.text())
    assert result.body is not None
    assert result.body.thrusters == ()


def test_level_rotors_on_the_frame_itself_are_no_outboards() -> None:
    # A quadrotor exported with y up: its rotors turn about a level axis, on the frame, on no
    # swivelling engine. They stay rotors.
    robot = RobotText("quad_export")
    for index, (x, z) in enumerate(((0.2, 0.2), (0.2, -0.2), (-0.2, 0.2), (-0.2, -0.2))):
        place = f'<origin xyz="{x} 0.05 {z}"/><axis xyz="0 1 0"/>'
        robot.joint(f"rotor_{index}_joint", "continuous", "base_link", f"rotor_{index}", place)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.thrusters == ()
    assert len(result.body.rotors) == 4


def test_a_floor_track_whose_carriages_slide_on_it_is_no_tracked_vehicle() -> None:
    # Fresh set 1748's robot track: two carriages slide on a rail whose frame a fixed joint
    # named for the track holds. A rail is no tread, its fixed frame neither.
    robot = RobotText("robot_track", root="track")
    robot.chain("track", ["track_joint_1"], "prismatic")
    robot.chain("track", ["track_joint_2"], "prismatic")
    robot.joint("track_base_link-base", "fixed", "track", "track_base")
    tree = tree_of(robot)
    assert tree.on_a_rail
    assert tracks(tree) == ()
    assert identify_urdf(robot.text()).structure != "UGV"


def test_a_tracked_vehicle_drawn_with_fixed_tracks_is_still_tracked() -> None:
    robot = RobotText("crawler")
    robot.joint("left_track_joint", "fixed", robot.root, "left_track")
    robot.joint("right_track_joint", "fixed", robot.root, "right_track")
    assert tracks(tree_of(robot)) == ("left_track_joint", "right_track_joint")
