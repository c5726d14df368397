"""The bound T: reported, and flagged when a declared bound differs."""

from __future__ import annotations

from solver.check import check_files
from tests.check.helpers import findings
from tests.conftest import RULES


def test_bound_of_the_paper_rules_is_900_as_declared() -> None:
    [bound] = check_files([RULES / "paper.yaml"]).findings
    assert bound.check == "bound"
    assert bound.message.startswith("T = 6 x 6 x 5 x 5 = 900 UI configurations at most")
    assert bound.message.endswith(", as declared")


def test_a_declared_bound_that_differs_is_an_error() -> None:
    [mismatch] = findings("bound-mismatch.yaml", check="bound-mismatch")
    assert mismatch.message == ("bound: 50 is not what the components give: T = 3 x 3 x 3 x 2 = 54")
    assert mismatch.level == "error"


def test_a_rule_set_without_bound_gets_t_reported_at_its_characteristics() -> None:
    [bound] = findings("duplicate-key.yaml", check="bound")
    assert (bound.location.path, bound.line) == ("characteristics", 3)
