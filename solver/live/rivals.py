"""Other watchers on the same graph: who they are, whether they answer differently, who writes.

Two watchers on one graph with different teams, rules, profiles or fixed values give different
answers to the same selection, and each would overwrite the other's on every change. So every
watcher *announces* itself under ``/teleop_ui/watchers`` (a parameter ``/teleop_ui/watchers/<its
node name>`` on ROS 1, a message on the topic ``/teleop_ui/watchers`` on ROS 2, both written by
:meth:`~solver.live.graph.GraphSource.announce` and withdrawn when it stops): its node name,
team, rules, what it answers with (a :func:`fingerprint` of the team, rules, profile and fixed
values) and its policy. A watcher that reads a running other watcher's announcement with another
fingerprint reports a ``rival`` event (both teams), and ``rival_gone`` when that one stops; two
watchers that agree are no rivals.

Who writes the answer, ``/teleop_ui/ui_configuration``, is the operator's choice (``--yield``,
the default, or ``--insist``): a yielding watcher leaves a running rival's different answer in
place and says so in its selection's notes; an insisting one writes its own over a yielding
rival's (which then yields to it). Of two insisting rivals, the one whose answer is there keeps
it: no two watchers ever overwrite each other in turn.

Announcements are a stranger's words like anything on a graph: at most :data:`MAX_ANNOUNCED`
are read per poll, each field bounded as the operator's selection is, and whether the named
watcher runs is asked of the source (:meth:`~solver.live.graph.GraphSource.running_watcher`),
at most every :data:`ASK_AGAIN` seconds for one found gone.

Not here: the answer itself (:mod:`solver.live.selection`), the loop (:mod:`solver.live.watcher`).
"""

from __future__ import annotations

import hashlib
import json
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Final

from solver.live.events import Event, Rival, RivalGone
from solver.live.graph import ANNOUNCEMENTS
from solver.live.values import selection_text

if TYPE_CHECKING:  # types only: `switch` reads announcements without the solving stack
    from solver.identify.profile import Profile
    from solver.live.given import FixedValues
    from solver.solving.solution import Solution

__all__ = [
    "ASK_AGAIN",
    "INSIST",
    "MAX_ANNOUNCED",
    "POLICIES",
    "WATCHERS",
    "YIELD",
    "Announcement",
    "Rivals",
    "announcement_key",
    "announcements",
    "fingerprint",
]

WATCHERS: Final = ANNOUNCEMENTS
YIELD: Final = "yield"
INSIST: Final = "insist"
POLICIES: Final = (YIELD, INSIST)
MAX_ANNOUNCED: Final = 8
ASK_AGAIN: Final = 5.0
_FIELDS: Final = ("watcher", "team", "rules", "fingerprint", "policy")


def fingerprint(solution: Solution, profile: Profile, fixed: FixedValues) -> str:
    """A digest of everything a watcher's answers depend on: equal for two watchers that give
    equal answers to every selection (file names and positions left out)."""
    rules = solution.rules
    data = {
        "team": solution.team.name,
        "characteristics": [
            [
                characteristic.name,
                [str(value) for value in characteristic.values],
                [
                    [c.name, [str(v) for v in c.values], c.low, c.high, c.cluster_size]
                    for c in characteristic.components
                ],
            ]
            for characteristic in rules.characteristics
        ],
        "constraints": [str(rule.describe()) for rule in rules.constraints],
        "team_key": rules.team_key,
        "selections": [
            [selection.kinematic_type, [[str(v) for v in domain] for domain in selection.domains]]
            for selection in solution.team.selections
        ],
        "profile": profile.digest,
        "fixed": [list(fixed.everywhere), [[r, list(v)] for r, v in fixed.per_robot]],
    }
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode("utf-8")).hexdigest()


def announcement_key(caller_id: str) -> str:
    """The key of a watcher's announcement under ``/teleop_ui/watchers``."""
    return caller_id.strip("/")


@dataclass(frozen=True, slots=True)
class Announcement:
    """What one watcher announces of itself under ``/teleop_ui/watchers``."""

    watcher: str
    team: str | None
    fingerprint: str | None
    policy: str
    # The rule set's name, for the operator's `switch`; not part of what makes a rival new.
    rules: str | None = field(default=None, compare=False)


def announcements(params: Mapping[str, Any]) -> list[Announcement]:
    """The announcements in ``params`` (the ``/teleop_ui`` subtree), by key, at most
    :data:`MAX_ANNOUNCED` of them read; each field short text or left out, and an entry that
    names no watcher dropped."""
    announced = params.get(WATCHERS)
    if not isinstance(announced, Mapping):
        return []
    items = sorted(announced.items(), key=lambda item: str(item[0]))[:MAX_ANNOUNCED]
    return [found for _key, value in items if (found := _read(value)) is not None]


def _read(value: Any) -> Announcement | None:
    """One announcement; ``None`` for anything that is not one."""
    if not isinstance(value, Mapping):
        return None
    fields: dict[str, str | None] = {}
    for name in _FIELDS:
        text, _note = selection_text(name, value.get(name)) if name in value else (None, None)
        fields[name] = text
    watcher = fields["watcher"]
    if watcher is None:
        return None
    policy = fields["policy"] if fields["policy"] in POLICIES else YIELD
    return Announcement(
        watcher, fields["team"], fields["fingerprint"], policy or YIELD, fields["rules"]
    )


class Rivals:
    """The rival watchers a watcher sees (see the module docstring)."""

    def __init__(
        self,
        caller_id: str,
        solution: Solution,
        digest: str,
        policy: str,
        running: Callable[[str], tuple[bool, str | None]],
    ) -> None:
        self.caller_id = caller_id
        self.team = solution.team.name
        self.policy = policy
        self.digest = digest
        self._running = running
        self._gone: dict[str, float] = {}  # watcher -> when it was found gone
        self._rivals: dict[str, Announcement] = {}
        self.announcement: dict[str, Any] = {
            "watcher": caller_id,
            "team": solution.team.name,
            "rules": solution.rules.name,
            "fingerprint": digest,
            "policy": policy,
        }

    def reset(self) -> None:
        """At a (re)synchronisation: every rival is reported again."""
        self._rivals = {}

    def needs_announcing(self, params: Mapping[str, Any]) -> bool:
        """Whether this watcher's own announcement is missing or not as it should be."""
        announced = params.get(WATCHERS)
        own = (
            announced.get(announcement_key(self.caller_id))
            if isinstance(announced, Mapping)
            else None
        )
        return own != self.announcement

    def update(self, params: Mapping[str, Any]) -> list[Event]:
        """``rival`` / ``rival_gone`` events for what the announcements in ``params`` (the
        ``/teleop_ui`` subtree) say now."""
        found: dict[str, Announcement] = {}
        for other in announcements(params):
            if other.watcher == self.caller_id or other.fingerprint == self.digest:
                continue
            if self.runs(other.watcher):
                found[other.watcher] = other
        events: list[Event] = [
            RivalGone(0, name) for name in sorted(set(self._rivals) - set(found))
        ]
        events += [
            Rival(0, name, other.team, self.team, self.policy)
            for name, other in sorted(found.items())
            if self._rivals.get(name) != other
        ]
        self._rivals = found
        return events

    def runs(self, watcher: str) -> bool:
        """Whether ``watcher`` still runs (the source's word, not asked again for
        :data:`ASK_AGAIN` seconds once it was found gone)."""
        now = time.monotonic()
        gone = self._gone.get(watcher)
        if gone is not None and now - gone < ASK_AGAIN:
            return False
        running, doubt = self._running(watcher)
        if running and doubt is None:
            self._gone.pop(watcher, None)
            return True
        self._gone[watcher] = now
        if len(self._gone) > 4 * MAX_ANNOUNCED:  # forget the oldest: bounded
            del self._gone[min(self._gone, key=self._gone.__getitem__)]
        return False

    def insists(self, watcher: str) -> bool:
        """Whether the rival ``watcher`` announced that it insists on writing its answer."""
        other = self._rivals.get(watcher)
        return other is not None and other.policy == INSIST
