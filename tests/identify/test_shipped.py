"""Motion controls the robot's packages ship, read from their launch, config and script texts."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from solver.identify import identify, load_profile
from solver.identify.body import detect_body
from solver.identify.readers.urdf import parse_urdf
from solver.identify.readers.workspace import ShippedFile, Workspace
from solver.identify.shipped import body_from_workspace, controls_from_workspace, named_joints
from tests.identify.builders import (
    LASER,
    RobotText,
    arm,
    biped,
    gazebo_sensor,
    humanoid,
    legged_manipulator,
    manipulator,
    pan_tilt_only,
    parallel_gripper,
    placed,
    quadrotor,
    quadruped,
    tilt_rotor,
    transmission,
    ugv,
)

PROFILE = load_profile()


def shipping(*texts: str) -> Workspace:
    files = tuple(
        ShippedFile("craft_bringup", f"craft_bringup/launch/{n}.launch.py", text)
        for n, text in enumerate(texts)
    )
    return Workspace("/ws/src", "craft_description", ("craft_bringup",), files)


def shipped(structure: str, *texts: str) -> dict[str, str]:
    found = controls_from_workspace(shipping(*texts), PROFILE, structure)
    return {c.motion_control: c.source for c in found}


def shipped_to_arms(text: str) -> list[list[str]]:
    """The controls ``text`` shows for a fixed arm and for a mobile manipulator."""
    return [list(shipped(structure, text)) for structure in ("Manipulator", "Mobile Manipulator")]


@pytest.mark.parametrize(
    ("name", "line"),
    [
        ("scripts/goals.py", "client = SimpleActionClient('move_base', MoveBaseAction)"),
        ("src/planner.cpp", "std::vector<geometry_msgs::Pose> waypoints;"),
    ],
)
def test_code_commented_out_in_a_script_or_a_node_ships_nothing(
    tmp_path: Path, name: str, line: str
) -> None:
    mark = "//" if name.endswith(".cpp") else "#"

    def controls_shipping(text: str, folder: str) -> dict[str, str]:
        path = described(tmp_path / folder, rover_with_a_lidar(), "")
        files = {name: f"#!/usr/bin/env python\n{text}\nuse(craft_description)\n"}
        package(tmp_path / folder / "ws" / "src", "craft_navigation", files)
        return controls_of(path)

    assert "Waypoint" in controls_shipping(line, "running")
    assert "Waypoint" not in controls_shipping(f"  {mark} {line}", "commented")


def test_a_bringup_that_runs_nav2_ships_waypoint_goals_named_by_its_file() -> None:
    assert shipped("UGV", "IncludeLaunchDescription('nav2_bringup')")["Waypoint"] == (
        "package craft_bringup: craft_bringup/launch/0.launch.py (nav2_bringup)"
    )


@pytest.mark.parametrize("structure", PROFILE.structure_names)
def test_navigation_shipped_drives_a_body_on_the_ground_and_no_other(structure: str) -> None:
    # The stack that takes the goals sends the base velocity commands, whatever wheels the
    # description draws; a vessel's, a walker's or a flier's navigation commands it another
    # way, and an arm, a head or a hand is sent no goals at all.
    nav2 = "IncludeLaunchDescription('nav2_bringup')"
    velocity = PROFILE.velocity_control(structure)
    shown = shipped(structure, nav2)
    if structure in ("UGV", "Mobile Manipulator", "Other"):
        assert (
            shown["Driving"]
            == shown["Waypoint"]
            == ("package craft_bringup: craft_bringup/launch/0.launch.py (nav2_bringup)")
        )
    else:
        assert velocity not in shown


def test_a_structure_a_profile_adds_is_not_driven_by_navigation() -> None:
    rule = next(r for r in PROFILE.package_controls if r.control == "navigation velocity")
    assert not rule.reads("Blimp")
    assert rule.reads("UGV")


def test_move_base_and_position_set_points_are_navigation_too() -> None:
    assert "Waypoint" in shipped("UGV", "<node pkg='move_base' type='move_base'/>")
    assert "Waypoint" in shipped("UAV", "rospy.Publisher('mavros/setpoint_position/local')")
    assert "Waypoint" in shipped("Hexapod", "# point_to_point.py: walk to each (x, y) listed")
    # A "go to" a place is navigation; a "go to" a state, a joint or sleep is not, nor
    # MoveIt's tutorial pose goal (an arm's).
    for place in (
        "self.go_to_pose(x, y)",
        "goto_depth(2.0)",
        "go_to_dock()",
        "goto_wp(3)",
        "go_to_lat_lon(a, b)",
    ):
        assert "Waypoint" in shipped("Underwater Vehicle", place)
    for other in (
        "go_to_stop_state_on_crash(this);",
        "arm.go_to_joint(q)",
        "goto_sleep()",
        "goto_joint_state(q)",
        "self.go_to_pose_goal()",
        "locobot.arm.go_to_home_pose()",
        "go_to_latest_frame()",
        "ego_to_target = t",
    ):
        assert shipped("Mobile Manipulator", other) == {}
    # A path planned by A* or followed (a path follower, a tracker, pure pursuit) is navigation.
    for path in (
        "from astar import plan",
        "a_star(grid)",
        "AStarPlanner(ox, oy)",
        "path_following.launch.py",
        "path_tracking_node",
        "PurePursuit",
    ):
        assert "Waypoint" in shipped("UGV", path), path
    assert shipped("UGV", "datastar_client(); a_start = 0") == {}
    assert shipped("UGV", "#include <AStar32U4.h>  // a motor board") == {}
    assert "Waypoint" in shipped("UGV", "a-star search")
    # Point-to-point scan matching (ICP) is no walk.
    for icp in ("TransformationEstimationPointToPoint()", "icp_method: point_to_point"):
        assert shipped("UGV", icp) == {}
    # A target pose is a vehicle's goal, but a walker's foot in its leg kinematics, and a
    # mobile manipulator's arm goal (its base's navigation shows otherwise).
    assert "Waypoint" in shipped("UGV", "self.target_pose = goal")
    # A number is no pose: a balancing robot's state feedback on its wheel's position.
    assert shipped("UGV", "self.target_pose = 0.0") == {}
    assert "Waypoint" in shipped("UGV", "self.target_pose = 0.0\nself.target_pose = msg.pose")
    assert shipped("Hexapod", "foot.target_pose = ik(leg)") == {}
    assert shipped("Mobile Manipulator", "arm.setPoseTarget(target_pose)") == {}
    assert shipped("Legged Mobile Manipulator", "arm.set_pose_target(target_pose)") == {}
    assert "Waypoint" in shipped("Mobile Manipulator", "goal = NavigateToPose.Goal()")
    # The goal topic RViz and Nav2 name `goal_pose` is a vehicle's or a walker's goal, but an
    # arm's goal on a body with arms (a MoveIt script's, a humanoid's arm kinematics); a word of
    # its own, not a reward weight.
    for goal in (
        "self.create_publisher(PoseStamped, '/goal_pose', 10)",
        "topic: goal_pose",
        "self.goal_pose_sub = self.create_subscription(PoseStamped, 'goal', cb, 1)",
        "def goal_pose_callback(self, msg):",
    ):
        assert "Waypoint" in shipped("UGV", goal), goal
        assert "Waypoint" in shipped("Quadruped", goal), goal
    assert shipped("Mobile Manipulator", "planning_component.set_goal_state(goal_pose)") == {}
    assert shipped("Humanoid", "arm_ik.solve(goal_pose)") == {}
    assert shipped("Quadruped", "reward = goal_pose_weight * distance") == {}
    # Nav2's simple commander and move_base_flex send a base its goals under their own names.
    for navigation in (
        "from nav2_simple_commander.robot_navigator import BasicNavigator",
        "nav = BasicNavigator(); nav.goToPose(target_pose)",
        "client = actionlib.SimpleActionClient('move_base_flex/exe_path', ExePathAction)",
        "from mbf_msgs.msg import MoveBaseAction",
    ):
        assert "Waypoint" in shipped("Mobile Manipulator", navigation), navigation


def test_an_arm_bolted_in_place_is_sent_no_waypoints_whatever_its_repository_holds() -> None:
    assert shipped("Manipulator", "target_pose = Pose()") == {}


def test_a_pan_tilt_unit_is_aimed_whatever_navigation_or_planning_its_repository_holds() -> None:
    # A sensor head's repository may hold a rover's Nav2 launch or a MoveIt setup for its two
    # joints: it is aimed by them (the description's guess), not driven or sent poses.
    for text in (
        "IncludeLaunchDescription('nav2_bringup')",
        "self.target_pose = goal",
        "Node(package='teleop_twist_keyboard')",
        "<include file='$(find ptu_moveit_config)/launch/move_group.launch'/>",
        "q = solve_ik(x, y, z)",
    ):
        assert shipped("Pan/Tilt Unit", text) == {}


def test_a_teleop_node_is_the_structures_velocity_control() -> None:
    teleop = "Node(package='teleop_twist_keyboard')"
    assert list(shipped("UGV", teleop)) == ["Driving"]
    assert list(shipped("UAV", teleop)) == ["Flight"]
    assert list(shipped("Quadruped", teleop)) == ["Walking"]


@pytest.mark.parametrize(
    "node",
    [
        # ROS 1 in C++: a joystick callback that publishes a Twist on cmd_vel.
        "#include <geometry_msgs/Twist.h>\n#include <sensor_msgs/Joy.h>\n"
        'pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 128);\n',
        # ROS 2 in Python, among other messages, a stamped Twist.
        "from sensor_msgs.msg import (\n    Imu,\n    Joy,\n)\n"
        "from geometry_msgs.msg import TwistStamped\n"
        "self.pub = self.create_publisher(TwistStamped, '/robot/cmd_vel', 10)\n",
        # ROS 2 in C++.
        '#include "sensor_msgs/msg/joy.hpp"\n#include "geometry_msgs/msg/twist_stamped.hpp"\n'
        'create_publisher<geometry_msgs::msg::TwistStamped>("cmd_vel", 10);\n',
        # A keyboard teleop of its own: keys read from the terminal, a Twist sent.
        "from geometry_msgs.msg import Twist\n\nimport sys, tty, termios\n"
        "self.publisher_ = self.create_publisher(Twist, 'cmd_vel', 10)\n",
        '#include <termios.h>\n#include <geometry_msgs/msg/twist.hpp>\nadvertise("cmd_vel");\n',
    ],
)
def test_a_node_of_the_robots_own_turning_a_joystick_or_keys_into_a_twist_is_a_teleop_node(
    node: str,
) -> None:
    assert list(shipped("UGV", node)) == ["Driving"]
    assert shipped("Manipulator", node) == {}


def test_a_node_sending_a_twist_with_no_joystick_or_keys_or_to_no_base_is_no_teleop_node() -> None:
    for node in (
        "from sensor_msgs.msg import Imu\nfrom geometry_msgs.msg import Twist\npub('cmd_vel')\n",
        "from sensor_msgs.msg import JoyFeedback\nfrom geometry_msgs.msg import Twist\n"
        "pub('cmd_vel')\n",
        "import termios\nfrom std_msgs.msg import Float64\npub('cmd_vel')\n",
        # A joystick's Twist to an arm's end effector, a gimbal's rates: no base's velocity.
        "from sensor_msgs.msg import Joy\nfrom geometry_msgs.msg import TwistStamped\n"
        "pub('/servo_node/delta_twist_cmds')\n",
        "#include <sensor_msgs/Joy.h>\n#include <geometry_msgs/Twist.h>\n"
        'advertise("gimbal/rate");\n',
    ):
        assert shipped("UGV", node) == {}, node


def test_moveits_planning_node_means_end_effector_goals() -> None:
    moveit = "<include file='$(find arm_moveit)/launch/move_group.launch'/>"
    assert list(shipped("Manipulator", moveit)) == ["End Effector"]


def test_a_base_or_a_gripper_alone_has_no_end_effector_whatever_moveit_its_repository_holds() -> (
    None
):
    moveit = "<include file='$(find fetch_moveit_config)/launch/move_group.launch'/>"
    assert shipped("UGV", moveit) == {}
    assert shipped("Gripper", moveit) == {}
    assert list(shipped("Mobile Manipulator", moveit)) == ["End Effector"]


def test_a_hand_alone_has_no_end_effector_whatever_its_arms_software_in_the_repository() -> None:
    # A vendor's repository holds the hand and the arm that carries it: the arm's MoveIt, its
    # driver's Cartesian poses and its inverse kinematics move the arm, not the hand alone.
    for arms in (
        "<include file='$(find lm3_moveit_config)/launch/move_group.launch'/>",
        "handler = CartesianPose(stream)\nhandler.move_to_cartesian(pose)",
        "q = solve_ik(x, y, z)",
    ):
        assert shipped("Hand", arms) == {}, arms
        assert list(shipped("Manipulator", arms)) == ["End Effector"], arms


def test_an_arm_moved_by_inverse_kinematics_to_a_target_is_sent_end_effector_goals() -> None:
    script = "from ikpy.chain import Chain\nangles = chain.inverse_kinematics(target)"
    assert list(shipped("Manipulator", script)) == ["End Effector"]
    assert list(shipped("Manipulator", "q = solve_ik(x, y, z)")) == ["End Effector"]
    # Spelled as other languages do (Indonesian ``invers``, German ``Kinematik``).
    for spelled in ("rospy.init_node('invers_kinematics_gui')", "inverseKinematik(x)"):
        assert list(shipped("Manipulator", spelled)) == ["End Effector"]
    # KDL's chain solvers and TRAC-IK, by their headers and names.
    for solver in (
        "#include <kdl/chainiksolverpos_nr.hpp>",
        "KDL::ChainIkSolverPos_LMA solver(chain);",
        'result = arm_KDL_IK(result, rpy, xyz, "ur5");',
        "#include <trac_ik/trac_ik.hpp>",
    ):
        assert list(shipped("Mobile Manipulator", solver)) == ["End Effector"]
    # A walker's inverse kinematics places its feet: no end effector of its own.
    assert shipped("Humanoid", script) == {}
    assert shipped("Quadruped", "legs = inverse_kinematics(foot)") == {}


@pytest.mark.parametrize(
    "text",
    [
        "from arm_ik.IKNode import main",  # IK in upper case, a word of a name
        "q = robot.iterativeIK(pose, q0)",
        "IK_SEED_BANK = [q0, q1]",
        "rospy.init_node('arm_ik')",  # joined by an underscore
        "self._ik_left = ArmKinematics('left')",
        "'console_scripts': ['arm_inv_kine_control = robot_arm_control.arm_inv_kine_control']",
        "from scaraKinematics import invKine",
        "J_inv = np.linalg.pinv(compute_jacobian(q))",  # a Cartesian velocity, through J
        "q_dot = J_inv @ v  # taking jacobian inverse with current joint angles",
        "invJ = inverse_jacobian(q)",
        "dq = invJacobian @ x_dot",
    ],
)
def test_inverse_kinematics_by_a_short_name_or_a_jacobian_inverted_is_an_arms_end_effector_control(
    text: str,
) -> None:
    assert shipped_to_arms(text) == [["End Effector"], ["End Effector"]]
    assert shipped("Hexapod", text) == {}  # a walker's places its feet


@pytest.mark.parametrize(
    "text",
    [
        "print('ik heb de arm gekalibreerd')",  # Dutch: "I calibrated the arm"
        "bike_lane = True",
        "kiosk_mode: false",
        "pick_and_place(obj)",
        "def compute_jacobian(q):",  # a Jacobian computed, not inverted
        "print('    // Generated Jacobian code to link %i' % (i + 1))",  # a code generator
        "self.jacobian = None\ninv_dt = 1.0 / dt",  # an inverse on the next line
        "bool jacobian_invalid = false;",
        "AÇIK = 1  # a gripper's state, Turkish for open",
        "T_ik = T_ij @ T_jk",  # an index
        "maintainer_email='dong_ik@example.com'",
        "T_inv_kinect = T.inverse()",
        "raise ValueError('invalid jacobian')",
        "SHELF_FRAME = 'IKEA_KALLAX'",  # a word of capitals IK begins
    ],
)
def test_ik_in_other_words_alone_in_lower_case_or_a_jacobian_only_computed_shows_no_end_effector(
    text: str,
) -> None:
    assert shipped_to_arms(text) == [[], []]


@pytest.mark.parametrize(
    "text",
    [
        "arm_cartesian_controller: {type: cartesian_controllers/CartesianMotionController}",
        "cartesian_impedance_example_controller",
        "twist_controller/command_twist",
        "client.call(JogLinear(v))",  # a maker's Cartesian jog
        "robot.MovePose(x, y, z, a, b, c)",
        "client = create_client(MoveCartesianLine, 'utarm/apisrv/moveto_cartesian_line')",
        "plan = group.compute_cartesian_path(poses, 0.01)",
        "gantry.move_to_cartesian(x, y, z)",
        "robot.movel(pose)",
        "dobot.MovL(x, y, z, r)",  # a maker's linear move
        "mc.send_coords([x, y, z, rx, ry, rz], 30, 0)",  # pymycobot's Cartesian move
        "mc.sync_send_coords(coords, 20)",
        "'set_servo_move': ('/xarm/set_position', MoveCartesian)",  # xArm's Cartesian move
        "arm.set_servo_cartesian(mvpose)",
        "MoveLinear.srv",
        "pub = rospy.Publisher('/ee_target', PoseStamped)",
        "goal = end_effector_goal(x)",
        "end_effector_velocity: [0, 0, 0.1]",
        "solve in task_space",
        "operational_space_controller",
    ],
)
def test_a_cartesian_controller_or_goal_an_arms_packages_ship_is_an_end_effector_control(
    text: str,
) -> None:
    assert shipped_to_arms(text) == [["End Effector"], ["End Effector"]]


@pytest.mark.parametrize(
    "text",
    [
        "# Cartesian product of the grid",  # the word alone
        "cartesian_grid = make_map()",
        "log(end_effector_pose)",  # a pose logged, not a goal
        "self.get_logger().info(f'{ee_pose}')",
        "create_publisher(PoseStamped, '/ee_pose', 10)",
        "planning_scene.remove_pose(marker)",
        "saved_move_poses = []",
        "moveline = 3",
        "send_coordsys(frame)",  # another word
    ],
)
def test_the_word_cartesian_or_a_logged_pose_is_no_end_effector_control(text: str) -> None:
    assert shipped("Manipulator", text) == {}


def test_a_body_of_no_arm_is_sent_no_cartesian_goals_whatever_its_packages_hold() -> None:
    for structure in ("UGV", "UAV", "Quadruped", "Humanoid", "Gripper", "Pan/Tilt Unit"):
        assert shipped(structure, "cartesian_controller: {type: CartesianMotionController}") == {}


@pytest.mark.parametrize(
    "text",
    [
        "gripper_controller: {type: position_controllers/GripperActionController}",
        "type: gripper_action_controller/GripperActionController",
    ],
)
def test_a_gripper_action_controller_an_arms_packages_configure_is_an_end_effector_control(
    text: str,
) -> None:
    assert shipped_to_arms(text) == [["End Effector"], ["End Effector"]]


@pytest.mark.parametrize(
    "text",
    [
        "client = ActionClient(node, GripperCommand, 'gripper_controller/gripper_cmd')",
        "sub = rospy.Subscriber('gripper_cmd', Float64, cb)",
        "robot.open_gripper()",
        "close_gripper: 5  # joystick button",
        "arm.openGripper()",
        "GRIPPER_OPEN = 0.04",
        "pub = create_publisher(Float64, '/gripper_command', 1)",
        "client = SimpleActionClient('gripper', GripperCommandAction)",
    ],
)
def test_a_grippers_open_and_close_alone_is_no_end_effector_control(text: str) -> None:
    # The gripper's joint, opened and closed: no Cartesian goal for the arm's end.
    assert shipped_to_arms(text) == [[], []]


@pytest.mark.parametrize(
    "structure",
    [
        "UGV",
        "UAV",
        "Surface Vessel",
        "Underwater Vehicle",
        "Quadruped",
        "Hexapod",
        "Biped",
        "Humanoid",
        "Serpentine",
        "Gripper",
        "Hand",
        "Pan/Tilt Unit",
        "Other",
    ],
)
def test_a_body_with_no_arm_is_not_given_end_effector_goals_by_a_gripper_action_controller(
    structure: str,
) -> None:
    assert shipped(structure, "type: gripper_action_controller/GripperActionController") == {}


@pytest.mark.parametrize("structure", ["Torso", "Legged Mobile Manipulator", "Aerial Manipulator"])
def test_every_body_with_an_arm_is_given_end_effector_goals_by_a_gripper_action_controller(
    structure: str,
) -> None:
    text = "type: gripper_action_controller/GripperActionController"
    assert list(shipped(structure, text)) == ["End Effector"]


@pytest.mark.parametrize(
    "text",
    [
        "offboard_control_mode: position",
        "pub = create_publisher(TrajectorySetpoint, 'fmu/trajectory_setpoint/in')",
        "mission: [wp1, wp2]",
        "from pymavlink import mavwp",
        "set_mode('GUIDED')",
        "mode = 'guided'",
        "set_guided = rospy.ServiceProxy('mavros/set_mode', SetMode)",
        "master.set_mode(COPTER_MODE_GUIDED)",
        "drone.set_mode(FlightMode.GUIDED)",
        "<include file='$(find hector_quadrotor_actions)/launch/actions.launch'/>",
        "client = PoseAction()",
        "destination: [1, 2, 3]",
        "srv.call('set_target 1 2 3')",
        "autoflight/start flight_plan.mavlink",
        "formation: triangle",
    ],
)
def test_a_flown_bodys_goals_its_packages_ship_are_waypoints(text: str) -> None:
    assert list(shipped("UAV", text)) == ["Waypoint"]
    assert list(shipped("Aerial Manipulator", text)) == ["Waypoint"]


def test_a_flown_bodys_goal_words_are_not_read_for_other_bodies() -> None:
    for structure in ("UGV", "Underwater Vehicle", "Manipulator", "Quadruped", "Other"):
        assert shipped(structure, "mission: [wp1]; offboard; formation: line") == {}


@pytest.mark.parametrize(
    "text",
    [
        "information transformation permission submissions",
        "offset_target = 3; reset_target(); dataset_target",
        "unguided; cv2.ximgproc.guidedFilter(img)",
        "self.fc_guided = msg.guided  # a flight controller's state, read",
        "self.is_guided = state.guided; reset_guided(); offset_guided = 1",
        "compose_action(); expose_action",
        "lookup_transform(destination_frame); shutil.copy(x, destination_dir)",
    ],
)
def test_a_flown_bodys_goal_words_inside_other_words_are_not_read(text: str) -> None:
    assert shipped("UAV", text) == {}


@pytest.mark.parametrize(
    "script",
    [
        "waypoints = [start, lift]; plan, _ = arm.compute_cartesian_path(waypoints, 0.01)",
        "#include <moveit/move_group_interface/move_group_interface.h>\n"
        "std::vector<Pose> waypoints;",
    ],
)
def test_the_waypoints_of_a_moveit_scripts_cartesian_path_are_no_navigation(script: str) -> None:
    assert "Waypoint" not in shipped("Mobile Manipulator", script)
    # The same word in a script of no arm's path is a base's goals.
    assert "Waypoint" in shipped("Mobile Manipulator", "waypoints = [start, dock]")


def test_moveit_inside_another_word_leaves_a_files_waypoints_read() -> None:
    assert "Waypoint" in shipped("UGV", "waypoint_combo->removeItem(i); moveItem(waypoints)")


def test_a_mavros_plugin_configuration_lists_set_points_and_missions_nobody_sends() -> None:
    # MAVROS' stock configuration names every plugin, used or not.
    config = "conn:\n  heartbeat_rate: 1.0\nmission:\n  pull_after_gcs: true\nsetpoint_position:\n"
    assert shipped("UAV", config) == {}
    # A script that streams set-points on its topic sends goals.
    assert "Waypoint" in shipped("UAV", config, "pub('mavros/setpoint_position/local', pose)")
    # The stock configuration names no navigation a base runs either.
    assert shipped("UGV", f"{config}move_base: {{}}") == {}
    # A launch file that sets MAVROS' heartbeat as a parameter is no stock configuration.
    bringup = "<param name='/mavros/conn/heartbeat_rate' value='1.0'/><node pkg='move_base'/>"
    assert "Waypoint" in shipped("UGV", bringup)
    assert "Waypoint" in shipped("UAV", f"{bringup}<node pkg='drone' type='offboard_node.py'/>")


def test_the_first_file_that_shows_a_control_is_named() -> None:
    found = shipped("UGV", "nothing here", "waypoint_follower", "bt_navigator")
    assert found["Waypoint"].endswith("1.launch.py (waypoint)")


def test_a_workspace_that_ships_nothing_shows_nothing() -> None:
    assert shipped("UGV", "<launch><node pkg='robot_state_publisher'/></launch>") == {}


def package(folder: Path, name: str, files: dict[str, str]) -> Path:
    root = folder / name
    root.mkdir(parents=True)
    (root / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")
    for relative, text in files.items():
        (root / relative).parent.mkdir(parents=True, exist_ok=True)
        (root / relative).write_text(text)
    return root


def rover_with_a_lidar() -> RobotText:
    robot = ugv()
    robot.add('  <gazebo><plugin name="d" filename="libgazebo_ros_diff_drive.so"/></gazebo>')
    robot.fixed(robot.root, "laser")
    robot.add(LASER)
    return robot


def described(tmp_path: Path, robot: RobotText, bringup: str) -> Path:
    """A description package holding ``robot`` and a bringup that finds it and runs
    ``bringup``; the description file."""
    src = tmp_path / "ws" / "src"
    own = package(src, "craft_description", {"urdf/craft.urdf": robot.text()})
    package(src, "craft_bringup", {"launch/bringup.launch": f"craft_description {bringup}"})
    return own / "urdf" / "craft.urdf"


def controls_of(path: Path, **options: object) -> dict[str, str]:
    result = identify(path, **options)  # type: ignore[arg-type]
    return {c.motion_control: c.source for c in result.motion_controls}


def test_a_description_in_its_package_is_read_with_the_packages_that_use_it(
    tmp_path: Path,
) -> None:
    path = described(tmp_path, rover_with_a_lidar(), "<node pkg='move_base'/>")
    found = controls_of(path)
    assert found["Waypoint"] == (
        "package craft_bringup: craft_bringup/launch/bringup.launch (move_base)"
    )
    assert "packages read for the controls they ship: craft_description, craft_bringup" in (
        identify(path).evidence
    )


def test_packages_that_ship_no_navigation_leave_no_guess_of_it(tmp_path: Path) -> None:
    path = described(tmp_path, rover_with_a_lidar(), "<node pkg='robot_state_publisher'/>")
    assert "Waypoint" not in controls_of(path)
    guessed = controls_of(path, look_around=False)
    assert guessed["Waypoint"].startswith("urdf: likely, not declared")


def test_the_navigation_named_for_the_robot_its_urdf_names_is_read_with_its_bringup(
    tmp_path: Path,
) -> None:
    # The URDF (<robot name="rover">) kept in rover_bringup; rover_navigation never names it.
    src = tmp_path / "ws" / "src"
    own = package(src, "rover_bringup", {"urdf/rover.urdf": rover_with_a_lidar().text()})
    package(src, "rover_navigation", {"launch/nav.launch": "<node pkg='move_base'/>"})
    package(src, "drone_navigation", {"launch/nav.launch": "<node pkg='move_base'/>"})
    assert controls_of(own / "urdf" / "rover.urdf")["Waypoint"] == (
        "package rover_navigation: rover_navigation/launch/nav.launch (move_base)"
    )


def test_a_package_can_be_named_for_a_description_kept_elsewhere(tmp_path: Path) -> None:
    path = described(tmp_path, quadrotor(), "<node pkg='teleop_twist_keyboard'/>")
    copy = tmp_path / "copter.urdf"
    copy.write_text(path.read_text())
    assert "Flight" in controls_of(copy, package=path.parent.parent)
    assert controls_of(copy) == controls_of(copy, look_around=False)


def test_an_arms_end_effector_goals_are_the_moveit_its_packages_ship(tmp_path: Path) -> None:
    path = described(tmp_path, manipulator(), "<include file='move_group.launch'/>")
    assert controls_of(path)["End Effector"] == (
        "package craft_bringup: craft_bringup/launch/bringup.launch (move_group)"
    )
    # Read alone, the arm's six joints and gripper make the Cartesian goals a guess.
    guess = controls_of(path, look_around=False)["End Effector"]
    assert guess.startswith("urdf: likely, not declared")


def test_packages_that_ship_no_cartesian_goals_leave_no_guess_of_them(tmp_path: Path) -> None:
    # Joint controllers and the sliders only: the arm takes joint goals, and no pose goal.
    path = described(tmp_path, manipulator(), "<node pkg='joint_state_publisher_gui'/>")
    assert set(controls_of(path)) == {"Joint"}
    assert "End Effector" in controls_of(path, look_around=False)


def picker(*extra: str) -> RobotText:
    """A rover a drive plugin moves, with an arm of six joints and a gripper on it."""
    robot = rover_with_a_lidar()
    arm(robot, robot.root)
    for xml in extra:
        robot.add(xml)
    return robot


def test_an_arm_only_drawn_on_a_driven_rover_is_commanded_by_nothing(tmp_path: Path) -> None:
    # The joint state publisher's sliders move it in RViz; no controller, no script.
    path = described(tmp_path, picker(), "<node pkg='joint_state_publisher_gui'/>")
    assert set(controls_of(path)) == {"Driving"}
    # Read alone, the arm is taken as commanded: a guess, as before.
    assert set(controls_of(path, look_around=False)) == {
        "Driving",
        "Joint",
        "End Effector",
        "Waypoint",
    }


@pytest.mark.parametrize(
    ("robot", "bringup"),
    [
        (picker(), "controller: {joints: [shoulder_pan, elbow]}"),  # a package names a joint
        (picker(transmission("elbow")), ""),  # the description commands one
    ],
)
def test_an_arm_a_package_or_the_description_commands_keeps_its_joint_goals(
    tmp_path: Path, robot: RobotText, bringup: str
) -> None:
    found = set(controls_of(described(tmp_path, robot, bringup)))
    # Its pose goals are what the packages ship, and these ship none.
    assert "Joint" in found
    assert "End Effector" not in found


def test_an_arm_a_trajectory_plugin_plays_is_commanded(tmp_path: Path) -> None:
    for filename in ("libgazebo_ros_joint_pose_trajectory.so", "gz-sim-joint-trajectory-system"):
        player = f'<gazebo><plugin name="t" filename="{filename}"/></gazebo>'
        assert "Joint" in controls_of(described(tmp_path / filename, picker(player), ""))


def test_a_pan_tilt_head_is_not_alone_on_a_body_its_packages_drive(tmp_path: Path) -> None:
    # A description trimmed to its sensor head, on a base a teleop node drives.
    robot = pan_tilt_only()
    robot.fixed(robot.root, "laser")
    robot.add(LASER)
    path = described(tmp_path, robot, "<node pkg='teleop_twist_keyboard'/>")
    driven = identify(path)
    assert (driven.structure, set(controls_of(path))) == ("Other", {"Driving"})
    assert (
        "a base driven by its packages' teleop node: package craft_bringup: "
        "craft_bringup/launch/bringup.launch (teleop_twist_keyboard)"
    ) in driven.evidence
    alone = identify(path, look_around=False)
    assert (alone.structure, set(controls_of(path, look_around=False))) == (
        "Pan/Tilt Unit",
        {"Joint"},
    )


def test_only_a_teleop_node_drives_a_pan_tilt_head_and_only_a_head_alone_is_driven(
    tmp_path: Path,
) -> None:
    # A head whose packages hold only navigation stays a pan/tilt unit, aimed.
    head = pan_tilt_only()
    aimed = identify(described(tmp_path / "nav", head, "<include file='nav2_bringup'/>"))
    assert (aimed.structure, [c.motion_control for c in aimed.motion_controls]) == (
        "Pan/Tilt Unit",
        ["Joint"],
    )
    # A rover whose packages ship a teleop node is driven, and says nothing of it.
    rover = identify(
        described(tmp_path / "rover", rover_with_a_lidar(), "<node pkg='teleop_twist_keyboard'/>")
    )
    assert rover.body is not None
    assert rover.body.driven_by == ""
    assert not any("teleop node" in line for line in rover.evidence)


def test_a_joy_teleop_aiming_the_heads_joints_drives_no_base_and_one_sending_a_twist_does(
    tmp_path: Path,
) -> None:
    # joy_teleop maps a joystick to any message: to the head's position controller, it aims
    # the pan/tilt unit (no base); to a Twist on cmd_vel, it drives the base the head is on.
    aiming = (
        "joy_teleop:\n  ros__parameters:\n    pantilt:\n      type: topic\n"
        "      interface_type: std_msgs/msg/Float64MultiArray\n"
        "      topic_name: /pantilt_controller/commands\n"
    )
    aimed = identify(described(tmp_path / "aim", pan_tilt_only(), aiming))
    assert (aimed.structure, [c.motion_control for c in aimed.motion_controls]) == (
        "Pan/Tilt Unit",
        ["Joint"],
    )
    driving = aiming.replace("std_msgs/msg/Float64MultiArray", "geometry_msgs/msg/Twist")
    driven = identify(described(tmp_path / "drive", pan_tilt_only(), driving))
    assert driven.structure == "Other"
    assert (
        "a base driven by its packages' teleop node: package craft_bringup: "
        "craft_bringup/launch/bringup.launch (joy_teleop)"
    ) in driven.evidence
    # ROS 1's way: the launch file starts joy_teleop, a configuration of its own maps a
    # button to a Twist on cmd_vel (its root named `teleop`).
    split = described(tmp_path / "split", pan_tilt_only(), "<node pkg='joy_teleop'/>")
    config = tmp_path / "split" / "ws" / "src" / "craft_bringup" / "config" / "teleop.yaml"
    config.parent.mkdir(parents=True)
    config.write_text(
        "teleop:\n  walk:\n    type: topic\n    message_type: geometry_msgs/Twist\n"
        "    topic_name: cmd_vel\n"
    )
    assert identify(split).structure == "Other"


def read_in_part(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, robot: RobotText, bringup: str
) -> Path:
    """``described``, with a second package using the description, and a bound of one file:
    the workspace is read in part."""
    from solver.identify.readers import workspace

    monkeypatch.setattr(workspace, "MAX_FILES", 1)
    path = described(tmp_path, robot, bringup)
    package(
        tmp_path / "ws" / "src", "craft_extras", {"a.launch": "craft_description", "b.yaml": ""}
    )
    return path


def test_an_arm_whose_packages_were_read_in_part_is_taken_as_commanded(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    bringup = "<node pkg='joint_state_publisher_gui'/>"
    path = read_in_part(tmp_path, monkeypatch, picker(), bringup)
    assert "Joint" in controls_of(path)


def test_an_arm_on_a_base_no_plugin_drives_is_taken_as_commanded(tmp_path: Path) -> None:
    robot = ugv()
    arm(robot, robot.root)
    assert "Joint" in controls_of(described(tmp_path, robot, ""))


def test_an_arm_only_drawn_on_a_walker_is_commanded_by_nothing(tmp_path: Path) -> None:
    """A dog with an arm its packages never name: the gait walks the dog, nothing moves the
    arm. A package naming one of its joints commands it."""
    quiet = described(tmp_path / "quiet", legged_manipulator(), "<node pkg='gait'/>")
    assert "Joint" not in controls_of(quiet)
    assert "Joint" in controls_of(quiet, look_around=False)  # alone: a guess, as before
    named = described(tmp_path / "named", legged_manipulator(), "arm: {joints: [elbow]}")
    assert "Joint" in controls_of(named)


def test_the_joints_packages_name_are_read_word_by_word() -> None:
    joints = ["elbow", "arm.wrist-1", "j7", "lift", "a b", "ur_shoulder_pan", "arm.tool"]
    texts = ("joints: [elbow, arm.wrist-1]", "cmd('/arm/j7.pos', tool)", "$(arg p)shoulder_pan")
    found = named_joints(shipping(*texts), joints)
    # A name no word can be ("a b") is taken as named; the end of a name after an underscore
    # names it (a launch file's prefix); "lift", and "arm.tool" whose words are apart, are not.
    assert found == {"elbow", "arm.wrist-1", "j7", "a b", "ur_shoulder_pan"}
    # Part of a longer word is no name, nor a name's last word alone ("1", "lift", "joint").
    assert named_joints(shipping("liftoff"), ["lift"]) == frozenset()
    last_words = ["wrist_1", "shoulder_lift", "elbow_joint", "left_ur_elbow_joint"]
    assert named_joints(shipping("default='1' lift.rviz joint"), last_words) == frozenset()
    assert named_joints(shipping("[elbow_joint]"), last_words) == {
        "elbow_joint",
        "left_ur_elbow_joint",
    }


@pytest.mark.parametrize(
    "stop",
    [
        'pkill -9 -f "gazebo|rviz2|move_group"',
        "killall -q move_group",
        "rosnode kill /move_group",
    ],
)
def test_a_script_that_kills_a_planner_does_not_run_it(tmp_path: Path, stop: str) -> None:
    path = described(tmp_path, manipulator(), f"{stop}\nros2 launch craft_description x.py")
    assert "move_group" not in controls_of(path).get("End Effector", "")
    path = described(tmp_path / "runs", manipulator(), "ros2 launch arm move_group.launch.py")
    assert "move_group" in controls_of(path)["End Effector"]


def test_only_the_kill_command_is_left_out_not_its_line_or_the_next() -> None:
    from solver.identify.readers.workspace import _KILLS

    assert (
        _KILLS.sub("", "pkill -f gz && ros2 launch nav2_bringup a")
        == "&& ros2 launch nav2_bringup a"
    )
    assert _KILLS.sub("", "killall 'a|b'; move_base") == "; move_base"
    assert _KILLS.sub("", "pkill -f gz | tee log\nmove_base") == "| tee log\nmove_base"
    # "rosnode" and "kill" on two lines are no command.
    text = "# needs rosnode\n\nkill -INT $PID\nnav2_bringup"
    assert _KILLS.sub("", text) == text


def test_a_file_name_is_shown_with_its_unprintable_characters_escaped() -> None:
    hostile = Workspace(
        "/ws",
        "p",
        ("p",),
        (ShippedFile("p", "p/\x1b[2Jnav\n.launch", "<node pkg='move_base'/>"),),
    )
    controls = controls_from_workspace(hostile, PROFILE, "UGV")
    assert {control.source for control in controls} == {
        "package p: p/\\x1b[2Jnav\\n.launch (move_base)"
    }


def test_a_description_package_alone_read_whole_ships_no_navigation(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    own = package(src, "craft_description", {"urdf/craft.urdf": rover_with_a_lidar().text()})
    path = own / "urdf" / "craft.urdf"
    assert "Waypoint" not in controls_of(path)
    assert "Waypoint" in controls_of(path, look_around=False)


def test_a_workspace_read_in_part_keeps_the_guess_and_says_why_in_a_note(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    bringup = "<node pkg='robot_state_publisher'/>"
    path = read_in_part(tmp_path, monkeypatch, rover_with_a_lidar(), bringup)
    result = identify(path)
    controls = {c.motion_control: c.source for c in result.motion_controls}
    assert controls["Waypoint"].startswith("urdf: likely, not declared")
    assert result.warnings == ()  # a bound of the workspace is no flaw of the robot: a note
    assert any("more than 1 files" in note for note in result.notes)


def test_a_package_named_that_holds_no_package_is_said_in_a_note(tmp_path: Path) -> None:
    path = tmp_path / "craft.urdf"
    path.write_text(rover_with_a_lidar().text())
    result = identify(path, package=tmp_path)
    assert result.notes == (
        f"package {tmp_path}: no package.xml names a package there; none is read",
    )


def one_link(name: str = "vehicle") -> RobotText:
    """A body exported as one link and its mesh, a camera frame on it."""
    robot = RobotText(name)
    robot.fixed(robot.root, "camera_link")
    return robot


def read_with(tmp_path: Path, robot: RobotText, bringup: str) -> tuple[str, tuple[str, ...]]:
    result = identify(described(tmp_path, robot, bringup))
    return result.structure, result.evidence


def test_a_body_that_shows_no_way_of_travelling_flies_when_its_packages_take_off(
    tmp_path: Path,
) -> None:
    structure, evidence = read_with(tmp_path, one_link(), "rospy.ServiceProxy('takeoff')")
    assert structure == "UAV"
    assert (
        "a flying body by its packages alone: package craft_bringup: "
        "craft_bringup/launch/bringup.launch (takeoff)"
    ) in evidence


def test_a_body_that_shows_no_way_of_travelling_dives_when_its_packages_are_an_auvs(
    tmp_path: Path,
) -> None:
    structure, _ = read_with(tmp_path, one_link(), "<node pkg='auv_control' type='depth'/>")
    assert structure == "Underwater Vehicle"


def test_a_body_that_shows_no_way_of_travelling_floats_when_its_packages_are_a_boats(
    tmp_path: Path,
) -> None:
    structure, _ = read_with(tmp_path, one_link(), "<node pkg='boat_control'/>")
    assert structure == "Surface Vessel"


def test_a_message_package_named_for_a_submersible_does_not_put_a_boat_under_water(
    tmp_path: Path,
) -> None:
    # A lab's boat pilot uses the lab's shared `auv_msgs`: its packages still name one medium.
    pilot = "<node pkg='asv_pilot'/>\nfrom auv_msgs.msg import NavSts"
    assert read_with(tmp_path / "boat", one_link(), pilot)[0] == "Surface Vessel"
    # A submersible's own words beside a boat's still name two media, which say nothing.
    both = "<node pkg='asv_pilot'/>\n<node pkg='auv_control'/>"
    assert read_with(tmp_path / "both", one_link(), both)[0] == "Other"


@pytest.mark.parametrize(
    "bringup",
    [
        "controller: {type: diff_drive_controller/DiffDriveController}",
        "<node pkg='ackermann_steering'/>",
        "skid_steer_drive: {}",
        "mecanum_drive: {wheel_radius: 0.05}",
        "# the rover's bringup",
        "ugv_base: {}",
        "agv_driver.py",
        "amr_fleet.launch",
        "lawn_mower: true",
        "mower_blade: off",
        "<node pkg='lawn_tractor_sim'/>",
        "tractor_params.yaml",
        "wheelchair_driver",
        "<node pkg='segway_sim'/>",
        "<node pkg='forklift_firmware'/>",
        "scooter_controller.py",
        "hoverboard_driver: {port: /dev/ttyUSB0}",
    ],
)
def test_a_body_that_shows_no_way_of_travelling_drives_when_its_packages_are_a_ground_vehicles(
    tmp_path: Path, bringup: str
) -> None:
    result = identify(described(tmp_path, one_link(), bringup))
    assert result.structure == "UGV"
    assert result.confidence < 0.95  # with doubt: nothing of it touches the ground
    said = "a ground vehicle by its packages alone"
    assert any(line.startswith(said) for line in result.evidence)
    assert {c.motion_control: c.source for c in result.motion_controls}["Driving"] == (
        "urdf: a ground vehicle with no wheel drawn"
    )


@pytest.mark.parametrize(
    "name", ["mid360_sensor_kit", "roof_sensor_rack", "multisensor_boxes", "lidar_backpack"]
)
def test_a_rig_of_sensors_a_vehicle_carries_is_not_that_vehicle(tmp_path: Path, name: str) -> None:
    result = identify(described(tmp_path, one_link(name), "<node pkg='ackermann_steering'/>"))
    assert result.structure == "Other"
    said = f"a rig of sensors by its name: robot name {name} (no vehicle its packages name is "
    assert f"{said}read as it, no control they ship)" in result.evidence


def test_the_controls_a_rigs_packages_ship_are_its_vehicles(tmp_path: Path) -> None:
    # The vehicle's packages run Nav2 and a teleop node: they move the vehicle, not the kit.
    bringup = "IncludeLaunchDescription('nav2_bringup')\nNode(package='teleop_twist_keyboard')"
    kit = identify(described(tmp_path / "kit", one_link("mid360_sensor_kit"), bringup))
    assert (kit.structure, kit.motion_controls) == ("Other", ())
    # A body of no such name, that travels no way either, is driven and navigated by them.
    plain = identify(described(tmp_path / "plain", one_link("mid360"), bringup))
    assert {c.motion_control for c in plain.motion_controls} == {"Driving", "Waypoint"}


class _Undeclared(RobotText):
    """A description hung from its root link without declaring it (a vehicle's ``base_link``,
    which the vehicle's own description makes)."""

    def text(self) -> str:
        return super().text().replace(f'  <link name="{self.root}"/>\n', "", 1)


def kit(top: str) -> RobotText:
    """A kit whose ``top`` link hangs from an undeclared ``base_link``, a lidar frame on it."""
    robot = _Undeclared("vehicle")
    robot.fixed(robot.fixed(robot.root, top), "lidar_link")
    return robot


def test_a_kit_hung_from_a_link_its_description_never_declares_is_a_rig_of_sensors(
    tmp_path: Path,
) -> None:
    robot = kit("sensor_kit_base_link")
    # A mount beside the kit that carries a declared sensor (a rear lidar) is the kit's too.
    robot.fixed(robot.root, "rear_lidar_mount")
    robot.fixed("rear_lidar_mount", "rear_lidar")
    robot.add(gazebo_sensor("rear_lidar", "ray", "rear_scan"))
    structure, evidence = read_with(tmp_path, robot, "ugv_base: {}")
    assert structure == "Other"
    said = "a rig of sensors by its name: the undeclared root's link sensor_kit_base_link"
    assert f"{said} (no vehicle its packages name is read as it, no control they ship)" in evidence


def test_a_kits_link_on_a_declared_base_or_a_plain_mount_leaves_the_packages_vehicle(
    tmp_path: Path,
) -> None:
    """A vehicle that declares its base and carries the kit is the vehicle; a part hung from
    an undeclared link whose name says no rig is its packages' vehicle too."""
    vehicle = RobotText("vehicle")
    vehicle.fixed(vehicle.fixed(vehicle.root, "sensor_kit_base_link"), "lidar_link")
    assert read_with(tmp_path / "vehicle", vehicle, "ugv_base: {}")[0] == "UGV"
    assert read_with(tmp_path / "mount", kit("lidar_mount"), "ugv_base: {}")[0] == "UGV"
    # Under an undeclared root: a body of its own beside the kit (no sensor on it) is the
    # vehicle's body; a kit's link on a joint that moves is no rig a vehicle bolts on.
    beside = kit("sensor_kit_base_link")
    beside.fixed(beside.root, "chassis_link")
    assert read_with(tmp_path / "beside", beside, "ugv_base: {}")[0] == "UGV"
    turning = _Undeclared("vehicle")
    turning.joint("spin", "continuous", turning.root, "sensor_kit_base_link")
    turning.fixed("sensor_kit_base_link", "lidar_link")
    assert read_with(tmp_path / "turning", turning, "ugv_base: {}")[0] != "Other"


def test_a_body_named_for_a_kit_of_no_sensors_is_still_its_packages_vehicle(tmp_path: Path) -> None:
    for name in ("starter_kit", "sensorless_rover", "rigid_body", "drilling_rig", "leg_test_rig"):
        assert read_with(tmp_path / name, one_link(name), "ugv_base: {}")[0] == "UGV", name


def test_ground_words_inside_longer_words_say_nothing(tmp_path: Path) -> None:
    assert read_with(tmp_path, one_link(), "amrita grovers ramrod")[0] == "Other"


@pytest.mark.parametrize(
    "bringup",
    [
        "px4 posix_sitl: iris, plane, rover",  # a flight stack lists rovers
        "<node pkg='uuv_control'/> diff_drive",  # a submersible's simulator's example
        "<node pkg='agv_driver'/> # TODO: port the drone's teleop",  # a rover names a drone
        "<node pkg='segway_sim' type='mpc_drone_node'/>",  # a Segway and a drone it carries
    ],
)
def test_a_ground_word_beside_another_mediums_says_nothing(tmp_path: Path, bringup: str) -> None:
    assert read_with(tmp_path, one_link(), bringup)[0] == "Other"
    # The other medium's word alone still says it.
    alone = read_with(tmp_path / "alone", one_link(), "px4 posix_sitl: iris, plane")
    assert alone[0] == "UAV"


def test_a_pan_tilt_unit_in_a_rovers_packages_stays_a_pan_tilt_unit(tmp_path: Path) -> None:
    """A body with a limb (a head's pan and tilt) is not put on the ground by its packages'
    words: the rover it sits on is another description."""
    structure, _ = read_with(tmp_path, pan_tilt_only(), "# ptu on our rover, diff_drive")
    assert structure == "Pan/Tilt Unit"


@pytest.mark.parametrize(
    "classes",
    [
        # COCO's, as a detector's script lists them, and Pascal VOC's.
        "CLASSES = ['person', 'car', 'boat', 'traffic light', 'fire hydrant', 'stop sign', "
        "'parking meter', 'teddy bear', 'hair drier', 'toothbrush']",
        "labels: [aeroplane, bicycle, boat, bottle, diningtable, pottedplant, tvmonitor]",
    ],
)
def test_a_boat_among_an_object_detectors_classes_puts_no_body_in_water(
    tmp_path: Path, classes: str
) -> None:
    structure, _ = read_with(tmp_path, one_link(), classes)
    assert structure == "Other"
    # Two of those classes make no label map: a boat named beside them is the robot.
    structure, _ = read_with(tmp_path / "two", one_link(), "boat_control # a teddy bear's zebra")
    assert structure == "Surface Vessel"


def test_read_alone_the_same_body_is_nothing_in_particular(tmp_path: Path) -> None:
    path = described(tmp_path, one_link(), "rospy.ServiceProxy('takeoff')")
    assert identify(path, look_around=False).structure == "Other"


def test_packages_of_two_kinds_of_vehicle_say_nothing_of_this_one(tmp_path: Path) -> None:
    structure, _ = read_with(tmp_path, one_link(), "takeoff(); rov_pilot")
    assert structure == "Other"


def test_a_body_whose_description_shows_how_it_travels_keeps_its_reading() -> None:
    """A rover or an arm in a repository of drones stays what it is; a gripper travels no way
    of its own; a camera's pan-tilt unit alone shows no way of travelling, so its packages say."""
    packages = shipping("takeoff()")
    for robot in (rover_with_a_lidar(), manipulator()):
        body = detect_body(parse_urdf(robot.text(), "r.urdf"), PROFILE)
        assert not body.travels_no_way
        assert body_from_workspace(body, packages, PROFILE) is body
    gripper = detect_body(parse_urdf(parallel_gripper().text(), "g.urdf"), PROFILE)
    assert not gripper.travels_no_way
    pan_tilt = detect_body(parse_urdf(pan_tilt_only().text(), "p.urdf"), PROFILE)
    assert body_from_workspace(pan_tilt, packages, PROFILE).shipped_as == "flight"


def slid_by_a_plugin(name: str = "vehicle") -> RobotText:
    """A box a planar-move plugin slides: nothing of it touches the ground."""
    robot = one_link(name)
    robot.add(
        '<gazebo><plugin name="mover" filename="libgazebo_ros_planar_move.so">'
        "<commandTopic>cmd_vel</commandTopic></plugin></gazebo>"
    )
    return robot


def test_a_body_a_plugin_alone_moves_travels_in_what_its_packages_say(tmp_path: Path) -> None:
    """The simulator slides it: its packages, an AUV's, say it dives."""
    structure, evidence = read_with(tmp_path, slid_by_a_plugin(), "<node pkg='auv_control'/>")
    assert structure == "Underwater Vehicle"
    assert any(line.startswith("in water below the surface by its packages") for line in evidence)


def test_a_body_a_plugin_moves_on_wheels_keeps_its_ground(tmp_path: Path) -> None:
    rover = slid_by_a_plugin()
    rover.chain(rover.root, ["left_wheel_joint"], kind="continuous")
    rover.chain(rover.root, ["right_wheel_joint"], kind="continuous")
    structure, _ = read_with(tmp_path, rover, "<node pkg='auv_control'/>")
    assert structure == "UGV"
    # A wheel drive (diff drive) is a ground base's, its wheels drawn or not.
    rover_box = one_link()
    rover_box.add(
        '<gazebo><plugin name="drive" filename="libgazebo_ros_diff_drive.so">'
        "<leftJoint>left_wheel_joint</leftJoint></plugin></gazebo>"
    )
    assert read_with(tmp_path / "box", rover_box, "<node pkg='auv_control'/>")[0] == "UGV"
    both = slid_by_a_plugin()  # a planar move beside a wheel drive: the wheels' base
    both.add('<gazebo><plugin name="drive" filename="libgazebo_ros_diff_drive.so"/></gazebo>')
    assert read_with(tmp_path / "both", both, "<node pkg='auv_control'/>")[0] == "UGV"
    # With packages that name no medium, the plugin's box is a ground base as before.
    assert read_with(tmp_path / "quiet", slid_by_a_plugin(), "<node pkg='map_server'/>")[0] == "UGV"


# A ros2_control configuration of a walker's legs, as a description package ships it.
JOINT_CONTROLLERS = (
    "legs_controller: {type: joint_trajectory_controller/JointTrajectoryController, "
    "joints: [FL_hip, FL_thigh, FL_calf]}"
)


def test_a_walker_whose_packages_configure_its_legs_controllers_and_no_gait_is_commanded_by_joint(
    tmp_path: Path,
) -> None:
    found = controls_of(described(tmp_path, quadruped(), JOINT_CONTROLLERS))
    assert found == {
        "Joint": "package craft_bringup: craft_bringup/launch/bringup.launch "
        "(joint_trajectory_controller): joint controllers naming joints of 4 legs, "
        "no gait shipped"
    }


@pytest.mark.parametrize(
    "controller",
    [
        "type: joint_trajectory_controller/JointTrajectoryController",
        "type: position_controllers/JointGroupPositionController",
        "type: effort_controllers/JointEffortController",
        "type: velocity_controllers/JointVelocityController",
        "type: forward_command_controller/ForwardCommandController",
        "type: JointPositionController",
    ],
)
def test_each_kind_of_joint_controller_naming_a_leg_commands_it(
    tmp_path: Path, controller: str
) -> None:
    bringup = f"legs: {{{controller}, joint: RR_calf}}"
    assert set(controls_of(described(tmp_path, quadruped(), bringup))) == {"Joint"}


# A ros_gz bridge's entry carrying a Gazebo Sim joint controller's command topic.
def bridged(topic: str) -> str:
    return (
        f'- ros_topic_name: "/craft/cmd"\n  gz_topic_name: "{topic}"\n'
        '  ros_type_name: "std_msgs/msg/Float64"\n  direction: ROS_TO_GZ'
    )


@pytest.mark.parametrize(
    "topic", ["/model/craft/joint/RR_calf/0/cmd_pos", "joint/RR_calf/cmd_force"]
)
def test_a_bridged_gazebo_command_topic_of_a_legs_joint_commands_it(
    tmp_path: Path, topic: str
) -> None:
    found = controls_of(described(tmp_path, quadruped(), bridged(topic)))
    assert set(found) == {"Joint"}
    assert "(joint/RR_calf/" in found["Joint"]


def test_a_bridged_command_topic_of_no_leg_leaves_the_guess_of_a_gait(tmp_path: Path) -> None:
    # A flipper's position topic, beside a leg joint named in a sensor's topic: no leg command.
    bridge = (
        bridged("/model/craft/joint/front_flipper/0/cmd_pos")
        + "\n"
        + bridged("/model/craft/joint/RR_calf/sensor/force_torque/forcetorque")
    )
    assert "Walking" in controls_of(described(tmp_path, quadruped(), bridge))


@pytest.mark.parametrize(
    ("robot", "bringup"),
    [
        # A gripper's controller on a walker carrying an arm: no leg named.
        (
            legged_manipulator,
            "gripper: {type: position_controllers/GripperActionController, joint: gripper_left}",
        ),
        # A head's joint group on a humanoid.
        (
            humanoid,
            "head: {type: position_controllers/JointGroupPositionController, "
            "joints: [neck_yaw, head_pitch]}",
        ),
        # A joint state broadcaster names every joint and commands none.
        (quadruped, "joint_state_broadcaster: {type: JointStateBroadcaster, joints: [FL_hip]}"),
    ],
)
def test_controllers_that_name_no_leg_or_command_none_leave_the_guess_of_a_gait(
    tmp_path: Path, robot: Callable[[], RobotText], bringup: str
) -> None:
    assert "Walking" in controls_of(described(tmp_path, robot(), bringup))


@pytest.mark.parametrize(
    "gait",
    [
        "gait_planner: {pattern: wave}",
        "walking_engine.launch",
        "locomotion_policy.onnx",
        "footstep_planner",
        "trot_speed: 0.3",
        "crawl_mode: true",
        "tripod: {height: 0.1}",
        "stride_length: 0.2",
        "controller: convex_mpc",
        "cpg: {frequency: 1.0}",
        "wbc: {weights: []}",
        "legged_control.launch",
        "ocs2_legged_robot",
        "rl_policy: model.pt",
        "remap: {from: cmd_vel, to: /dog/cmd_vel}",
        "<node pkg='teleop_twist_keyboard'/>",
        "<node pkg='joy' type='joy_node'/>",
        "champ_base",
    ],
)
def test_a_walker_whose_packages_ship_a_gait_is_still_walked(tmp_path: Path, gait: str) -> None:
    found = controls_of(described(tmp_path, quadruped(), f"{JOINT_CONTROLLERS}\n{gait}"))
    assert "Walking" in found
    assert "Joint" not in found


def test_a_script_named_for_a_gait_is_one_whatever_its_text_says(tmp_path: Path) -> None:
    # A script replaying recorded joint angles through the legs' controllers, its text
    # naming no gait, its file's name one.
    path = described(tmp_path, quadruped(), JOINT_CONTROLLERS)
    scripts = path.parents[2] / "craft_bringup" / "scripts"
    scripts.mkdir()
    (scripts / "normal_walk.py").write_text("angles = load('joint_angle_1.npy')\n")
    assert "Walking" in controls_of(path)
    # A folder's name is not the file's: a plain script in a folder named for a gait says
    # nothing.
    (scripts / "normal_walk.py").rename(scripts / "replay.py")
    scripts.rename(scripts.parent / "walking")
    assert set(controls_of(path)) == {"Joint"}
    # A word that holds a gait's word is none: a sidewalk's map, a walkthrough.
    (scripts.parent / "walking" / "sidewalk_map.yaml").write_text("frame: map\n")
    assert set(controls_of(path)) == {"Joint"}


@pytest.mark.parametrize(
    "controller",
    [
        "type: effort_controllers/JointPositionController",
        "type: position_controllers/JointPositionController",
        "type: velocity_controllers/JointVelocityController",
        "type: effort_controllers/JointEffortController",
    ],
)
def test_a_controller_of_a_legs_joint_its_own_takes_joint_commands_beside_the_gait(
    tmp_path: Path, controller: str
) -> None:
    # Written as ROS 1 configurations write it: the controller's name, its type, its joint.
    bringup = f"FL_calf_position_controller:\n  {controller}\n  joint: FL_calf\ngait: trot"
    found = controls_of(described(tmp_path, quadruped(), bringup))
    assert found == {
        "Walking": "urdf: likely, not declared: 4 legs to walk on",
        "Joint": f"package craft_bringup: craft_bringup/launch/bringup.launch "
        f"({controller.removeprefix('type: ')}): a controller of a joint's own on joints of 4 legs",
    }


@pytest.mark.parametrize(
    "bringup",
    [
        # What a gait writes to: the legs' group or trajectory controller.
        f"{JOINT_CONTROLLERS}\ngait: trot",
        "legs: {type: position_controllers/JointGroupPositionController, joints: [FL_calf]}\n"
        "gait: trot",
        # A joint's own controller, of no leg (a head's), beside the legs' group controller.
        "neck_position_controller: {type: effort_controllers/JointPositionController, "
        f"joint: neck}}\n{JOINT_CONTROLLERS}\ngait: trot",
        # A group controller named like a joint's own.
        "joint_position_controller: {type: forward_command_controller/ForwardCommandController, "
        "joints: [FL_hip, FL_thigh]}\ngait: trot",
    ],
)
def test_a_gaits_group_controller_or_a_joints_own_of_no_leg_gives_no_joint_commands(
    tmp_path: Path, bringup: str
) -> None:
    assert set(controls_of(described(tmp_path, quadruped(), bringup))) == {"Walking"}


def test_a_gait_planner_package_beside_the_robots_keeps_the_guess_of_a_gait(
    tmp_path: Path,
) -> None:
    """Its planner names none of the robot's packages, so its files are not read; its name
    says a gait is in the workspace."""
    path = described(tmp_path, quadruped(), JOINT_CONTROLLERS)
    package(tmp_path / "ws" / "src", "gait_planner", {"src/gait.cpp": "// step planner"})
    assert set(controls_of(path)) == {"Walking"}


def test_a_walker_whose_packages_configure_no_joint_controller_keeps_the_guess_of_a_gait(
    tmp_path: Path,
) -> None:
    found = controls_of(described(tmp_path, biped(), "<node pkg='robot_state_publisher'/>"))
    assert set(found) == {"Walking"}
    assert found["Walking"].startswith("urdf: likely, not declared: 2 legs to walk on")


def test_a_walker_read_alone_or_in_part_keeps_the_guess_of_a_gait(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    alone = described(tmp_path / "alone", quadruped(), JOINT_CONTROLLERS)
    assert set(controls_of(alone, look_around=False)) == {"Walking"}
    # What a bound left unread may hold the gait.
    in_part = read_in_part(tmp_path / "part", monkeypatch, quadruped(), JOINT_CONTROLLERS)
    assert set(controls_of(in_part)) == {"Walking"}


def test_joint_controllers_of_a_body_with_one_leg_or_none_change_nothing(tmp_path: Path) -> None:
    arm_alone = controls_of(described(tmp_path / "arm", manipulator(), JOINT_CONTROLLERS))
    assert "Walking" not in arm_alone
    assert not [source for source in arm_alone.values() if "no gait shipped" in source]
    rover = controls_of(described(tmp_path / "rover", rover_with_a_lidar(), JOINT_CONTROLLERS))
    assert set(rover) == {"Driving"}


# A ros_control configuration of a quadrotor's four rotors, as a description package ships it.
ROTOR_CONTROLLERS = (
    "rotors_controller: {type: velocity_controllers/JointGroupVelocityController, "
    "joints: [rotor_0_joint, rotor_1_joint, rotor_2_joint, rotor_3_joint]}"
)


def test_a_drone_whose_packages_command_its_rotors_and_ship_no_flight_software_has_them_commanded(
    tmp_path: Path,
) -> None:
    found = controls_of(described(tmp_path, quadrotor(), ROTOR_CONTROLLERS))
    assert found == {
        "Joint": "package craft_bringup: craft_bringup/launch/bringup.launch "
        "(velocity_controllers): joint controllers naming its rotors, no flight software"
    }  # no flight guessed: nothing its author ships flies it


def test_a_drone_without_its_packages_is_flown(tmp_path: Path) -> None:
    alone = described(tmp_path, quadrotor(), ROTOR_CONTROLLERS)
    assert controls_of(alone, look_around=False)["Flight"] == "urdf: 4 rotor joint(s)"


@pytest.mark.parametrize(
    "software",
    [
        "attitude_controller: {rate: 100}",
        "altitude_hold.py",
        "<node pkg='mavros'/>",
        "px4_sitl",
        "ardupilot_gazebo",
        "take_off.py",
        "hover_thrust: 0.5",
        "mission_planner",
        "waypoint_follower",
        "lee_position_controller_node",
        "<include file='$(find rotors_gazebo)/launch/spawn_mav.launch'/>",
        "remap: {from: cmd_vel, to: /copter/cmd_vel}",
        "<node pkg='teleop_twist_keyboard'/>",
        "<node pkg='joy' type='joy_node'/>",
        "(thrust, err_roll, err_pitch) = pid(roll, pitch, yaw, thrust)",
    ],
)
def test_a_drone_whose_packages_ship_flight_software_is_only_flown(
    tmp_path: Path, software: str
) -> None:
    found = controls_of(described(tmp_path, quadrotor(), f"{ROTOR_CONTROLLERS}\n{software}"))
    assert "Flight" in found
    assert "Joint" not in found


@pytest.mark.parametrize(
    "text",
    [
        "# Permission is hereby granted, free of charge",
        "transmission_interface",
        "except KeyboardInterrupt:",
        "<node pkg='hoverboard_driver'/>",
        "enjoy_the_flight_of_the_rotors: true",
        "roll, pitch, yaw = euler_from_quaternion(q)",  # read, not held
    ],
)
def test_flight_words_inside_other_words_are_no_flight_software(tmp_path: Path, text: str) -> None:
    found = controls_of(described(tmp_path, quadrotor(), f"{ROTOR_CONTROLLERS}\n{text}"))
    assert "Joint" in found


def test_rotor_controllers_read_alone_or_in_part_change_nothing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    alone = described(tmp_path / "alone", quadrotor(), ROTOR_CONTROLLERS)
    assert "Joint" not in controls_of(alone, look_around=False)
    in_part = read_in_part(tmp_path / "part", monkeypatch, quadrotor(), ROTOR_CONTROLLERS)
    assert "Joint" not in controls_of(in_part)


def test_controllers_naming_no_rotor_command_none_of_them(tmp_path: Path) -> None:
    broadcaster = "joint_state_broadcaster: {type: JointStateBroadcaster, joints: [rotor_0_joint]}"
    assert "Joint" not in controls_of(described(tmp_path / "state", quadrotor(), broadcaster))
    gimbal = "gimbal: {type: position_controllers/JointPositionController, joint: gimbal_pitch}"
    assert "Joint" not in controls_of(described(tmp_path / "gimbal", quadrotor(), gimbal))


def namespaced_quadrotor() -> RobotText:
    """RotorS' way: every rotor named under the vehicle's namespace."""
    robot = RobotText("firefly")
    for i in range(4):
        robot.joint(f"firefly/rotor_{i}_joint", "continuous", robot.root, f"firefly/rotor_{i}")
    return robot


def test_namespaced_rotors_are_named_by_their_name_after_the_namespace(tmp_path: Path) -> None:
    gimbal = "gimbal: {type: position_controllers/JointPositionController, joint: gimbal_pitch}"
    assert "Joint" not in controls_of(described(tmp_path / "g", namespaced_quadrotor(), gimbal))
    found = controls_of(described(tmp_path / "r", namespaced_quadrotor(), ROTOR_CONTROLLERS))
    assert "joint controllers naming its rotors" in found["Joint"]


def test_a_controller_of_a_tilting_rotors_mount_its_own_takes_joint_commands_beside_flight(
    tmp_path: Path,
) -> None:
    # Written as ROS 1 configurations write it: the controller's name, its type, its joint.
    bringup = "tilt_left:\n  type: position_controllers/JointPositionController\n  joint: tilt_left"
    found = controls_of(described(tmp_path, tilt_rotor(), bringup))
    assert found["Flight"] == "urdf: 2 rotor joint(s)"
    assert found["Joint"] == (
        "package craft_bringup: craft_bringup/launch/bringup.launch "
        "(position_controllers/JointPositionController): a controller of a joint's own on a "
        "rotor's or thruster's mount"
    )


def rover_with_a_camera_head() -> RobotText:
    """A wheeled rover whose camera turns on a pan joint with a transmission (what a course's
    robot pet draws): the head points a sensor."""
    robot = ugv()
    head = robot.chain(robot.root, ["camera_pan"])
    robot.add(gazebo_sensor(head, "camera", "front_camera"))
    robot.add(transmission("camera_pan", "EffortJointInterface"))
    return robot


def test_a_controller_of_a_heads_joint_its_own_takes_joint_commands_on_a_vehicle(
    tmp_path: Path,
) -> None:
    # Written as ROS 1 configurations write it: the controller's name, its type, its joint.
    bringup = "camera_position_controller:\n  type: effort_controllers/JointPositionController\n"
    found = controls_of(
        described(tmp_path, rover_with_a_camera_head(), bringup + "  joint: camera_pan")
    )
    assert found["Joint"].startswith(
        "package craft_bringup: craft_bringup/launch/bringup.launch "
        "(effort_controllers/JointPositionController): a controller of a joint's own on a "
        "pan/tilt head"
    )


def test_a_dynamixel_controller_of_a_heads_joint_its_own_takes_joint_commands_on_a_vehicle(
    tmp_path: Path,
) -> None:
    # As dynamixel_controllers' ROS 1 configurations write it: its module, the joint's name.
    bringup = (
        "camera_pan_controller:\n  controller:\n    package: dynamixel_controllers\n"
        "    module: joint_position_controller\n    type: JointPositionController\n"
        "  joint_name: camera_pan\n  joint_speed: 4.0\n"
    )
    found = controls_of(described(tmp_path, rover_with_a_camera_head(), bringup))
    assert found["Joint"].endswith("a controller of a joint's own on a pan/tilt head")
    # Its torque module too; another joint's (no joint the description draws) commands none.
    torque = bringup.replace("position", "torque")
    assert "Joint" in controls_of(described(tmp_path / "t", rover_with_a_camera_head(), torque))
    # Written module first, or in flow style: the same.
    for written in (
        "camera_pan_controller:\n  controller: {module: joint_position_controller,\n"
        "    type: JointPositionController, package: dynamixel_controllers}\n"
        "  joint_name: camera_pan\n",
        "camera_pan_controller: {controller: {package: dynamixel_controllers, "
        "module: joint_position_controller}, joint_name: camera_pan}\n",
    ):
        folder = tmp_path / f"w{len(written)}"
        assert "Joint" in controls_of(described(folder, rover_with_a_camera_head(), written))
    other = bringup.replace("joint_name: camera_pan", "joint_name: mast_lift")
    assert "Joint" not in controls_of(described(tmp_path / "o", rover_with_a_camera_head(), other))


@pytest.mark.parametrize(
    "bringup",
    [
        # A transmission alone: who commands the head is not said.
        "joint_state_controller: {type: joint_state_controller/JointStateController}",
        # A controller of another joint's own (no joint the description draws).
        "mast: {type: position_controllers/JointPositionController, joint: mast_lift}",
    ],
)
def test_no_heads_controller_of_its_own_gives_a_vehicle_no_joint_commands(
    tmp_path: Path, bringup: str
) -> None:
    assert "Joint" not in controls_of(described(tmp_path, rover_with_a_camera_head(), bringup))


def rover_on_suspensions() -> RobotText:
    """A four-wheeled rover whose wheels each hang from a vertical slide (a suspension)."""
    robot = RobotText("rover")
    for i, (x, y) in enumerate([(0.3, 0.25), (0.3, -0.25), (-0.3, 0.25), (-0.3, -0.25)]):
        placed(robot, f"sus{i}_joint", "prismatic", robot.root, f"sus{i}", xyz=f"{x} {y} 0")
        placed(robot, f"wheel{i}_joint", "continuous", f"sus{i}", f"wheel{i}", axis="0 1 0")
    return robot


def configured(tmp_path: Path, robot: RobotText, controllers: str) -> Path:
    """A description package holding ``robot`` and a controller configuration
    (``config/controllers.yaml``); the description file."""
    files = {"urdf/craft.urdf": robot.text(), "config/controllers.yaml": controllers}
    return package(tmp_path / "ws" / "src", "craft_description", files) / "urdf" / "craft.urdf"


# ROS 2's way: the controller manager is given each controller's type, and each controller
# its joints under its own parameters; a state broadcaster beside them lists every joint.
SUSPENSIONS = """
controller_manager:
  ros__parameters:
    suspension_controller:
      type: position_controllers/JointGroupPositionController
    wheel_controller:
      type: velocity_controllers/JointGroupVelocityController
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
suspension_controller:
  ros__parameters:
    joints: [sus0_joint, sus1_joint, sus2_joint, sus3_joint]
wheel_controller:
  ros__parameters:
    joints: [wheel0_joint, wheel1_joint, wheel2_joint, wheel3_joint]
joint_state_broadcaster:
  ros__parameters:
    extra_joints: [sus0_joint, sus1_joint]
"""


@pytest.mark.parametrize(
    ("robot", "controllers"),
    [
        (rover_on_suspensions, SUSPENSIONS),
        # ROS 1's way: a forward command or a trajectory controller of a camera's pan joint,
        # its type and its joints side by side (under a namespace).
        (
            rover_with_a_camera_head,
            "rover:\n  scanner:\n    type: forward_command_controller/ForwardCommandController\n"
            "    joints: [camera_pan]",
        ),
        (
            rover_with_a_camera_head,
            "head: {type: position_controllers/JointTrajectoryController, joints: [camera_pan]}",
        ),
        # ROS 2 nodes named with a namespace: the manager names the controller by its last part.
        (
            rover_on_suspensions,
            "/rover/controller_manager:\n  ros__parameters:\n    sus:\n"
            "      type: position_controllers/JointGroupPositionController\n"
            "/rover/sus:\n  ros__parameters:\n    joints: [sus0_joint]",
        ),
    ],
    ids=["suspensions", "forward", "trajectory", "node-names"],
)
def test_joint_controllers_given_a_ground_vehicles_mounts_or_head_take_joint_commands(
    tmp_path: Path, robot: Callable[[], RobotText], controllers: str
) -> None:
    found = controls_of(configured(tmp_path, robot(), controllers))
    assert found["Driving"]
    assert found["Joint"].startswith("package craft_description: craft_description/config/")
    assert found["Joint"].endswith(
        "joint controllers naming a ground vehicle's mount or head joint"
    )


@pytest.mark.parametrize(
    "controllers",
    [
        # The wheels' own speeds alone: the drive, no mount's joint.
        SUSPENSIONS.replace("sus0_joint, sus1_joint, sus2_joint, sus3_joint", "wheel0_joint"),
        # The suspensions only a state broadcaster lists.
        SUSPENSIONS.replace("joints: [sus0_joint, sus1_joint, sus2_joint, sus3_joint]", "{}"),
        # A file YAML cannot read (a tab before a key) says nothing.
        SUSPENSIONS.replace("suspension_controller:\n  ros__parameters:", "x:\n\tros__parameters:"),
        # Each controller's type under its own parameters: the broadcaster's joints are its own.
        "mast: {ros__parameters: {type: position_controllers/JointGroupPositionController, "
        "joints: [mast_joint]}}\n"
        "broadcaster: {ros__parameters: {type: joint_state_broadcaster/JointStateBroadcaster, "
        "joints: [sus0_joint]}}",
        # Longer than any controller configuration: a map or a data set, not read.
        SUSPENSIONS + "# " + "x" * 70_000 + "\npoints: [" + "0, " * 30_000 + "0]\n",
    ],
    ids=["wheels", "broadcaster", "unreadable", "own-parameters", "too-long"],
)
def test_no_controller_given_a_ground_vehicles_mounts_gives_it_no_joint_commands(
    tmp_path: Path, controllers: str
) -> None:
    assert "Joint" not in controls_of(configured(tmp_path, rover_on_suspensions(), controllers))


def test_a_flown_bodys_head_given_to_a_joint_controller_is_no_ground_vehicles(
    tmp_path: Path,
) -> None:
    robot = quadrotor()
    robot.chain(robot.root, ["camera_pan"])
    head = "gimbal: {type: position_controllers/JointGroupPositionController, joints: [camera_pan]}"
    assert "Joint" not in controls_of(configured(tmp_path, robot, head))


@pytest.mark.parametrize(
    "bringup",
    [
        # A joint's own controller of no mount (an aileron's).
        "aileron: {type: position_controllers/JointPositionController, joint: aileron_left}",
        # The mounts named in a group controller, what a flight controller writes to.
        "tilts: {type: position_controllers/JointGroupPositionController, "
        "joints: [tilt_left, tilt_right]}",
    ],
)
def test_no_mounts_controller_of_its_own_gives_a_flown_body_no_joint_commands(
    tmp_path: Path, bringup: str
) -> None:
    assert "Joint" not in controls_of(described(tmp_path, tilt_rotor(), bringup))


def test_a_flight_stack_package_beside_the_robots_keeps_its_rotors_to_it(tmp_path: Path) -> None:
    path = described(tmp_path, quadrotor(), ROTOR_CONTROLLERS)
    package(tmp_path / "ws" / "src", "px4_msgs", {"msg/VehicleCommand.msg": "uint32 command"})
    assert set(controls_of(path)) == {"Flight"}
