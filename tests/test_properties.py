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

import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from solver import RuleSet, Team, robots, solve
from solver.core.rules import parse_rules
from solver.core.team import parse_team
from solver.engines.fast import robots as robots_stream
from solver.files.yamlio import parse_document
from solver.reporting.listing import numbered_robots, write_robots
from solver.reporting.render import csv_row


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
    solution = solve(team)
    listed = io.StringIO()
    write_robots(solution, listed, fmt=fmt)
    names = team.rules.names
    reference = io.StringIO()
    if fmt == "csv":
        writer = csv.writer(reference, lineterminator="\n")
        writer.writerow(csv_row(["configuration", *names]))
        writer.writerows([number, *csv_row(robot)] for number, robot in numbered_robots(solution))
    else:
        for number, robot in numbered_robots(solution):
            line = {"configuration": number, **dict(zip(names, robot, strict=True))}
            reference.write(json.dumps(line, ensure_ascii=False) + "\n")
    assert listed.getvalue() == reference.getvalue()
