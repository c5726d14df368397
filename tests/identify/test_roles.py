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


def pushed_pods(*, in_water: bool) -> RobotText:
    """Two unnamed pods on swivels (``p1_yaw``, ``p2_yaw``) that force plugins push on command,
    on a hull a buoyancy plugin floats (``in_water``) or on a bare body."""
    robot = RobotText("r")
    for i, y in ((1, 0.2), (2, -0.2)):
        builders.placed(robot, f"p{i}_yaw", "revolute", robot.root, f"p{i}", xyz=f"0 {y} -0.1")
        robot.add(pushed(f"p{i}"))
    if in_water:
        robot.add(FLOATS)
    return robot


def pushed(link: str) -> str:
    return builders.model_plugin(
        f"{link}_force", "libgazebo_ros_force.so", f"<link_name>{link}</link_name>"
    )


FLOATS = builders.model_plugin("b", "libbuoyancy_plugin.so", "<surface_z>0</surface_z>")


def test_a_swivel_on_a_hull_in_water_whose_link_a_force_plugin_pushes_is_a_thruster() -> None:
    found = roles(pushed_pods(in_water=True))
    assert found["p1_yaw"] == (
        "thruster",
        "<link_name> of force plugin libgazebo_ros_force.so: a link it pushes, on a body in water",
    )
    assert identify_urdf(pushed_pods(in_water=True).text()).structure == "Surface Vessel"
    # Out of water a force plugin pushes whatever it is given (a drone's rotor, a test rig):
    # no thruster.
    assert "thruster" not in {role for role, _ in roles(pushed_pods(in_water=False)).values()}


def test_a_pushed_link_past_an_arms_joints_on_a_slide_or_a_rudder_is_no_thruster() -> None:
    # An ROV's arm whose last link a force plugin pushes (a tether's pull, a test load) stays
    # an arm; a float's heave slide that waves push, and a rudder, stay what they were.
    rov = builders.underwater_vehicle()
    rov.chain(rov.root, ["arm_joint_1", "arm_joint_2", "arm_joint_3", "arm_joint_4"])
    rov.add(pushed("arm_joint_4_link"))
    assert roles(rov)["arm_joint_4"][0] != "thruster"
    float_ = RobotText("r")
    builders.placed(float_, "heave", "prismatic", float_.root, "float", axis="0 0 1")
    float_.add(pushed("float"))
    float_.add(FLOATS)
    assert roles(float_)["heave"][0] != "thruster"
    # A rudder a current pushes is a control surface.
    boat = pushed_pods(in_water=True)
    builders.placed(boat, "rudder_joint", "revolute", boat.root, "rudder", xyz="-0.5 0 -0.1")
    boat.add(pushed("rudder"))
    assert roles(boat)["rudder_joint"][0] == "fin"


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


def test_lift_and_drag_on_spinning_joints_are_propellers_on_limited_ones_control_surfaces() -> None:
    # Gazebo models a propeller as a lift-drag plugin on a blade joint that turns without
    # limits; a control surface deflects within limits. Names say nothing here.
    robot = RobotText("frame")
    for i in range(4):
        robot.joint(f"m{i}", "continuous", robot.root, f"blade{i}")
        robot.add(
            builders.model_plugin(
                f"ld{i}", "libLiftDragPlugin.so", f"<control_joint>m{i}</control_joint>"
            )
        )
    robot.chain(robot.root, ["surface_a"])
    robot.add(
        builders.model_plugin(
            "ld_a", "libLiftDragPlugin.so", "<control_joint>surface_a</control_joint>"
        )
    )
    result = identify_urdf(robot.text())
    roles = {role.joint: role for role in result.roles}
    assert {roles[f"m{i}"].role for i in range(4)} == {"rotor"}
    assert roles["m0"].evidence == (
        "<control_joint> of lift plugin libLiftDragPlugin.so, turning without limits (a propeller)"
    )
    assert roles["surface_a"].role == "fin"
    assert result.structure == "UAV"


def test_a_spinning_joint_a_lift_plugin_names_on_a_body_in_water_is_no_rotor() -> None:
    robot = builders.underwater_vehicle()
    robot.joint("spinner", "continuous", robot.root, "spinner_link")
    robot.add(
        builders.model_plugin(
            "ld", "libLiftDragPlugin.so", "<control_joint>spinner</control_joint>"
        )
    )
    result = identify_urdf(robot.text())
    assert {role.joint: role.role for role in result.roles}["spinner"] == "fin"
    assert result.structure == "Underwater Vehicle"


def test_a_gazebo_sim_lift_drag_system_names_fins_by_its_file_name() -> None:
    # Gazebo Sim spells the plugin with dashes: gz-sim-lift-drag-system (and the advanced
    # one); the joints it names have neutral names here, so only the plugin says what they are.
    robot = RobotText("glider")
    for i, filename in enumerate(("gz-sim-lift-drag-system", "gz-sim-advanced-lift-drag-system")):
        robot.chain(robot.root, [f"j{i}"])
        robot.add(
            builders.model_plugin(
                f"gz::sim::systems::LiftDrag{i}",
                filename,
                f"<control_joint_name>j{i}</control_joint_name>",
            )
        )
    roles = {role.joint: role.role for role in identify_urdf(robot.text()).roles}
    assert roles == {"j0": "fin", "j1": "fin"}


def test_a_vrx_surface_plugin_in_a_lib_file_is_a_hull_at_the_surface() -> None:
    robot = RobotText("wamv")
    for side in ("left", "right"):
        robot.joint(f"{side}_thruster_joint", "continuous", robot.root, f"{side}_thruster")
    robot.add(
        builders.model_plugin("vrx::Surface", "libSurface.so", "<link_name>base_link</link_name>")
    )
    result = identify_urdf(robot.text())
    assert result.structure == "Surface Vessel"


def sampling_rover(springs: bool = True) -> RobotText:
    """A tracked rover lowering a sampling chamber: one driven slide from the base, under it a
    holder and the chamber on two hinges, each held on a torsional spring plugin (they yield
    to the ground; nobody drives them)."""
    robot = builders.tracked()
    robot.joint("slide", "prismatic", robot.root, "coupling")
    robot.joint("holder_hinge", "revolute", "coupling", "holder")
    robot.joint("chamber_hinge", "revolute", "holder", "chamber")
    robot.add(builders.transmission("slide"))
    if springs:
        for joint in ("holder_hinge", "chamber_hinge"):
            robot.add(
                builders.model_plugin(
                    f"{joint}_spring",
                    "libgazebo_joint_torsional_spring.so",
                    f"<kx>10</kx><set_point>0</set_point><joint>{joint}</joint>",
                )
            )
    return robot


def test_joints_a_spring_plugin_holds_are_passive_and_leave_a_one_joint_tool_no_arm() -> None:
    found = roles(sampling_rover())
    assert found["holder_hinge"] == (
        "passive",
        "<joint> of spring plugin libgazebo_joint_torsional_spring.so",
    )
    assert found["chamber_hinge"][0] == "passive"
    assert found["slide"][0] != "arm"
    assert identify_urdf(sampling_rover().text()).structure == "UGV"
    # The same three joints with no spring: a short arm on a rover.
    assert identify_urdf(sampling_rover(springs=False).text()).structure == "Mobile Manipulator"


def arm_car(*, grasp: bool) -> RobotText:
    """A wheeled base carrying a chain of six unnamed joints whose last link holds two one-joint
    chains turning without limits, not side by side (``j7``, ``j8``: a sloppy gripper's jaws, no
    word or shape says so); with ``grasp``, a grasp plugin names their links as the gripper's
    and the last link as its palm (``libgazebo_grasp_fix.so``'s ``<arm>`` entry)."""
    robot = builders.ugv()
    tip = robot.chain(robot.root, [f"j{i}" for i in range(1, 7)])
    for name, place in (("j7", "0.05 0.08 0"), ("j8", "0.03 -0.08 0.02")):
        builders.placed(robot, name, "continuous", tip, f"{name}_link", xyz=place)
    if grasp:
        robot.add(
            builders.model_plugin(
                "gazebo_grasp_fix",
                "libgazebo_grasp_fix.so",
                f"<arm><arm_name>my_arm</arm_name><palm_link>{tip}</palm_link>"
                "<gripper_link> j7_link </gripper_link><gripper_link>j8_link</gripper_link>"
                "</arm><update_rate>50</update_rate>",
            )
        )
    return robot


def test_the_links_a_grasp_plugin_names_as_a_grippers_are_moved_by_its_fingers() -> None:
    found = roles(arm_car(grasp=True))
    assert found["j7"] == ("finger", "<gripper_link> of grasp plugin libgazebo_grasp_fix.so")
    assert found["j8"][0] == "finger"
    assert found["j6"][0] == "arm"  # its palm is the arm's last link, no finger
    assert identify_urdf(arm_car(grasp=True).text()).structure == "Mobile Manipulator"
    # Without the plugin nothing says the two turning joints close on anything.
    assert identify_urdf(arm_car(grasp=False).text()).structure != "Mobile Manipulator"


def test_a_swivel_named_joint_that_carries_a_finger_is_no_caster() -> None:
    # Three fingers on a palm, two of them on preshape joints into links named swivel_N: the
    # swivels turn fingers, not wheels, so the hand is no mobile base.
    robot = RobotText("hand", root="palm")
    for i in (1, 2):
        swivel = builders.placed(
            robot, f"preshape_{i}", "revolute", "palm", f"swivel_{i}", xyz=f"0 {0.03 * i} 0"
        )
        robot.chain(swivel, [f"proximal_{i}", f"distal_{i}"])
    robot.chain("palm", ["proximal_3", "distal_3"])
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.casters == ()
    assert result.structure != "UGV"


def axles_carrying_propellers(count: int, *, in_water: bool = False) -> RobotText:
    """``count`` unnamed axles on endless joints, each carrying a ``prop<i>`` link on a fixed
    joint (how a simulator's model fixes a propeller to its motor's shaft)."""
    robot = RobotText("model")
    for i in range(count):
        axle = robot.joint(f"motor{i}_to_axle{i}", "continuous", robot.root, f"axle{i}")
        robot.fixed(axle, f"prop{i}")
    if in_water:
        robot.add(builders.model_plugin("buoyancy", "libbuoyancy_gazebo_plugin.so"))
    return robot


def test_an_axle_turning_a_propeller_fixed_to_it_is_a_rotor_or_in_water_a_thruster() -> None:
    found = roles(axles_carrying_propellers(6))
    assert found["motor0_to_axle0"] == (
        "rotor",
        "turns the propeller-named link prop0 fixed to it",
    )
    assert identify_urdf(axles_carrying_propellers(6).text()).structure == "UAV"
    wet = roles(axles_carrying_propellers(2, in_water=True))
    assert {role for role, _ in wet.values()} == {"thruster"}


def test_an_axle_whose_fixed_link_has_no_propeller_name_plays_no_rotor() -> None:
    robot = RobotText("model")
    for i in range(4):
        robot.fixed(robot.joint(f"j{i}", "continuous", robot.root, f"axle{i}"), f"disc{i}")
    assert all(role != "rotor" for role, _ in roles(robot).values())


def test_a_hub_carrying_a_wheel_and_a_brake_rotor_is_a_wheel_not_a_rotor() -> None:
    car = RobotText("car")
    for corner, (x, y) in (
        ("fl", (1.2, 0.7)),
        ("fr", (1.2, -0.7)),
        ("rl", (-1.2, 0.7)),
        ("rr", (-1.2, -0.7)),
    ):
        hub = builders.placed(
            car,
            f"{corner}_hub_joint",
            "continuous",
            car.root,
            f"{corner}_hub",
            xyz=f"{x} {y} -0.2",
            axis="0 1 0",
        )
        car.fixed(hub, f"{corner}_tyre")
        car.fixed(hub, f"{corner}_brake_rotor")
    result = identify_urdf(car.text())
    assert result.structure == "UGV"
    assert "rotor" not in {role.role for role in result.roles}


def test_steering_motors_carrying_wheels_are_no_rotors() -> None:
    swerve = RobotText("swerve")
    for corner, (x, y) in (
        ("fl", (0.3, 0.3)),
        ("fr", (0.3, -0.3)),
        ("rl", (-0.3, 0.3)),
        ("rr", (-0.3, -0.3)),
    ):
        module = builders.placed(
            swerve,
            f"{corner}_steer_motor",
            "revolute",
            swerve.root,
            f"{corner}_module",
            xyz=f"{x} {y} 0",
        )
        swerve.fixed(module, f"{corner}_wheel")
    assert identify_urdf(swerve.text()).structure != "UAV"


def test_a_grippers_spinning_part_named_a_prop_is_the_grippers_and_flies_nothing() -> None:
    # A servo gripper's horn turns without limits on a leaf link named after it
    # (``left_gripper`` into ``left/gripper_prop_link``): one on each of two arms is no pair
    # of rotors, and the wheeled base carrying the arms is not flown.
    robot = RobotText("two_armed_base")
    builders.wheeled_base(robot, 4)
    for side in ("left", "right"):
        tip = builders.arm(robot, robot.root, f"{side}_")
        robot.joint(f"{side}_gripper", "continuous", tip, f"{side}/gripper_prop_link")
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    found = {role.joint: role.role for role in result.roles}
    assert found["left_gripper"] == found["right_gripper"] == "finger"


def ball_robot(params: str) -> RobotText:
    """A ball that rolls on two unnamed joints (a spin about z, a roll about x), moved by a
    plugin of its own (``libball_controller.so``) with ``params``."""
    ball = RobotText("ball")
    spun = ball.joint("spin", "continuous", ball.root, "inner", '<axis xyz="0 0 1"/>')
    ball.joint("roll", "continuous", spun, "shell", '<axis xyz="1 0 0"/>')
    ball.add(builders.model_plugin("ctl", "libball_controller.so", params))
    return ball


@pytest.mark.parametrize(
    ("spacing", "size"),
    [
        ("wheelSeparation", "wheel_diameter"),
        ("wheel_track", "wheelRadius"),
        ("wheelDistance", "wheel-radius"),
    ],
)
def test_a_plugin_of_its_own_that_gives_wheel_spacing_and_size_drives_the_body(
    spacing: str, size: str
) -> None:
    result = identify_urdf(
        ball_robot(
            "<leftJoint>roll</leftJoint><rightJoint>spin</rightJoint>"
            f"<{spacing}>0.5</{spacing}><{size}>0.2</{size}>"
        ).text()
    )
    assert result.structure == "UGV"
    assert {r.joint: r.evidence for r in result.roles}["roll"] == (
        "<leftJoint> of drive plugin libball_controller.so"
    )


def test_the_joints_such_a_plugin_names_not_as_wheels_keep_their_own_roles() -> None:
    """A robot's own plugin drives its base and names its arm's joints too: the arm stays."""
    robot = RobotText("mybot")
    for side, y in (("left", 0.2), ("right", -0.2)):
        builders.placed(
            robot, f"{side}_joint", "continuous", robot.root, side, xyz=f"0 {y} 0", axis="0 1 0"
        )
    robot.chain(robot.root, ["j1", "j2", "j3", "j4", "j5", "j6"])
    robot.add(
        builders.model_plugin(
            "ctl",
            "libmybot_gazebo.so",
            "<leftJoint>left_joint</leftJoint><rightJoint>right_joint</rightJoint>"
            "<wheelSeparation>0.4</wheelSeparation><wheelDiameter>0.1</wheelDiameter>"
            + "".join(f"<joint{i}>j{i}</joint{i}>" for i in range(1, 7)),
        )
    )
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    assert {r.role for r in result.roles if r.joint.startswith("j")} == {"arm"}


@pytest.mark.parametrize(
    ("tag", "topic", "drives"),
    [
        ("commandTopic", "pod/cmd_vel", True),  # a robot's own holonomic drive
        ("cmd_vel_topic", "cmd_vel", True),
        ("commandTopic", "pod/joint_command", False),  # not a velocity command
        ("topicName", "cmd_vel", False),  # the tag every plugin names its own topic by
    ],
)
def test_a_plugin_of_its_own_taking_velocity_commands_drives_the_body(
    tag: str, topic: str, *, drives: bool
) -> None:
    # A pod on spheres fixed under it, moved only by its own plugin.
    pod = RobotText("pod")
    pod.fixed(pod.root, "left_wheel")
    pod.fixed(pod.root, "right_wheel")
    pod.add(builders.model_plugin("ctl", "libpod_control.so", f"<{tag}>{topic}</{tag}>"))
    result = identify_urdf(pod.text())
    assert ("Driving" in {c.motion_control for c in result.motion_controls}) is drives


def test_a_plugin_that_gives_a_wheel_size_alone_drives_nothing() -> None:
    result = identify_urdf(ball_robot("<wheelDiameter>0.2</wheelDiameter>").text())
    assert result.structure != "UGV"


def tracked_chair(params: str) -> RobotText:
    """A tracked wheelchair as its author drew it: two side frames (``limgf``, ``rimgf``), two
    flippers on limited hinges each, no name a track's, moved by a plugin of its own file
    (``libsimple.so``) with ``params``."""
    chair = RobotText("chair")
    for side, y in (("l", 0.3), ("r", -0.3)):
        frame = builders.placed(chair, f"{side}imgf", "fixed", chair.root, f"{side}imgf")
        for end, x in (("f", 0.3), ("r", -0.3)):
            builders.placed(
                chair,
                f"{end}{side}",
                "revolute",
                frame,
                f"{end}{side}_link",
                xyz=f"{x} {y} 0",
                axis="0 1 0",
            )
    chair.add(builders.model_plugin("simple_tracked_vehicle", "libsimple.so", params))
    return chair


def test_a_plugin_of_its_own_that_names_a_left_and_a_right_track_moves_the_body_on_them() -> None:
    tracks = "<body>base_link</body><left_track>limgf</left_track>"
    result = identify_urdf(tracked_chair(f"{tracks}<right_track>rimgf</right_track>").text())
    assert (result.structure, result.evidence[0]) == ("UGV", "tracks: libsimple.so")
    assert identify_urdf(tracked_chair(tracks).text()).structure != "UGV"  # one side: no tracks
    elsewhere = f"{tracks}<right_track>stereo_right</right_track>"  # no link of the body
    assert identify_urdf(tracked_chair(elsewhere).text()).structure != "UGV"


def two_hinges(word: str) -> RobotText:
    """Two hinges with stops on level axles, one on each side, named ``WORD_izquierda_joint``
    and ``WORD_derecha_joint``: wheels only by their name (else two hinges that swing about the
    line between them: no jaws either, they never close on each other)."""
    base = RobotText("base")
    for side, y in (("izquierda", 0.3), ("derecha", -0.3)):
        builders.placed(
            base, f"{word}_{side}_joint", "revolute", base.root, f"{word}_{side}",
            xyz=f"0 {y} 0", axis="0 1 0",
        )  # fmt: skip
    return base


@pytest.mark.parametrize("word", ["wheel", "rueda", "llanta", "roue", "whl"])
def test_a_wheel_named_in_spanish_or_french_or_shortened_is_a_wheel(word: str) -> None:
    """``Acople_1__rueda_1``: the wheel's name in the language its makers wrote;
    ``front_left_whl_joint``: its name shortened."""
    result = identify_urdf(two_hinges(word).text())
    assert (result.structure, {role.role for role in result.roles}) == ("UGV", {"wheel"})


@pytest.mark.parametrize("word", ["proue", "rouet", "ruota", "ruotante", "whlx"])
def test_a_word_holding_roue_inside_it_or_italians_rotate_names_no_wheel(word: str) -> None:
    result = identify_urdf(two_hinges(word).text())
    assert (result.structure, {role.role for role in result.roles}) == ("Other", {"other"})


def jaws(word: str) -> RobotText:
    """A four-joint chain of unnamed axes (``eje_1``) ending in two hinged jaws named with
    ``word`` (``garra_d``, ``garra_i``)."""
    robot = RobotText("brazo")
    tip = robot.chain(robot.root, [f"eje_{i}" for i in range(1, 5)])
    for side, y in (("d", 0.02), ("i", -0.02)):
        builders.placed(
            robot, f"{word}_{side}", "revolute", tip, f"{word}_{side}_link",
            xyz=f"0 {y} 0.05", axis="1 0 0",
        )  # fmt: skip
    return robot


@pytest.mark.parametrize("word", ["pinza", "garra", "greifer"])
def test_a_gripper_named_in_spanish_or_german_is_read_by_its_name(word: str) -> None:
    """``Pinza_Garra_D``: a gripper's jaw named in the language its makers wrote."""
    fingers = [r for r in identify_urdf(jaws(word).text()).roles if r.role == "finger"]
    assert [r.evidence for r in fingers] == [f"gripper name ({word}_{s})" for s in "di"]


def test_jaws_named_for_nothing_are_told_by_their_shape_alone() -> None:
    fingers = [r for r in identify_urdf(jaws("xyz").text()).roles if r.role == "finger"]
    assert [r.evidence for r in fingers] == [
        "one of two jaws side by side at the end of a chain (eje_4_link)"
    ] * 2
