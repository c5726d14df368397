"""Shared by the check tests: the fixtures folder, running checks, random small rule sets.

The brute-force oracle (:func:`valid_robots`) enumerates every combination with
``itertools.product`` and keeps those for which every constraint ``holds``: it shares no code
with python-constraint or with :mod:`solver.core.analysis`.
"""

from __future__ import annotations

import itertools
import random
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import yaml
from hypothesis import strategies as st

from solver.check import Finding, check_files
from solver.core.constraints import RuleConstraint, Value
from solver.core.rules import parse_rules
from solver.core.ruleset import RuleSet
from solver.files.yamlio import parse_document
from tests.conftest import ROOT

FIXTURES = ROOT / "tests" / "fixtures" / "check"


def fixture(name: str) -> Path:
    return FIXTURES / name


def findings(*names: str, check: str | None = None) -> list[Finding]:
    """The findings of checking fixture files together (only ``check``'s, if given)."""
    report = check_files([fixture(name) for name in names])
    return [f for f in report.findings if check is None or f.check == check]


def intricate_rules(types: int = 1_000, characteristics: int = 999, shared: int = 1_000) -> str:
    """A rule set within every size limit that takes ``check`` minutes (item 6 of issue 36).

    ``types`` kinematic types, each with a constraint of its own (so each type's questions go
    to an oracle of its own), beside ``shared`` constraints about every type, each forbidding
    one pair of values of two of ``characteristics`` characteristics of three values (seeded,
    so every run writes the same file). Every type then has some 1,200 classes no first model
    shows, each a question of its own: with the defaults, 108 KB that took 111 s of CPU and
    2.8 GB to check, 99 s and 480 MB since.
    """
    chosen = random.Random(36)
    lines = [
        "name: intricate",
        "characteristics:",
        f"  kinematic_type: {{values: [{', '.join(f'K{i}' for i in range(types))}]}}",
        *(f"  c{c}: {{values: [a, b, c]}}" for c in range(characteristics)),
        "constraints:",
        *(f"  - forbid: {{kinematic_type: K{i}, c{i % characteristics}: a}}" for i in range(types)),
    ]
    for _ in range(shared):
        first, second = chosen.sample(range(characteristics), 2)
        one, other = chosen.choice("abc"), chosen.choice("abc")
        lines.append(f"  - forbid: {{c{first}: {one}, c{second}: {other}}}")
    return "\n".join(lines) + "\n"


def where(found: Sequence[Finding]) -> list[tuple[str, int, int]]:
    """(file name, line, column) of each finding, in report order."""
    return [(Path(f.location.file).name, f.line, f.column) for f in found]


def valid_robots(
    rules: RuleSet,
    domains: Sequence[Sequence[Value]],
    constraints: Sequence[RuleConstraint] | None = None,
) -> list[tuple[Value, ...]]:
    """Brute force: every combination over ``domains`` that satisfies ``constraints``."""
    chosen = rules.constraints if constraints is None else constraints
    return [
        robot
        for robot in itertools.product(*domains)
        if all(rule.holds(dict(zip(rules.names, robot, strict=True))) for rule in chosen)
    ]


def _selection(draw: st.DrawFn, domain: list[Any]) -> list[Any]:
    return draw(st.lists(st.sampled_from(domain), min_size=1, max_size=len(domain), unique=True))


@st.composite
def rule_sets(draw: st.DrawFn, max_constraints: int = 5) -> RuleSet:
    """A random small rule set: 1-3 types, 1-2 more characteristics, 0-5 constraints mixing
    ``forbid``, ``require`` and ``when``/``require`` over one or two characteristics."""
    domains: dict[str, list[Any]] = {"kind": [f"T{i}" for i in range(draw(st.integers(1, 3)))]}
    characteristics: dict[str, Any] = {"kind": {"values": domains["kind"]}}
    for j in range(draw(st.integers(1, 2))):
        if draw(st.booleans()):
            values = [f"v{j}{k}" for k in range(draw(st.integers(1, 4)))]
            domains[f"cat{j}"] = values
            characteristics[f"cat{j}"] = {"values": values}
        else:
            high = draw(st.integers(1, 6))
            domains[f"num{j}"] = list(range(1, high + 1))
            characteristics[f"num{j}"] = {"range": {"min": 1, "max": high}}
    names = sorted(domains)
    constraints = []
    for index in range(draw(st.integers(0, max_constraints))):
        kind = draw(st.sampled_from(["forbid", "require", "when"]))
        first = draw(st.lists(st.sampled_from(names), min_size=1, max_size=2, unique=True))
        rule: dict[str, Any] = {"name": f"r{index}"}
        if kind == "forbid":
            rule["forbid"] = {name: _selection(draw, domains[name]) for name in first}
        elif kind == "require":
            rule["require"] = {name: _selection(draw, domains[name]) for name in first}
        else:
            then = draw(st.lists(st.sampled_from(names), min_size=1, max_size=2, unique=True))
            rule["when"] = {name: _selection(draw, domains[name]) for name in first}
            rule["require"] = {name: _selection(draw, domains[name]) for name in then}
        constraints.append(rule)
    data = {"characteristics": characteristics, "constraints": constraints}
    return parse_rules(parse_document(yaml.safe_dump(data, sort_keys=False), "random.yaml"))


def pigeonhole_rules(pigeons: int = 16, holes: int = 15) -> str:
    """A rule set of ``pigeons`` characteristics of ``holes`` values, no two alike (a forbid
    for each pair and value): no robot exists when there are more pigeons than holes, and
    resolution (so a SAT solver) takes exponentially many conflicts to prove it."""
    values = ", ".join(f"h{h}" for h in range(holes))
    return (
        "name: pigeonhole\ncharacteristics:\n  kinematic_type:\n    values: [A]\n"
        + "".join(f"  p{i}:\n    values: [{values}]\n" for i in range(pigeons))
        + "constraints:\n"
        + "".join(
            f"  - forbid: {{p{i}: h{h}, p{j}: h{h}}}\n"
            for h in range(holes)
            for i in range(pigeons)
            for j in range(i + 1, pigeons)
        )
    )
