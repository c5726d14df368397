"""The order of a component's sensors before they are cut into clusters: the article's three
organisations of clusters (Section 3, after Equation (2)), chosen in the presentation grammar
(``clusters: order:``) or with ``layouts --cluster-order``.

- ``alphabetical``: by topic name, numbers read as numbers (``image_raw_2`` before
  ``image_raw_10``);
- ``priority``: most commonly used first, as the grammar's ``priority:`` list declares them
  (a topic, its last part, or a sensor's title: ``/robot1/camera/image_raw_3``,
  ``image_raw_3``, ``visual display 3``); the others after them, alphabetically;
- ``data rate``: the most bytes per second first (measured from a bag, ``--rates-bag``), the
  topics it did not record after them, alphabetically. A sensor's topic is found in the bag
  by its name, else by its last part where one topic of the bag ends so (a bag recorded under
  ``/uav1`` read for layouts without a namespace); a bag holding none of the sensors' topics
  is said (:func:`matched_rates`) and the sensors ordered alphabetically.

The first sensor in this order is in the first cluster: the primary view's. The order used is
written into the layout's design note (``clusterOrder``). Not here: reading a bag's rates
(:func:`solver.identify.readers.bags.read_bag_rates`); the clusters (:mod:`solver.layouts.plan`).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import replace
from typing import TypeVar

from solver.errors import Fault, InputError, Location
from solver.layouts.grammar import ORDERS, Grammar
from solver.layouts.presentation import Presentation
from solver.untrusted import shown

T = TypeVar("T")

__all__ = ["matched_rates", "natural", "ordered", "rate_of", "with_order", "without_data"]


def natural(text: str) -> tuple[tuple[int, int | str], ...]:
    """``text`` as a sort key whose runs of digits compare as numbers."""
    return tuple(
        (0, int(part)) if part.isdigit() else (1, part) for part in re.split(r"(\d+)", text)
    )


def ordered(
    sensors: Sequence[T], named: Callable[[T], tuple[str, str]], grammar: Grammar
) -> list[T]:
    """``sensors`` in the grammar's cluster order; ``named`` gives a sensor's topic and title."""
    if grammar.order == "priority":
        rank = {name: index for index, name in enumerate(grammar.priority)}

        def declared(sensor: T) -> tuple[int, tuple[tuple[int, int | str], ...]]:
            topic, title = named(sensor)
            names = (topic, topic.rpartition("/")[2], title)
            return min((rank[n] for n in names if n in rank), default=len(rank)), natural(topic)

        return sorted(sensors, key=declared)
    if grammar.order == "data rate":
        rates = dict(grammar.rates)
        by_last = _by_last_part(rates)

        def measured(sensor: T) -> tuple[float, tuple[tuple[int, int | str], ...]]:
            topic = named(sensor)[0]
            return -rate_of(topic, rates, by_last, -1.0), natural(topic)

        return sorted(sensors, key=measured)
    return sorted(sensors, key=lambda sensor: natural(named(sensor)[0]))


def with_order(
    presentation: Presentation,
    order: str | None = None,
    rates: Mapping[str, float] | None = None,
) -> Presentation:
    """``presentation`` with the cluster order chosen (``order``: ``--cluster-order``; None:
    the grammar's) and the data it needs (``rates``: ``--rates-bag``'s); a located
    :class:`~solver.errors.InputError` for an unknown order, or one that needs data it was
    not given (at the option, or at the presentation file's line)."""
    grammar = presentation.grammar
    chosen = order if order is not None else grammar.order
    if chosen not in ORDERS:
        raise InputError.at(
            "--cluster-order",
            f"unknown cluster order {shown(chosen, quoted=True)}; known: " + ", ".join(ORDERS),
        )
    needs = _needs(grammar, chosen, given=rates is not None)
    if needs and order is None:
        raise InputError.at(
            presentation.file, needs, line=grammar.order_line, path="grammar.clusters.order"
        )
    if needs:
        raise InputError.at("--cluster-order", needs)
    if rates is not None and chosen != "data rate":
        raise InputError.at("--rates-bag", f"is for the 'data rate' order, not {chosen!r}")
    measured = tuple(sorted((rates or {}).items()))
    return replace(presentation, grammar=replace(grammar, order=chosen, rates=measured))


def _needs(grammar: Grammar, order: str, *, given: bool) -> str:
    """What ``order`` needs that is not there (``given``: a bag's rates were read), or ``""``."""
    if order == "data rate" and not given:
        return "the data rate order needs each topic's bytes per second: --rates-bag BAG"
    if order == "priority" and not grammar.priority:
        return (
            "the priority order needs the grammar's clusters: priority: list "
            "(topics or sensors, most used first)"
        )
    return ""


def without_data(presentation: Presentation, where: str) -> tuple[Presentation, Fault | None]:
    """``presentation`` for a command that reads no bag (``where``: ``layouts --robot``,
    ``watch --layouts``): its own cluster order where it has the data the order needs; else
    ``alphabetical``, the grammar saying why (the layout's design note), and the warning to
    give once, located at the presentation file's ``order:`` line."""
    grammar = presentation.grammar
    if not _needs(grammar, grammar.order, given=False):
        return presentation, None
    asked = (
        "each topic's bytes per second, from a bag"
        if grammar.order == "data rate"
        else ("the grammar's clusters: priority: list")
    )
    note = (
        f"{grammar.order!r} was asked for and needs {asked}, which {where} does not have: "
        "ordered alphabetically"
    )
    where_ = Location(presentation.file, line=grammar.order_line, path="grammar.clusters.order")
    applied = replace(grammar, order="alphabetical", order_note=note)
    return replace(presentation, grammar=applied), Fault(where_, note)


def _by_last_part(rates: Mapping[str, float]) -> dict[str, float]:
    """The bag's topics by their last part, where one topic only ends so."""
    ends: dict[str, list[float]] = {}
    for topic, rate in rates.items():
        ends.setdefault(topic.rpartition("/")[2], []).append(rate)
    return {end: found[0] for end, found in ends.items() if len(found) == 1}


def rate_of(
    topic: str, rates: Mapping[str, float], by_last: Mapping[str, float], missing: float
) -> float:
    """``topic``'s bytes per second: by its name, else by its last part (``by_last``, from
    :func:`_by_last_part`), else ``missing``."""
    if topic in rates:
        return rates[topic]
    return by_last.get(topic.rpartition("/")[2], missing)


def matched_rates(
    presentation: Presentation, sensors: Iterable[str], bag: str
) -> tuple[Presentation, Fault | None]:
    """``presentation`` ordering by data rate, checked against the sensors' topics
    (``sensors``) of the layouts to write: where the bag (``bag``, as the option named it)
    holds none of them, by name or last part, the sensors are ordered alphabetically, the
    grammar saying why, and the warning to give, located at the bag."""
    grammar = presentation.grammar
    if grammar.order != "data rate":
        return presentation, None
    rates = dict(grammar.rates)
    by_last = _by_last_part(rates)
    wanted = sorted(set(sensors), key=natural)
    if not wanted or any(rate_of(t, rates, by_last, -1.0) >= 0 for t in wanted):
        return presentation, None
    recorded = sorted(rates, key=natural)
    note = (
        f"no sensor topic of the layouts ({_some(wanted)}) is in the bag, by name or by its "
        f"last part (the bag's topics: {_some(recorded) if recorded else 'none'}): the data "
        "rate order found no rates; ordered alphabetically"
    )
    applied = replace(grammar, order="alphabetical", order_note=note)
    return replace(presentation, grammar=applied), Fault(Location(bag), note)


def _some(names: Sequence[str], count: int = 3) -> str:
    more = len(names) - count
    return ", ".join(shown(name) for name in names[:count]) + (
        f" and {more} more" if more > 0 else ""
    )
