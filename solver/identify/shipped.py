"""Motion controls the robot's packages ship: what their launch, configuration and script
files run, read as text (:mod:`solver.identify.readers.workspace` finds and reads them).

The profile's ``motion.packages`` rules say which texts mean which control: a bringup that
runs Nav2 or move_base, a script that streams MAVROS position set-points or follows waypoints
(Waypoint); a teleop node (a velocity control, read by structure as topics are: Driving for a
base, Flight for a drone, Walking for a walker); a MoveIt ``move_group`` or servo (End
Effector). A rule may exclude structures (no navigation for an arm bolted to a table, whatever
its repository holds). Each control names the file that shows it, the first one found in the
order the packages were read (the description's package first).

What the packages ship is the robot's author's word, stronger than a guess: when they were read
whole (``Workspace.complete``), the description's navigation guess is not made
(:func:`solver.identify.motion.controls_from_description`); they ship navigation or they do
not. When a bound stopped the reading, the guess stays.
"""

from __future__ import annotations

from solver.identify.interfaces import Control
from solver.identify.profile import VELOCITY, Profile
from solver.identify.readers.workspace import Workspace
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = ["controls_from_workspace"]


def controls_from_workspace(
    workspace: Workspace, profile: Profile, structure: str
) -> tuple[Control, ...]:
    """One control per rule that a file of the robot's packages matches, with that file."""
    found: dict[str, str] = {}
    for rule in profile.package_controls:
        if structure in rule.not_for:
            continue
        control = profile.velocity_control(structure) if rule.control == VELOCITY else rule.control
        if control in found:
            continue
        for shipped in workspace.files:
            matched = rule.match.find(shipped.text)
            if matched is not None:
                where = shown(shipped.path, limit=SHOWN_FILE_NAME_CHARS)
                package = shown(shipped.package)
                found[control] = f"package {package}: {where} ({shown(matched)})"
                break
    return tuple(Control(control, source) for control, source in found.items())
