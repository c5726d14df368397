"""Coverage of each characteristic's values by its UI components (presentation groups,
cluster arrangements).

Every value must need exactly one component: a value in none (a *gap*) leaves its robots
without a UI configuration, so they get the default one; a value in two (an *overlap*) makes
the choice of configuration a minimisation problem (and usually is a typo). For whole-number
characteristics the components are ranges, so the checks also look at the ranges themselves:
inverted ranges, ranges that serve no value, and ranges left open at one end. Read literally,
the article's equation 2 (``1 < i <= 5``, ``6 < i <= 10``, ...) leaves 1, 6, 11 and 16 in no
arrangement; these checks find exactly those gaps.

Works on the loaded components only (``Characteristic.membership``, ``Component.low/high``);
no constraint solving. Characteristics that declare no components (each value its own) are
covered by construction.

Not here: whether the overlaps make "can share a component" non-transitive
(:mod:`solver.check.equivalence`).
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.context import RulesContext, integer_runs
from solver.check.finding import Check, Finding
from solver.core.constraints import Value
from solver.core.ruleset import Characteristic, Component
from solver.untrusted import shown

__all__ = ["CHECKS", "declared_range"]

_BOUNDS = ("min", "above", "max", "below")


def declared_range(
    context: RulesContext, characteristic: Characteristic, component: Component
) -> str:
    """How the file wrote a component's range: ``above: 6, max: 10``."""
    spec = context.raw(context.component_path(characteristic, component))
    if not isinstance(spec, dict):
        return ""
    return ", ".join(f"{key}: {spec[key]}" for key in _BOUNDS if key in spec)


def _named(context: RulesContext, characteristic: Characteristic, component: Component) -> str:
    if characteristic.kind != "integer":
        return shown(component.name, quoted=True)
    declared = declared_range(context, characteristic, component)
    return f"{shown(component.name, quoted=True)} ({declared})"


def _declared(characteristic: Characteristic) -> bool:
    return characteristic.declared_components and bool(characteristic.components)


def _gaps(context: RulesContext) -> Iterator[Finding]:
    for characteristic in context.rules.characteristics:
        if not _declared(characteristic):
            continue
        missing = [
            v
            for v, members in zip(characteristic.values, characteristic.membership, strict=True)
            if not members
        ]
        if characteristic.kind != "integer":
            for value in missing:
                yield GAP.finding(
                    context.value_location(characteristic, value),
                    f"{characteristic.name} {shown(str(value), quoted=True)} is in no "
                    f"component: robots with it "
                    "get the default UI configuration",
                )
            continue
        for run in integer_runs(missing):
            yield _integer_gap(context, characteristic, run)


def _integer_gap(
    context: RulesContext, characteristic: Characteristic, run: tuple[int, ...]
) -> Finding:
    ranged = [c for c in characteristic.components if c.values]
    before = [c for c in ranged if int(c.values[-1]) < run[0]]
    after = [c for c in ranged if int(c.values[0]) > run[-1]]
    below = max(before, key=lambda c: int(c.values[-1])) if before else None
    above = min(after, key=lambda c: int(c.values[0])) if after else None
    counts = str(run[0]) if len(run) == 1 else f"{run[0]}..{run[-1]}"
    parts = []
    if below is not None:
        parts.append(f"{_named(context, characteristic, below)} ends at {below.values[-1]}")
    if above is not None:
        parts.append(f"{_named(context, characteristic, above)} starts at {above.values[0]}")
    reason = f": {' and '.join(parts)}" if parts else ""
    if above is not None:
        location = context.component_location(characteristic, above, "min", "above")
    elif below is not None:
        location = context.component_location(characteristic, below, "max", "below")
    else:
        location = context.locate(("characteristics", characteristic.name, "components"))
    return GAP.finding(
        location,
        f"{characteristic.name} {counts} is in no component{reason}; "
        "robots with it get the default UI configuration",
    )


def _overlaps(context: RulesContext) -> Iterator[Finding]:
    for characteristic in context.rules.characteristics:
        if not _declared(characteristic):
            continue
        # Consecutive values with the same components are one finding ("5..6 is in ...").
        groups: list[tuple[tuple[int, ...], list[Value]]] = []
        for value, members in zip(characteristic.values, characteristic.membership, strict=True):
            if len(members) < 2:
                continue
            same_run = (
                groups
                and groups[-1][0] == members
                and (characteristic.kind == "integer" and int(groups[-1][1][-1]) == int(value) - 1)
            )
            if same_run:
                groups[-1][1].append(value)
            else:
                groups.append((members, [value]))
        for members, values in groups:
            components = [characteristic.components[i] for i in members]
            names = [_named(context, characteristic, c) for c in components]
            last = components[-1]
            if characteristic.kind == "integer":
                listed = str(values[0]) if len(values) == 1 else f"{values[0]}..{values[-1]}"
                location = context.component_location(characteristic, last, "min", "above")
            else:
                listed = shown(str(values[0]), quoted=True)
                path = (*context.component_path(characteristic, last), "values")
                location = context.locate(context.lists.path(path, values[0]))
            yield OVERLAP.finding(
                location,
                f"{characteristic.name} {listed} is in {len(components)} components: "
                f"{', '.join(names[:-1])} and {names[-1]}",
            )


def _ranges(context: RulesContext, *, want: str) -> Iterator[Finding]:
    for characteristic in context.rules.characteristics:
        if not _declared(characteristic):
            continue
        low_end, high_end = characteristic.values[0], characteristic.values[-1]
        for component in characteristic.components:
            location = context.component_location(characteristic, component)
            named = _named(context, characteristic, component)
            inverted = (
                component.low is not None
                and component.high is not None
                and component.low > component.high
            )
            if want == "inverted" and inverted:
                yield INVERTED.finding(
                    location,
                    f"{characteristic.name} component {named} has an inverted "
                    f"range: it starts at {component.low} and ends at "
                    f"{component.high}, so it serves no value",
                )
            elif want == "empty" and not inverted and not component.values:
                where = (
                    ""
                    if characteristic.kind != "integer"
                    else f": {characteristic.name} only takes {low_end}..{high_end}"
                )
                yield EMPTY.finding(
                    location, f"{characteristic.name} component {named} serves no value{where}"
                )
            elif (
                want == "unbounded"
                and characteristic.kind == "integer"
                and (component.low is None or component.high is None)
            ):
                side, end = ("upper", high_end) if component.high is None else ("lower", low_end)
                yield UNBOUNDED.finding(
                    location,
                    f"{characteristic.name} component {named} has no {side} bound: "
                    f"it reaches the range's end ({end}) and silently grows "
                    "if the range does",
                )


def _inverted(context: RulesContext) -> Iterator[Finding]:
    yield from _ranges(context, want="inverted")


def _empty(context: RulesContext) -> Iterator[Finding]:
    yield from _ranges(context, want="empty")


def _unbounded(context: RulesContext) -> Iterator[Finding]:
    yield from _ranges(context, want="unbounded")


GAP = Check(
    "coverage-gap",
    "error",
    "rules",
    "A value of a characteristic that no component serves: a sensor type in no presentation "
    "group, or a sensor count in no arrangement. Robots with that value have no UI "
    "configuration and get the default one. For whole-number characteristics consecutive "
    "missing counts are reported together, at the bound of the component that should start "
    "there (the literal reading of the article's equation 2, `above: 1, max: 5`, "
    "`above: 6, max: 10`, ..., misses exactly 1, 6, 11 and 16).",
    _gaps,
)
OVERLAP = Check(
    "coverage-overlap",
    "warning",
    "rules",
    "A value that two or more components serve: a sensor type in two presentation groups, or "
    "a count in two arrangements. The solver still works (it picks the fewest configurations "
    "by an exact minimum cover) but the UI a robot gets is no longer determined by its "
    "values alone, and overlapping ranges are most often an off-by-one slip.",
    _overlaps,
)
INVERTED = Check(
    "inverted-range",
    "error",
    "rules",
    "An arrangement whose lower bound lies above its upper bound (`min: 10, max: 5`, or "
    "`above: 5, below: 6`), so it serves no count at all.",
    _inverted,
)
EMPTY = Check(
    "empty-component",
    "error",
    "rules",
    "A component that serves no value of its characteristic: a presentation group with an "
    "empty value list, or an arrangement whose range lies wholly outside the characteristic's "
    "range. It still counts in the bound T and can never be used.",
    _empty,
)
UNBOUNDED = Check(
    "unbounded-range",
    "warning",
    "rules",
    "An arrangement declared with only one bound (`above: 25` and no `max`). It ends where the "
    "characteristic's range ends, which is what the author meant today, but it silently takes "
    "every new count if the range is ever extended. Write the upper (or lower) bound out.",
    _unbounded,
)

CHECKS: tuple[Check[RulesContext], ...] = (GAP, OVERLAP, INVERTED, EMPTY, UNBOUNDED)
