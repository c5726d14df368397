"""Layouts of the robots on a live graph (``teleop-ui watch --layouts DIR``), and where the
answer's are.

When a robot appears or changes (``robot_added``, ``robot_changed``: its description, its
identification or its topics), its Lichtblick layouts are written into its own folder,
``DIR/uav1/config-001.json`` (the robot of the root namespace: ``DIR`` itself), one per UI
configuration its combinations take, as ``teleop-ui layouts --robot`` writes one
(:func:`solver.layouts.robot.robot_layout`): under its namespace, its panels on its real
topics (names, types and directions from the graph), its own sensor tiles, a joint command
naming the joints of its description. Each file is written atomically: an operator's tool
never reads half of one.

**The team layout**, ``DIR/team.json`` (:mod:`solver.layouts.team`): every robot's layouts as
tabs of one Lichtblick layout, one tab per (robot, configuration) its combinations take,
beside the follower panel of this project's extension, which switches tabs as the answer
changes. It is written again whenever a robot appears, changes or goes (what it holds
changed), never on a switch, so an operator imports it again only when the robots changed.

**Where the answer's layouts are** (:meth:`LiveLayouts.links`, the watcher puts them in its
answer and its ``selection_changed`` events): the active robot's layout of the selected
configuration (written first when none of its combinations took that configuration: a mode
it was asked for and does not offer), and the team layout with the tab of that (robot,
configuration); each with its address when the watcher serves the folder
(``watch --serve``, :mod:`solver.live.server`). None for the robot with no active robot, or
when the robot has no layout (it could not be identified, or its namespace is no ROS 2
name). What could not be written, and panels left without a real topic, are warnings
(:meth:`LiveLayouts.take_warnings`: the command prints them on stderr).

**Only ROS names reach a file name or an address.** A robot's folder is its namespace,
written only when it is a ROS 2 name (letters, digits and ``_`` between slashes: no ``..``,
no ``%``, nothing an address must escape); file names are the project's own
(``config-001.json``, ``team.json``). Addresses are the server's own followed by the file's
path below ``DIR``, percent-encoded all the same.

**Bounded.** Every layout the watcher writes while it runs, the team layout included, counts
against the limits of a command (:mod:`solver.limits`): at most ``written-files`` files and
``written-bytes`` bytes in all (a layout written again replaces its file: its new size
counts, not another file). Past either, a new layout is not written: one warning says so
(the first time), and the robot's answers name no layout. No link inside ``DIR`` is followed
(a folder someone planted as ``DIR/uav1``): that robot gets no layout and a warning naming
the link (:func:`solver.files.atomic.write_all_atomic`).

Not here: the events themselves (:mod:`solver.live.events`); the layouts
(:mod:`solver.layouts`); serving them (:mod:`solver.live.server`).
"""

from __future__ import annotations

import json
from collections.abc import Collection, Mapping
from pathlib import Path
from typing import Any
from urllib.parse import quote

from solver.errors import SolverError
from solver.files.atomic import write_atomic
from solver.layouts.foxglove import layout_filename
from solver.layouts.ordering import without_data
from solver.layouts.plan import check_namespace
from solver.layouts.presentation import Presentation, load_presentation
from solver.layouts.robot import RobotLayout, robot_layout
from solver.layouts.team import TEAM_FILE, TeamTab, tab_title, team_layout
from solver.limits import limit
from solver.live.robot import LiveRobot
from solver.live.selection import RESULT_PARAM, ActiveSelection, LayoutLink
from solver.solving.assignment import Assignment
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = ["LAYOUTS_PATH", "LiveLayouts"]

# Where the server serves the folder: ``http://HOST:PORT/layouts/<path below DIR>``.
LAYOUTS_PATH = "/layouts/"


class LiveLayouts:
    """Writes each robot's layouts and the team layout into ``directory`` as the watcher
    reports robots (:meth:`sync`), and says where the active robot's are (:meth:`links`).

    ``base_url``: the server's address (``http://127.0.0.1:8770``) when the folder is
    served, so that links carry addresses; ``answer_url``: where the follower reads answers
    (written into the team layout; ``None``: from the viewer's data source only)."""

    def __init__(
        self,
        directory: str | Path,
        solution: Solution,
        presentation: Presentation | None = None,
        *,
        base_url: str | None = None,
        answer_url: str | None = None,
    ) -> None:
        self.directory = Path(directory).absolute()
        self.solution = solution
        # No bag of rates here: an order that needs one is applied alphabetically, said once.
        self.presentation, unordered = without_data(
            presentation if presentation is not None else load_presentation(), "watch --layouts"
        )
        self.base_url = base_url
        self.answer_url = answer_url
        self._robots: dict[str, LiveRobot] = {}
        # (namespace, file name) -> the path written for the robot as it is now, and its
        # layout (for the team layout), with the number of the write that made it.
        self._written: dict[tuple[str, str], tuple[Path, dict[str, Any], int]] = {}
        # Robot states whose layout was refused (a warning said why): not tried again each poll.
        self._refused: set[tuple[str, str]] = set()
        self._writes = 0
        # Every file written while the watcher runs, and its size now (the bound counts them).
        self._sizes: dict[Path, int] = {}
        self._bounded = False  # a limit stopped a layout (and a warning said so)
        self._warnings: list[str] = [] if unordered is None else [str(unordered)]
        self._synced = False
        # The team layout as last made (what it holds: each tab's robot, configuration and
        # write), where it was written (``None``: it could not be), and (robot, configuration)
        # -> its tab.
        self._team: tuple[tuple[str, int, int], ...] | None = None
        self._team_path: Path | None = None
        self._tabs: dict[tuple[str, int], int] = {}

    @property
    def team_path(self) -> Path:
        return self.directory / TEAM_FILE

    def take_warnings(self) -> list[str]:
        """The warnings (located, escaped) since the last call, for stderr."""
        warnings, self._warnings = self._warnings, []
        return warnings

    def sync(self, robots: Mapping[str, LiveRobot], changed: Collection[str]) -> None:
        """``robots`` are every robot on the graph now (by namespace), ``changed`` those added
        or changed since the last call: their layouts are written again, and the team layout
        when what it holds changed."""
        if self._synced and not changed and robots.keys() == self._robots.keys():
            return
        self._synced = True
        self._robots = dict(robots)
        self._written = {
            key: value
            for key, value in self._written.items()
            if key[0] in robots and key[0] not in changed
        }
        self._refused = {key for key in self._refused if key[0] in robots and key[0] not in changed}
        for namespace in sorted(changed):
            robot = robots.get(namespace)
            if robot is None:
                continue
            for combination in robot.combinations:
                self._write(robot, combination.assignment)
        self._write_team()

    def links(self, selection: ActiveSelection | None) -> tuple[LayoutLink, ...]:
        """Where the layouts of ``selection``'s answer are (see the module docstring)."""
        if selection is None or selection.assignment is None:
            return ()
        links: list[LayoutLink] = []
        robot = self._robots.get(selection.request.robot or "")
        if robot is not None:
            path = self._write(robot, selection.assignment)
            if path is not None:
                links.append(LayoutLink("foxglove", str(path), self._url(path)))
        if self._team_path is not None:
            tab = self._tabs.get((selection.request.robot or "", selection.assignment.number))
            team = self._team_path
            links.append(LayoutLink("team", str(team), self._url(team), tab))
        return tuple(links)

    def _url(self, path: Path) -> str | None:
        if self.base_url is None:
            return None
        below = path.relative_to(self.directory).as_posix()
        return f"{self.base_url}{LAYOUTS_PATH}{quote(below)}"

    def _write(self, robot: LiveRobot, assignment: Assignment) -> Path | None:
        """The robot's layout of ``assignment``'s configuration, written once per robot state
        (``None``: it has none; a warning says why)."""
        name = layout_filename(assignment.number, default=assignment.is_default)
        key = (robot.namespace, name)
        if key in self._written:
            return self._written[key][0]
        if robot.identification is None or key in self._refused:
            return None
        path = self._written_now(robot, assignment, key, name)
        if path is None:
            self._refused.add(key)
        return path

    def _written_now(
        self, robot: LiveRobot, assignment: Assignment, key: tuple[str, str], name: str
    ) -> Path | None:
        """The layout written (``None``: refused, and a warning says why)."""
        assert robot.identification is not None  # _write's caller checked
        try:
            namespace = check_namespace(robot.namespace, robot.namespace)
            target = self.directory.joinpath(*namespace.split("/")[1:], name)
            # A file past `written-files` is refused before its layout is built.
            refused = f"no layout for {shown(robot.namespace)}"
            if self._past_bound(refused, target, 0):
                return None
            layout = robot_layout(
                self.solution,
                assignment,
                self.presentation,
                namespace=namespace,
                topics=robot.graph_topics(),
                topics_source=f"{robot.namespace} topics",
                joints=robot.identification.joints,
                file=str(target),
            )
            size = len(layout.text.encode("utf-8", "backslashreplace"))
            if self._past_bound(refused, target, size):
                return None
            path = write_atomic(target, layout.text, within=self.directory)
        except SolverError as error:
            self._warnings.append(
                f"no layout for {shown(robot.namespace)}: {shown(str(error), limit=None)}"
            )
            return None
        self._writes += 1
        self._written[key] = (path, json.loads(layout.text), self._writes)
        self._sizes[path] = size
        self._warnings += _warnings(layout)
        return path

    def _write_team(self) -> None:
        """``DIR/team.json`` again when the tabs it holds changed (see the module docstring)."""
        tabs: list[TeamTab] = []
        held: dict[tuple[str, int], int] = {}  # (robot, configuration) -> the write
        for namespace, robot in sorted(self._robots.items()):
            for combination in robot.combinations:
                assignment = combination.assignment
                name = layout_filename(assignment.number, default=assignment.is_default)
                written = self._written.get((namespace, name))
                if written is None or (namespace, assignment.number) in held:
                    continue
                values = [value for _, value in combination.values]
                title = tab_title(
                    namespace, assignment.number, values, default=assignment.is_default
                )
                tabs.append(TeamTab(namespace, assignment.number, title, written[1]))
                held[namespace, assignment.number] = written[2]
        made = tuple((robot, number, write) for (robot, number), write in held.items())
        if made == self._team:
            return
        # Not made again until what it holds changes, whether it is written or not.
        self._team, self._team_path, self._tabs = made, None, {}
        target = self.team_path
        try:
            text = json.dumps(
                team_layout(
                    tabs,
                    answer_topic=RESULT_PARAM,
                    answer_url=self.answer_url,
                    note=_team_note(len({t.robot for t in tabs}), self.directory),
                    file=str(target),
                ),
                indent=2,
                sort_keys=True,
            )
            size = len(text.encode("utf-8")) + 1
            if self._past_bound("no team layout", target, size):
                return
            self._team_path = write_atomic(target, text + "\n", within=self.directory)
        except SolverError as error:
            self._warnings.append(f"no team layout: {shown(str(error), limit=None)}")
            return
        self._sizes[target] = size
        self._tabs = {pair: index for index, pair in enumerate(held)}

    def _past_bound(self, refused: str, path: Path, size: int) -> bool:
        """Whether writing ``size`` bytes to ``path`` would take the watcher past a limit; the
        first time, a warning says so (``refused``: what is not written), located at the
        folder."""
        files = len(self._sizes) + (path not in self._sizes)
        total = sum(self._sizes.values()) - self._sizes.get(path, 0) + size
        for name, count, noun in (
            ("written-files", files, "files to write"),
            ("written-bytes", total, "bytes to write"),
        ):
            if limit(name).exceeded(count):
                if not self._bounded:
                    self._bounded = True
                    what = f"{noun} (every layout the watcher writes)"
                    past = f"{self.directory}: {limit(name).message(count, noun=what)}"
                    self._warnings.append(
                        f"{refused} (nor for later robots: the watcher's layouts reached a "
                        f"limit): {shown(past, limit=None)}"
                    )
                return True
        return False


def _warnings(layout: RobotLayout) -> list[str]:
    return [shown(str(warning), limit=None) for warning in layout.warnings]


def _team_note(robots: int, directory: Path) -> str:
    return (
        f"teleop-ui: the team layout of {robots} robot(s), one tab per robot and UI "
        f"configuration, written by teleop-ui watch --layouts {directory}; the follower panel "
        "switches tabs as the operator switches; import this file again when robots join or "
        "change"
    )
