"""Loading rule sets: the article's rules as data, user extensions, and every malformation."""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable
from pathlib import Path

import pytest

import solver.core.rules as rules_module
from solver import RulesError, load_rules, load_team, solve
from solver.core.rules import default_rules_path
from solver.core.ruleset import Component
from solver.errors import TooLargeError
from tests.conftest import RULES

WriteFile = Callable[[str, str], Path]

MINIMAL = """\
characteristics:
  kinematic_type:
    values: [UAV, UGV]
  sensor_type:
    values: [2D Camera, Microphone]
    components:
      - {name: visual, values: [2D Camera]}
      - {name: audio, values: [Microphone]}
"""


def messages(error: RulesError) -> list[str]:
    return [str(fault) for fault in error.faults]


def test_the_paper_rules_have_the_articles_characteristics_and_bound() -> None:
    rules = load_rules(RULES / "paper.yaml")
    assert rules.names == ("kinematic_type", "motion_control", "sensor_type", "sensor_count")
    assert [len(c.values) for c in rules.characteristics] == [6, 6, 10, 50]
    assert rules.bound_factors == (6, 6, 5, 5)
    assert rules.bound == 900 == rules.declared_bound
    assert rules.key.name == "kinematic_type"


def test_the_paper_rules_group_sensors_as_figure_7() -> None:
    sensors = load_rules(RULES / "paper.yaml").characteristic("sensor_type")
    groups = {c.name: c.values for c in sensors.components}
    assert groups == {
        "visual display": ("2D Camera", "3D Camera"),
        "spherical display": ("360 Camera",),
        "audio": ("Speaker", "Microphone"),
        "haptic": ("Force Sensor",),
        "point cloud": ("2D Scanning", "3D Scanning", "LIDAR", "RGB-D Camera"),
    }


@pytest.mark.parametrize(
    ("count", "arrangement", "clusters"),
    [
        (1, "individual", 1),
        (5, "individual", 5),
        (6, "clusters of 2", 3),
        (10, "clusters of 2", 5),
        (11, "clusters of 3", 4),
        (16, "clusters of 5", 4),
        (25, "clusters of 5", 5),
        (26, "clusters of 10", 3),
        (50, "clusters of 10", 5),
    ],
)
def test_the_paper_rules_cluster_sensor_counts_as_equation_2(
    count: int, arrangement: str, clusters: int
) -> None:
    sensors = load_rules(RULES / "paper.yaml").characteristic("sensor_count")
    (component,) = sensors.components_of(count)
    assert (component.name, component.clusters(count)) == (arrangement, clusters)


def test_the_marine_rules_make_vessels_kinematic_types_beside_the_articles_six() -> None:
    rules = load_rules(RULES / "marine.yaml")
    assert rules.key.values[-2:] == ("Surface Vessel", "Underwater Vehicle")
    assert [len(c.values) for c in rules.characteristics] == [8, 6, 13, 50]
    groups = {c.name: c.values for c in rules.characteristic("sensor_type").components}
    assert groups["sonar display"] == ("Sonar",)
    assert groups["navigation gauges"] == ("DVL", "Depth Gauge")
    assert rules.bound == 8 * 6 * 7 * 5 == rules.declared_bound


def test_the_marine_survey_team_solves_to_the_counts_its_selection_implies() -> None:
    solution = solve(load_team("marine-survey"))
    counts = {t.kinematic_type: (t.valid_robots, t.ui_configurations) for t in solution.by_type}
    assert counts == {
        # 2 controls x 1 sensor type x counts 1..2; configurations: 2 x 1 x 1 (individual).
        "UAV": (2 * 1 * 2, 2 * 1 * 1),
        # 2 controls x 3 sensor types (visual, point cloud, sonar display) x counts 1..5;
        # configurations 2 x 3 x 1.
        "Surface Vessel": (2 * 3 * 5, 2 * 3 * 1),
        # 3 controls x 4 sensor types in 3 components (DVL and Depth Gauge share the
        # navigation gauges) x counts 1..8 in 2 arrangements (individual, clusters of 2).
        "Underwater Vehicle": (3 * 4 * 8, 3 * 3 * 2),
    }


def test_the_default_rules_are_the_shipped_paper_rules() -> None:
    assert default_rules_path().read_bytes() == (RULES / "paper.yaml").read_bytes()


def test_without_components_every_value_is_its_own_component(write_file: WriteFile) -> None:
    rules = load_rules(write_file("r.yaml", MINIMAL))
    kinematic = rules.characteristic("kinematic_type")
    assert [c.name for c in kinematic.components] == ["UAV", "UGV"]
    assert rules.bound == 4


def test_a_range_without_components_has_one_component_per_count(write_file: WriteFile) -> None:
    rules = load_rules(
        write_file(
            "r.yaml",
            MINIMAL + "  sensor_count:\n    range: {min: 3, max: 100000}\n",
        )
    )
    counts = rules.characteristic("sensor_count")
    assert len(counts.values) == len(counts.components) == len(counts.membership) == 99_998
    assert counts.components[-1] == Component(
        "100000", 99_997, (100_000,), low=100_000, high=100_000
    )
    assert counts.components[1:3] == (
        Component("4", 1, (4,), low=4, high=4),
        Component("5", 2, (5,), low=5, high=5),
    )
    assert counts.membership[7] == (7,)
    assert [counts.index(3), counts.index(100_000), counts.index(2), counts.index(True)] == [
        0,
        99_997,
        None,
        None,
    ]
    assert rules.bound == 4 * 99_998


def test_a_short_ranges_components_equal_the_same_components_listed(
    write_file: WriteFile,
) -> None:
    implicit = load_rules(
        write_file(
            "a.yaml", "characteristics:\n  k:\n    values: [A]\n  n:\n    range: {min: 1, max: 2}\n"
        )
    )
    listed = load_rules(
        write_file(
            "b.yaml",
            "characteristics:\n  k:\n    values: [A]\n  n:\n    range: {min: 1, max: 2}\n"
            "    components:\n"
            "      - {name: '1', min: 1, max: 1}\n      - {name: '2', min: 2, max: 2}\n",
        )
    )
    a, b = implicit.characteristic("n"), listed.characteristic("n")
    assert a.components == tuple(b.components)
    assert tuple(b.components) == a.components
    assert a.membership == b.membership
    assert hash(a.components) == hash(tuple(b.components))
    assert a.components != a.components[:1]


def test_a_rule_set_may_add_kinematic_types_and_characteristics_of_its_own(
    write_file: WriteFile,
) -> None:
    rules = load_rules(
        write_file(
            "r.yaml",
            MINIMAL.replace("[UAV, UGV]", "[UAV, Quadruped]")
            + "  battery:\n    values: [low, high]\n",
        )
    )
    assert rules.key.values == ("UAV", "Quadruped")
    assert rules.characteristic("battery").kind == "categorical"
    assert rules.bound == 2 * 2 * 2


def test_the_team_key_defaults_to_the_first_characteristic(write_file: WriteFile) -> None:
    assert load_rules(write_file("r.yaml", MINIMAL)).team_key == "kinematic_type"


def test_constraints_are_read_as_data(write_file: WriteFile) -> None:
    rules = load_rules(
        write_file(
            "r.yaml",
            MINIMAL
            + """\
constraints:
  - name: microphones only on UGVs
    when: {sensor_type: Microphone}
    require: {kinematic_type: UGV}
  - forbid: {kinematic_type: UAV, sensor_type: {component: audio}}
""",
        )
    )
    first, second = rules.constraints
    assert first.name == "microphones only on UGVs"
    assert first.location.line == 10
    assert second.name == "constraint 2"
    assert first.holds({"kinematic_type": "UGV", "sensor_type": "Microphone"})
    assert not first.holds({"kinematic_type": "UAV", "sensor_type": "Microphone"})
    assert not second.holds({"kinematic_type": "UAV", "sensor_type": "Microphone"})
    assert second.holds({"kinematic_type": "UGV", "sensor_type": "Microphone"})


def test_an_unknown_value_in_a_component_is_named_with_a_suggestion(write_file: WriteFile) -> None:
    path = write_file("r.yaml", MINIMAL.replace("values: [Microphone]}", "values: [Mic]}"))
    with pytest.raises(RulesError) as caught:
        load_rules(path)
    assert messages(caught.value) == [
        f"{path}:8:32: characteristics.sensor_type.components[1].values[0]: unknown sensor_type "
        "value 'Mic' (did you mean 'Microphone'?)"
    ]
    assert caught.value.faults[0].code == "unknown-reference"


def test_every_problem_in_a_rule_file_is_reported_at_once(write_file: WriteFile) -> None:
    path = write_file(
        "r.yaml",
        """\
name: broken
bound: -3
characteristics:
  kinematic_type:
    values: [UAV, UAV]
  sensor_type:
    values: [2D Camera]
    range: {min: 1, max: 5}
  sensor_count:
    range: {min: 9, max: 2}
  speed:
    values: [slow]
    components:
      - {name: fast, values: [quick]}
    colour: red
constraints:
  - require: {size: 3}
  - name: both
    require: {speed: slow}
    forbid: {speed: slow}
""",
    )
    with pytest.raises(RulesError) as caught:
        load_rules(path)
    codes = [fault.code for fault in caught.value.faults]
    assert codes == [
        "out-of-range",
        "duplicate-value",
        "missing-field",
        "out-of-range",
        "unknown-reference",
        "unknown-field",
        "unknown-reference",
        "missing-field",
    ]
    assert [f.location.line for f in caught.value.faults] == [2, 5, 7, 10, 14, 15, 17, 18]


def test_a_team_key_must_name_a_categorical_characteristic(write_file: WriteFile) -> None:
    with pytest.raises(RulesError, match="team_key names no characteristic: 'kinematic'"):
        load_rules(write_file("r.yaml", "team_key: kinematic\n" + MINIMAL))
    with pytest.raises(RulesError, match="must be a categorical characteristic"):
        load_rules(
            write_file(
                "r.yaml", MINIMAL + "  count:\n    range: {min: 1, max: 3}\nteam_key: count\n"
            )
        )


def test_the_default_team_key_may_not_declare_components(write_file: WriteFile) -> None:
    with pytest.raises(RulesError, match="is the team key: each of its values is its own"):
        load_rules(
            write_file(
                "r.yaml",
                MINIMAL.replace(
                    "    values: [UAV, UGV]\n",
                    "    values: [UAV, UGV]\n    components: [{name: air, values: [UAV, UGV]}]\n",
                ),
            )
        )


def test_integer_arrangements_accept_exclusive_bounds(write_file: WriteFile) -> None:
    rules = load_rules(
        write_file(
            "r.yaml",
            """\
characteristics:
  kinematic_type: {values: [UAV]}
  sensor_count:
    range: {min: 1, max: 10}
    components:
      - {name: few, above: 1, max: 5}
      - {name: many, min: 6, below: 11, cluster_size: 2}
""",
        )
    )
    few, many = rules.characteristic("sensor_count").components
    assert few.values == (2, 3, 4, 5)
    assert (many.low, many.high, many.values) == (6, 10, (6, 7, 8, 9, 10))
    assert rules.characteristic("sensor_count").components_of(1) == ()


def test_an_empty_file_is_not_a_rule_set(write_file: WriteFile) -> None:
    with pytest.raises(RulesError, match="the file is empty; expected a rule set"):
        load_rules(write_file("r.yaml", "# nothing yet\n"))


def test_a_list_is_not_a_rule_set(write_file: WriteFile) -> None:
    with pytest.raises(RulesError, match="got a list"):
        load_rules(write_file("r.yaml", "- UAV\n- UGV\n"))


def test_huge_integer_domains_are_refused(write_file: WriteFile) -> None:
    with pytest.raises(TooLargeError, match=r"at most 100000 are accepted \(limit 'values'"):
        load_rules(
            write_file("r.yaml", MINIMAL + "  count:\n    range: {min: 1, max: 10000000000}\n")
        )


def test_a_value_listed_twice_in_a_constraint_is_an_error(write_file: WriteFile) -> None:
    path = write_file(
        "r.yaml",
        MINIMAL + "constraints:\n"
        "  - forbid: {kinematic_type: UAV, sensor_type: [Microphone, Microphone]}\n",
    )
    with pytest.raises(RulesError) as caught:
        load_rules(path)
    assert messages(caught.value) == [
        f"{path}:10:61: constraints[0].forbid.sensor_type[1]: 'Microphone' is listed twice"
    ]


def test_a_range_written_as_a_list_is_refused_because_a_list_is_a_set(
    write_file: WriteFile,
) -> None:
    with pytest.raises(RulesError) as caught:
        load_rules(write_file("r.yaml", MINIMAL + "  sensor_count:\n    range: [1, 50]\n"))
    assert [str(fault).split(": ", 1)[1] for fault in caught.value.faults] == [
        "characteristics.sensor_count.range: range of 'sensor_count' is a list ([1, 50]), but "
        "a list means a set of values (a team's `sensor_count: [2, 6]` is 2 and 6); write the "
        "range as {min: 1, max: 50}"
    ]


def test_a_rule_set_read_twice_unchanged_is_the_same_value(tmp_path: Path) -> None:
    path = tmp_path / "rules.yaml"
    path.write_text("characteristics:\n  kinematic_type:\n    values: [UGV]\n", encoding="utf-8")
    first = load_rules(path)
    assert load_rules(path) is first


def test_an_edited_rule_set_is_read_again(tmp_path: Path) -> None:
    path = tmp_path / "rules.yaml"
    path.write_text("characteristics:\n  kinematic_type:\n    values: [UGV]\n", encoding="utf-8")
    assert load_rules(path).characteristics[0].values == ("UGV",)
    path.write_text("characteristics:\n  kinematic_type:\n    values: [UAV]\n", encoding="utf-8")
    assert load_rules(path).characteristics[0].values == ("UAV",)
    path.write_text(
        "characteristics:\n  kinematic_type:\n    values: [UAV, UAV]\n", encoding="utf-8"
    )
    with pytest.raises(RulesError, match="duplicate value"):
        load_rules(path)


def test_rule_sets_read_from_many_threads_at_once_are_each_read_right(tmp_path: Path) -> None:
    # The studio reads rule sets from many threads. More files than are kept, read in a
    # different order by each thread, so that kept rule sets are looked up, added and dropped
    # by several threads at once; the interpreter switches threads as often as it can.
    files = []
    for i in range(3 * rules_module._KEPT_FILES):
        path = tmp_path / f"rules-{i}.yaml"
        path.write_text(
            f"name: set {i}\ncharacteristics:\n  kinematic_type:\n    values: [T{i}]\n",
            encoding="utf-8",
        )
        files.append((path, f"set {i}", (f"T{i}",)))
    threads = 8
    start = threading.Barrier(threads)
    wrong: list[str] = []
    failures: list[BaseException] = []

    def hammer(offset: int) -> None:
        start.wait()
        try:
            for turn in range(20):
                for path, name, values in files[offset:] + files[:offset]:
                    rules = load_rules(path)
                    if (rules.name, rules.characteristics[0].values) != (name, values):
                        wrong.append(f"{path.name} read as {rules.name} on turn {turn}")
        except BaseException as error:  # a thread's exception is lost unless kept
            failures.append(error)

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)
    try:
        workers = [threading.Thread(target=hammer, args=(5 * n,)) for n in range(threads)]
        for worker in workers:
            worker.start()
        for worker in workers:
            worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert failures == []
    assert wrong == []
    assert len(rules_module._READ) <= rules_module._KEPT_FILES
