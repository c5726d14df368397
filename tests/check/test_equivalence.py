""" "Can share a component" must be transitive; otherwise a witness triple is reported."""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import Any

import yaml
from hypothesis import given
from hypothesis import strategies as st

from solver.check import check_files
from solver.check.equivalence import witness_triple
from solver.core.constraints import Value
from solver.core.rules import load_rules, parse_rules
from solver.core.ruleset import Characteristic, Component
from solver.files.yamlio import parse_document
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
        "component"
    )


def test_overlapping_arrangements_give_a_witness_triple_of_counts() -> None:
    [finding] = findings("coverage-overlap.yaml", check="non-transitive")
    assert (
        "1 ~ 6 (both in 'few') and 6 ~ 7 (both in 'many'), but 1 and 7 share no component"
        in finding.message
    )


def _brute_triple(
    characteristic: Characteristic, first: Component, second: Component
) -> tuple[Value, Value, Value] | None:
    """The definition, value by value: the first A only in X that has a C only in Y."""
    in_first, in_second = set(first.values), set(second.values)
    shared = [v for v in characteristic.values if v in in_first and v in in_second]
    if not shared:
        return None
    for a in (v for v in characteristic.values if v in in_first and v not in in_second):
        for c in (v for v in characteristic.values if v in in_second and v not in in_first):
            if not any(a in k.values and c in k.values for k in characteristic.components):
                return a, shared[0], c
    return None


@st.composite
def _overlapping_components(draw: st.DrawFn) -> Characteristic:
    """A characteristic with random, often overlapping components: arrangements or groups."""
    if draw(st.booleans()):
        high = draw(st.integers(2, 30))
        components = []
        for index in range(draw(st.integers(2, 7))):
            low, top = sorted(draw(st.lists(st.integers(1, high), min_size=2, max_size=2)))
            bounds = {"min": low, "max": top}
            if draw(st.integers(0, 4)) == 0:
                del bounds[draw(st.sampled_from(["min", "max"]))]  # an open end
            components.append({"name": f"a{index}", **bounds})
        spec: dict[str, Any] = {"range": {"min": 1, "max": high}, "components": components}
    else:
        values = [f"v{i}" for i in range(draw(st.integers(2, 8)))]
        spec = {
            "values": values,
            "components": [
                {
                    "name": f"g{index}",
                    "values": draw(
                        st.lists(
                            st.sampled_from(values), min_size=1, max_size=len(values), unique=True
                        )
                    ),
                }
                for index in range(draw(st.integers(2, 7)))
            ],
        }
    text = yaml.safe_dump({"characteristics": {"kind": {"values": ["A"]}, "x": spec}})
    return parse_rules(parse_document(text, "random.yaml")).characteristic("x")


@given(_overlapping_components())
def test_witness_triples_are_those_of_the_definition(characteristic: Characteristic) -> None:
    for first, second in itertools.combinations(characteristic.components, 2):
        assert witness_triple(characteristic, first, second) == _brute_triple(
            characteristic, first, second
        )


def test_check_reports_every_triple_of_a_thousand_sliding_arrangements(tmp_path: Path) -> None:
    # 1,000 arrangements of 15 counts, each overlapping the next by 5, over 1..10,010.
    windows = "\n".join(
        f"      - {{name: w{k}, min: {10 * k + 1}, max: {10 * k + 15}}}" for k in range(1000)
    )
    rules = tmp_path / "slide.yaml"
    rules.write_text(
        "name: slide\ncharacteristics:\n  kind: {values: [A, B]}\n  n:\n"
        f"    range: {{min: 1, max: 10010}}\n    components:\n{windows}\n",
        encoding="utf-8",
    )
    found = [f for f in check_files([rules]).findings if f.check == "non-transitive"]
    assert len(found) == 999
    assert found[0].message == (
        "'can share a component' is not transitive for n: 1 ~ 11 (both in 'w0') and 11 ~ 16 "
        "(both in 'w1'), but 1 and 16 share no component"
    )
    assert found[-1].message.endswith(
        "9981 ~ 9991 (both in 'w998') and 9991 ~ 9996 (both in 'w999'), but 9981 and 9996 "
        "share no component"
    )
