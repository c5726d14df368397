"""Invariants of solving, on random rule sets and teams (hypothesis).

The oracle is plain brute force: every combination of the team's selected values, kept when it
satisfies every rule constraint (``RuleConstraint.holds``), grouped by the components its values
belong to. It shares no code with python-constraint or the partitioner.
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import math
from dataclasses import replace
from typing import Any

import highspy
import numpy as np
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from solver import RuleSet, Team, robots, solve
from solver.core.rules import parse_rules
from solver.core.team import parse_team
from solver.engines import structure
from solver.engines.fast import robots as robots_stream
from solver.files.output import csv_row
from solver.files.yamlio import parse_document
from solver.reporting.listing import numbered_robots, write_robots


@st.composite
def rule_data(
    draw: st.DrawFn, with_constraints: bool = True, irregular: bool = False
) -> dict[str, Any]:
    """A random rule set; ``irregular`` adds overlapping components and gaps."""
    types = [f"T{i}" for i in range(draw(st.integers(1, 3)))]
    characteristics: dict[str, Any] = {"kind": {"values": types}}
    for j in range(draw(st.integers(1, 3))):
        if draw(st.booleans()):
            values = [f"v{j}{k}" for k in range(draw(st.integers(1, 5)))]
            labels = draw(
                st.lists(
                    st.integers(0, len(values) - 1), min_size=len(values), max_size=len(values)
                )
            )
            components = [
                {
                    "name": f"c{j}{label}",
                    "values": [v for v, lab in zip(values, labels, strict=True) if lab == label],
                }
                for label in sorted(set(labels))
            ]
            if irregular and draw(st.booleans()):
                # One more component over random values: overlaps with the others.
                components.append(
                    {
                        "name": f"extra{j}",
                        "values": draw(st.lists(st.sampled_from(values), min_size=1, unique=True)),
                    }
                )
            if irregular and len(components) > 1 and draw(st.booleans()):
                components.pop(0)  # its values may now be in no component: a gap
            characteristics[f"cat{j}"] = {"values": values, "components": components}
        else:
            high = draw(st.integers(1, 12))
            cuts = sorted(draw(st.sets(st.integers(2, high), max_size=3))) if high > 1 else []
            bounds = [1, *cuts, high + 1]
            characteristics[f"num{j}"] = {
                "range": {"min": 1, "max": high},
                "components": [
                    {
                        "name": f"a{j}{i}",
                        "min": low,
                        "max": nxt - 1,
                        "cluster_size": draw(st.integers(1, 3)),
                    }
                    for i, (low, nxt) in enumerate(itertools.pairwise(bounds))
                ],
            }
    data: dict[str, Any] = {"characteristics": characteristics}
    if with_constraints:
        constraints = []
        for _ in range(draw(st.integers(0, 3))):
            names = draw(
                st.lists(
                    st.sampled_from(sorted(characteristics)), min_size=1, max_size=2, unique=True
                )
            )
            conditions = {
                name: draw(
                    st.lists(
                        st.sampled_from(_domain(characteristics[name])), min_size=1, unique=True
                    )
                )
                for name in names
            }
            if len(names) == 2 and draw(st.booleans()):
                first, second = names
                constraints.append(
                    {"when": {first: conditions[first]}, "require": {second: conditions[second]}}
                )
            else:
                constraints.append({"forbid": conditions})
        data["constraints"] = constraints
    return data


def _domain(spec: dict[str, Any]) -> list[Any]:
    if "values" in spec:
        return list(spec["values"])
    return list(range(spec["range"]["min"], spec["range"]["max"] + 1))


@st.composite
def problems(draw: st.DrawFn, with_constraints: bool = True, irregular: bool = False) -> Team:
    data = draw(rule_data(with_constraints, irregular))
    rules = parse_rules(parse_document(yaml.safe_dump(data, sort_keys=False), "rules.yaml"))
    key, *others = rules.characteristics
    chosen = draw(st.lists(st.sampled_from([str(v) for v in key.values]), min_size=1, unique=True))
    team: dict[str, Any] = {}
    for type_name in chosen:
        selection: dict[str, Any] = {}
        for characteristic in others:
            if characteristic.kind == "integer":
                selection[characteristic.name] = draw(st.sampled_from(characteristic.values))
            else:
                selection[characteristic.name] = draw(
                    st.lists(st.sampled_from(characteristic.values), min_size=1, unique=True)
                )
        team[type_name] = selection
    document = parse_document(yaml.safe_dump({"team": team}, sort_keys=False), "team.yaml")
    return parse_team(document, rules)


def brute_force(team: Team, type_index: int) -> list[tuple[Any, ...]]:
    rules = team.rules
    domains = team.selections[type_index].domains
    return [
        robot
        for robot in itertools.product(*domains)
        if all(rule.holds(dict(zip(rules.names, robot, strict=True))) for rule in rules.constraints)
    ]


def component_key(rules: RuleSet, robot: tuple[Any, ...]) -> tuple[int, ...]:
    return tuple(
        c.membership[c.values.index(v)][0]
        for c, v in zip(rules.characteristics, robot, strict=True)
    )


@settings(max_examples=120, deadline=None)
@given(problems())
def test_every_valid_robot_is_in_exactly_one_nonempty_configuration(team: Team) -> None:
    solution = solve(team)
    rules = team.rules
    for index, summary in enumerate(solution.by_type):
        valid = brute_force(team, index)
        assert summary.valid_robots == len(valid)
        assert summary.ui_configurations == len({component_key(rules, r) for r in valid})
        mine = [c for c in solution.configurations if c.kinematic_type == summary.kinematic_type]
        assert sum(c.robots for c in mine) == len(valid)
        assert all(c.robots > 0 for c in mine)
        for robot in valid:
            configuration = solution.configuration_for(robot)
            assert configuration is not None
            assert all(
                value in component.values
                for value, component in zip(robot, configuration.components, strict=True)
            )


@settings(max_examples=120, deadline=None)
@given(problems())
def test_configurations_never_exceed_the_bound_and_totals_add_up(team: Team) -> None:
    solution = solve(team)
    assert solution.totals.ui_configurations <= solution.bound
    assert solution.totals.valid_robots == sum(t.valid_robots for t in solution.by_type)
    assert solution.totals.ui_configurations == len(solution.configurations)
    assert [c.number for c in solution.configurations] == list(
        range(1, len(solution.configurations) + 1)
    )
    assert solution.default_configuration == len(solution.configurations) + 1


@settings(max_examples=120, deadline=None)
@given(problems(with_constraints=False))
def test_without_constraints_the_counts_follow_the_closed_form(team: Team) -> None:
    # SPEC section 4: robots = product of selection sizes; configurations = product of the
    # numbers of components the selections reach.
    solution = solve(team)
    for selection, summary in zip(team.selections, solution.by_type, strict=True):
        assert summary.valid_robots == math.prod(len(d) for d in selection.domains)
        reached = [
            len({c.membership[c.values.index(v)][0] for v in domain})
            for c, domain in zip(team.rules.characteristics, selection.domains, strict=True)
        ]
        assert summary.ui_configurations == math.prod(reached)


@settings(max_examples=150, deadline=None)
@given(problems(irregular=True))
def test_all_engines_give_identical_partitions(team: Team) -> None:
    reference = solve(team, engine="csp")
    for engine in ("fast", "structure", "auto"):
        other = solve(team, engine=engine)
        assert other.by_type == tuple(
            replace(t, method=m.method)
            for t, m in zip(reference.by_type, other.by_type, strict=True)
        )
        assert other.configurations == reference.configurations
        assert other.proven_minimal == reference.proven_minimal


@settings(max_examples=150, deadline=None)
@given(problems(irregular=True))
def test_fast_enumeration_yields_exactly_the_reference_robots(team: Team) -> None:
    for selection in team.selections:
        reference = sorted(robots(team.rules, selection.domains), key=repr)
        assert sorted(robots_stream(team.rules, selection), key=repr) == reference


@settings(max_examples=150, deadline=None)
@given(problems(irregular=True))
def test_counting_without_enumeration_equals_the_enumerated_counts(team: Team) -> None:
    counted = solve(team, count_only=True)
    enumerated = solve(team, engine="fast")
    assert [(t.valid_robots, t.ui_configurations, t.unserved_robots) for t in counted.by_type] == [
        (t.valid_robots, t.ui_configurations, t.unserved_robots) for t in enumerated.by_type
    ]
    assert counted.configurations == ()
    assert counted.default_configuration == enumerated.default_configuration


@settings(max_examples=100, deadline=None)
@given(problems(irregular=True), st.sampled_from(["csv", "jsonl"]))
def test_the_block_listing_is_the_robot_by_robot_listing(team: Team, fmt: str) -> None:
    listed = io.StringIO()
    write_robots(solve(team), listed, fmt=fmt)
    assert listed.getvalue() == listing_from_configurations(team, fmt)


def listing_from_configurations(team: Team, fmt: str) -> str:
    """Every robot in the fast engine's order, numbered by searching the listed configurations
    of the solution for the one it is given (:meth:`Solution.configuration_for`)."""
    solution = solve(team)
    names = team.rules.names
    numbered = [
        (
            solution.default_configuration if found is None else found.number,
            robot,
        )
        for selection in team.selections
        for robot in robots_stream(team.rules, selection)
        for found in [solution.configuration_for(robot)]
    ]
    reference = io.StringIO()
    if fmt == "csv":
        writer = csv.writer(reference, lineterminator="\n")
        writer.writerow(csv_row(["configuration", *names]))
        writer.writerows([number, *csv_row(robot)] for number, robot in numbered)
    else:
        for number, robot in numbered:
            line = {"configuration": number, **dict(zip(names, robot, strict=True))}
            reference.write(json.dumps(line, ensure_ascii=False) + "\n")
    return reference.getvalue()


@settings(max_examples=100, deadline=None)
@given(problems(irregular=True), st.sampled_from(["csv", "jsonl"]))
def test_robots_numbered_from_the_counts_alone_are_numbered_as_the_configurations_say(
    team: Team, fmt: str
) -> None:
    listed = io.StringIO()
    write_robots(solve(team, count_only=True), listed, fmt=fmt)
    assert listed.getvalue() == listing_from_configurations(team, fmt)
    by_rows = list(numbered_robots(solve(team, count_only=True)))
    assert by_rows == list(numbered_robots(solve(team)))


@st.composite
def overlapping(draw: st.DrawFn) -> Team:
    """Characteristics whose every value is in two components: sliding windows (covers that
    multiply across characteristics), a cycle of pairs (odd cycles do not: their product is
    covered jointly) or rings of three components over apart blocks of four values (covered
    jointly block by block), with random selections and, sometimes, a rule linking two of
    them."""
    characteristics: dict[str, Any] = {"kind": {"values": ["T0", "T1"]}}
    for j in range(draw(st.integers(2, 3))):
        values = [f"v{j}{k}" for k in range(draw(st.integers(3, 7)))]
        if draw(st.integers(0, 2)) == 0:
            values = [f"v{j}{k}" for k in range(4 * draw(st.integers(1, 2)))]
            groups = []
            for start in range(0, len(values), 4):
                a, b, c, d = values[start : start + 4]
                groups += [[a, b, d], [b, c, d], [c, a]]
        elif draw(st.booleans()):
            width = draw(st.integers(2, 3))
            starts = range(0, max(len(values) - width, 0) + 1, draw(st.integers(1, width - 1)))
            groups = [values[s : s + width] for s in starts]
            if groups[-1][-1] != values[-1]:
                groups.append(values[-width:])
        else:
            groups = [[v, values[(k + 1) % len(values)]] for k, v in enumerate(values)]
        characteristics[f"c{j}"] = {
            "values": values,
            "components": [{"name": f"g{j}{k}", "values": g} for k, g in enumerate(groups)],
        }
    data: dict[str, Any] = {"characteristics": characteristics}
    if draw(st.booleans()):
        data["constraints"] = [
            {
                "forbid": {
                    "c0": draw(st.sampled_from(characteristics["c0"]["values"])),
                    "c1": draw(st.sampled_from(characteristics["c1"]["values"])),
                }
            }
        ]
    rules = parse_rules(parse_document(yaml.safe_dump(data, sort_keys=False), "rules.yaml"))
    team = {
        kind: {
            c.name: draw(st.lists(st.sampled_from(c.values), min_size=1, unique=True))
            for c in rules.characteristics[1:]
        }
        for kind in draw(st.lists(st.sampled_from(["T0", "T1"]), min_size=1, unique=True))
    }
    document = parse_document(yaml.safe_dump({"team": team}, sort_keys=False), "team.yaml")
    return parse_team(document, rules)


def fewest_configurations(rules: RuleSet, valid: list[tuple[Any, ...]]) -> int:
    """The minimum hitting set of the robots' usable configurations, as one 0/1 program over
    every robot given straight to HiGHS (none of the solver's splitting)."""
    usable = [
        set(
            itertools.product(
                *(
                    c.membership[c.values.index(v)]
                    for c, v in zip(rules.characteristics, robot, strict=True)
                )
            )
        )
        for robot in valid
    ]
    keys = sorted(set().union(*usable))
    column = {key: i for i, key in enumerate(keys)}
    model = highspy.Highs()  # type: ignore[no-untyped-call]  # no hints in highspy
    model.setOptionValue("output_flag", False)
    every = np.arange(len(keys), dtype=np.int32)
    model.addVars(len(keys), np.zeros(len(keys)), np.ones(len(keys)))
    model.changeColsIntegrality(len(keys), every, np.ones(len(keys), dtype=np.uint8))
    model.changeColsCost(len(keys), every, np.ones(len(keys)))
    for found in usable:
        model.addRow(
            1, highspy.kHighsInf, len(found), [column[k] for k in found], [1.0] * len(found)
        )
    model.run()
    return round(model.getInfo().objective_function_value)


@settings(max_examples=150, deadline=None)
@given(overlapping())
def test_engines_agree_where_values_overlap_in_several_characteristics(team: Team) -> None:
    reference = solve(team, engine="csp")
    for engine in ("fast", "structure"):
        assert solve(team, engine=engine).configurations == reference.configurations
    counted = solve(team, count_only=True).by_type
    assert [t.ui_configurations for t in counted] == [
        t.ui_configurations for t in reference.by_type
    ]
    listed = io.StringIO()
    write_robots(solve(team, count_only=True), listed)
    assert listed.getvalue() == listing_from_configurations(team, "csv")
    for index, summary in enumerate(reference.by_type):
        valid = brute_force(team, index)
        assert summary.valid_robots == len(valid)
        assert summary.ui_configurations == fewest_configurations(team.rules, valid)
        for robot in valid:
            configuration = reference.configuration_for(robot)
            assert configuration is not None
            assert all(
                value in component.values
                for value, component in zip(robot, configuration.components, strict=True)
            )


@settings(max_examples=120, deadline=None)
@given(problems(irregular=True))
def test_blocks_held_as_numpy_masks_give_what_lists_of_combinations_give(team: Team) -> None:
    reference = solve(team, engine="csp")
    expected = listing_from_configurations(team, "csv")
    every_block_a_mask = 0
    kept, structure.VECTOR = structure.VECTOR, every_block_a_mask
    try:
        counted = solve(team, count_only=True)
        partitioned = solve(team, engine="structure")
        listed = io.StringIO()
        write_robots(solve(team, count_only=True), listed)
    finally:
        structure.VECTOR = kept
    assert [(t.valid_robots, t.ui_configurations, t.unserved_robots) for t in counted.by_type] == [
        (t.valid_robots, t.ui_configurations, t.unserved_robots) for t in reference.by_type
    ]
    assert partitioned.configurations == reference.configurations
    assert listed.getvalue() == expected
