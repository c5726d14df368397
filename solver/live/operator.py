"""The operator's side of the ``/teleop_ui`` convention: switching by hand (``teleop-ui switch``,
and a click in the studio's Live view).

An operator station says which robot is active and which values of the rule set's
characteristics it asks for (docs/live.md): ``/teleop_ui/active_robot`` and
``/teleop_ui/active_<characteristic>``, ROS 1 parameters or ROS 2 topics (``std_msgs/String``,
reliable, transient-local); a watcher answers on ``/teleop_ui/ui_configuration``. A
:class:`Station` does it through the graph's own source (the one lookup,
:func:`solver.live.sources.open_source`): it writes a :class:`Switch`, waits, bounded, for the
answer of a running watcher that names that robot with those values, and
:func:`switch_robot` hands it back (:class:`Switched`).

*Checked before anything is written* (:func:`check_switch`, located :class:`InputError`\\ s):
the robot's name is a ROS name; each NAME is a characteristic of the rule set and each VALUE
one of its values, when the rule set is known: given (``--team`` / ``--rules``, the studio's
feed), or announced by the graph's running watchers (``/teleop_ui/watchers``,
:mod:`solver.live.rivals`: the rule set they name, when it is one shipped with teleop-ui).
Where the graph does not tell, only the names' syntax is checked, and :attr:`Switched.rules`
says why. The robot must be on the graph (a namespace with a ``robot_description``); a DDS
graph's participants are discovered one by one, so it is looked for until discovery is quiet
(:data:`LOOK_QUIET`, and no participant found whose endpoints are not; at most
:data:`LOOK_LIMIT` seconds), as a one-shot look at DDS waits; a
rule set a watcher announced there is looked for until that watcher is seen running (at most
:data:`LOOK_LIMIT`).

*What is read back is a stranger's*: the answer and the announcements are bounded by the source
(:mod:`solver.live.values`), shown escaped by :func:`render_switched`, and an answer counts only
when the watcher it names still runs (:meth:`~solver.live.graph.GraphSource.running_watcher`).

*How long the selection lasts.* A ROS 1 master keeps the parameters. On ROS 2 the selection is
this station's writers' samples: a watcher reads them (a late one too: transient-local) while
the station's participant stays, and keeps what it read once the participant has left; a
watcher started later does not see them. ``teleop-ui switch`` keeps its participant until the
answer or the end of the wait; the studio keeps its station while it runs.

Not here: the watcher's side (:mod:`solver.live.selection`, :mod:`solver.live.watcher`).
"""

from __future__ import annotations

import json
import math
import re
import threading
import time
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Final

from solver.core.ruleset import RuleSet
from solver.errors import InputError, SolverError, did_you_mean
from solver.live.discovery import normalise_namespace, robot_namespaces
from solver.live.given import ACTIVE_PREFIX
from solver.live.graph import ANNOUNCEMENTS, MISSING, GraphSource
from solver.live.rivals import announcements
from solver.live.selection import ACTIVE_ROBOT, NAMESPACE, RESULT_PARAM, WRITER_KEY
from solver.live.values import MAX_SELECTION_CHARS, kind_of
from solver.ros.names import full_topic_name_problem
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver.live.sources import GraphAddress

__all__ = [
    "DEFAULT_WAIT",
    "LOOK_LIMIT",
    "LOOK_QUIET",
    "Station",
    "Switch",
    "Switched",
    "check_switch",
    "open_station",
    "render_switched",
    "robot_name",
    "switch_robot",
    "switched_data",
    "unanswered",
]

# Seconds to wait for the watcher's answer, unless told otherwise (``switch --wait``).
DEFAULT_WAIT: Final = 5.0
# Looking for the robot and the watchers' announcements on a graph whose participants are
# discovered one by one: until nothing new (no robot, announcement, endpoint or parameter name)
# for LOOK_QUIET seconds, at most LOOK_LIMIT (and, on DDS, a participant found before its
# endpoints, or a watcher that announced a rule set, is waited for until LOOK_LIMIT, not
# LOOK_QUIET).
LOOK_QUIET: Final = 0.5
LOOK_LIMIT: Final = 5.0
# Seconds between looks at the answer when the source wakes no one (a ROS 1 master).
POLL: Final = 0.05
_ANSWER_KEY: Final = RESULT_PARAM.rsplit("/", 1)[1]
# A characteristic's name as a topic or parameter name holds it: a ROS name token.
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_LISTED: Final = 8


@dataclass(frozen=True, slots=True)
class Switch:
    """What the operator selects: the robot's namespace, and (characteristic, value) pairs; an
    empty value clears that characteristic's selection."""

    robot: str
    values: tuple[tuple[str, str], ...] = ()

    @property
    def asked(self) -> tuple[tuple[str, str], ...]:
        """The values asked for (the cleared ones left out): what the answer must hold."""
        return tuple((name, value) for name, value in self.values if value)


@dataclass(frozen=True, slots=True)
class Switched:
    """A switch written on ``graph`` (as a person reads its address) and what came of it:
    ``answer``, the running watcher's answer naming the robot with the values asked (``None``
    when none came within ``wait`` seconds; ``there`` is then what the graph held);
    ``rules``, the file of the rule set the switch was checked against (``None``: only the
    syntax was, and ``why`` says why, when there were values or ``clear``); ``cleared``, the
    selections cleared beside; ``order``, the rule set's characteristics in order (what the
    text shows the combination in)."""

    graph: str
    switch: Switch
    wait: float
    answer: dict[str, Any] | None
    rules: str | None = None
    why: str | None = None
    there: Any = field(default=None, compare=False)
    cleared: tuple[str, ...] = ()
    order: tuple[str, ...] = ()


def robot_name(text: str) -> str:
    """``text`` as a robot's namespace (``uav1``, ``/uav1/`` -> ``/uav1``; ``/`` the root); a
    located :class:`InputError` for anything that is no ROS name."""
    candidate = text if text.startswith("/") else "/" + text
    if len(candidate) > 1 and candidate.endswith("/"):
        candidate = candidate[:-1]
    problem = None if candidate == "/" else full_topic_name_problem(candidate)
    if not text:
        problem = "is empty (the robot described at the root is '/')"
    if problem is None and len(candidate) > MAX_SELECTION_CHARS:
        problem = f"is longer than {MAX_SELECTION_CHARS} characters ({len(candidate):,})"
    if problem is not None:
        # The checked name is the absolute one: where it differs, the problem says so.
        same = not text or candidate in (text, text[:-1])
        it = "it" if same else shown(candidate, quoted=True)
        raise InputError.at(
            "<arguments>",
            f"the robot {shown(text, quoted=True)} is no ROS name: {it} {problem}",
            path="ROBOT",
        )
    return normalise_namespace(candidate)


def check_switch(robot: str, values: Mapping[str, str], rules: RuleSet | None) -> Switch:
    """The switch to ``robot`` with ``values`` (NAME -> VALUE; ``""`` clears), checked against
    ``rules`` when known (see the module docstring): each value as the rule set writes it
    (``sensor_count=03`` is ``3``), in the rule set's order."""
    namespace = robot_name(robot)
    checked: dict[str, str] = {}
    for name, value in values.items():
        _check_name(name, rules)
        checked[name] = value if not value else _check_value(name, value, rules)
    order = {name: index for index, name in enumerate(rules.names)} if rules else {}
    ordered = sorted(checked.items(), key=lambda item: order.get(item[0], len(order)))
    return Switch(namespace, tuple(ordered))


def _check_name(name: str, rules: RuleSet | None) -> None:
    if rules is not None and name not in rules.names:
        raise InputError.at(
            "<arguments>",
            f"unknown characteristic {shown(name, quoted=True)}{did_you_mean(name, rules.names)};"
            f" the rules ({rules.file}) have: {', '.join(rules.names)}",
            path=shown(name),
        )
    if name == "robot":
        raise InputError.at(
            "<arguments>",
            "/teleop_ui/active_robot names the active robot: give the robot as ROBOT (a "
            "characteristic called 'robot' is the robot's own value or --set, not the operator's)",
            path=name,
        )
    if _NAME.fullmatch(name) is None or full_topic_name_problem(
        f"{NAMESPACE}/{ACTIVE_PREFIX}{name}"
    ):
        raise InputError.at(
            "<arguments>",
            f"{shown(name, quoted=True)} is no characteristic name a topic or parameter can "
            "hold (a letter, then letters, digits or '_')",
            path=shown(name),
        )


def _check_value(name: str, value: str, rules: RuleSet | None) -> str:
    if rules is None:
        if len(value) > MAX_SELECTION_CHARS or not value.isprintable():
            raise InputError.at(
                "<arguments>",
                f"{shown(value, quoted=True)} is no value a watcher reads (printable text of at "
                f"most {MAX_SELECTION_CHARS} characters)",
                path=name,
            )
        return value
    characteristic = rules.characteristic(name)
    parsed = characteristic.parse_value(value)
    if parsed is None:
        values = characteristic.values
        if characteristic.kind == "integer" and values:
            has, hint = f"whole numbers {values[0]} to {values[-1]}", ""
        else:
            names = [str(v) for v in values]
            more = f", ... ({len(names)} in all)" if len(names) > _LISTED else ""
            has = ", ".join(shown(v) for v in names[:_LISTED]) + more
            hint = did_you_mean(value, names)
        raise InputError.at(
            "<arguments>",
            f"{shown(value, quoted=True)} is not a value of {name}{hint}; the rules "
            f"({rules.file}) have: {has}",
            path=name,
        )
    return str(parsed)


class Station:
    """An operator station on one graph, through its source (which it closes): it writes the
    selection and reads the answer (see the module docstring). Thread-safe: one switch at a
    time."""

    def __init__(self, source: GraphSource) -> None:
        self.source = source
        self.name = source.name
        # A DDS graph discovers its participants one by one, long after their words on a busy
        # machine; a ROS master answers at once (a watcher it does not know has stopped).
        self._discovers = self.name.startswith("ros2://")
        self.busy = threading.Lock()
        self._woken = threading.Event()
        self._graph_changed = True
        source.on_change = self._on_change
        source.on_params = self._woken.set

    def _on_change(self) -> None:
        self._graph_changed = True
        self._woken.set()

    def _params(self) -> dict[str, Any]:
        """The ``/teleop_ui`` parameters now: with the whole graph when it changed (on DDS,
        whether a watcher runs is whether its participant is there)."""
        if self._graph_changed:
            self._graph_changed = False
            return dict(self.source.observe(NAMESPACE).params)
        return dict(self.source.observe_params(NAMESPACE)[1])

    def look(
        self,
        robot: str,
        *,
        announcements: bool,
        wants_rules: bool = False,
        limit: float | None = None,
    ) -> tuple[tuple[str, ...], dict[str, Any]]:
        """The robots on the graph and the ``/teleop_ui`` parameters, once ``robot`` is there
        (and, with ``announcements``, a watcher that announced its rule set is seen running), or
        once the graph has been quiet for :data:`LOOK_QUIET` seconds (at most
        :data:`LOOK_LIMIT`). On a DDS graph a rule set announced by a watcher not yet seen
        running is waited for until :data:`LOOK_LIMIT`, and so is an announcement whose writer
        is found before its sample, and a participant found before its readers and writers: on
        a busy machine each may come long after the rest of the graph, and a switch that
        stopped looking would check its values for syntax only and write a misspelt one (a ROS
        master tells at once: a stale announcement there costs no wait). With ``wants_rules``
        (values to check or ``--clear``, and no rule set given; it needs ``announcements``), a
        running watcher that announces one is waited for until :data:`LOOK_LIMIT` once the
        robot is there: a watcher's participant may be discovered well after the robot's, and
        nothing on the graph says one is coming. ``limit``: seconds instead of
        :data:`LOOK_LIMIT` (``switch --look``)."""
        limit = LOOK_LIMIT if limit is None else limit
        start = quiet_since = time.monotonic()
        seen: Any = None
        while True:
            self._woken.clear()
            observation = self.source.observe(NAMESPACE)
            self._graph_changed = False
            robots = robot_namespaces(observation.param_names)
            params = dict(observation.params)
            # A watcher's announcement may come before its answer's writer is discovered
            # (a busy machine): it counts once that watcher is seen running.
            running = announcements and self._an_announcer_runs(params, start, limit)
            if robot in robots and (not announcements or running):
                return robots, params
            now = time.monotonic()
            announced = sorted(map(str, _mapping(params.get(ANNOUNCEMENTS))))
            # Anything newly discovered (a participant's writers and readers, a parameter's
            # name) is news: a watcher's announcement comes after its endpoints are found.
            state = (
                robots,
                announced,
                running,
                observation.publishers,
                observation.subscribers,
                observation.param_names,
                observation.discovering,
            )
            # On DDS a participant found is awaited until its endpoints are (the robot, or a
            # watcher, may be that one), an announcement once its writer is found (its sample
            # comes after the match), and its watcher once the announcement is read.
            awaited = self._discovers and (
                observation.discovering
                or (
                    robot in robots
                    # (a running announcer with the robot there ended the look above)
                    and (bool(announced) or _announcing(observation.param_names) or wants_rules)
                )
            )
            changed = state != seen
            if changed:
                seen, quiet_since = state, now
            # The limit holds however often the graph changes (a participant that flaps).
            quiet = not changed and now - quiet_since >= LOOK_QUIET and not awaited
            if quiet or now - start >= limit:
                return robots, params
            self._woken.wait(POLL)

    def _an_announcer_runs(self, params: Mapping[str, Any], start: float, limit: float) -> bool:
        """A watcher that announces a rule set in ``params`` is seen running: asked one by one,
        the first running one ends the asking, and none is asked past ``limit`` seconds from
        ``start`` (on ROS 1 each asking may wait for a node that does not answer)."""
        for announced in announcements(params):
            if time.monotonic() - start >= limit:
                return False
            if announced.rules is not None and self._runs(announced.watcher):
                return True
        return False

    def announced_rules(self, params: Mapping[str, Any]) -> tuple[RuleSet | None, str]:
        """The rule set the graph's running watchers announce, and how it is known (or why
        not)."""
        names: dict[str, str] = {}  # rule set name -> a watcher announcing it
        for announced in announcements(params):
            if announced.rules is not None and self._runs(announced.watcher):
                names.setdefault(announced.rules, announced.watcher)
        if not names:
            return None, f"no running watcher on {self.name} announces its rule set"
        if len(names) > 1:
            listed = ", ".join(shown(name, quoted=True) for name in sorted(names))
            return None, f"the watchers on {self.name} announce different rule sets ({listed})"
        ((name, watcher),) = names.items()
        found = _shipped_rules(name)
        if found is None:
            return None, (
                f"the watcher {shown(watcher)} announces the rule set {shown(name, quoted=True)}, "
                "which is not one shipped with teleop-ui (give --rules or --team to check "
                "against it)"
            )
        return found, f"the rule set the watcher {shown(watcher)} announces"

    def _runs(self, watcher: str) -> bool:
        running, doubt = self.source.running_watcher(watcher)
        return running and doubt is None

    def write(self, switch: Switch, clear: Iterable[str] = ()) -> None:
        """The selection on the graph: the values first (an empty one, or a name in ``clear``,
        cleared), the robot last, so that a watcher woken by the robot reads the values too."""
        for name, value in switch.values:
            key = f"{NAMESPACE}/{ACTIVE_PREFIX}{name}"
            if value:
                self.source.set_param(key, value)
            else:
                self.source.delete_param(key)
        for name in clear:
            self.source.delete_param(f"{NAMESPACE}/{ACTIVE_PREFIX}{name}")
        self.source.set_param(f"{NAMESPACE}/{ACTIVE_ROBOT}", switch.robot)

    def wait(
        self,
        switch: Switch,
        seconds: float,
        before: Any = MISSING,
        cleared: tuple[str, ...] = (),
    ) -> tuple[dict[str, Any] | None, Any]:
        """The answer of a running watcher naming ``switch``'s robot with its values, within
        ``seconds``; else ``None`` and what the graph held then.

        The answer does not say which selection it answers, only the combination chosen: a
        value cleared (in ``switch`` or ``cleared``) is in no answer, and a watcher may answer
        the robot before it has read every value (on DDS each topic has its own writer). So a
        matching answer counts at once only when it is new (not ``before``, the answer there
        before the switch was written) and the switch cleared nothing; otherwise once the
        watcher has written no other for :data:`LOOK_QUIET` seconds (its last word)."""
        deadline = time.monotonic() + seconds
        settles = bool(cleared) or any(not value for _, value in switch.values)
        candidate: Any = MISSING
        since = 0.0
        while True:
            self._woken.clear()
            there = self._params().get(_ANSWER_KEY, MISSING)
            now = time.monotonic()
            if self._answers(there, switch, cleared):
                if there != candidate:
                    candidate, since = there, now
                fresh = there != before and not settles
                if fresh or now - since >= LOOK_QUIET or now >= deadline:
                    return dict(there), there
            else:
                candidate = MISSING
            if now >= deadline:
                return None, there
            self._woken.wait(min(POLL, deadline - now))

    def _answers(self, answer: Any, switch: Switch, cleared: tuple[str, ...] = ()) -> bool:
        """Whether ``answer`` is a running watcher's for ``switch``: its robot, the values
        asked in its combination (and, where the answer says what it was asked, ``active``,
        the values cleared not asked)."""
        if not isinstance(answer, Mapping):
            return False
        robot = answer.get("robot")
        if not isinstance(robot, str) or normalise_namespace(robot) != switch.robot:
            return False
        combination = _mapping(answer.get("combination"))
        if any(str(combination.get(name)) != value for name, value in switch.asked):
            return False
        active = answer.get("active")
        if isinstance(active, Mapping):
            wanted = {**dict.fromkeys(cleared), **{n: v or None for n, v in switch.values}}
            if any(active.get(name) != value for name, value in wanted.items()):
                return False
        writer = answer.get(WRITER_KEY)
        return isinstance(writer, str) and self._runs(writer)

    def close(self) -> None:
        """Leave the graph (on DDS, the selection's writers go with the participant)."""
        self.source.on_change = self.source.on_params = None
        self.source.close()


def open_station(address: GraphAddress, *, timeout: float = 2.0) -> Station:
    """A :class:`Station` on the graph at ``address`` (:func:`solver.live.sources.graph_address`;
    ``timeout``: seconds each call to a master may take). The caller closes it."""
    from solver.live.sources import open_source

    return Station(open_source(address, timeout=timeout, push=False))


def switch_robot(
    station: Station,
    robot: str,
    values: Mapping[str, str] | None = None,
    *,
    rules: RuleSet | None = None,
    clear: bool = False,
    wait: float = DEFAULT_WAIT,
    look: float | None = None,
) -> Switched:
    """Make ``robot`` the active one on ``station``'s graph with ``values`` (NAME -> VALUE;
    ``""`` clears one), checked against ``rules`` (else the rule set the graph's watchers
    announce), and wait up to ``wait`` seconds for the answer (see the module docstring).
    ``clear``: every other selection of a value (of the rule set, and on the graph) is
    cleared, so the robot's own values apply. ``look``: seconds at most to look for the robot
    and a running watcher's rule set before writing (default :data:`LOOK_LIMIT`; each look ends
    as soon as they are found). A located :class:`InputError`, with nothing
    written, for a switch that cannot be made: a name or value refused, no such robot."""
    values = dict(values or {})
    switch = check_switch(robot, values, rules)
    if not station.busy.acquire(timeout=wait):
        raise InputError.at(station.name, "another switch is under way from this station")
    try:
        robots, params = station.look(
            switch.robot,
            announcements=rules is None,
            wants_rules=rules is None and (bool(values) or clear),
            limit=look,
        )
        why = None
        if rules is None:
            rules, said = station.announced_rules(params)
            # Without values or --clear the rule set only orders the text: nothing to warn of.
            why = None if rules is not None or not (values or clear) else said
            switch = check_switch(robot, values, rules)
        if switch.robot not in robots:
            raise _no_robot(switch.robot, station.name, robots)
        cleared = _to_clear(switch, rules, params) if clear else ()
        station.write(switch, cleared)
        answer, there = station.wait(switch, wait, params.get(_ANSWER_KEY, MISSING), cleared)
    finally:
        station.busy.release()
    how, order = (None, ()) if rules is None else (rules.file, rules.names)
    return Switched(station.name, switch, wait, answer, how, why, there, cleared, order)


def _to_clear(switch: Switch, rules: RuleSet | None, params: Mapping[str, Any]) -> tuple[str, ...]:
    """The characteristics whose selection ``--clear`` clears: the rule set's, and those
    selected on the graph, but those the switch names."""
    given = {name for name, _ in switch.values}
    on_graph = [
        str(key)[len(ACTIVE_PREFIX) :]
        for key in params
        if str(key).startswith(ACTIVE_PREFIX) and str(key) != ACTIVE_ROBOT
    ]
    names = [*(rules.names if rules else ()), *sorted(on_graph)]
    return tuple(
        name
        for name in dict.fromkeys(names)
        if name not in given and name != "robot" and _NAME.fullmatch(name)
    )


def _no_robot(robot: str, graph: str, robots: tuple[str, ...]) -> InputError:
    listed = ", ".join(shown(r) for r in robots[:_LISTED]) or "none"
    more = f", ... ({len(robots)} in all)" if len(robots) > _LISTED else ""
    return InputError.at(
        "<arguments>",
        f"no robot {robot} on {graph} (no {robot.rstrip('/')}/robot_description)"
        f"{did_you_mean(robot, robots)}; robots there: {listed}{more}",
        path="ROBOT",
    )


def _announcing(param_names: Iterable[str]) -> bool:
    """Someone writes the watchers' announcements (on DDS: a writer of ``/teleop_ui/watchers``
    is found, whether or not its sample has come)."""
    key = f"{NAMESPACE}/{ANNOUNCEMENTS}"
    return any(name == key or name.startswith(f"{key}/") for name in param_names)


def _mapping(value: Any) -> Mapping[Any, Any]:
    return value if isinstance(value, Mapping) else {}


def _shipped_rules(name: str) -> RuleSet | None:
    """The rule set shipped with teleop-ui whose name is ``name``, if one is."""
    from solver.core.rules import load_rules, shipped_path

    for path in sorted(shipped_path().glob("*.yaml")):
        try:
            rules = load_rules(path)
        except SolverError:  # an identification profile, a presentation: no rule set
            continue
        if rules.name == name:
            return rules
    return None


# -- output --------------------------------------------------------------------------------------


def _jsonable(value: Any) -> Any:
    """``value`` as JSON can hold it (a ROS 1 answer may hold binary data, dates, ...)."""
    if isinstance(value, Mapping):
        return {str(key): _jsonable(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [_jsonable(item) for item in value]
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if value is None or isinstance(value, str | int | float | bool):
        return value
    return kind_of(value)


def switched_data(switched: Switched) -> dict[str, Any]:
    """``teleop-ui switch --format json``: the graph, the robot and the values selected (a
    cleared one ``null``), the rule set checked against (``null``: syntax only), and the
    watcher's answer as it wrote it (``null``: none within the wait)."""
    selection: dict[str, str | None] = {
        name: value or None for name, value in switched.switch.values
    }
    selection.update(dict.fromkeys(switched.cleared))
    return {
        "graph": switched.graph,
        "robot": switched.switch.robot,
        "selection": selection,
        "rules": switched.rules,
        "answer": None if switched.answer is None else _jsonable(switched.answer),
    }


def render_switched(switched: Switched, fmt: str = "text") -> str:
    """The answer as ``teleop-ui switch`` prints it: JSON (:func:`switched_data`), or text for a
    person; every value from the graph escaped, and paths and addresses never cut."""
    if fmt == "json":
        return json.dumps(switched_data(switched), ensure_ascii=False) + "\n"
    answer = switched.answer
    if answer is None:
        return ""
    asked = _asked(switched.switch)
    combination = _mapping(answer.get("combination"))
    names = [n for n in switched.order if n in combination]
    names += [n for n in combination if n not in names]
    values = ", ".join(shown(str(combination[n])) for n in names) or "(nothing known)"
    lines = [f"{asked} -> UI configuration {_configuration(answer)}  <- {values}"]
    team = answer.get("team")
    lines.append(
        f"  answered by {shown(str(answer.get(WRITER_KEY)))}"
        + (f" for team {shown(team)}" if isinstance(team, str) else "")
    )
    notes = answer.get("notes")
    if isinstance(notes, list):
        lines += [f"  note: {shown(str(note), limit=None)}" for note in notes]
    lines += _layout_lines(answer.get("layouts"))
    return "".join(line + "\n" for line in lines)


def _asked(switch: Switch) -> str:
    """``/ugv1 Waypoint``: the robot and the values asked, as the watcher's text shows them."""
    return " ".join(shown(v) for v in (switch.robot, *(value for _, value in switch.asked)))


def _configuration(answer: Mapping[str, Any]) -> str:
    number = shown(str(answer.get("configuration")))
    if answer.get("default") is True:
        reasons = answer.get("reasons")
        said = "; ".join(str(r) for r in reasons) if isinstance(reasons, list) else ""
        return f"{number} (default): {shown(said, limit=None)}" if said else f"{number} (default)"
    return number


def _layout_lines(layouts: Any) -> list[str]:
    """Each layout target's path and address, each on its own line, whole (an operator copies
    them)."""
    lines = []
    for target, entry in _mapping(layouts).items():
        data = _mapping(entry)
        label = f"  layout {shown(str(target))}"
        path = data.get("path")
        tab = data.get("tab")
        where = shown(str(path), limit=None) if path is not None else "(no path)"
        if isinstance(tab, int) and not isinstance(tab, bool):
            where += f" (tab {tab})"
        lines.append(f"{label:<18} {where}")
        url = data.get("url")
        if url is not None:
            lines.append(f"{'':<18} {shown(str(url), limit=None)}")
    return lines


def unanswered(switched: Switched) -> str:
    """What ``teleop-ui switch`` says when no answer came (see :class:`Switched`)."""
    asked = _asked(switched.switch)
    there = switched.there
    if there is MISSING or there is None:
        held = "no answer is there"
    elif isinstance(there, Mapping):
        held = (
            f"the answer there is for {shown(str(there.get('robot')))} (UI configuration "
            f"{shown(str(there.get('configuration')))}) from {shown(str(there.get(WRITER_KEY)))}"
        )
    else:
        held = f"what is there is no answer ({kind_of(there)})"
    written = (
        "the selection was offered while switch waited (a watcher started later does not see it)"
        if switched.graph.startswith("ros2://")
        else "the selection is written"
    )
    return (
        f"no watcher answered {asked} on {switched.graph} within {switched.wait:g} s "
        f"({held}): {written}; is a watcher running there (teleop-ui watch)?"
    )
