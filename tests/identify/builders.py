"""Small robot descriptions the identification tests write themselves.

:class:`RobotText` builds URDF text joint by joint; the functions below build one robot of each
kind the classifier knows (wheeled and tracked UGVs, multirotors, arms, torsos, humanoids,
quadrupeds, bipeds, hands, aerial and legged manipulators).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field


@dataclass
class RobotText:
    name: str
    root: str = "base_link"
    joints: list[str] = field(default_factory=list)
    links: list[str] = field(default_factory=list)
    extra: list[str] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.links.append(self.root)

    def joint(self, name: str, kind: str, parent: str, child: str, body: str = "") -> str:
        self.links.append(child)
        self.joints.append(
            f'  <joint name="{name}" type="{kind}"><parent link="{parent}"/>'
            f'<child link="{child}"/>{body}</joint>'
        )
        return child

    def chain(self, parent: str, names: list[str], kind: str = "revolute") -> str:
        """A serial chain of joints ``names``; each child link is ``<joint>_link``."""
        link = parent
        for name in names:
            link = self.joint(
                name,
                kind,
                link,
                f"{name}_link",
                '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
                if kind in ("revolute", "prismatic")
                else "",
            )
        return link

    def fixed(self, parent: str, child: str) -> str:
        return self.joint(f"{child}_fixed", "fixed", parent, child)

    def add(self, xml: str) -> None:
        self.extra.append(xml)

    def text(self) -> str:
        links = "\n".join(f'  <link name="{link}"/>' for link in self.links)
        return (
            f'<?xml version="1.0"?>\n<robot name="{self.name}">\n{links}\n'
            + "\n".join(self.joints + self.extra)
            + "\n</robot>\n"
        )


def solid(text: str, *links: str) -> str:
    """``text`` with each of ``links`` given a mass: a part one could hold, not a frame."""
    for link in links:
        text = text.replace(
            f'<link name="{link}"/>',
            f'<link name="{link}"><inertial><mass value="0.2"/></inertial></link>',
        )
    return text


# A rod's inertia, long along its own x (its least moment a twelfth of the others).
ROD_ALONG_X = 'ixx="0.002" ixy="0" ixz="0" iyy="0.025" iyz="0" izz="0.025"'


def weighted(text: str, link: str, centre: str, inertia: str = ROD_ALONG_X) -> str:
    """``text`` with ``link`` given a mass whose centre is at ``centre`` in its own frame, and
    ``inertia``'s terms (a rod along x unless told; none when empty)."""
    terms = f"<inertia {inertia}/>" if inertia else ""
    return text.replace(
        f'<link name="{link}"/>',
        f'<link name="{link}"><inertial><origin xyz="{centre}"/><mass value="1.5"/>{terms}'
        "</inertial></link>",
    )


def gazebo_sensor(link: str, kind: str, name: str, inner: str = "", plugin: str = "") -> str:
    plugin_xml = f'<plugin name="{name}_plugin" filename="{plugin}"/>' if plugin else ""
    return (
        f'  <gazebo reference="{link}"><sensor type="{kind}" name="{name}">{inner}'
        f"{plugin_xml}</sensor></gazebo>"
    )


def model_plugin(name: str, filename: str, params: str = "") -> str:
    return f'  <gazebo><plugin name="{name}" filename="{filename}">{params}</plugin></gazebo>'


LASER = gazebo_sensor("laser", "ray", "laser")
CAMERA = gazebo_sensor("cam", "camera", "cam")


def transmission(joint: str, interface: str = "PositionJointInterface") -> str:
    """A ROS 1 ``<transmission>`` driving ``joint`` (a controller commands it)."""
    return (
        f'  <transmission name="{joint}_trans"><type>transmission_interface/'
        f'SimpleTransmission</type><joint name="{joint}"><hardwareInterface>'
        f"hardware_interface/{interface}</hardwareInterface></joint>"
        f'<actuator name="{joint}_motor"/></transmission>'
    )


def joint_xml(name: str, kind: str, parent: str, child: str, *pose: str) -> str:
    """One joint as URDF text, placed: ``pose`` is its origin's xyz and its axis, as written
    (for a robot written whole, where :class:`RobotText` would add each link itself)."""
    xyz, axis = pose
    limit = '<limit lower="-1" upper="1" effort="1" velocity="1"/>' if kind == "revolute" else ""
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin xyz="{xyz}"/><axis xyz="{axis}"/>{limit}</joint>'
    )


def ring_of_legs(
    name: str, legs: int, places: Callable[[float, float], tuple[tuple[str, str], ...]]
) -> str:
    """A robot ``name`` written whole: ``legs`` legs (coxa, femur, tibia) around a body, the
    ``i``-th one's joints placed by ``places(x, y)`` (each an origin's xyz and an axis, as
    :func:`joint_xml` takes them) for the unit vector ``(x, y)`` of its bearing."""
    links, joints = ["body"], []
    for i in range(legs):
        angle = 2 * math.pi * i / legs
        names = (f"coxa_{i}", f"femur_{i}", f"tibia_{i}")
        links += [f"{part}_link" for part in names]
        parent = "body"
        for part, (xyz, axis) in zip(names, places(math.cos(angle), math.sin(angle)), strict=True):
            joints.append(joint_xml(part, "revolute", parent, f"{part}_link", xyz, axis))
            parent = f"{part}_link"
    body = "".join(f'<link name="{link}"/>' for link in links) + "".join(joints)
    return f'<robot name="{name}">{body}</robot>'


def wheeled_base(robot: RobotText, wheels: int = 2) -> None:
    for side in ("left", "right", "rear_left", "rear_right")[:wheels]:
        robot.joint(f"wheel_{side}_joint", "continuous", robot.root, f"wheel_{side}_link")


def arm(
    robot: RobotText, parent: str, prefix: str = "", joints: int = 6, gripper: bool = True
) -> str:
    names = [
        f"{prefix}shoulder_pan",
        f"{prefix}shoulder_lift",
        f"{prefix}elbow",
        *(f"{prefix}wrist_{i}" for i in range(1, joints - 2)),
    ][:joints]
    tip = robot.chain(parent, names)
    if gripper:
        robot.chain(tip, [f"{prefix}gripper_finger_left"], "prismatic")
        robot.joint(
            f"{prefix}gripper_finger_right",
            "prismatic",
            tip,
            f"{prefix}gripper_finger_right_link",
            f'<mimic joint="{prefix}gripper_finger_left"/>'
            '<limit lower="0" upper="1" effort="1" velocity="1"/>',
        )
    return tip


def leg(robot: RobotText, parent: str, prefix: str, joints: tuple[str, ...]) -> str:
    tip = robot.chain(parent, [f"{prefix}_{j}" for j in joints])
    return robot.fixed(tip, f"{prefix}_foot")


def ugv() -> RobotText:
    robot = RobotText("rover")
    wheeled_base(robot, 4)
    return robot


def tracked() -> RobotText:
    robot = RobotText("crawler")
    robot.add(model_plugin("tracks", "libSimpleTrackedVehiclePlugin.so"))
    robot.chain(robot.root, ["flipper_front_j", "flipper_front_motor_j"])
    return robot


def quadrotor(rotors: int = 4) -> RobotText:
    robot = RobotText("copter")
    for i in range(rotors):
        robot.joint(f"rotor_{i}_joint", "continuous", robot.root, f"rotor_{i}")
    return robot


def manipulator() -> RobotText:
    robot = RobotText("arm6")
    arm(robot, robot.root)
    return robot


def torso() -> RobotText:
    robot = RobotText("dual")
    waist = robot.chain(robot.root, ["torso_waist"])
    arm(robot, waist, "left_", 7)
    arm(robot, waist, "right_", 7)
    return robot


def mobile_manipulator() -> RobotText:
    robot = RobotText("fetcher")
    wheeled_base(robot)
    lift = robot.chain(robot.root, ["torso_lift"], "prismatic")
    arm(robot, lift)
    robot.chain(lift, ["head_pan", "head_tilt"])
    return robot


def humanoid() -> RobotText:
    robot = RobotText("biped_arms")
    for side in ("l", "r"):
        leg(
            robot,
            robot.root,
            f"{side}_leg",
            ("hip_yaw", "hip_roll", "hip_pitch", "knee", "ankle_pitch", "ankle_roll"),
        )
        arm(robot, robot.root, f"{side}_", 5)
    robot.chain(robot.root, ["neck_yaw", "head_pitch"])
    return robot


def quadruped() -> RobotText:
    robot = RobotText("dog")
    for corner in ("FL", "FR", "RL", "RR"):
        leg(robot, robot.root, corner, ("hip", "thigh", "calf"))
    return robot


def biped() -> RobotText:
    robot = RobotText("legs")
    for side in ("l", "r"):
        leg(robot, robot.root, side, ("hip_pitch", "knee", "ankle"))
    return robot


def hand() -> RobotText:
    robot = RobotText("hand5", root="palm")
    for finger in ("index", "middle", "ring", "little", "thumb"):
        robot.chain(robot.root, [f"{finger}_finger_{i}" for i in range(3)])
    return robot


def aerial_manipulator() -> RobotText:
    robot = quadrotor()
    arm(robot, robot.root, joints=3)
    return robot


def legged_manipulator() -> RobotText:
    robot = quadruped()
    arm(robot, robot.root, joints=6)
    return robot


def pan_tilt_only() -> RobotText:
    robot = RobotText("ptu")
    robot.chain(robot.root, ["pan_joint", "tilt_joint"])
    return robot


def surface_vessel() -> RobotText:
    """A catamaran: two thrusters on the hull, a buoyancy plugin with a waterline."""
    robot = RobotText("catamaran")
    for side in ("left", "right"):
        robot.joint(f"{side}_thruster_joint", "continuous", robot.root, f"{side}_thruster")
    robot.add(
        model_plugin(
            "hull",
            "libhull_buoyancy.so",
            "<link_name>base_link</link_name><metacentric_width>0.1</metacentric_width>",
        )
    )
    return robot


def underwater_vehicle() -> RobotText:
    """A torpedo: one propeller a thruster plugin names, four fins a fin plugin names."""
    robot = RobotText("torpedo")
    robot.joint("prop_joint", "continuous", robot.root, "prop")
    robot.add(model_plugin("drive", "libthruster_model.so", "<jointName>prop_joint</jointName>"))
    for i in range(4):
        robot.chain(robot.root, [f"surface{i}"])
        robot.add(model_plugin(f"f{i}", "libfin_plugin.so", f"<joint_name>surface{i}</joint_name>"))
    robot.add(model_plugin("water", "libunderwater_object.so"))
    return robot


def propellers_fixed() -> RobotText:
    """A multirotor whose propellers are fixed links, carrying a two-joint arm."""
    robot = RobotText("flying_arm")
    for i in range(4):
        robot.fixed(robot.root, f"prop{i}")
    robot.chain(robot.root, ["j1", "j2"])
    return robot


def fixed_wing() -> RobotText:
    """A plane of fixed links only: a main wing, ailerons, a tail."""
    robot = RobotText("plane")
    for link in ("main_wing", "aileron_left", "aileron_right", "horizontal_tail", "motor"):
        robot.fixed(robot.root, link)
    return robot


def tilt_rotor() -> RobotText:
    """A tilt-rotor: two tilting rotor units, two ailerons."""
    robot = RobotText("tilter")
    for side in ("left", "right"):
        tilt = robot.chain(robot.root, [f"tilt_{side}"])
        robot.joint(f"rotor_{side}_joint", "continuous", tilt, f"rotor_{side}")
        robot.chain(robot.root, [f"aileron_{side}"])
    return robot


def caster_base() -> RobotText:
    """A differential base with two passive casters (a swivel and a wheel each)."""
    robot = RobotText("caster_bot")
    wheeled_base(robot, 2)
    for corner in ("front", "rear"):
        robot.joint(
            f"{corner}_swivel",
            "continuous",
            robot.root,
            f"{corner}_swivel_link",
            '<axis xyz="0 0 1"/>',
        )
        robot.joint(
            f"{corner}_roller", "continuous", f"{corner}_swivel_link", f"{corner}_roller_wheel"
        )
    return robot


def parallel_gripper() -> RobotText:
    """A gripper of one motion: one actuated knuckle, the rest of the linkage mimics it."""
    robot = RobotText("two_jaw")
    robot.chain(robot.root, ["finger_joint"])
    for name in ("left_inner_knuckle", "right_outer_knuckle", "right_inner_knuckle"):
        robot.joint(
            f"{name}_joint",
            "revolute",
            robot.root,
            name,
            '<mimic joint="finger_joint"/><limit lower="0" upper="1" effort="1" velocity="1"/>',
        )
    return robot


def wheel_legged_manipulator() -> RobotText:
    """Four legs each ending in a wheel, two arms."""
    robot = RobotText("centaur")
    for corner in ("front_left", "front_right", "rear_left", "rear_right"):
        tip = robot.chain(robot.root, [f"{corner}_hip", f"{corner}_knee", f"{corner}_ankle"])
        robot.joint(f"{corner}_wheel_joint", "continuous", tip, f"{corner}_wheel")
    arm(robot, robot.root, "left_", 6)
    arm(robot, robot.root, "right_", 6)
    return robot


def placed(
    robot: RobotText,
    name: str,
    kind: str,
    parent: str,
    child: str,
    *,
    xyz: str = "0 0 0",
    rpy: str = "0 0 0",
    axis: str = "0 0 1",
    extra: str = "",
) -> str:
    """A joint with its place, its turn and its axis written out (limits on a revolute or
    prismatic one); ``extra`` is more of the joint's elements (a ``<mimic>``)."""
    limits = (
        '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
        if kind in ("revolute", "prismatic")
        else ""
    )
    body = f'<origin xyz="{xyz}" rpy="{rpy}"/><axis xyz="{axis}"/>{limits}{extra}'
    return robot.joint(name, kind, parent, child, body)


def geared_arm() -> RobotText:
    """An arm drawn as gear pairs: on each link a drive gear (a leaf, actuated) beside the joint
    it turns (a mimic of the gear, at half its speed), which carries the rest of the arm."""
    robot = RobotText("geared", root="base")
    link = "base"
    for i in range(1, 5):
        placed(robot, f"drive{i}", "revolute", link, f"drive{i}_gear", xyz="0.02 0 0.05")
        link = placed(
            robot,
            f"joint{i}",
            "revolute",
            link,
            f"link{i}",
            xyz="0 0 0.1",
            axis="0 1 0" if i % 2 else "0 0 1",
            extra=f'<mimic joint="drive{i}" multiplier="-0.5"/>',
        )
    return robot


def linkage_biped() -> RobotText:
    """Two legs whose knees are worked by a crank on the hip (a parallel linkage): the crank is
    actuated, the knee a mimic of it."""
    robot = RobotText("linkage_biped", root="pelvis")
    for side, y in (("l", 0.1), ("r", -0.1)):
        hip = placed(robot, f"{side}_hip", "revolute", "pelvis", f"{side}_hip_link", xyz=f"0 {y} 0")
        thigh = placed(robot, f"{side}_thigh", "revolute", hip, f"{side}_thigh_link", axis="0 1 0")
        placed(robot, f"{side}_crank", "revolute", hip, f"{side}_crank_link", axis="0 1 0")
        shin = placed(
            robot,
            f"{side}_knee",
            "revolute",
            thigh,
            f"{side}_shin",
            xyz="0 0 -0.3",
            axis="0 1 0",
            extra=f'<mimic joint="{side}_crank"/>',
        )
        robot.fixed(shin, f"{side}_foot")
    return robot


def simulated_root(robot: RobotText, body: str) -> str:
    """The six joints a simulator's or a planner's description writes for a floating base, from
    ``robot``'s root to ``body`` (three slides, then roll, pitch and yaw): ``body``."""
    link = robot.root
    for name, kind, axis in (
        ("x", "prismatic", "1 0 0"),
        ("y", "prismatic", "0 1 0"),
        ("z", "prismatic", "0 0 1"),
        ("roll", "revolute", "1 0 0"),
        ("pitch", "revolute", "0 1 0"),
        ("yaw", "revolute", "0 0 1"),
    ):
        child = body if name == "yaw" else f"base_{name}_link"
        link = placed(robot, f"base_{name}", kind, link, child, axis=axis)
    return link


def walker(legs: int = 6, *, simulated_base: bool = False, joints: int = 3) -> RobotText:
    """A walker whose joints say nothing (j0a, j0b, ...): alike chains of ``joints`` joints
    (three or more) around its body, each ending in a tip below where it starts.
    ``simulated_base``: the body hangs from a ``world`` link by the six joints a simulator's
    description writes for a floating base (three slides, then roll, pitch and yaw)."""
    robot = RobotText("walker", root="world" if simulated_base else "body")
    if simulated_base:
        simulated_root(robot, "body")
    for i in range(legs):
        x = 0.1 * (i % (legs // 2)) - 0.1
        y = 0.08 if i < legs // 2 else -0.08
        link = placed(robot, f"j{i}a", "revolute", "body", f"l{i}a", xyz=f"{x} {y} 0")
        link = placed(robot, f"j{i}b", "revolute", link, f"l{i}b", xyz="0.05 0 0", axis="0 1 0")
        for extra in range(joints - 3):  # more pitch joints along the leg, 0.03 m apart
            link = placed(
                robot,
                f"j{i}x{extra}",
                "revolute",
                link,
                f"l{i}x{extra}",
                xyz="0.03 0 0",
                axis="0 1 0",
            )
        last = placed(robot, f"j{i}c", "revolute", link, f"l{i}c", xyz="0.06 0 0", axis="0 1 0")
        robot.joint(f"tip{i}", "fixed", last, f"tip{i}_link", '<origin xyz="0.05 0 -0.1"/>')
    return robot


def snake(modules: int = 8, *, name: str = "modules") -> RobotText:
    """A snake: equal modules 0.1 m apart, each joint's axis square to the last's; called
    ``name`` (by default a name that says nothing: its shape alone speaks)."""
    robot = RobotText(name, root="m0")
    link = "m0"
    for i in range(1, modules + 1):
        axis = "0 0 1" if i % 2 else "0 1 0"
        link = placed(robot, f"j{i}", "revolute", link, f"m{i}", xyz="0.1 0 0", axis=axis)
    return robot


def forearm_hand() -> RobotText:
    """A hand hung from its forearm: a 2-joint wrist into the palm, five 3-joint fingers."""
    robot = RobotText("forearm_hand", root="forearm")
    wrist = robot.chain("forearm", ["wr1", "wr2"])
    robot.joint("palm_fixed", "fixed", wrist, "palm")
    for finger in ("ff", "mf", "rf", "lf", "th"):
        robot.chain("palm", [f"{finger}j3", f"{finger}j2", f"{finger}j1"])
    return robot


def one_motion_gripper() -> RobotText:
    """Two jaws of two links each closed by one actuated joint (the rest mimic it), no
    gripper word in any name."""
    robot = RobotText("jaws", root="base")
    r1 = placed(robot, "r1", "revolute", "base", "r1_link", xyz="0 0.008 0.05", axis="1 0 0")
    placed(
        robot,
        "r2",
        "revolute",
        r1,
        "r2_link",
        xyz="0 0.05 0.03",
        axis="-1 0 0",
        extra='<mimic joint="r1"/>',
    )
    l1 = placed(
        robot,
        "l1",
        "revolute",
        "base",
        "l1_link",
        xyz="0 -0.008 0.05",
        axis="-1 0 0",
        extra='<mimic joint="r1"/>',
    )
    placed(
        robot,
        "l2",
        "revolute",
        l1,
        "l2_link",
        xyz="0 -0.05 0.03",
        axis="1 0 0",
        extra='<mimic joint="r1"/>',
    )
    return robot


def sensing_rover() -> str:
    """A four-wheeled rover with a laser, a camera and a differential drive plugin."""
    robot = ugv()
    robot.add(LASER)
    robot.add(CAMERA)
    robot.add(model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    return robot.text()
