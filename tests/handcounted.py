"""Rule sets small enough to count by hand, for the tests of the model, the partition, the
engines and the JSON of a configuration: every expected number is worked out here, not by the
code under test.

:data:`SMALL_RULES` (a team key, sensor types in two components, counts in two arrangements, one
constraint) with :data:`SMALL_TEAM`:

- UGV, counts {1, 2, 5}: 3 sensor types x 3 counts = 9 robots; visual or audio, few ({1, 2}) or
  many ({5}): 4 configurations, numbered 1-4 (visual/few 4 robots, visual/many 2, audio/few 2,
  audio/many 1);
- UAV, no microphone: 2 sensor types x 6 counts = 12 robots; visual/few (4 robots, number 5)
  and visual/many (8, number 6): 2 configurations;
- 21 robots, 6 configurations in all.

:data:`OVERLAPPING_RULES`: lidar in both components (``one`` and ``two``), sonar in none (a gap).
"""

from __future__ import annotations

from solver.core.rules import parse_rules
from solver.core.ruleset import RuleSet
from solver.core.team import Team, parse_team
from solver.files.yamlio import parse_document

__all__ = ["OVERLAPPING_RULES", "SMALL_RULES", "SMALL_TEAM", "rules_of", "team_of"]

SMALL_RULES = """\
name: small
characteristics:
  kinematic_type:
    values: [UGV, UAV]
  sensor_type:
    values: [camera, lidar, microphone]
    components:
      - {name: visual, values: [camera, lidar]}
      - {name: audio, values: [microphone]}
  sensor_count:
    range: {min: 1, max: 6}
    components:
      - {name: few, min: 1, max: 2}
      - {name: many, min: 3, max: 6, cluster_size: 2}
constraints:
  - name: no microphone on a UAV
    forbid: {kinematic_type: UAV, sensor_type: microphone}
"""

SMALL_TEAM = """\
name: small team
team:
  UGV: {sensor_count: [1, 2, 5]}
  UAV: {}
"""

OVERLAPPING_RULES = """\
name: overlapping
characteristics:
  kinematic_type:
    values: [UGV]
  sensor_type:
    values: [camera, lidar, microphone, sonar]
    components:
      - {name: one, values: [camera, lidar]}
      - {name: two, values: [lidar, microphone]}
"""


def rules_of(text: str = SMALL_RULES) -> RuleSet:
    return parse_rules(parse_document(text, "rules.yaml"))


def team_of(text: str = SMALL_TEAM, rules: str = SMALL_RULES) -> Team:
    return parse_team(parse_document(text, "team.yaml"), rules_of(rules))
