"""A call's time budget: made from the limits table or a given number, refused when spent,
with the call, the budget and the limit named."""

from __future__ import annotations

import math
import time
from dataclasses import replace

import pytest

from solver.deadline import Deadline
from solver.errors import InputError, Location, TimeLimitError, TooLargeError
from solver.limits import limit


def test_a_deadline_takes_its_budget_from_the_limits_table_unless_given_one() -> None:
    assert Deadline.start("check-seconds", "check").seconds == limit("check-seconds").value
    assert Deadline.start("check-seconds", "check", 0.5).seconds == 0.5


@pytest.mark.parametrize("seconds", [0, -1, math.inf, math.nan])
def test_a_budget_that_is_not_a_positive_number_of_seconds_is_refused(seconds: float) -> None:
    with pytest.raises(InputError, match="a time limit is a positive number of seconds"):
        Deadline.start("check-seconds", "check", seconds)


def test_a_fresh_deadline_lets_the_work_go_on() -> None:
    deadline = Deadline.start("check-seconds", "check", 60)
    deadline.check(Location("rules.yaml"))
    assert not deadline.passed()
    assert 0 < deadline.remaining() <= 60


def test_a_spent_deadline_is_refused_at_the_location_with_the_call_and_the_limit_named() -> None:
    spent = replace(Deadline.start("check-seconds", "check", 0.5), end=time.monotonic() - 1)
    assert spent.passed()
    assert spent.remaining() == 0
    with pytest.raises(TimeLimitError) as caught:
        spent.check(Location("rules.yaml"))
    assert str(caught.value) == (
        "rules.yaml: check stopped after 0.5 s (limit 'check-seconds', docs/security.md; "
        "--time-limit sets it)"
    )
    assert caught.value.faults[0].code == "too-slow"
    assert isinstance(caught.value, TooLargeError)  # refused like any other limit: status 2


def test_a_budget_no_option_sets_says_none() -> None:
    spent = replace(
        Deadline.start("cover-seconds", "the cover", option=""), end=time.monotonic() - 1
    )
    assert str(spent.error(Location("rules.yaml"))) == (
        "rules.yaml: the cover stopped after 10 s (limit 'cover-seconds', docs/security.md)"
    )
