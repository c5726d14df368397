"""The structure of a body (UAV, Humanoid, Quadruped, ...) and the rule set's type for it.

:func:`classify` reads the part counts of a :class:`~solver.identify.body.Body` through the
profile's ordered structure rules: the first rule whose ``when`` conditions all hold is the
reading. Its confidence is the rule's own, lowered by the profile's ``doubt_factor`` for each
``expect`` condition the body does not meet and for an SRDF that disagrees with the tree about
the number of arms. The *kinematic type* is the first of the rule's ``kinematic_types`` that the
rule set has (so a rule set with a ``Quadruped`` type classifies quadrupeds), or ``None``.

Not here: finding the parts (:mod:`solver.identify.body`).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from solver.core.ruleset import RuleSet
from solver.identify.body import Body
from solver.identify.planning_groups import arm_plans
from solver.identify.profile import BOOLEAN_FEATURES, Profile
from solver.identify.readers.urdf import Urdf
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver.identify.readers.srdf import Srdf

__all__ = ["Reading", "classify", "kinematic_type_for"]


@dataclass(frozen=True, slots=True)
class Reading:
    """What the classifier makes of a body."""

    structure: str
    kinematic_type: str | None
    confidence: float
    evidence: tuple[str, ...]
    # The structure rules tried, in order, each with why it held or did not (--explain).
    path: tuple[str, ...] = ()


def kinematic_type_for(structure: str, profile: Profile, rules: RuleSet) -> str | None:
    """The rule set's kinematic type for ``structure`` (``None`` if it has none)."""
    rule = next((r for r in profile.structures if r.name == structure), None)
    if rule is None:
        return None
    known = {str(v).casefold(): str(v) for v in rules.key.values}
    return next((known[t.casefold()] for t in rule.kinematic_types if t.casefold() in known), None)


def classify(
    body: Body,
    profile: Profile,
    rules: RuleSet,
    *,
    root: str = "",
    srdf: Srdf | None = None,
    urdf: Urdf | None = None,
) -> Reading:
    """The structure, kinematic type, confidence and evidence of ``body``."""
    features = body.features()
    rule = next((r for r in profile.structures if r.matches(features)), None)
    evidence = list(body.evidence(root))
    path = decision_path(features, profile)
    if rule is None:
        evidence.append("no structure rule of the profile matches this body")
        return Reading("Other", None, 0.0, tuple(evidence), path)
    confidence = rule.confidence
    # A catch-all rule says why nothing else fit: the parts every other rule read.
    parts = [
        f"{value} {name.replace('_', ' ')}"
        for name, value in features.items()
        if value and name not in BOOLEAN_FEATURES
    ]
    why = ", ".join(c.describe() for c in rule.when) or (
        "no other structure matched; the body has "
        + (", ".join(parts) or "no parts")
        + ("" if features["mobile_base"] else ", no mobile base")
    )
    where = (
        "" if rule.location is None else f" ({Path(rule.location.file).name}:{rule.location.line})"
    )
    evidence.append(f"structure {rule.name}: {why}{where}")
    for condition in rule.expect:
        if not condition.holds(features):
            confidence *= profile.doubt_factor
            evidence.append(f"doubt: a typical {rule.name} has {condition.describe()}")
    if srdf is not None:
        confidence *= _srdf_agreement(body, srdf, profile, evidence, urdf)
    kinematic_type = kinematic_type_for(rule.name, profile, rules)
    if kinematic_type is None:
        evidence.append(
            f"the rule set {shown(rules.name, quoted=True)} has no kinematic type for {rule.name} "
            f"(it has {', '.join(str(v) for v in rules.key.values)}): Other under it, "
            f"reason: {rule.name.lower()}"
        )
    elif kinematic_type != rule.name:
        evidence.append(f"{rule.name} is the rule set's {kinematic_type}")
    return Reading(rule.name, kinematic_type, round(confidence, 2), tuple(evidence), path)


def decision_path(features: dict[str, int], profile: Profile) -> tuple[str, ...]:
    """The structure rules in order up to the first that holds, each with why (or why not)."""
    lines = []
    for rule in profile.structures:
        failed = [c for c in rule.when if not c.holds(features)]
        if not failed:
            held = ", ".join(c.describe() for c in rule.when) or "the catch-all"
            lines.append(f"{rule.name}: yes ({held})")
            break
        why = ", ".join(f"needs {c.describe()}, has {features.get(c.feature, 0)}" for c in failed)
        lines.append(f"{rule.name}: no ({why})")
    return tuple(lines)


def _srdf_agreement(
    body: Body, srdf: Srdf, profile: Profile, evidence: list[str], urdf: Urdf | None
) -> float:
    distinct = arm_plans(body, srdf, profile.limb("arm_min_joints"), urdf)
    arms = body.count("arm")
    parts = [
        f"SRDF: {len(distinct)} arm planning group(s)"
        + (f" ({', '.join(g.name for g in distinct)})" if distinct else "")
    ]
    if srdf.end_effectors:
        parts.append(
            ", ".join(f"end effector {e.name} on {e.parent_link}" for e in srdf.end_effectors)
        )
    if srdf.virtual_joints:
        parts.append(", ".join(f"{v.type} virtual joint {v.name}" for v in srdf.virtual_joints))
    if any(v.type != "fixed" for v in srdf.virtual_joints):
        parts.append("a virtual joint is a planning convention, no evidence that the base moves")
    evidence.append("; ".join(parts))
    if distinct and len(distinct) != arms:
        evidence.append(f"doubt: the SRDF plans {len(distinct)} arm(s), the tree shows {arms}")
        return profile.doubt_factor
    return 1.0
