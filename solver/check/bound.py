"""The bound T: how many distinct UI configurations a rule set can ever produce.

T is the product over characteristics of their numbers of components (the article's equation
3: 6 x 6 x 5 x 5 = 900). The check reports it for every rule set, as information, and flags a
rule set whose declared ``bound:`` differs, which means the file's documentation and its
components disagree (a component added, split or removed without updating the bound).

Not here: how many configurations a team needs (``teleop-ui solve``).
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.context import RulesContext
from solver.check.finding import Check, Finding

__all__ = ["CHECKS", "bound_text"]


def bound_text(context: RulesContext) -> str:
    """``T = 6 x 6 x 5 x 5 = 900`` (characteristic order)."""
    factors = " x ".join(str(f) for f in context.rules.bound_factors)
    return f"T = {factors} = {context.rules.bound}"


def _location(context: RulesContext) -> tuple[str, ...]:
    return ("bound",) if context.rules.declared_bound is not None else ("characteristics",)


def _bound(context: RulesContext) -> Iterator[Finding]:
    rules = context.rules
    names = " x ".join(c.name for c in rules.characteristics)
    if rules.declared_bound is None:
        declared = ""
    elif rules.declared_bound == rules.bound:
        declared = ", as declared"
    else:
        declared = f", not the declared {rules.declared_bound}"
    yield BOUND.finding(
        context.locate(_location(context), key=True),
        f"{bound_text(context)} UI configurations at most (components of {names}){declared}",
    )


def _mismatch(context: RulesContext) -> Iterator[Finding]:
    rules = context.rules
    if rules.declared_bound is not None and rules.declared_bound != rules.bound:
        yield MISMATCH.finding(
            context.locate(("bound",)),
            f"bound: {rules.declared_bound} is not what the components give: {bound_text(context)}",
        )


BOUND = Check(
    "bound",
    "info",
    "rules",
    "The bound T of the rule set: the product over characteristics of their numbers of "
    "components, the most UI configurations any team can ever need (the article's equation "
    "3). Reported for every rule set that loads.",
    _bound,
)
MISMATCH = Check(
    "bound-mismatch",
    "error",
    "rules",
    "The rule set declares a `bound:` that differs from T as its components give it: the "
    "components were changed and the bound was not (or the other way round).",
    _mismatch,
)

CHECKS: tuple[Check[RulesContext], ...] = (BOUND, MISMATCH)
