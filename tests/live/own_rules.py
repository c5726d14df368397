"""A rule set, team and profile of the live tests' own, with names the article never uses.

Its kinematic types are ``frame`` values (Quadcopter, Rover), its motion control is ``mode``,
its sensor type ``feed`` and its count ``sensors``; it adds two characteristics identification
knows nothing of: ``autonomy`` (the operator chooses it: ``/teleop_ui/active_autonomy``) and
``link`` (fixed per robot: ``--set /ns:link=...`` or the robot's ``<ns>/teleop_ui/link``). Each
autonomy level is a component of its own, so changing it changes the configuration. The profile
extends the shipped one with the mappings to these names. Expected configuration numbers are
asked of :func:`solver.assign` from the combination a robot should have.
"""

from __future__ import annotations

from pathlib import Path

from solver.core.team import load_team
from solver.identify.profile import Profile, load_profile
from solver.solving.assignment import assign
from solver.solving.solution import Solution, solve

RULES = """\
name: Own live rules (test)
team_key: frame
characteristics:
  frame:
    values: [Quadcopter, Rover]
  mode:
    values: [Flight, Driving, Waypoint]
  feed:
    values: [2D Camera, LIDAR]
  sensors:
    range: {min: 1, max: 4}
    components:
      - {name: few, min: 1, max: 4, cluster_size: 1}
  autonomy:
    values: [teleoperated, supervised]
  link:
    values: [Wi-Fi, LTE, Tether]
    components:
      - {name: wireless, values: [Wi-Fi, LTE]}
      - {name: tethered, values: [Tether]}
"""

TEAM = """\
name: Own live team
rules: own-rules.yaml
team:
  Quadcopter: {mode: [Flight, Waypoint], sensors: 4}
  Rover: {mode: [Driving, Waypoint], sensors: 4}
"""

# Another team under the same rules: a rival watcher's.
OTHER_TEAM = """\
name: Other live team
rules: own-rules.yaml
team:
  Quadcopter: {mode: [Waypoint], sensors: 2}
  Rover: {mode: [Driving], sensors: 2}
"""

PROFILE = """\
extends: shipped
characteristics: {motion_control: mode, sensor_type: feed, sensor_count: sensors}
structures:
  - {name: UAV, kinematic_types: [Quadcopter]}
  - {name: UGV, kinematic_types: [Rover]}
"""


def write_own(directory: Path) -> tuple[Solution, Profile]:
    """The rule set, both teams and the profile in ``directory``; the team's solution."""
    for name, text in (
        ("own-rules.yaml", RULES),
        ("own-team.yaml", TEAM),
        ("other-team.yaml", OTHER_TEAM),
        ("own-profile.yaml", PROFILE),
    ):
        (directory / name).write_text(text, encoding="utf-8")
    return solve(load_team(directory / "own-team.yaml")), load_profile(
        directory / "own-profile.yaml"
    )


def drone(solution: Solution, **values: str) -> int:
    """The configuration of the test quadrotor (Flight, one camera) with ``values``."""
    return assign(
        solution,
        {"frame": "Quadcopter", "mode": "Flight", "feed": "2D Camera", "sensors": "1"} | values,
    ).number


def rover(solution: Solution, **values: str) -> int:
    """The configuration of the test rover (Driving, one laser scanner) with ``values``."""
    return assign(
        solution, {"frame": "Rover", "mode": "Driving", "feed": "LIDAR", "sensors": "1"} | values
    ).number
