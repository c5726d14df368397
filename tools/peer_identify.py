"""The peer of issue 42, item 3, for ``identify``: a small URDF read directly with lxml.

What a programmer would write without teleop-ui to answer the same question of a small
description as ``teleop-ui identify``: parse the URDF with lxml (entities and the network
off, as any reader of a stranger's file should), find the wheels (continuous joints named
like wheels, or named by a drive plugin's ``<leftJoint>``/``<rightJoint>``) and the arms
(chains of revolute or prismatic joints), call it a UGV, a manipulator or a mobile
manipulator, list the ``<sensor>`` elements by type, and guess Driving from a drive plugin or
wheels. No profile, no rule set, no locations, no limits: the peer's only job is the answer
for a description like ``examples/diff_drive_lidar.urdf``.

    python tools/peer_identify.py [URDF]     # prints "UGV lidar:1 Driving" for the example

``tools/startup_cpu.py`` times it against ``teleop-ui identify`` of the same file as whole
processes.
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

from lxml import etree

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "examples" / "diff_drive_lidar.urdf"
SENSOR_KINDS = {"ray": "lidar", "gpu_ray": "lidar", "camera": "camera", "depth": "depth_camera"}


def identify(path: Path = EXAMPLE) -> tuple[str, dict[str, int], list[str]]:
    """(kinematic type, sensors by kind, motion controls) of a URDF."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True)
    robot = etree.parse(str(path), parser).getroot()
    joints = {j.get("name"): j.get("type") for j in robot.iter("joint")}
    plugins = [p for p in robot.iter("plugin") if "drive" in (p.get("filename") or "")]
    driven = {e.text for p in plugins for e in p if e.tag in ("leftJoint", "rightJoint")}
    wheels = {
        name
        for name, kind in joints.items()
        if kind == "continuous" and ("wheel" in (name or "") or name in driven)
    }
    arm = [n for n, kind in joints.items() if kind in ("revolute", "prismatic")]
    if wheels and len(arm) >= 3:
        structure = "Mobile Manipulator"
    elif wheels:
        structure = "UGV"
    else:
        structure = "Manipulator"
    sensors = Counter(
        SENSOR_KINDS.get(s.get("type") or "", s.get("type") or "") for s in robot.iter("sensor")
    )
    controls = ["Driving"] if plugins or wheels else []
    if len(arm) >= 3:
        controls.append("Joint")
    return structure, dict(sensors), controls


def main() -> None:
    structure, sensors, controls = identify(Path(sys.argv[1]) if len(sys.argv) > 1 else EXAMPLE)
    found = " ".join(f"{kind}:{count}" for kind, count in sorted(sensors.items()))
    print(structure, found, " ".join(controls))


if __name__ == "__main__":
    main()
