"""Rule sets as values: components, runs of counts, characteristics and their classes, built
directly, without a file."""

from __future__ import annotations

import pytest

from solver.core.constraints import Condition, RuleConstraint
from solver.core.ruleset import (
    Characteristic,
    Component,
    OnePerValue,
    RuleSet,
    Run,
    one_component_each,
)
from solver.errors import Location


def sensors() -> Characteristic:
    visual = Component("visual", 0, ("2D Camera", "3D Camera"))
    audio = Component("audio", 1, ("Microphone",))
    return Characteristic(
        name="sensor_type",
        label="Sensor type",
        kind="categorical",
        values=("2D Camera", "3D Camera", "Microphone"),
        components=(visual, audio),
        membership=((0,), (0,), (1,)),
        declared_components=True,
    )


def counts(low: int, high: int) -> Characteristic:
    values = Run(range(low, high + 1))
    components, membership = one_component_each(values)
    return Characteristic("sensor_count", "Sensor count", "integer", values, components, membership)


def test_an_arrangement_shows_a_count_as_clusters_rounded_up() -> None:
    pairs = Component("clusters of 2", 1, (6, 7, 8), low=6, high=10, cluster_size=2)
    assert [pairs.clusters(n) for n in (6, 7, 8)] == [3, 4, 4]


def test_an_arrangement_describes_its_range_open_or_closed() -> None:
    assert Component("a", 0, (), low=6, high=10).describe_range() == "6..10"
    assert Component("b", 0, (), low=26).describe_range() == "26.."
    assert Component("c", 0, ("x",)).describe_range() == ""


def test_a_run_finds_a_whole_number_by_arithmetic_and_nothing_else() -> None:
    run = Run(range(3, 8))
    assert [run.position(3), run.position(7), run.position(8), run.position(2)] == [
        0,
        4,
        None,
        None,
    ]
    assert [run.position(True), run.position(4.0), run.position("4")] == [None, None, None]
    assert Run(()).position(1) is None


def test_one_component_per_value_is_made_when_asked_and_equals_the_tuple_listed() -> None:
    components = OnePerValue(Run(range(1, 4)))
    listed = (
        Component("1", 0, (1,), low=1, high=1),
        Component("2", 1, (2,), low=2, high=2),
        Component("3", 2, (3,), low=3, high=3),
    )
    assert len(components) == 3
    assert components[1] is components[1]
    assert components == listed
    assert listed == components
    assert hash(components) == hash(listed)
    assert components[-1] == listed[-1]
    assert components[0:2] == listed[0:2]
    assert components != listed[:2]
    assert repr(components) == "OnePerValue(<3 items>)"


def test_one_component_per_named_value_has_no_range() -> None:
    (only,) = OnePerValue(("UAV",))
    assert only == Component("UAV", 0, ("UAV",))
    assert only.low is None
    assert only.high is None


def test_without_declared_components_each_value_is_in_its_own() -> None:
    characteristic = counts(1, 100_000)
    assert characteristic.membership[41] == (41,)
    assert characteristic.components_of(42) == (Component("42", 41, (42,), low=42, high=42),)
    assert characteristic.is_partition


def test_a_characteristic_finds_its_values_and_their_components() -> None:
    characteristic = sensors()
    assert characteristic.index("Microphone") == 2
    assert characteristic.index("Speaker") is None
    assert [c.name for c in characteristic.components_of("3D Camera")] == ["visual"]
    assert characteristic.components_of("Speaker") == ()
    assert characteristic.component("audio") == Component("audio", 1, ("Microphone",))
    assert characteristic.component("haptic") is None


def test_a_value_in_two_components_makes_no_partition() -> None:
    both = Characteristic(
        "k", "K", "categorical", ("a", "b"), (Component("x", 0, ("a", "b")),), ((0,), (0, 0))
    )
    assert not both.is_partition
    assert sensors().is_partition


@pytest.mark.parametrize(
    ("text", "value"),
    [("3", 3), (" 50 ", 50), ("+7", 7), ("51", None), ("0", None), ("٣", None), ("1_0", None)],
)
def test_a_count_is_read_from_ascii_digits_within_the_range(text: str, value: int | None) -> None:
    assert counts(1, 50).parse_value(text) == value


def test_a_count_of_more_digits_than_63_bits_hold_is_no_value() -> None:
    assert counts(1, 50).parse_value("1" * 4_300) is None


def test_a_named_value_is_read_as_written() -> None:
    assert sensors().parse_value("Microphone") == "Microphone"
    assert sensors().parse_value("microphone") is None


def team_rules(constraints: tuple[RuleConstraint, ...] = ()) -> RuleSet:
    kinematic = Characteristic(
        "kinematic_type",
        "Kinematic type",
        "categorical",
        ("UAV", "UGV"),
        *one_component_each(("UAV", "UGV")),
    )
    return RuleSet(
        "r", "r.yaml", (kinematic, sensors(), counts(1, 4)), "kinematic_type", constraints
    )


def test_a_rule_set_names_its_characteristics_and_its_key() -> None:
    rules = team_rules()
    assert rules.names == ("kinematic_type", "sensor_type", "sensor_count")
    assert rules.positions == {"kinematic_type": 0, "sensor_type": 1, "sensor_count": 2}
    assert (rules.key.name, rules.key_position) == ("kinematic_type", 0)
    assert rules.characteristic("sensor_type") == sensors()
    with pytest.raises(KeyError):
        rules.characteristic("battery")


def test_the_bound_multiplies_the_components_of_every_characteristic() -> None:
    rules = team_rules()
    assert rules.bound_factors == (2, 2, 4)
    assert rules.bound == 16


def test_values_the_rules_cannot_tell_apart_share_a_class() -> None:
    rules = team_rules()
    assert rules.value_classes[1] == (("2D Camera", "3D Camera"), ("Microphone",))
    assert rules.value_classes[2] == ((1,), (2,), (3,), (4,))
    assert rules.value_class_index[1] == {"2D Camera": 0, "3D Camera": 0, "Microphone": 1}


def test_a_constraint_naming_one_value_sets_it_apart_from_its_component() -> None:
    no_3d_on_uav = RuleConstraint(
        "no 3D on UAV",
        "forbid",
        (),
        (
            Condition("kinematic_type", frozenset({"UAV"}), "is UAV"),
            Condition("sensor_type", frozenset({"3D Camera"}), "is 3D Camera"),
        ),
        Location("r.yaml", 12),
    )
    rules = team_rules((no_3d_on_uav,))
    assert rules.value_classes[0] == (("UAV",), ("UGV",))
    assert rules.value_classes[1] == (("2D Camera",), ("3D Camera",), ("Microphone",))


def test_a_rule_set_shows_itself_in_one_line() -> None:
    assert repr(team_rules()) == (
        "<RuleSet 'r' (r.yaml): kinematic_type, sensor_type, sensor_count; 0 constraints>"
    )
