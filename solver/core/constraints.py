"""Constraints a rule set declares between characteristic values, as data.

A rule file says which combinations may exist, for example "Flight only for UAVs"::

    constraints:
      - name: Flight only for UAVs
        when: {motion_control: Flight}
        require: {kinematic_type: UAV}
      - name: no force feedback on drones
        forbid: {kinematic_type: UAV, sensor_type: Force Sensor}

Each becomes a :class:`RuleConstraint`: a ``require`` rule holds when its ``when`` conditions
do not all hold or its ``require`` conditions all hold (no ``when``: always required); a
``forbid`` rule holds unless all of its conditions hold together. A :class:`Condition` is "the
value of one characteristic lies in this set", with the set already resolved from what the
file wrote (a value, a list, a range, a component, a complement).

Not here: reading the YAML (:mod:`solver.core.rules`) or turning constraints into a
python-constraint problem (:mod:`solver.core.model`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Literal

from solver.errors import Location
from solver.untrusted import shown

__all__ = ["Condition", "RuleConstraint", "Value"]

Value = str | int


@dataclass(frozen=True, slots=True)
class Condition:
    """The value of ``characteristic`` lies in ``allowed``; ``text`` is how the file wrote it."""

    characteristic: str
    allowed: frozenset[Value]
    text: str

    def holds(self, value: Value) -> bool:
        return value in self.allowed

    def __str__(self) -> str:
        return f"{self.characteristic} {self.text}"


@dataclass(frozen=True, slots=True)
class RuleConstraint:
    """One declared constraint, named and located so that explanations can cite it."""

    name: str
    kind: Literal["require", "forbid"]
    when: tuple[Condition, ...]
    conditions: tuple[Condition, ...]
    location: Location = field(compare=False)

    @property
    def characteristics(self) -> tuple[str, ...]:
        """The characteristics this constraint reads, in the order it mentions them."""
        names: dict[str, None] = {}
        for condition in (*self.when, *self.conditions):
            names.setdefault(condition.characteristic, None)
        return tuple(names)

    def holds(self, robot: Mapping[str, Value]) -> bool:
        """Whether ``robot`` (a value for every characteristic this reads) satisfies the rule."""
        if self.kind == "forbid":
            return not all(c.holds(robot[c.characteristic]) for c in self.conditions)
        if not all(c.holds(robot[c.characteristic]) for c in self.when):
            return True
        return all(c.holds(robot[c.characteristic]) for c in self.conditions)

    def predicate(self) -> Callable[..., bool]:
        """:meth:`holds` as a function of the values in :attr:`characteristics` order.

        Built once per constraint so the constraint solver's inner loop does set lookups only.
        """
        order = {name: position for position, name in enumerate(self.characteristics)}
        when = tuple((order[c.characteristic], c.allowed) for c in self.when)
        then = tuple((order[c.characteristic], c.allowed) for c in self.conditions)
        if self.kind == "forbid":

            def forbids(*values: Value) -> bool:
                return not all(values[i] in allowed for i, allowed in then)

            return forbids

        def requires(*values: Value) -> bool:
            if not all(values[i] in allowed for i, allowed in when):
                return True
            return all(values[i] in allowed for i, allowed in then)

        return requires

    def describe(self) -> str:
        """One line a rule author recognises: the name and what it says."""
        if self.kind == "forbid":
            body = "forbid " + " and ".join(str(c) for c in self.conditions)
        elif self.when:
            body = (
                "when "
                + " and ".join(str(c) for c in self.when)
                + " require "
                + " and ".join(str(c) for c in self.conditions)
            )
        else:
            body = "require " + " and ".join(str(c) for c in self.conditions)
        return f"{shown(self.name, quoted=True)} ({body})"
