"""Rule sets as values: characteristics, their values, the UI components they map to.

A rule set is written once and reused for many teams. It declares

* the **characteristics** (kinematic type, motion control, ... or any of the user's own), each
  either *categorical* (a list of named values) or *integer* (a range such as 1..50);
* for each characteristic, its **components**: the UI component every value needs. Values in the
  same component can share a UI configuration (the article's presentation groups and cluster
  arrangements). Without a ``components`` list every value is its own component
  (:class:`OnePerValue`);
* which characteristic team files are keyed by (``team_key``, the kinematic type);
* optional **constraints** between values (:mod:`solver.core.constraints`) and a declared ``bound``.

Every type here is frozen; nothing here reads a file.

Not here: reading a rule file (:mod:`solver.core.rules`), team selections
(:mod:`solver.core.team`), solving (:mod:`solver.solving.solution`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Literal, TypeVar, overload

from solver.core.constraints import RuleConstraint, Value
from solver.errors import Location
from solver.files.yamlio import Document
from solver.untrusted import shown

__all__ = [
    "Characteristic",
    "Component",
    "Kind",
    "OnePerValue",
    "RuleSet",
    "Run",
    "one_component_each",
]

Kind = Literal["categorical", "integer"]
T = TypeVar("T")

_WHOLE_NUMBER = re.compile(r"[+-]?[0-9]+")


@dataclass(frozen=True, slots=True)
class Component:
    """One UI component: the values of a characteristic that it serves.

    For integer characteristics a component is an *arrangement*: a range of counts shown as
    ``ceil(count / cluster_size)`` clusters. ``low``/``high`` are the inclusive bounds as
    declared (``None`` where the file left the range open).
    """

    name: str
    index: int
    values: tuple[Value, ...]
    description: str = ""
    low: int | None = None
    high: int | None = None
    cluster_size: int = 1
    location: Location | None = field(default=None, compare=False)

    def clusters(self, count: int) -> int:
        """How many UI elements ``count`` sensors take in this arrangement."""
        return math.ceil(count / self.cluster_size)

    def describe_range(self) -> str:
        """``6..10`` or ``26..`` (open) for an arrangement; empty for categorical components."""
        if self.low is None and self.high is None:
            return ""
        return f"{'' if self.low is None else self.low}..{'' if self.high is None else self.high}"


class Run(tuple[int, ...]):
    """Whole numbers ``low..high`` in order: an integer characteristic's values as the reader
    makes them. A count's position and the counts ``low..N`` need no look at the others."""

    __slots__ = ()

    def position(self, value: object) -> int | None:
        """Where ``value`` is, or None; only whole numbers (not ``True``) are looked up here."""
        if type(value) is not int or not self or not self[0] <= value <= self[-1]:
            return None
        return value - self[0]


class _Made(Sequence[T]):
    """A read-only sequence whose items are made when asked for, equal (and hashing) as the
    tuple of the same items would."""

    __slots__ = ()

    def _item(self, index: int) -> T:
        raise NotImplementedError

    def _key(self) -> object:
        """What two sequences of this class are equal by, without making their items."""
        raise NotImplementedError

    @overload
    def __getitem__(self, index: int) -> T: ...
    @overload
    def __getitem__(self, index: slice) -> tuple[T, ...]: ...
    def __getitem__(self, index: int | slice) -> T | tuple[T, ...]:
        positions = range(len(self))
        if isinstance(index, slice):
            return tuple(self._item(i) for i in positions[index])
        return self._item(positions[index])

    def __iter__(self) -> Iterator[T]:
        return (self._item(i) for i in range(len(self)))

    def __eq__(self, other: object) -> bool:
        if type(other) is type(self):
            return self._key() == other._key()
        if isinstance(other, Sequence) and not isinstance(other, str):
            return len(other) == len(self) and all(a == b for a, b in zip(self, other, strict=True))
        return NotImplemented

    def __hash__(self) -> int:
        return hash(tuple(self))

    def __repr__(self) -> str:
        return f"{type(self).__name__}(<{len(self)} items>)"


class OnePerValue(_Made[Component]):
    """The components of a characteristic declared without ``components``: value *i* is
    component *i*, named after it. Each is made when first asked for (and kept), so a range
    of 100,000 counts costs nothing to read until something looks at its components."""

    __slots__ = ("_made", "_values")

    def __init__(self, values: Sequence[Value]) -> None:
        self._values = values
        self._made: dict[int, Component] = {}

    def __len__(self) -> int:
        return len(self._values)

    def _item(self, index: int) -> Component:
        made = self._made.get(index)
        if made is None:
            value = self._values[index]
            number = value if isinstance(value, int) else None
            made = Component(str(value), index, (value,), low=number, high=number)
            self._made[index] = made
        return made

    def _key(self) -> object:
        return self._values


class _Itself(_Made[tuple[int, ...]]):
    """The membership of :class:`OnePerValue` components: value *i* is in component *i*."""

    __slots__ = ("_size",)

    def __init__(self, size: int) -> None:
        self._size = size

    def __len__(self) -> int:
        return self._size

    def _item(self, index: int) -> tuple[int, ...]:
        return (index,)

    def _key(self) -> object:
        return self._size


def one_component_each(
    values: Sequence[Value],
) -> tuple[Sequence[Component], Sequence[tuple[int, ...]]]:
    """The components and membership of a characteristic declared without ``components``:
    value *i* is component *i*, made when asked for (100,000 counts are common)."""
    return OnePerValue(values), _Itself(len(values))


@dataclass(frozen=True)
class Characteristic:
    """A named variable with a finite domain and the components its values map to."""

    name: str
    label: str
    kind: Kind
    values: tuple[Value, ...]
    components: Sequence[Component]
    # membership[i]: indices of the components that value i belongs to (normally exactly one).
    membership: Sequence[tuple[int, ...]]
    declared_components: bool = False
    description: str = ""
    location: Location | None = field(default=None, compare=False)

    @cached_property
    def positions(self) -> dict[Value, int]:
        """Value -> its position in the domain."""
        return {value: index for index, value in enumerate(self.values)}

    def index(self, value: Value) -> int | None:
        """Position of ``value`` in the domain, or ``None`` if it is not a value of this."""
        if isinstance(self.values, Run) and type(value) is int:
            return self.values.position(value)
        return self.positions.get(value)

    def components_of(self, value: Value) -> tuple[Component, ...]:
        """The components ``value`` needs (empty for a value in no component: a gap)."""
        position = self.index(value)
        if position is None:
            return ()
        return tuple(self.components[i] for i in self.membership[position])

    def component(self, name: str) -> Component | None:
        return self._components_by_name.get(name)

    @cached_property
    def _components_by_name(self) -> dict[str, Component]:
        # The first of a name, as a walk of the list finds it (a duplicate is a fault).
        found: dict[str, Component] = {}
        for component in self.components:
            found.setdefault(component.name, component)
        return found

    @cached_property
    def is_partition(self) -> bool:
        """Every value in exactly one component: "shares a component" is an equivalence."""
        return all(len(members) == 1 for members in self.membership)

    def parse_value(self, text: str) -> Value | None:
        """The domain value written as ``text`` (``"3"`` for integers), or ``None``."""
        if self.kind == "integer":
            # ASCII digits only: int() also reads "٣" (Arabic-Indic three) and "1_0" as numbers,
            # which no one typing a robot's characteristics means.
            if _WHOLE_NUMBER.fullmatch(text.strip()) is None or len(text.strip()) > 20:
                return None  # more digits than 63 bits hold: no value (int() of 4,300 raises)
            number = int(text.strip())
            return number if self.index(number) is not None else None
        return text if text in self.positions else None


@dataclass(frozen=True)
class RuleSet:
    """A whole rule set: characteristics in declared order, the team key, the constraints."""

    name: str
    file: str
    characteristics: tuple[Characteristic, ...]
    team_key: str
    constraints: tuple[RuleConstraint, ...] = ()
    declared_bound: int | None = None
    description: str = ""
    source: str = ""
    document: Document | None = field(default=None, compare=False, repr=False)

    def __repr__(self) -> str:  # short, for notebooks: the fields are one attribute away
        return (
            f"<RuleSet {shown(self.name, quoted=True)} ({self.file}): {', '.join(self.names)}; "
            f"{len(self.constraints)} constraints>"
        )

    @cached_property
    def _by_name(self) -> dict[str, Characteristic]:
        return {c.name: c for c in self.characteristics}

    def characteristic(self, name: str) -> Characteristic:
        """The characteristic called ``name``; :class:`KeyError` if there is none."""
        return self._by_name[name]

    @cached_property
    def names(self) -> tuple[str, ...]:
        return tuple(c.name for c in self.characteristics)

    @cached_property
    def positions(self) -> dict[str, int]:
        """Characteristic name -> its position in :attr:`characteristics`."""
        return {name: index for index, name in enumerate(self.names)}

    @property
    def key(self) -> Characteristic:
        """The characteristic team files are keyed by (the kinematic type)."""
        return self._by_name[self.team_key]

    @cached_property
    def key_position(self) -> int:
        return self.names.index(self.team_key)

    @property
    def bound(self) -> int:
        """T: how many distinct UI configurations the rules could ever produce."""
        return math.prod(len(c.components) for c in self.characteristics)

    @property
    def bound_factors(self) -> tuple[int, ...]:
        return tuple(len(c.components) for c in self.characteristics)

    @cached_property
    def value_classes(self) -> tuple[tuple[tuple[Value, ...], ...], ...]:
        """Per characteristic: its values grouped into classes the rules cannot tell apart.

        Two values are in one class when they belong to the same components and meet exactly
        the same conditions of every constraint. Classes keep domain order (by first value).
        Counting works on classes instead of values (:mod:`solver.engines.structure`).
        """
        found = []
        for characteristic in self.characteristics:
            conditions = [
                condition.allowed
                for rule in self.constraints
                for condition in (*rule.when, *rule.conditions)
                if condition.characteristic == characteristic.name
            ]
            groups: dict[tuple[object, ...], list[Value]] = {}
            for value, membership in zip(
                characteristic.values, characteristic.membership, strict=True
            ):
                signature = (membership, *(value in allowed for allowed in conditions))
                groups.setdefault(signature, []).append(value)
            found.append(tuple(tuple(members) for members in groups.values()))
        return tuple(found)

    @cached_property
    def value_class_index(self) -> tuple[dict[Value, int], ...]:
        """Per characteristic: value -> the index of its class in :attr:`value_classes`."""
        return tuple(
            {value: index for index, members in enumerate(classes) for value in members}
            for classes in self.value_classes
        )
