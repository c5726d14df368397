"""Motion controls a robot description shows by itself, without a topic list.

From the URDF: a drive plugin (diff_drive, skid_steer, a tracked vehicle) or wheels driven
through a transmission / ``ros2_control`` mean the robot is driven; rotors or flight plugins
mean it is flown; limb joints (arms, heads, flippers) with a transmission
mean its joints are commanded one by one.
From the SRDF: a MoveIt planning group over an arm means joint-space and end-effector goals; an
``<end_effector>`` not on a leg means end-effector goals (:mod:`solver.identify.plans`). Which
control each of these means is the profile's ``motion.description`` (data); this module only
says which of them a robot has.

Navigation (Waypoint) and walking commands live in launch and config files, not in the robot
description: they come from topics (:mod:`solver.identify.interfaces`).
"""

from __future__ import annotations

from solver.identify.body import Body
from solver.identify.interfaces import Control
from solver.identify.plans import arm_plans, hand_effectors
from solver.identify.profile import Profile
from solver.identify.srdf import Srdf
from solver.identify.urdf import Urdf

__all__ = ["controls_from_description"]


def controls_from_description(
    body: Body,
    profile: Profile,
    srdf: Srdf | None = None,
    *,
    urdf: Urdf | None = None,
    urdf_source: str = "urdf",
    srdf_source: str = "srdf",
) -> tuple[Control, ...]:
    """The motion controls the body (and SRDF) show, each with what shows it."""
    found: list[Control] = []

    def add(source: str, text: str) -> None:
        for control in profile.description_control(source):
            found.append(Control(control, text))

    if body.drive_plugins or body.tracks:
        plugins = ", ".join((*body.drive_plugins, *body.tracks)[:3])
        add("drive_plugin", f"{urdf_source}: drive plugin {plugins}")
    if body.controlled_wheels:
        add(
            "controlled_wheels",
            f"{urdf_source}: {len(body.controlled_wheels)} wheel joint(s) with a transmission",
        )
    if body.flying:
        if body.rotors:
            what = f"{len(body.rotors)} rotor joint(s)"
        elif body.flight_plugins:
            what = f"flight plugin {body.flight_plugins[0]}"
        else:
            what = f"{len(body.fixed_rotors)} fixed rotor joint(s) of a trimmed model"
        add("flight", f"{urdf_source}: {what}")
    if body.controlled_joints:
        add(
            "controlled_joints",
            f"{urdf_source}: {len(body.controlled_joints)} limb joint(s) with a transmission",
        )
    if srdf is not None:
        groups = arm_plans(body, srdf, profile.limb("arm_min_joints"), urdf)
        if groups:
            add(
                "srdf_group",
                f"{srdf_source}: planning group(s) {', '.join(g.name for g in groups)}",
            )
        if effectors := hand_effectors(body, srdf, urdf):
            add(
                "srdf_end_effector",
                f"{srdf_source}: end effector(s) {', '.join(e.name for e in effectors)}",
            )
    merged: dict[str, list[str]] = {}
    for control in found:
        merged.setdefault(control.motion_control, []).append(control.source)
    return tuple(Control(name, "; ".join(sources)) for name, sources in merged.items())
