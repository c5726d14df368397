"""Scaled rule sets and teams for the benchmarks, with their counts from closed forms.

Every benchmark asserts the counts it times. The expected counts here are computed from the
generator's parameters by plain arithmetic (SPEC.md section 4's closed form, and inclusion-
exclusion for the one constraint), never by the code under test.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
import yaml

from solver import Team, load_team


@dataclass(frozen=True)
class Scale:
    """A generated team: T kinematic types x M motion controls x S sensor types (G groups) x
    counts 1..C (A equal arrangements); optionally one constraint forbidding sensor S0 with
    more than C - F sensors, which removes F robots per type and motion control."""

    types: int
    motions: int
    sensors: int
    groups: int
    counts: int
    arrangements: int
    forbidden: int = 0

    @property
    def robots(self) -> int:
        return self.types * self.motions * (self.sensors * self.counts - self.forbidden)

    @property
    def configurations(self) -> int:
        # Forbidding S0's top counts never empties an arrangement for the other sensors of
        # S0's group (every group has at least two sensors here).
        return self.types * self.motions * self.groups * self.arrangements

    def rules(self) -> dict[str, object]:
        step = self.counts // self.arrangements
        data: dict[str, object] = {
            "name": f"scaled {self.robots:.0e}",
            "characteristics": {
                "kinematic_type": {"values": [f"T{i}" for i in range(self.types)]},
                "motion_control": {"values": [f"M{i}" for i in range(self.motions)]},
                "sensor_type": {
                    "values": [f"S{i}" for i in range(self.sensors)],
                    "components": [
                        {
                            "name": f"G{g}",
                            "values": [
                                f"S{i}" for i in range(self.sensors) if i % self.groups == g
                            ],
                        }
                        for g in range(self.groups)
                    ],
                },
                "sensor_count": {
                    "range": {"min": 1, "max": self.counts},
                    "components": [
                        {
                            "name": f"A{a}",
                            "min": a * step + 1,
                            "max": self.counts if a == self.arrangements - 1 else (a + 1) * step,
                            "cluster_size": a + 1,
                        }
                        for a in range(self.arrangements)
                    ],
                },
            },
        }
        if self.forbidden:
            data["constraints"] = [
                {
                    "name": "S0 carries few sensors",
                    "forbid": {
                        "sensor_type": "S0",
                        "sensor_count": {"min": self.counts - self.forbidden + 1},
                    },
                }
            ]
        return data

    def team(self, folder: Path) -> Team:
        rules_path = folder / "rules.yaml"
        rules_path.write_text(yaml.safe_dump(self.rules(), sort_keys=False), encoding="utf-8")
        team_path = folder / "team.yaml"
        team_path.write_text(
            yaml.safe_dump(
                {
                    "name": f"scaled {self.robots:.0e}",
                    "rules": "rules.yaml",
                    "team": {f"T{i}": {} for i in range(self.types)},
                },
                sort_keys=False,
            ),
            encoding="utf-8",
        )
        return load_team(team_path)


# What the `scaled` fixture gives: a function that builds the team of a Scale in a fresh folder.
Scaled = Callable[[Scale], Team]


@pytest.fixture
def scaled(tmp_path_factory: pytest.TempPathFactory) -> Scaled:
    """Build the team of a :class:`Scale` in a fresh folder."""

    def build(scale: Scale) -> Team:
        return scale.team(tmp_path_factory.mktemp("scaled"))

    return build


def order(number: int) -> int:
    return round(math.log10(number))
