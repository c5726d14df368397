"""How the body moves as a whole: on the ground, in the air, in water.

Beside the joints' own roles (:mod:`solver.identify.actuation`), the description shows how the
body travels in a few more ways, each read here:

* *Ground*: tracks (a track plugin or track names); a body that rolls on wheels, casters,
  tracks or a drive plugin is grounded (:func:`grounded`).
* *Air*: wings and control surfaces (fixed links, or fin joints named so); flight words in a
  model plugin's parameters (a vehicle plugin of its own), not on a body that rolls or walks,
  or in the robot's name when the body is bare (no movable joint, plugin or sensor: an
  aircraft exported as one mesh); rotor-named joints too few to fly, said as such.
* *Water*: thrusters a thruster plugin lists by a link no joint moves (a hull's list), and
  thruster-named leaf links fixed to the hull, two or more (propellers left out); rotors by
  their names that all turn about level axes on a body with no wheel or wing, two or more,
  which push it along and lift nothing (a boat's outboards: :func:`pushing_rotors`); hints
  of a hull at the surface (a surface plugin, ``<metacentric_width>``; a body whose buoyancy
  compensation, buoyancy over weight, has a hull's reserve (1.1 or more): it floats; a GPS or
  a lidar where nothing says the body dives: satellites are heard and laser light carries only
  above the water) or of a body below it (hydrodynamics or underwater-object plugins, a DVL or
  pressure sensor); the robot's name (``sailboat``) when nothing else says how the body
  travels.
  Buoyancy says only that the body is in water.
* *Trimmed models*: wheel joints of type fixed, and rotor-named leaf links fixed to the body
  (motor-named ones too, on a body where no joint moves), still say what the whole model does
  (read with doubt by :mod:`solver.identify.classifier`).

Not here: the joints' own roles (:mod:`solver.identify.actuation`), where the body is placed
(:mod:`solver.identify.placement`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Collection, Sequence
from itertools import islice

from solver.identify.actuation import MOTOR, mirrored_across, with_role
from solver.identify.limbs import Limb, moved_by
from solver.identify.pose import Vector, parallel, perpendicular
from solver.identify.readers.urdf import Cylinder, Joint
from solver.identify.roles import Role
from solver.identify.sensors import element_kind, plugin_kind
from solver.identify.tree import JointTree

__all__ = [
    "fixed_rotors",
    "fixed_thrusters",
    "fixed_wheels",
    "flight_hints",
    "grounded",
    "listed_thrusters",
    "not_rotors",
    "propellers",
    "pushing_rotors",
    "surface_hints",
    "tracks",
    "underwater_hints",
    "vessel_name",
    "water_frames",
    "wings",
]

_ROTATING = ("continuous", "revolute")
# A propeller drawn as a disc: a cylinder at least this many times as wide (its radius) as it
# is thick; discs alike are within this share of one radius; a multirotor has at least three
# and at most sixteen (a stranger's thousands of discs are read as none).
_DISC = 2.0
_DISC_SPREAD = 0.1
_FEWEST_DISCS = 3
_MOST_DISCS = 16
# A wing drawn as a board: a box, as the body rests, at least this many times as wide across
# the body (its span) as it is long along it (its chord), and its chord at least this many
# times its thickness (a bar, a bumper or a sensor rail is as thick as it is long).
_SPAN_OVER_CHORD = 3.0
_CHORD_OVER_THICKNESS = 3.0
# Parts whose fixed joints say a body stands on the ground, whatever discs it has.
_NOT_ROTORS = ("wheel", "caster", "track", "leg")
# A plugin that sets a body's twist in space (Gazebo Sim's VelocityControl), air or ground alike.
_VELOCITY_CONTROL = re.compile(r"velocity[_-]?control", re.IGNORECASE)
_PLANAR_MOVE = re.compile(r"planar[_-]?move", re.IGNORECASE)
_GPS = re.compile(r"gps|navsat|gnss", re.IGNORECASE)
# Buoyancy over weight a hull floats with: a surface hull carries a reserve (measured on the
# development part: 1.2 to 12.5); a submersible is trimmed a hair above neutral (1.01, so it
# rises when its thrusters stop) and works below the surface.
_HULL_RESERVE = 1.1
# Gazebo's contact and friction settings of a collision (``<surface><friction>``, the contact
# layer): every simulated body has them, afloat or not; no word of a hull at the surface.
_CONTACT_SETTINGS = frozenset({"surface", "contact_surface_layer"})


def grounded(tree: JointTree, roles: dict[str, Role]) -> bool:
    """The body moves on the ground: wheels, casters, tracks or a drive plugin."""
    return bool(
        with_role(roles, "wheel")
        or with_role(roles, "caster")
        or tracks(tree)
        or tree.labels("drive")
    )


def tracks(tree: JointTree) -> tuple[str, ...]:
    """Track plugins and track-named joints (:meth:`JointTree.tread`), each once."""
    found = list(tree.labels("track"))
    found += [j.name for j in tree.urdf.joints if tree.tread(j)]
    return tuple(dict.fromkeys(found))


def not_rotors(tree: JointTree, roles: dict[str, Role]) -> list[str]:
    """Rotor-named spinning leaves left without a role: too few to fly."""
    return [
        j.name
        for j in tree.urdf.joints
        if j.movable
        and j.type in _ROTATING
        and j.name not in roles
        and tree.matches("rotor", j)
        and not tree.matches("wheel", j)
        and j.child not in tree.moving_below
    ]


def listed_thrusters(tree: JointTree, roles: dict[str, Role]) -> list[str]:
    """Thrusters a thruster plugin lists by a link of no moving joint (a hull's list)."""
    links = {link.name for link in tree.urdf.links}
    found = []
    for plugin in tree.reader.plugins_of("thruster"):
        named = [text for tag, text in plugin.params if text in links]
        joints = [tree.urdf.parent_joint(link) for link in named]
        if not any(j is not None and j.name in roles for j in joints):
            found += [f"{link} ({tree.reader.plugin_label(plugin)})" for link in named][:1]
    return found


def fixed_thrusters(tree: JointTree) -> list[str]:
    """Thruster-named leaf links fixed to the hull, two or more (a vehicle trimmed of its
    propellers, a plugin pushing the hull), when no thruster plugin lists them: in water, by
    thruster names alone."""
    if tree.reader.plugins_of("thruster"):
        return []
    return [f"{link} (fixed)" for link in tree.reader.fixed_thrusters]


def fixed_wheels(tree: JointTree, roles: dict[str, Role]) -> list[str]:
    """Wheel joints of type fixed (a trimmed model), when no wheel turns; not on a body bolted
    to the world (its root is ``world`` and no joint moves between it and the wheel: a cart's
    casters under a table the model fixes in place)."""
    if with_role(roles, "wheel"):
        return []
    return [
        j.name
        for j in tree.urdf.joints
        if j.type == "fixed" and tree.matches("wheel", j) and j.parent not in tree.bolted
    ]


def fixed_rotors(tree: JointTree) -> list[str]:
    """Rotor-named leaf links fixed to a part no joint moves (a trimmed multirotor); on a body
    where nothing moves, leaf links drawn as propeller discs side by side, whatever their
    names (:func:`_discs`).

    Not on a body with legs or wheels: there a fixed ``*_rotor`` link is a motor's; nor a
    wheel-named link, fixed wherever (a trimmed ground base's wheel below its motor link,
    ``front_left_motor_link_to_front_left_wheel_link``, its joint named for both links).
    """
    legs_or_wheels = any(
        j.movable and (tree.matches("leg", j) or tree.matches("wheel", j)) for j in tree.urdf.joints
    )
    if tree.reader.marine or legs_or_wheels:
        return []
    on_the_hull = tree.reader.still  # links no movable joint moves
    # On a body where nothing moves, a motor fixed at a leaf turns what the model leaves out:
    # a wheel would be modelled (a wheel link), so it is a propeller's (a quadcopter of fixed
    # arm and motor links that a force plugin moves).
    still = not any(j.movable for j in tree.urdf.joints)
    leaves = [
        j
        for j in tree.urdf.joints
        if j.type == "fixed" and not tree.urdf.children(j.child) and not tree.matches("wheel", j)
    ]
    found = [
        j.name
        for j in leaves
        if j.parent in on_the_hull
        and (tree.matches("rotor", j) or (still and MOTOR.search(f"{j.name} {j.child}")))
    ]
    if still and len(found) < tree.profile.limb("min_rotors"):
        found = _discs(tree, on_the_hull)
    if _ride_on_modules(tree, leaves, on_the_hull, len(found)):
        return []
    return found if len(found) >= tree.profile.limb("min_rotors") else []


def _ride_on_modules(
    tree: JointTree, leaves: list[Joint], on_the_hull: Collection[str], found: int
) -> bool:
    """As many rotor-named ``leaves`` (fixed leaf joints) or more are fixed to links that joints
    move as to the hull: the parts every module of a chain carries (a screw-driven snake's
    `propeller_<n>` on each unit, fresh set 1862), not a trimmed multirotor's rotors, which all
    sit on its hull."""
    riding = sum(1 for j in leaves if j.parent not in on_the_hull and tree.matches("rotor", j))
    return found > 0 and riding >= found


def _discs(tree: JointTree, on_the_hull: Collection[str]) -> list[str]:
    """Leaf joints fixed to the hull whose links are drawn as propeller discs
    (:func:`_thin`, turning about the vertical), at least :data:`_FEWEST_DISCS` of them, laid
    out as rotors are (:func:`_rotor_layout`); none when more than :data:`_MOST_DISCS` thin
    cylinders hang there (read no further: no pose is worked out). None on a body with fixed
    wheels, casters, tracks or legs (a trimmed ground robot's round brushes, a table's pads)."""
    sensed = {tag.link for tag in tree.urdf.sensors if tag.link is not None}
    thin: list[tuple[Joint, Cylinder]] = []
    for joint in tree.urdf.joints:
        shape = _thin(tree, joint, on_the_hull, sensed)
        if shape is not None:
            thin.append((joint, shape))
            if len(thin) > _MOST_DISCS:
                return []
    up = (0.0, 0.0, 1.0)
    discs = [
        (joint.name, shape.radius, _disc_place(tree, joint.child, shape))
        for joint, shape in thin
        if parallel(tree.poses.turned(joint.child, shape.rpy, up), up)
    ]
    if len(discs) < _FEWEST_DISCS or not _rotor_layout(discs) or _stands(tree):
        return []
    return [name for name, _, _ in discs]


def _thin(
    tree: JointTree, joint: Joint, on_the_hull: Collection[str], sensed: set[str]
) -> Cylinder | None:
    """The cylinder ``joint``'s link is drawn as, when the joint is a leaf fixed to the hull
    and the link (no sensor's) a cylinder at least :data:`_DISC` times as wide (radius) as it
    is thick; else None."""
    link = tree.urdf.link(joint.child)
    shape = None if link is None else link.cylinder
    if (
        shape is None
        or joint.type != "fixed"
        or tree.urdf.children(joint.child)
        or joint.parent not in on_the_hull
        or joint.child in sensed
        or shape.radius < _DISC * shape.length
    ):
        return None
    return shape


def _disc_place(tree: JointTree, link: str, shape: Cylinder) -> Vector:
    at = tree.poses.place(link)
    offset = tree.poses.turned(link, (0.0, 0.0, 0.0), shape.xyz)
    return (at[0] + offset[0], at[1] + offset[1], at[2] + offset[2])


def _rotor_layout(discs: list[tuple[str, float, Vector]]) -> bool:
    """The discs are all of one size (radii within :data:`_DISC_SPREAD`), at one height
    (within a radius) and not below the body's frame (feet, pads), side by side (none over
    another: a stack of plates is no rotor) and not all on one line (a row of plates, antennas
    on a bar)."""
    radii, heights = [r for _, r, _ in discs], [p[2] for _, _, p in discs]
    radius = min(radii)
    alike = max(radii) <= (1 + _DISC_SPREAD) * radius and max(heights) - min(heights) <= radius
    apart = all(
        math.dist(one[2][:2], other[2][:2]) >= radius
        for at, one in enumerate(discs)
        for other in discs[at + 1 :]
    )
    (x0, y0, _), (x1, y1, _) = discs[0][2], discs[1][2]
    spread_out = any(
        abs((x1 - x0) * (p[1] - y0) - (y1 - y0) * (p[0] - x0)) >= radius * radius
        for _, _, p in discs[2:]
    )
    return alike and apart and spread_out and min(heights) >= -radius


def _stands(tree: JointTree) -> bool:
    """A fixed joint named as a wheel's, a caster's, a track's or a leg's: a body on the
    ground, a trimmed model of one."""
    return any(
        j.type == "fixed" and any(tree.matches(part, j) for part in _NOT_ROTORS)
        for j in tree.urdf.joints
    )


def wings(tree: JointTree, roles: dict[str, Role]) -> list[str]:
    """Wings and ailerons (fixed links, or fin joints named so) and, beside a wing, fixed
    control surfaces (a tail, a rudder); with none of them, boards beside a propeller
    (:func:`propellers`)."""
    if tree.reader.marine:
        return []
    found = _named_wings(tree, roles)
    if found:
        return found
    return _boards(tree) if _pulled_along(tree, roles) else []


def pushing_rotors(tree: JointTree, roles: dict[str, Role]) -> dict[str, Role]:
    """Rotors by their names, two or more (the profile's ``min_rotors``), each turning for ever
    about a level axis written (URDF's default axis, x, says nothing, nor a CAD export's
    placeholder limits) as the body rests, each on an engine that swivels about the upright on
    the hull and carries nothing else that moves (:func:`_on_an_outboard`), or some two of them
    square to each other (:func:`_push_many_ways`), on a body with no
    wheel (turning, or fixed: a trimmed model's gear, :func:`fixed_wheels`), no wing (:func:`wings`,
    or any link named so), no flight plugin and neither an aircraft's nor an airship's name:
    a boat's outboards, which push it along and lift nothing, so they are thrusters. A
    multirotor's rotors sit on its frame (an export drawn with y up turns them level), a
    plane's on fixed nacelles beside its wings, an arm's or a leg's motor rotors on links that
    carry the next joint."""
    names = with_role(roles, "rotor")
    rotors = [j for j in map(tree.urdf.joint, names) if j is not None]
    if (
        len(rotors) < max(len(names), tree.profile.limb("min_rotors"))
        or any(
            not (j.endless and j.axis_written) or abs(tree.poses.axis(j)[_UP]) > _LEVEL_AXIS
            for j in rotors
        )
        or _flies_or_rolls(tree, roles)
    ):
        return {}
    if all(_on_an_outboard(tree, j) for j in rotors):
        why = (
            "named as a rotor, but turning about a level axis on an engine that swivels about "
            "the upright, on a body with no wheel or wing: it pushes the body along, lifting "
            "nothing (a boat's outboard)"
        )
    elif _push_many_ways(tree, roles, rotors):
        why = (
            "named as a rotor, but turning about a level axis square to another's, on a body "
            "with no wheel or wing: they push the body every way on the level, lifting nothing "
            "(a vessel's thrusters set around its hull)"
        )
    else:
        return {}
    return {j.name: Role(j.name, "thruster", why) for j in rotors}


def _flies_or_rolls(tree: JointTree, roles: dict[str, Role]) -> bool:
    """The body is an aircraft's or stands on wheels: a flight plugin, an airship's or an
    aircraft's name, a wheel (turning, or fixed: a trimmed model's gear), a wing (named, or a
    link named so)."""
    flight = tree.profile.plugin_pattern("flight")
    return bool(
        tree.labels("flight")
        or tree.reader.named_airship
        or (flight is not None and flight.search(tree.urdf.name))
        or with_role(roles, "wheel")
        or fixed_wheels(tree, roles)
        or any("wing" in tree.parts_of(link.name) for link in tree.urdf.links)
        or wings(tree, roles)
    )


def _push_many_ways(tree: JointTree, roles: dict[str, Role], rotors: Sequence[Joint]) -> bool:
    """Three level rotors or more, some two square to each other, each on the hull (no joint
    moves it), all at one height (they spread over the upright at most :data:`_FLAT` of their
    spread on the level), on a body that neither goes on the ground nor walks: they push the
    hull every way on the level, as a vessel's thrusters set around it do. A multirotor drawn
    with y up turns its rotors level too, but all along one line (its up), and a helicopter's
    or a quadplane's drawn so spread over the upright (its up, again); a vectored airship's
    swing on mounts; a walker's or a tracked base's fans, a cube's momentum wheels are one or
    two. More than :data:`_MOST_THRUSTERS` are no hull's, and are not compared pair by pair."""
    if not _MANY_WAYS <= len(rotors) <= _MOST_THRUSTERS or grounded(tree, roles):
        return False
    if any(j.movable and tree.matches("leg", j) for j in tree.urdf.joints):
        return False
    if any(j.parent not in tree.reader.still for j in rotors):
        return False
    places = [tree.poses.place(j.child) for j in rotors]
    ups = [place[_UP] for place in places]
    spread = max(math.dist(one[:2], other[:2]) for one in places for other in places)
    if max(ups) - min(ups) > _FLAT * spread:
        return False
    axes = [tree.poses.axis(j) for j in rotors]
    return any(perpendicular(one, other) for at, one in enumerate(axes) for other in axes[at + 1 :])


# Rotors that push a hull every way: three at least (one or two on a body are fans or momentum
# wheels); and how far over the upright they may spread, as a part of their spread on the level.
_MANY_WAYS = 3
_FLAT = 0.25
# A vessel's thrusters are a few (the sets' have four to eight): past this many, a stranger's
# thousands of level rotors are no hull's, not compared pair by pair (a bound on the work).
_MOST_THRUSTERS = 16


def _on_an_outboard(tree: JointTree, rotor: Joint) -> bool:
    """``rotor`` turns on an engine: the nearest movable joint above it swivels about the
    upright, hangs from the hull (no movable joint above it) and moves nothing but ``rotor``."""
    known: dict[str, str | None] = {}
    name = moved_by(tree.urdf, rotor.parent, known)
    engine = None if name is None else tree.urdf.joint(name)
    if engine is None or engine.type not in _ROTATING:
        return False
    if abs(tree.poses.axis(engine)[_UP]) < 1 - _LEVEL_AXIS:
        return False
    if moved_by(tree.urdf, engine.parent, known) is not None:
        return False
    # Two movable joints at most are looked for (a big subtree below is walked no further).
    moving = list(islice((j for j in tree.urdf.subtree_joints(engine.child) if j.movable), 2))
    return [j.name for j in moving] == [rotor.name]


# The up part of a unit axis at most this far from level (about 11 degrees) is level.
_UP = 2
_LEVEL_AXIS = 0.2


def _named_wings(tree: JointTree, roles: dict[str, Role]) -> list[str]:
    """Wings and ailerons named so or told by their hinges, and the fixed control surfaces
    beside them; none without a wing."""
    fixed = [j for j in tree.urdf.joints if not j.movable]
    found = [j.child for j in fixed if "wing" in tree.parts_of(j.child)]
    found += [
        n for n in with_role(roles, "fin") if (j := tree.urdf.joint(n)) and tree.matches("wing", j)
    ]
    found += _ailerons(tree, roles, found)
    surfaces = [j.child for j in fixed if "fin" in tree.parts_of(j.child)]
    return found + surfaces if found else []


def propellers(tree: JointTree, roles: dict[str, Role]) -> list[str]:
    """Endless leaves of no role on the hull (a part no joint moves) turning about the body's
    long axis as it rests (level, along x), beside a wing drawn as a board (:func:`_boards`):
    a plane's propellers, pulling or pushing it along, whatever their names. None on a body in
    water (a ship's screws turn so) or where a wing is named (that wing says it flies)."""
    if tree.reader.marine:
        return []
    pulled = _pulled_along(tree, roles)  # the cheapest test first: most bodies have none
    return pulled if pulled and not _named_wings(tree, roles) and _boards(tree) else []


def _pulled_along(tree: JointTree, roles: dict[str, Role]) -> list[str]:
    """The joints :func:`propellers` reads, whether or not a board is beside them."""
    on_the_hull = tree.reader.still
    along = (1.0, 0.0, 0.0)
    return [
        joint.name
        for joint in tree.urdf.joints
        if joint.name not in roles
        and joint.endless
        and joint.parent in on_the_hull
        and joint.child not in tree.moving_below
        and parallel(tree.poses.axis(joint), along)
    ]


def _boards(tree: JointTree) -> list[str]:
    """Links on the hull drawn as a box that, as the body rests, spans the body (across, y)
    :data:`_SPAN_OVER_CHORD` times its chord (along, x) and whose chord is
    :data:`_CHORD_OVER_THICKNESS` times its thickness (upright, z): a wing, a tailplane, drawn
    as a board. A fin stands upright, a bumper or a sensor bar is as thick as it is long."""
    found = []
    for name in sorted(tree.reader.still):
        link = tree.urdf.link(name)
        box = None if link is None else link.box
        if box is None:
            continue
        along, across, upright = tree.poses.extent(name, box.rpy, box.size)
        if across >= _SPAN_OVER_CHORD * along and along >= _CHORD_OVER_THICKNESS * upright:
            found.append(name)
    return found


def _ailerons(tree: JointTree, roles: dict[str, Role], found: list[str]) -> list[str]:
    """Control-surface joints (fins) that are a wing's ailerons whatever their names: a pair
    mirrored across the body, turning about axes across it
    (:func:`~solver.identify.actuation.mirrored_across`), with a fin behind them (a rudder or
    an elevator; :func:`solver.identify.actuation.joint_roles` tells an unnamed airframe's
    so). None when a wing is already found."""
    if found:
        return []
    fins = [j for n in with_role(roles, "fin") if (j := tree.urdf.joint(n)) is not None]
    for first, second in mirrored_across(tree, fins):
        ahead = tree.poses.place(first.child)[0]
        if any(tree.poses.place(j.child)[0] < ahead for j in fins):
            return [first.child, second.child]
    return []


def _on_a_hull(tree: JointTree, thrusters: int) -> bool:
    """Something puts the body in water (its plugins or names, or ``thrusters``), and no
    plugin says its thrusters fly it in air or space (RoleReader.spaceborne)."""
    return not tree.reader.spaceborne and (tree.reader.marine or thrusters > 0)


def surface_hints(tree: JointTree, *, thrusters: int = 0) -> tuple[str, ...]:
    """A body in water at the surface: surface plugins, and the words the profile's ``surface``
    pattern reads in the hull's own elements (``<metacentric_width>``, wind on its buoyancy)
    or in the parameters of its water plugins, never in a sensor's settings (a barometer's
    water-surface offset) nor in an underwater plugin's (a buoyancy engine's surface), nor in a
    ``<surface>`` of numbers (where the water's surface lies, :func:`_water_level`); a body
    whose buoyancy compensation has a hull's reserve (it floats). With none of them, and nothing
    of a body below the surface (no plugin, sensor or frame of one), a GPS or a lidar says it:
    satellites are heard, and a laser scans, only above the water; both together say it over
    a submersible's water plugin, though over nothing else that dives it
    (:func:`_heard_and_scanned`). ``thrusters``: how many
    thrusters the body has; any (an unnamed pair of screws, :mod:`solver.identify.actuation`)
    put it in water though no plugin or name says so. The robot's name as a surface craft's
    (``sailboat``, ``asv``, ``catamaran``, whole words; ``RoleReader.named_vessel``) floats a
    body in water whatever its water plugins are also used for (a hydrodynamics plugin moves
    hulls at the surface too), unless a flight plugin or a DVL or depth sensor says otherwise."""
    pattern = tree.profile.plugin_pattern("surface")
    if pattern is None or not _on_a_hull(tree, thrusters):
        return ()
    hints = list(tree.labels("surface"))
    if tree.reader.named_vessel:  # a boat, a catamaran, an ASV: a hull at the surface
        hints.append(f"robot name {tree.urdf.name}")
    hints += sorted(
        tag for tag in tree.urdf.tags if pattern.search(tag) and tag not in _CONTACT_SETTINGS
    )
    below = {id(plugin) for plugin in tree.reader.plugins_of("underwater")}
    for part in ("marine", "thruster", "surface"):
        for plugin in tree.reader.plugins_of(part):
            if id(plugin) in below:
                continue  # a diver's plugin names the surface it rises to, not a hull on it
            hints += sorted(
                {
                    tag.lower()
                    for tag, text in plugin.params
                    if pattern.search(tag) and not _water_level(tag, text)
                }
            )
    hints += _floating_hull(tree)
    if not hints and not _dives_but_by_plugins(tree):
        hints += _heard_and_scanned(tree)
    if not hints and not underwater_hints(tree) and not water_frames(tree):
        hints += _nothing_dives(tree, thrusters)
    return tuple(dict.fromkeys(hints))


def _nothing_dives(tree: JointTree, thrusters: int) -> list[str]:
    """A body in water that nothing places below or at the surface: a GPS or a lidar on it
    says above water; with no water plugin and no pressure sensor at all (a diver's depth
    gauge is a pressure sensor), its thrusters alone do, with doubt (nothing dives it), when
    they are as few as a surface craft's (a hull's pair, a WAM-V's four): more push the body
    in every direction, up and down too, as a submersible's six or eight do."""
    found = _above_water_sensors(tree)
    if (
        not found
        and thrusters <= _SURFACE_THRUSTERS
        and not any(tree.reader.plugins_of(p) for p in _WATER_PLUGINS)
        and not _pressure_sensor(tree)
    ):
        found = [THRUSTERS_ALONE]
    return found


def _pressure_sensor(tree: JointTree) -> bool:
    """A pressure sensor or plugin, as the profile's sensor rules read them (a barometer in
    air, a depth gauge in water): what an autopilot of a submersible holds its depth with."""
    return any(element_kind(s, tree.profile) in _PRESSURE_KINDS for s in tree.urdf.sensors) or any(
        plugin_kind(p, tree.profile) in _PRESSURE_KINDS for p in tree.urdf.plugins
    )


# In water by its thrusters alone (their names, or screws by place), with no water plugin, no
# sensor or frame of a diver, no name: nothing makes the body dive, so it floats, with doubt (a
# hull with a pair of thrusters, as every such labelled row of the development part is).
THRUSTERS_ALONE = "thrusters alone (no water plugin, DVL or depth gauge)"
# The most thrusters a surface craft has (a twin-hull's pair, a WAM-V's four).
_SURFACE_THRUSTERS = 4
_PRESSURE_KINDS = ("barometer", "pressure")
_WATER_PLUGINS = ("marine", "thruster", "underwater")


def _water_level(tag: str, text: str) -> bool:
    """A plugin's ``<surface>`` holding only numbers (``0 0 40``, ``100.0``): where the water's
    surface lies in the world, a setting of every body in water, afloat or diving."""
    numbers = text.split()
    if tag.lower() != "surface" or not numbers:
        return False
    try:
        [float(number) for number in numbers]
    except ValueError:
        return False
    return True


def _floating_hull(tree: JointTree) -> list[str]:
    """The body (its root link, or a link fixed to it) declares a buoyancy compensation with a
    hull's reserve (``_HULL_RESERVE`` or more): buoyancy over weight, it floats (a part of it, a
    thruster, may sink: not the body), when the whole body keeps that reserve
    (:func:`_afloat`; a hull of no mass written cannot be weighed against the rest: its own
    reserve says it). A body trimmed just above neutral is a submersible's."""
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    hulls = [
        link
        for link in tree.urdf.links
        if link.buoyancy is not None
        and link.buoyancy >= _HULL_RESERVE
        and moved_by(tree.urdf, link.name, known) is None
    ]
    afloat = any(hull.mass is not None for hull in hulls) and _afloat(tree)  # weighed once
    for hull in hulls:
        if hull.mass is None or afloat:
            return [f"{hull.name} buoyancy {hull.buoyancy:g} x weight (floats)"]
    return []


def _afloat(tree: JointTree) -> bool:
    """The whole body has a hull's reserve: its buoyancy over its whole weight, each link's
    buoyancy over weight by its mass (a link that writes none displaces nothing; one a
    hydrodynamics plugin makes neutrally buoyant, its weight), is ``_HULL_RESERVE`` or more.
    A hull's reserve that the arm it carries takes up (a submersible trimmed to neutral with
    its arm) floats nothing."""
    weight = lift = 0.0
    for link in tree.urdf.links:
        if link.mass is not None:
            weight += link.mass
            lift += link.mass * (link.buoyancy or 0.0)
    return lift >= _HULL_RESERVE * weight


def _above_water_sensors(tree: JointTree) -> list[str]:
    """GPS receivers (sensor elements of a satellite type, plugins named so, or a frame fixed
    to the body named so) and lidars (a ray sensor the profile reads as a lidar: it scans in
    air, water absorbs its light)."""
    # A receiver's frame alone, fixed to the hull (a description of frames for a driver's
    # tf): as the DVL's frame says below (:func:`water_frames`), the GPS's says above.
    known: dict[str, str | None] = {}
    frames = [
        f"{link.name} (a GPS frame: heard above water)"
        for link in tree.urdf.links
        if _GPS.search(link.name) and moved_by(tree.urdf, link.name, known) is None
    ]
    return [*_receivers(tree), *_lidars(tree), *frames][:1]


def _heard_and_scanned(tree: JointTree) -> list[str]:
    """A GPS receiver (a sensor element or a plugin) and a lidar (a sensor element) both on the
    body: it works at the surface, whatever water plugin it also carries (a hull simulated with
    a submersible's hydrodynamics); a diver carries one of them at most. Not read when anything
    but a water plugin says the body dives (:func:`_dives_but_by_plugins`)."""
    receivers, lidars = _receivers(tree), _lidars(tree)
    return [receivers[0], lidars[0]] if receivers and lidars else []


def _dives_but_by_plugins(tree: JointTree) -> bool:
    """Something other than a water plugin puts the body below the surface: a submersible's
    name, a sensor the ``underwater`` pattern reads (a DVL, a depth gauge) or its frame, a
    pressure sensor."""
    return (
        tree.reader.named_submersible
        or bool(water_frames(tree))
        or _pressure_sensor(tree)
        or bool(_diving_sensors(tree))
    )


def _receivers(tree: JointTree) -> list[str]:
    found = [
        f"{s.name or s.type} (GPS: heard above water)"
        for s in tree.urdf.sensors
        if s.type in ("gps", "navsat")
    ]
    return found + [
        f"{tree.reader.plugin_label(p)} (GPS: heard above water)"
        for p in tree.urdf.plugins
        if _GPS.search(f"{p.name} {p.filename}")
    ]


def _lidars(tree: JointTree) -> list[str]:
    return [
        f"{s.name or s.type} (lidar: scans in air)"
        for s in tree.urdf.sensors
        if element_kind(s, tree.profile) == "lidar"
    ]


def underwater_hints(tree: JointTree) -> tuple[str, ...]:
    """Thruster and underwater plugins, and sensors (by type, name or plugin) the profile's
    ``underwater`` pattern reads: a DVL, a pressure sensor; the robot's name as a submersible's
    (``auv``, ``rov``, whole words)."""
    if not tree.reader.marine:
        return ()
    hints = [*tree.labels("thruster"), *tree.labels("underwater")]
    if tree.reader.named_submersible:  # an AUV, an ROV: a body below the surface
        hints.append(f"robot name {tree.urdf.name}")
    hints += _diving_sensors(tree)
    return tuple(dict.fromkeys(hints))


def _diving_sensors(tree: JointTree) -> list[str]:
    """The sensors (by type, name or plugin) the profile's ``underwater`` pattern reads: a
    DVL, a subsea pressure sensor."""
    pattern = tree.profile.plugin_pattern("underwater")
    if pattern is None:
        return []
    return [
        sensor.name
        for sensor in tree.urdf.sensors
        if pattern.search(f"{sensor.type} {sensor.device_text}")
    ]


def water_frames(tree: JointTree) -> tuple[str, ...]:
    """Links fixed to the body whose names the profile's ``underwater`` pattern reads (a DVL's
    frame): a Doppler log or a subsea sensor works only in water, so its frame puts the body in
    water below the surface, with no plugin or sensor element behind it."""
    known: dict[str, str | None] = {}
    return tuple(
        link.name
        for link in tree.urdf.links
        if _DVL.search(link.name) and moved_by(tree.urdf, link.name, known) is None
    )


# A Doppler velocity log's frame, by the words of the profile's dvl sensor rule (not the whole
# underwater plugin pattern: a camera's `depth_sensor_link` is no subsea sensor).
_DVL = re.compile(r"dvl|doppler", re.IGNORECASE)


def flight_hints(tree: JointTree, roles: dict[str, Role], limbs: Sequence[Limb]) -> tuple[str, ...]:
    """Plugins whose parameters use the flight vocabulary (a vehicle plugin of its own that
    sets a drone's topics). Not on a body that moves on the ground or walks: there a word such
    as ``drone`` in a parameter is a name (another robot's namespace), not flight.
    """
    pattern = tree.profile.plugin_pattern("flight")
    if pattern is None or tree.labels("flight"):
        return ()
    # A body that shows no way of travelling says what it is only by its name: an aircraft
    # exported as one link and its mesh (`Fixed_Wing_UAV`), a drone a simulator moves by
    # setting its pose or its velocity (a velocity plugin moves a wheelless body in the air as
    # well as on the ground), flies, with doubt; so does an airship named so.
    said = pattern.search(tree.urdf.name) or tree.reader.named_airship
    named = (
        (f"robot name {tree.urdf.name}",)
        if said and _travels_no_way_read(tree, roles, limbs, pushed=True)
        else ()
    )
    walks = any(limb.kind == "leg" for limb in limbs)
    if walks or grounded(tree, roles):
        return named
    found = tuple(
        f"the parameters of plugin {tree.reader.plugin_label(p)}"
        for p in tree.urdf.plugins
        if any(pattern.search(text) for _, text in p.params)
    )
    return found + named


def vessel_name(tree: JointTree, roles: dict[str, Role], limbs: Sequence[Limb]) -> tuple[str, ...]:
    """The robot's name as a craft's in water, whole words (a surface craft's: ``boat``,
    ``sailboat``, ``usv``; a submersible's: ``auv``, ``rov``), when nothing else says how the
    body travels (:func:`_travels_no_way_read`). A hull exported as a few frames, or with only
    its rudder and sail on joints, is a vessel by its name, with doubt."""
    named = tree.reader.named_vessel or tree.reader.named_submersible
    if not named or not _travels_no_way_read(tree, roles, limbs):
        return ()
    return (f"robot name {tree.urdf.name}",)


def _pushes(tree: JointTree, label: str) -> bool:
    """A drive plugin that sets a wheelless body's velocity wherever it is: a velocity control,
    or a planar move on a body gravity does not pull (a drone a simulator holds at its height)."""
    return bool(
        _VELOCITY_CONTROL.search(label) or (tree.urdf.gravity_off and _PLANAR_MOVE.search(label))
    )


def _travels_no_way_read(
    tree: JointTree, roles: dict[str, Role], limbs: Sequence[Limb], *, pushed: bool = False
) -> bool:
    """Nothing says how the body travels: no wheel, caster, track, rotor or thruster, no leg or
    arm, no gripper (a gripper named for its use is a gripper), no plugin that moves it, flies
    it or puts it in water. ``pushed``: a velocity-control plugin on a body with no wheel,
    caster or track (it sets the body's twist, in the air as on the ground) says nothing of
    where it travels either, nor a planar move on a body with gravity off (a simulator's drone
    held at its height); a drive plugin, or a planar move on a body gravity pulls, does."""
    moves = {"wheel", "caster", "rotor", "thruster", "gripper"} & {r.role for r in roles.values()}
    if moves or tracks(tree) or any(limb.kind in ("arm", "leg") for limb in limbs):
        return False
    drives = tree.labels("drive")
    if drives and not (pushed and all(_pushes(tree, label) for label in drives)):
        return False
    return not any(tree.labels(part) for part in ("flight", "marine", "thruster"))
