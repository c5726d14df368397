""""Can share a component" must be transitive; otherwise a witness triple is reported."""

from __future__ import annotations

from solver.check.equivalence import witness_triple
from solver.rules import load_rules
from tests.check.helpers import findings, fixture


def test_overlapping_groups_give_a_witness_triple() -> None:
    sensors = load_rules(fixture("non-transitive.yaml")).characteristic("sensor_type")
    visual, ranging = sensors.components
    assert witness_triple(sensors, visual, ranging) == ("Camera", "Lidar", "Mic")


def test_nested_groups_give_no_witness_triple() -> None:
    sensors = load_rules(fixture("nested-components.yaml")).characteristic("sensor_type")
    visual, anything = sensors.components
    assert witness_triple(sensors, visual, anything) is None
    assert findings("nested-components.yaml", check="non-transitive") == []


def test_check_reports_the_witness_triple_a_b_c() -> None:
    [finding] = findings("non-transitive.yaml", check="non-transitive")
    assert finding.message == (
        "'can share a component' is not transitive for sensor_type: 'Camera' ~ 'Lidar' (both "
        "in 'visual') and 'Lidar' ~ 'Mic' (both in 'ranging'), but 'Camera' and 'Mic' share no "
        "component")


def test_overlapping_arrangements_give_a_witness_triple_of_counts() -> None:
    [finding] = findings("coverage-overlap.yaml", check="non-transitive")
    assert "1 ~ 6 (both in 'few') and 6 ~ 7 (both in 'many'), but 1 and 7 share no component" \
        in finding.message
