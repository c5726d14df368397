"""The viewers' rules as shipped data (solver.layouts.checks.data): the files name the commit
they were read from, and their small type language finds every place a value does not fit,
by path; field references name the values of a panel's config."""

from __future__ import annotations

from typing import Any

import pytest

from solver.layouts.checks.data import field_values, lichtblick_rules, rviz_rules, type_problems


def problems(value: Any, spec: Any) -> list[tuple[str, str]]:
    return list(type_problems(value, spec, "config"))


def test_each_data_file_names_the_upstream_commit_it_was_read_from() -> None:
    for rules in (lichtblick_rules(), rviz_rules()):
        assert len(rules["source"]["commit"]) == 40
    assert lichtblick_rules() is lichtblick_rules()  # read once per process


def test_scalars_fit_their_kind_and_a_boolean_is_no_number() -> None:
    assert problems(1.5, "number") == []
    assert problems(True, "number") == [("config", "must be a number (got a boolean)")]
    assert problems(float("nan"), "number") == [("config", "must be a number (got a number)")]
    assert problems(3, "topic") == [("config", "must be a topic name (string) (got a number)")]
    assert problems(None, "any") == []


def test_a_value_is_one_of_an_enum_by_type_and_value() -> None:
    assert problems("row", {"enum": ["row", "column"]}) == []
    assert problems(1, {"enum": [True]}) == [("config", "must be one of True (got a number)")]


def test_each_item_of_a_list_or_tuple_is_checked_at_its_index() -> None:
    assert problems([1, "x", 3], {"list": "number"}) == [
        ("config[1]", "must be a number (got a string)")
    ]
    assert problems([1], {"tuple": ["number", "string"]}) == [
        ("config", "must be a list of 2 (got a list)")
    ]


def test_a_closed_object_names_a_key_the_viewer_never_reads_and_an_open_one_allows_it() -> None:
    keys = {"topic": "topic", "speed": "number"}
    assert problems({"topic": "/x", "sped": 1}, {"object": keys}) == [
        ("config.sped", "is not a key the viewer reads (it reads: speed, topic)")
    ]
    assert problems({"topic": "/x", "sped": 1}, {"open": keys}) == []
    assert problems({"a": {"speed": "fast"}}, {"map": {"object": keys}}) == [
        ("config.a.speed", "must be a number (got a string)")
    ]


def test_either_fits_when_one_option_fits() -> None:
    either = {"either": ["number", {"list": "string"}]}
    assert problems(["a"], either) == []
    assert problems("a", either) == [("config", "must be one of: a number, a list")]


def test_a_type_the_data_file_does_not_define_is_a_mistake_of_the_data_not_of_the_layout() -> None:
    with pytest.raises(ValueError, match="bad type form in the rules data: 'set'"):
        problems([], {"set": "number"})


def test_a_field_reference_names_keys_items_and_the_keys_of_a_map() -> None:
    config = {"paths": [{"value": "/a.x"}, {"value": "/b.y"}], "topics": {"/t1": {}, "/t2": {}}}
    assert list(field_values(config, "paths.[].value")) == [
        ("paths[0].value", "/a.x"),
        ("paths[1].value", "/b.y"),
    ]
    assert list(field_values(config, "topics.{}")) == [("topics./t1", "/t1"), ("topics./t2", "/t2")]
    assert list(field_values(config, "missing.value")) == []
    with pytest.raises(ValueError, match="must end a field reference"):
        list(field_values(config, "topics.{}.x"))
