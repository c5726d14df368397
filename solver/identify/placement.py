"""Where the body is: joints that only place it in the world, a floating or a planar base.

A description may place its body by joints that move no part of it: a ``floating`` or
``planar`` joint that carries the body, or a chain of joints at the root that slide along x and
y and turn about z (a planar base, as simulators model a mobile base) or slide along x, y, z and
turn about all three (a simulated floating base) or about z alone (a simulated hovering body, a
drone's four degrees of freedom). :func:`placement` finds them; the root
chain's joints are then nobody's limb. Slides along x and y (and z) and a turn about z whose
slides each travel less than a simulator's world (:data:`MACHINE_TRAVEL`) are a machine's
axes (an XY table or a Cartesian gantry turning a tool): they place nothing, and are an arm's
joints.

A ``floating`` joint that carries only a leaf part is no base: it is a part a simulator poses
(a propeller drawn turning, :mod:`solver.identify.roles`); nor is a ``floating`` or ``planar``
joint that carries fewer of the description's actuated joints than lie outside it (a contest
field's box sliding on a planar joint beside a gantry arm fixed to the world). An SRDF's
virtual joint is a planning convention (MoveIt's setup assistant writes a ``planar`` one by
default): it says nothing about whether the base moves, and is not read here.

Not here: what moves the body (:mod:`solver.identify.vehicle`).
"""

from __future__ import annotations

from dataclasses import dataclass

from solver.identify.readers.urdf import Joint
from solver.identify.roles import main_axis
from solver.identify.tree import JointTree

__all__ = ["MACHINE_TRAVEL", "Placement", "placement"]

# Root slides along x and y (and z) whose written limits each let them travel less than this
# (metres) are a machine's axes (an XY table's or a small gantry's), not a base a simulator
# places: those move it over tens of metres (the labelled sets' travel 20 m or more).
MACHINE_TRAVEL = 2.0


@dataclass(frozen=True, slots=True)
class Placement:
    """The floating and planar bases found (a joint's name, or a line saying what places the
    body) and the root joints that only place it."""

    floating: tuple[str, ...] = ()
    planar: tuple[str, ...] = ()
    placing: tuple[str, ...] = ()  # root joints: x, y and a turn; x, y, z and one or three turns
    machine: tuple[str, ...] = ()  # root slides that travel as a machine's axes


def placement(tree: JointTree) -> Placement:
    """The floating and planar bases of ``tree``."""
    floating = [j.name for j in tree.urdf.joints if j.type == "floating" and _carries(tree, j)]
    planar = [j.name for j in tree.urdf.joints if j.type == "planar" and _carries(tree, j)]
    placing = _root_axes(tree)
    machine = _machine_slides(tree, placing) if len(placing) in (3, 4) else []
    if machine:
        placing = []
    elif len(placing) == 6:
        floating.append(f"root joints {', '.join(placing)} (x, y, z and three turns)")
    elif len(placing) == 4:
        floating.append(f"root joints {', '.join(placing)} (x, y, z and a turn about z)")
    elif len(placing) == 3:
        planar.append(f"root joints {', '.join(placing)} (x, y and a turn about z)")
    return Placement(tuple(floating), tuple(planar), tuple(placing), tuple(machine))


def _carries(tree: JointTree, joint: Joint) -> bool:
    """The joint carries the body: more of it than one part (a joint below it, or the root
    has no other joint: a body of one link placed in the world), and no fewer of the
    description's actuated joints than lie outside it, above it or beside it (a box that
    slides on a planar joint beside an arm fixed to the world, a ball a floating joint places
    beside a robot, is no base). Mimic joints follow another and are not counted, nor are
    floating and planar joints (two robots placed side by side in one file each carry a
    body)."""
    urdf = tree.urdf
    if not urdf.children(joint.child) and len(urdf.children(urdf.root)) != 1:
        return False
    inside = sum(1 for below in urdf.subtree_joints(joint.child) if _moves_the_body(below))
    everywhere = sum(1 for other in urdf.joints if _moves_the_body(other))
    return inside >= everywhere - inside


def _moves_the_body(joint: Joint) -> bool:
    """An actuated joint of a body, not one that places a body in the world."""
    return joint.actuated and joint.type not in ("floating", "planar")


def _root_axes(tree: JointTree) -> list[str]:
    """Joints at the root that only place the body: x, y and a turn about z (planar), or x,
    y, z and three turns or a turn about z (a simulated floating or hovering base); [] when the
    root is not so.
    """
    chain = _root_chain(tree)
    if len(chain) >= 3 and _moves(chain[:3]) == ({0, 1}, [2]):
        return [j.name for j in chain[:3]]
    if len(chain) == 6 and _moves(chain) == ({0, 1, 2}, [0, 1, 2]):
        return [j.name for j in chain]
    if len(chain) == 4 and _moves(chain) == ({0, 1, 2}, [2]):
        return [j.name for j in chain]
    return []


def _machine_slides(tree: JointTree, placing: list[str]) -> list[str]:
    """The root joints' slides (x and y of a planar pattern, x, y and z of a hovering one)
    when each travels less than :data:`MACHINE_TRAVEL` between its written limits (a
    machine's axes: an XY table's, a Cartesian gantry's); else [], and for a body something
    else says travels (a drive, flight or water plugin, a rotor: a vehicle in a small world)."""
    if _travels(tree):
        return []
    joints = [joint for name in placing if (joint := tree.urdf.joint(name)) is not None]
    slides = [joint for joint in joints if joint.type == "prismatic"]
    short = all(
        joint.lower is not None
        and joint.upper is not None
        and abs(joint.upper - joint.lower) < MACHINE_TRAVEL
        for joint in slides
    )
    return [joint.name for joint in slides] if short else []


def _travels(tree: JointTree) -> bool:
    """A drive, flight or water plugin, or a rotor-named joint, says the body travels."""
    return bool(
        tree.labels("drive")
        or tree.labels("flight")
        or tree.reader.marine
        or any(tree.matches("rotor", joint) for joint in tree.urdf.joints)
    )


def _root_chain(tree: JointTree) -> list[Joint]:
    """The unbranched actuated joints right below the root (at most six)."""
    chain: list[Joint] = []
    link = tree.urdf.root
    while len(chain) < 6:
        below = tree.urdf.children(link)
        if len(below) != 1:
            break
        joint = below[0]
        link = joint.child
        if joint.type == "fixed":
            continue
        if joint.type not in ("prismatic", "revolute", "continuous") or not joint.actuated:
            break
        chain.append(joint)
    return chain


def _moves(chain: list[Joint]) -> tuple[set[int], list[int]]:
    """The axes a chain slides along and (sorted) the axes it turns about."""
    slides = {main_axis(j.axis) for j in chain if j.type == "prismatic"}
    turns = sorted(main_axis(j.axis) for j in chain if j.type != "prismatic")
    return slides, turns
