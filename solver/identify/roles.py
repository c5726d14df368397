"""What each moving joint of a robot does: its role, and the evidence that decided it.

A description says what a joint does in several places. :class:`RoleReader` reads them in order
of strength, and the first that speaks decides:

1. A Gazebo model plugin that names the joint in a parameter: a thruster plugin's
   ``<jointName>`` (also a thruster link it lists), a motor model's ``<jointName>`` (a rotor), a
   drive plugin's ``<leftJoint>`` (a wheel; a joint it names for steering steers), a fin or
   lift-drag plugin's ``<joint_name>`` (a fin or control surface; a rotor when the joint turns
   without limits: a propeller blade's lift); on a body in water, a swivel or a spin on the
   hull whose link a force plugin pushes (``gazebo_ros_force``'s ``<link_name>``) is a
   thruster. Which plugin is which is the profile's ``plugins`` patterns; a plugin that gives
   a wheel spacing and a wheel size (``<wheelSeparation>``, ``<wheelDiameter>``) is a drive
   plugin whatever it is called (a robot's own drive plugin), and the joints it names by a
   side or as wheels (``<leftJoint>``, ``<wheel_joint>``) are its wheels; its other joints
   (an arm's, a head's) it drives otherwise.
2. The joint's place and shape: a vertical swivel that carries a wheel and nothing else is a
   caster (the wheel below it is the caster's); a propeller on a body in water is a thruster;
   a propeller on a ``floating`` joint with nothing below (a visual part a simulator poses) is
   a rotor.
3. Names last: the profile's part patterns on the joint and its child link (``thruster``,
   ``fin``, ``wing`` for control surfaces, ``caster``, ``wheel``, ``rotor``, ``gripper``).

The roles here are the ones a single joint plays: wheel, steering, caster, rotor, thruster, fin,
gripper. The limb roles (leg, arm, head, mount, trunk) come from the chains the other joints
form (:mod:`solver.identify.limbs`), fingers from grippers and from where chains hang
(:mod:`solver.identify.hands`); the roles of a whole robot's joints, wheels found by place when
names say nothing among them, are :mod:`solver.identify.actuation`'s.

Not here: chains and limbs (:mod:`solver.identify.limbs`), the structure
(:mod:`solver.identify.classifier`).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass
from functools import cached_property

from solver.identify.pose import local_axis
from solver.identify.profile import PartMatcher, Profile
from solver.identify.readers.urdf import Joint, PluginTag, Urdf

__all__ = ["JOINT_ROLES", "POSED", "Role", "RoleReader"]

JOINT_ROLES = ("wheel", "steering", "caster", "rotor", "thruster", "fin", "gripper")
_ROTATING = ("continuous", "revolute")
# Plugin part -> the role of a joint it names, strongest first (a propeller a thruster plugin
# and a lift-drag plugin both name is a thruster).
_PLUGIN_ROLES = (
    ("thruster", "thruster"),
    ("flight", "rotor"),
    ("drive", "wheel"),
    ("lift", "fin"),
    ("spring", "passive"),  # a joint held on a spring yields: nobody drives it
    ("grasp", "gripper"),  # a grasp plugin's <gripper_link>: a finger (not its <palm_link>)
)
_Z = 2
# The evidence of a propeller a simulator poses on a floating joint (counted however few).
POSED = ", a part a simulator poses (floating joint)"


# A drive plugin's parameters, read by what they give (tags compared without case, ``_`` or
# ``-``): the wheels' spacing, and their size.
_WHEEL_SPACING = frozenset({"wheelseparation", "wheeltrack", "wheeldistance"})
_WHEEL_SIZE = frozenset({"wheeldiameter", "wheelradius"})


# A tracked vehicle plugin's parameters (Gazebo's ``SimpleTrackedVehiclePlugin`` and the
# plugins written after it): the link of each side's track.
_TRACK_SIDES = frozenset({"lefttrack", "righttrack"})

# A plugin's parameter that names the topic it takes commands on, and a velocity command's
# topic (its last part): a Twist on ``cmd_vel``, as every drive plugin takes it.
_COMMAND_TOPICS = frozenset({"commandtopic", "cmdveltopic"})
_VELOCITY_TOPIC = re.compile(r"\s*cmd_vel\s*", re.IGNORECASE)


# The parameters of such a plugin that name its wheels (``<leftJoint>``, ``<wheel_joint>``); a
# robot's own plugin may name other joints too (an arm's, a head's), which it drives otherwise.
_WHEEL_TAG = re.compile(r"left|right|wheel|front|rear|back|steer", re.IGNORECASE)
# Plugins that name links, not joints: a joint is named by the link it moves.
_BY_LINK = frozenset({"thruster", "grasp"})


def _pattern_parts(plugin: PluginTag, profile: Profile) -> frozenset[str]:
    """The parts the profile's plugin patterns read in what names ``plugin`` (:func:`_said`)."""
    said = _said(plugin)
    return frozenset(part for part, pattern in profile.plugins if pattern.search(said))


def _said(plugin: PluginTag) -> str:
    """What a plugin says it is: its file, which is what runs; else its name, a label its author
    chose (often copied from the plugin above it: a frame publisher named ``simple_buoyancy``),
    which speaks only for a plugin that gives no file."""
    return plugin.filename.strip() or plugin.name


def _plain(tag: str) -> str:
    """A parameter's tag as tags are compared: without case, ``_`` or ``-``."""
    return re.sub(r"[_-]", "", tag).lower()


def _tags(plugin: PluginTag) -> set[str]:
    """The plugin's parameter tags, each made plain (:func:`_plain`)."""
    return {_plain(tag) for tag, _ in plugin.params}


def _wheel_geometry(tags: set[str]) -> bool:
    """Whether a plugin of these parameter ``tags`` sets both a wheel spacing and a size."""
    return bool(tags & _WHEEL_SPACING and tags & _WHEEL_SIZE)


@dataclass(frozen=True, slots=True)
class Role:
    """One joint's role and the evidence that decided it, in words a person can check."""

    joint: str
    role: str
    evidence: str


# A robot name that says a craft at the surface, read as whole words (``simple_boat``,
# ``sailboat001``, ``chelon_asv``, ``stinger_tug``; a word ending in boat, ``blueboat``; not
# ``airship``, ``mothership``, ``tugger``, ``boathouse`` or a lab's ``vessel``).
_VESSEL_NAME = re.compile(
    r"(^|[_/\d-])([a-z]*boat|tug|ship|asv|usv|catamaran|yacht|kayak|canoe|barge"
    r"|ferry|sail)s?([_/\d-]|$)",
    re.IGNORECASE,
)


# A robot named for a rig of sensors a vehicle carries: a sensor kit, rack, suite, tower, box,
# pod, array or mount (``mid360_sensor_kit``, ``multisensor_rack``), a sensor backpack: a kit
# mounted on a vehicle or a person, not the vehicle.
_RIG_NAME = re.compile(
    r"sensors?[_-]?(kit|rig|rack|suite|tower|box(es)?|pod|array|mount)s?([_/\d-]|$)"
    r"|(^|[_/\d-])backpacks?([_/\d-]|$)",
    re.IGNORECASE,
)


def _rig_on_undeclared_root(urdf: Urdf) -> str | None:
    """What names the body a rig of sensors when the description hangs from a link it never
    declares (a vehicle's ``base_link``, which the vehicle's own description makes) and is a
    kit that vehicle includes: all it fixes to that link is a link named for a rig of sensors
    (``sensor_kit_base_link``) and mounts that carry a declared sensor (a rear lidar beside the
    kit), nothing that moves and no body of its own. None otherwise (a vehicle's body beside
    its kit, a pan/tilt head on the undeclared link)."""
    root = urdf.link(urdf.root)
    if root is None or root.declared:
        return None
    sensed = {tag.link for tag in urdf.sensors}
    kit = None
    for joint in urdf.children(root.name):
        if joint.movable:
            return None
        if _RIG_NAME.search(joint.child):
            kit = kit or joint.child
        elif not sensed.intersection((joint.child, *urdf.fixed_below(joint.child))):
            return None
    return None if kit is None else f"the undeclared root's link {kit}"


# A robot name that says a craft below the surface, read as whole words (``rov_model``,
# ``my_auv``, ``submarine``; not ``rover``), an ROV's or AUV's with a usual prefix too
# (``AROV``, ``bluerov2``, ``openrov``; not ``petrov`` or ``improv``).
_SUBMERSIBLE_NAME = re.compile(
    r"(^|[_/\d-])((a|b|blue|open|mini|micro|sea|deep|sub|my)?(auv|rov)|uuv|submarine|submersible)"
    r"s?([_/\d-]|$)",
    re.IGNORECASE,
)


# A robot name that says a lighter-than-air craft, read as whole words (``burn_cream_blimp``,
# ``airship``, ``Dirigible_2``): an aircraft by its name, as the flight words say one. Not a
# plugin's name (a tracker plugin named for a blimp it follows runs on a rover too).
_AIRSHIP_NAME = re.compile(
    r"(^|[_/\d\s-])(blimp|airship|dirigible|zeppelin)s?([_/\d\s-]|$)", re.IGNORECASE
)


# The tags in which plugins give the density of the medium they work in (thrusters, lift and
# drag, Gazebo Sim's buoyancy and hydrodynamics), and the density (kg/m³) below which it is
# air's: air's is about 1.2, fresh water's 1000, sea water's about 1027.
_DENSITY_TAGS = ("fluid_density", "air_density", "uniform_fluid_density", "water_density")
_AIR_DENSITY = 100.0


# A plugin's entry that is a rotorcraft's (``<rotor>``, ``<rotors>``), read as a whole tag;
# and the plugin parts that put a body in water (such a plugin's rotor entries are not flown).
_ROTOR_ENTRY = re.compile(r"rotors?", re.IGNORECASE)
_WATER_PARTS = frozenset({"marine", "surface", "underwater"})


def main_axis(axis: tuple[float, float, float]) -> int:
    """0, 1 or 2 for an axis along x, y or z; -1 for a slanted one."""
    sizes = [abs(v) for v in axis]
    top = max(sizes)
    return sizes.index(top) if top > 0 and sorted(sizes)[1] < 1e-6 else -1


class RoleReader:
    """The single-joint roles of one description (see the module docstring)."""

    def __init__(self, urdf: Urdf, profile: Profile, parts_of: PartMatcher) -> None:
        self.urdf = urdf
        self.profile = profile
        self.parts_of = parts_of
        # A plugin says water by its words (a hydrodynamics, buoyancy or boat plugin): then no
        # plugin's rotor entries fly the body (``_plugin_parts``).
        said = {id(p): _pattern_parts(p, profile) for p in urdf.plugins}
        self.water_plugins = any(parts & _WATER_PARTS for parts in said.values())
        self.plugin_parts = {id(p): self._plugin_parts(p, said[id(p)]) for p in urdf.plugins}
        self.fixed_thrusters = self._fixed_thrusters()
        self.named_vessel = self._named_vessel()
        self.named_submersible = self._name_says(_SUBMERSIBLE_NAME)
        self.named_airship = self._name_says(_AIRSHIP_NAME)
        # What names the body a rig of sensors (the robot's name, else a kit's link), or None.
        self.named_rig = (
            f"robot name {urdf.name}"
            if _RIG_NAME.search(urdf.name)
            else _rig_on_undeclared_root(urdf)
        )
        # Plugins that say the body works in air by the density they give its medium.
        self.air_plugins = self._air_plugins()
        self.spaceborne = self._spaceborne()
        self.marine = not self.spaceborne and (
            bool(self.plugins_of("marine") or self.plugins_of("thruster") or self.fixed_thrusters)
            # A plugin only a submerged body runs (a subsea pressure gauge, a DVL): in water.
            or bool(self.plugins_of("underwater"))
            or any(self.matches("thruster", joint) for joint in urdf.joints if joint.movable)
            # A craft named for the water (a boat, an ASV, an AUV): its propellers push it.
            or self.named_vessel
            or self.named_submersible
        )
        # A plugin that names a joint outright speaks before a force plugin pushing its link.
        self.named = {**self._pushed_thrusters(), **self._named_by_plugins()}

    def _spaceborne(self) -> bool:
        """A craft its thrusters fly in air or space, no name of a boat or a submersible: beside
        a space plugin (a reaction wheel, air or cold-gas thrusters) and nothing of water, or
        given air's density (:meth:`_air_plugins`), whatever plugin damps the body (a
        hydrodynamics plugin as an aircraft's drag). Its thrusters do not put it in water."""
        if not (self.plugins_of("thruster") or self.fixed_thrusters):
            return False
        if self.named_vessel or self.named_submersible:
            return False
        if self.air_plugins:
            return True
        water = self.plugins_of("marine") or self.plugins_of("underwater")
        return bool(self.plugins_of("space")) and not water

    def _air_plugins(self) -> tuple[PluginTag, ...]:
        """The plugins that give the density of the medium they work in (a thruster plugin's
        ``<fluid_density>``, a lift and drag plugin's ``<air_density>``, a buoyancy or
        hydrodynamics plugin's water density), when a thruster plugin gives one and every
        density given is air's, above nothing and under :data:`_AIR_DENSITY` (an aircraft's
        thrusters at 1.204 kg/m³, its wings' lift at 1.225); none when one is water's (a
        submersible's thrusters and fins at 1000 or more; a sailboat's sail in air, its hull in
        water) or no thruster gives its own (a sail's lift alone says nothing of them)."""
        given = [(p, p.numbers(*_DENSITY_TAGS)) for p in self.urdf.plugins]
        given = [(p, values) for p, values in given if values]
        thrusters = {id(p) for p in self.plugins_of("thruster")}
        if not any(id(p) in thrusters for p, _ in given):
            return ()
        if not all(0 < value < _AIR_DENSITY for _, values in given for value in values):
            return ()
        return tuple(p for p, _ in given)

    def _name_says(self, words: re.Pattern[str]) -> bool:
        """The robot's own name holds one of ``words`` and no flight plugin flies it."""
        return bool(words.search(self.urdf.name)) and not self.plugins_of("flight")

    def _named_vessel(self) -> bool:
        """The robot's own name is a surface craft's (:data:`_VESSEL_NAME`: ``boat``, ``sailboat``,
        ``asv``, ``catamaran``, as whole words), and no flight plugin flies it nor a sensor of a
        body below the water (a DVL, a depth gauge) dives it."""
        if not self._name_says(_VESSEL_NAME):
            return False
        below = self.profile.plugin_pattern("underwater")
        return below is None or not any(
            below.search(f"{sensor.type} {sensor.device_text}") for sensor in self.urdf.sensors
        )

    def _fixed_thrusters(self) -> tuple[str, ...]:
        """Thruster-named leaf links fixed to the root's part, at least ``min_rotors`` of them (a
        vehicle trimmed of its propellers, moved by a plugin that pushes the hull): in water."""
        leaves = [
            joint
            for joint in self.urdf.joints
            if joint.type == "fixed"
            and not self.urdf.children(joint.child)
            and self.matches("thruster", joint)
        ]
        if len(leaves) < self.profile.limb("min_rotors"):
            return ()
        found = tuple(joint.child for joint in leaves if joint.parent in self.still)
        return found if len(found) >= self.profile.limb("min_rotors") else ()

    @cached_property
    def still(self) -> frozenset[str]:
        """Links no movable joint moves (the root's part), in one walk from the root."""
        return frozenset((self.urdf.root, *self.urdf.fixed_below(self.urdf.root)))

    def _plugin_parts(self, plugin: PluginTag, said: frozenset[str]) -> frozenset[str]:
        """What ``plugin`` is: the parts its words say (``said``), and what its entries and
        parameters show whatever it is called."""
        found = set(said)
        # A plugin that lists thruster entries drives thrusters, whatever it is called (a
        # floating body's controller with a <thruster> per propeller).
        thruster = self.profile.plugin_pattern("thruster")
        if thruster is not None and any(thruster.search(group) for group in plugin.groups):
            found.add("thruster")
        # One that lists rotor entries and no thruster flies the body, whatever it is called (a
        # quadrotor's own thrust model with a <rotors> entry per propeller link, as Gazebo's
        # multicopter control lists a <rotor> per motor), when no plugin says water.
        elif not self.water_plugins and any(_ROTOR_ENTRY.fullmatch(g) for g in plugin.groups):
            found.add("flight")
            found.discard("thruster")
        # A plugin that gives a wheel spacing and a wheel size drives wheels, whatever it is
        # called (a robot's own drive plugin, ``<wheelSeparation>`` and ``<wheelDiameter>``).
        tags = _tags(plugin)
        if _wheel_geometry(tags):
            found.add("drive")
        # One that takes a command topic of velocities (``<commandTopic>ropod/cmd_vel``) moves
        # the body on them, whatever it is called (a robot's own holonomic drive), unless a
        # plugin says water (a vessel's or a vehicle's thrusters take them too).
        if not self.water_plugins and any(
            _plain(tag) in _COMMAND_TOPICS and _VELOCITY_TOPIC.fullmatch(text.rsplit("/", 1)[-1])
            for tag, text in plugin.params
        ):
            found.add("drive")
        # A plugin that names a left and a right track, each a link of the body, moves the body
        # on them, whatever it is called (a tracked wheelchair's ``libsimple.so``).
        if tags >= _TRACK_SIDES and self._names_links(plugin, _TRACK_SIDES):
            found.add("track")
        if "flight" in found:
            found.discard("drive")  # a multicopter's velocity control flies it
        return frozenset(found)

    def _names_links(self, plugin: PluginTag, tags: frozenset[str]) -> bool:
        """Every parameter of ``plugin`` whose tag is one of ``tags`` names a link of the body."""
        return all(
            self.urdf.link(text.strip()) is not None
            for tag, text in plugin.params
            if _plain(tag) in tags
        )

    def plugins_of(self, part: str) -> list[PluginTag]:
        """The model plugins whose file name (or name, when none) the profile reads as ``part``."""
        return [p for p in self.urdf.plugins if part in self.plugin_parts[id(p)]]

    def plugin_label(self, plugin: PluginTag) -> str:
        return plugin.filename or plugin.name

    def _named_by_plugins(self) -> dict[str, Role]:
        """Joints a plugin names in a parameter, with the role that plugin gives them."""
        found: dict[str, Role] = {}
        for part, role in _PLUGIN_ROLES:
            for plugin in self.plugins_of(part):
                label = self.plugin_label(plugin)
                for tag, joint in self._joints_named(part, plugin):
                    if joint in found:
                        continue
                    kind = "steering" if role == "wheel" and "steer" in tag.lower() else role
                    why = f"<{tag}> of {part} plugin {label}"
                    if kind == "fin" and self._spins(joint):
                        # Lift and drag on a joint that turns without limits: a propeller's
                        # blade (how Gazebo models rotors), not a control surface's travel.
                        kind, why = "rotor", why + ", turning without limits (a propeller)"
                    found[joint] = Role(joint, kind, why)
        return found

    def _joints_named(self, part: str, plugin: PluginTag) -> Iterator[tuple[str, str]]:
        """The movable joints ``plugin`` (read as ``part``) names, each with the parameter's tag:
        by their names; a thruster plugin may list its thrusters, a grasp plugin its fingers,
        by the links they move (a hull's thruster list, ``<gripper_link>``, not the grasp
        plugin's ``<palm_link>``). A drive plugin known by its wheel geometry alone names its
        wheels by side."""
        drive = self.profile.plugin_pattern("drive")
        by_geometry = part == "drive" and not (drive and drive.search(_said(plugin)))
        for tag, text in plugin.params:
            if by_geometry and not _WHEEL_TAG.search(tag):
                continue
            if part == "grasp" and "gripper" not in tag.lower():
                continue
            joint = self.urdf.joint(text)
            if (joint is None or not joint.movable) and part in _BY_LINK:
                joint = self.urdf.parent_joint(text)  # the joint that moves the link named
            if joint is not None and joint.movable:
                yield tag, joint.name

    def _pushed_thrusters(self) -> dict[str, Role]:
        """On a body in water, the joint whose link a force plugin pushes on command (its
        ``<link_name>``): a thruster, when it is a swivel or a spin (revolute or continuous) on
        the hull itself and no fin's or wing's (not an arm's last link, a float's heave, a
        rudder a current pushes)."""
        if not self.marine:
            return {}
        found: dict[str, Role] = {}
        for plugin in self.plugins_of("force"):
            label = self.plugin_label(plugin)
            for tag, text in plugin.params:
                joint = self.urdf.parent_joint(text)
                if (
                    joint is None
                    or not joint.movable
                    or joint.name in found
                    or joint.type not in _ROTATING
                    or joint.parent not in self.still
                    or self.matches("fin", joint)
                    or self.matches("wing", joint)
                ):
                    continue
                why = f"<{tag}> of force plugin {label}: a link it pushes, on a body in water"
                found[joint.name] = Role(joint.name, "thruster", why)
        return found

    def _spins(self, name: str) -> bool:
        """The joint turns without limits (continuous): it spins, it does not deflect."""
        joint = self.urdf.joint(name)
        return joint is not None and joint.type == "continuous" and not self.marine

    def matches(self, part: str, joint: Joint) -> bool:
        return part in self.parts_of(joint.name) or part in self.parts_of(joint.child)

    def read(self, joint: Joint, moving_below: set[str]) -> Role | None:
        """The single-joint role of ``joint``, or ``None`` (a limb joint, or fixed)."""
        if joint.type == "floating":
            return self._posed(joint)
        if not joint.movable or joint.type not in (*_ROTATING, "prismatic"):
            return None
        named = self.named.get(joint.name)
        if named is not None:
            return named
        if joint.type in _ROTATING:
            role = self._by_name(joint, joint.child in moving_below, moving_below)
            if role is not None:
                return role
        own = self.parts_of(joint.name)
        # A joint whose own name says it is an arm joint (left_wrist_roll_joint into
        # left_hand_roll_link) stays one.
        arm_joint = "arm" in own and "gripper" not in own
        if (self.matches("gripper", joint) or self.on_palm(joint)) and not arm_joint:
            return Role(joint.name, "gripper", self._named("gripper", joint))
        return None

    def _by_name(self, joint: Joint, carries: bool, moving_below: set[str]) -> Role | None:
        if self.matches("thruster", joint):
            return Role(joint.name, "thruster", self._named("thruster", joint))
        if self.marine and self.matches("rotor", joint) and not carries:
            return Role(joint.name, "thruster", self._named("rotor", joint) + " on a body in water")
        # A control surface deflects within limits; a wing or fin on a joint that turns without
        # limits flaps or spins (a toy's wings on a wheeled base, a propeller named for a wing).
        if (
            not carries
            and (self.matches("fin", joint) or self.matches("wing", joint))
            and not self._spins(joint.name)
        ):
            part = "fin" if self.matches("fin", joint) else "wing"
            return Role(joint.name, "fin", self._named(part, joint) + " (a control surface)")
        if self.matches("caster", joint) and self._rolls_on(joint, moving_below):
            return Role(joint.name, "caster", self._named("caster", joint))
        # Wheels first: a wheel's motor link may be named *_rotor.
        if self.matches("wheel", joint):
            return Role(joint.name, "wheel", self._named("wheel", joint))
        # A gripper's part first: an arm's gripper servo horn may be named *_prop_link.
        if self.matches("rotor", joint) and not carries and not self.matches("gripper", joint):
            return Role(joint.name, "rotor", self._named("rotor", joint) + ", a spinning leaf")
        if carries or not joint.endless:
            return None
        return self._by_turned_part(joint)

    def _by_turned_part(self, joint: Joint) -> Role | None:
        """An endless joint carrying nothing that moves, by the named part fixed below it."""
        propeller = self._turns(joint, "rotor")
        if propeller is not None:
            kind = "thruster" if self.marine else "rotor"
            return Role(joint.name, kind, f"turns the propeller-named link {propeller} fixed to it")
        # A rim turning the tyre fixed to it (a CAD export naming only the tyre), the rim named
        # by its corner (``front_left_rim``: the leg pattern's corners name no part here). Not
        # a body's own joint carrying a wheel-named link (a planar base's yaw).
        corner = frozenset({"leg"})
        tyre = self._turns(joint, "wheel", also=corner)
        if tyre is not None and self.parts_of(joint.child) & {"wheel", *corner}:
            return Role(joint.name, "wheel", f"turns the wheel-named link {tyre} fixed to it")
        return None

    def _turns(self, joint: Joint, part: str, also: frozenset[str] = frozenset()) -> str | None:
        """The ``part``-named link fixed below ``joint``'s child (an axle carrying its
        propeller, a rim its tyre), when no link fixed there names another part than ``part``
        and ``also`` (a car's hub carries its wheel and a brake rotor): what the joint turns
        (the first found, walking down from the child)."""
        found = None
        for link in self.urdf.fixed_below(joint.child):
            parts = self.parts_of(link)
            if parts - {part, *also}:
                return None
            if found is None and part in parts:
                found = link
        return found

    def _rolls_on(self, joint: Joint, moving_below: set[str]) -> bool:
        """All that moves below ``joint`` is endless joints with nothing moving beyond them (a
        caster's wheel), or nothing: a swivel carrying a finger is no caster."""
        return all(
            below.child not in moving_below and (not below.movable or below.type == "continuous")
            for below in self.urdf.children(joint.child)
        )

    def _posed(self, joint: Joint) -> Role | None:
        """A propeller on a ``floating`` joint with nothing below it: a visual part a simulator
        poses (it turns it), a rotor however few there are."""
        if self.urdf.children(joint.child) or not self.matches("rotor", joint):
            return None
        if self.marine:
            return Role(joint.name, "thruster", self._named("rotor", joint) + " on a body in water")
        return Role(joint.name, "rotor", self._named("rotor", joint) + POSED)

    def on_palm(self, joint: Joint) -> bool:
        """A movable joint on a link named as a hand or palm moves a finger."""
        return "gripper" in self.parts_of(joint.parent)

    def _moved(self, link: str) -> bool:
        """Some movable joint above ``link`` moves it (it is not on the base)."""
        return link not in self.still

    def _named(self, part: str, joint: Joint) -> str:
        where = joint.name if part in self.parts_of(joint.name) else f"its link {joint.child}"
        return f"{part} name ({where})"

    def casters(self, wheels: dict[str, Role]) -> dict[str, Role]:
        """Swivels on the base that carry one wheel and nothing else, and their wheels: passive
        casters. A swivel a drive plugin names steers; one at the end of a leg is the leg's.
        """
        found: dict[str, Role] = {}
        for name, role in wheels.items():
            wheel = self.urdf.joint(name)
            if wheel is None or role.role != "wheel" or name in self.named:
                continue
            swivel = self.urdf.parent_joint(wheel.parent)
            if (
                swivel is None
                or swivel.type not in _ROTATING
                or not swivel.movable
                or main_axis(local_axis(swivel)) != _Z
                or len([j for j in self.urdf.children(wheel.parent) if j.movable]) != 1
            ):
                continue
            if swivel.name in self.named or self._moved(swivel.parent):
                continue  # a swivel at the end of a leg steers the leg's wheel
            found[swivel.name] = Role(
                swivel.name, "caster", f"a vertical swivel carrying only the wheel {name}"
            )
            found[name] = Role(name, "caster", f"the wheel of the caster swivel {swivel.name}")
        return found
