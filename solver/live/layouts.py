"""Layouts of the robots on a live graph (``teleop-ui watch --layouts DIR``).

When a robot appears or changes (``robot_added``, ``robot_changed``: its description, its
identification or its topics), its Lichtblick layouts are written into its own folder,
``DIR/uav1/config-001.json`` (the robot of the root namespace: ``DIR`` itself), one per UI
configuration its combinations take, as ``teleop-ui layouts --robot`` writes one
(:func:`solver.layouts.robot.robot_layout`): under its namespace, its panels on its real
topics (names, types and directions from the graph), its own sensor tiles, a joint command
naming the joints of its description. Each file is written atomically: an operator's tool
never reads half of one.

Each ``selection_changed`` event gets ``"layout"``: the active robot's layout of the selected
configuration (written first when none of its combinations took that configuration: a mode
it was asked for and does not offer), ``null`` with no active robot or when the robot has no
layout (it could not be identified, or its namespace is no ROS 2 name); the text format gets a
``layout`` line. What could not be written, and panels left without a real topic, are
warnings for stderr.

**Bounded.** Every layout the watcher writes while it runs counts against the limits of a
command (:mod:`solver.limits`): at most ``written-files`` files and ``written-bytes`` bytes in
all (a layout written again replaces its file: its new size counts, not another file). Past
either, a new layout is not written: one warning says so (the first time), and the robot's
selections get ``"layout": null``. No link inside ``DIR`` is followed (a folder someone
planted as ``DIR/uav1``): that robot gets no layout and a warning naming the link
(:func:`solver.files.atomic.write_all_atomic`).

Not here: the events themselves (:mod:`solver.live.events`); the layouts
(:mod:`solver.layouts`).
"""

from __future__ import annotations

import json
from pathlib import Path

from solver.errors import SolverError
from solver.files.atomic import write_atomic
from solver.layouts.foxglove import layout_filename
from solver.layouts.plan import check_namespace
from solver.layouts.presentation import Presentation, load_presentation
from solver.layouts.robot import RobotLayout, robot_layout
from solver.limits import limit
from solver.live.discovery import normalise_namespace
from solver.live.events import Event, RobotAdded, RobotChanged, RobotRemoved, SelectionChanged
from solver.live.robot import LiveRobot
from solver.solving.assignment import Assignment
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = ["LiveLayouts"]


class LiveLayouts:
    """Writes each robot's layouts into ``directory`` as events report robots, and names the
    active robot's in selection events."""

    def __init__(
        self,
        directory: str | Path,
        solution: Solution,
        presentation: Presentation | None = None,
    ) -> None:
        self.directory = Path(directory)
        self.solution = solution
        self.presentation = presentation if presentation is not None else load_presentation()
        self._robots: dict[str, LiveRobot] = {}
        # (namespace, file name) -> the path written for the robot as it is now.
        self._written: dict[tuple[str, str], Path] = {}
        # Every file written while the watcher runs, and its size now (the bound counts them).
        self._sizes: dict[Path, int] = {}
        self._bounded = False  # a limit stopped a layout (and a warning said so)

    def update(self, event: Event) -> list[str]:
        """Write what ``event`` calls for; the warnings (located, escaped) for stderr."""
        if isinstance(event, RobotAdded | RobotChanged):
            namespace = event.robot.namespace
            self._robots[namespace] = event.robot
            self._written = {k: v for k, v in self._written.items() if k[0] != namespace}
            warnings: list[str] = []
            for combination in event.robot.combinations:
                warnings += self._write(event.robot, combination.assignment)[1]
            return warnings
        if isinstance(event, RobotRemoved):
            self._robots.pop(event.namespace, None)
            return []
        if isinstance(event, SelectionChanged):
            return self._active(event)[1]
        return []

    def path(self, event: SelectionChanged) -> str | None:
        """The active robot's layout of the selected configuration, or None."""
        return self._active(event)[0]

    def with_layout(self, text: str, event: Event, fmt: str) -> str:
        """``text`` (one rendered event) with ``layout`` added when it is a selection."""
        if not isinstance(event, SelectionChanged):
            return text
        path = self.path(event)
        if fmt == "json":
            data = json.loads(text)
            data["layout"] = path
            return json.dumps(data, ensure_ascii=False) + "\n"
        return text + f"{'layout':<16}{shown(path) if path else '(no layout)'}\n"

    def _active(self, event: SelectionChanged) -> tuple[str | None, list[str]]:
        selection = event.selection
        if selection is None or selection.assignment is None or selection.request.robot is None:
            return None, []
        robot = self._robots.get(normalise_namespace(selection.request.robot))
        if robot is None:
            return None, []
        path, warnings = self._write(robot, selection.assignment)
        return (str(path) if path is not None else None), warnings

    def _write(self, robot: LiveRobot, assignment: Assignment) -> tuple[Path | None, list[str]]:
        """The robot's layout of ``assignment``'s configuration, written once per robot state."""
        name = layout_filename(assignment.number, default=assignment.is_default)
        key = (robot.namespace, name)
        if key in self._written:
            return self._written[key], []
        if robot.identification is None:
            return None, []
        try:
            namespace = check_namespace(robot.namespace, robot.namespace)
            target = self.directory.joinpath(*namespace.split("/")[1:], name)
            # A file past `written-files` is refused before its layout is built.
            past = self._past_bound(target, 0)
            if past is not None:
                return None, self._bound_warning(robot, past)
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
            past = self._past_bound(target, size)
            if past is not None:
                return None, self._bound_warning(robot, past)
            path = write_atomic(target, layout.text, within=self.directory)
        except SolverError as error:
            return None, [
                f"no layout for {shown(robot.namespace)}: {shown(str(error), limit=None)}"
            ]
        self._written[key] = path
        self._sizes[path] = size
        return path, _warnings(layout)

    def _past_bound(self, path: Path, size: int) -> str | None:
        """Why writing ``size`` bytes to ``path`` would take the watcher past a limit, if it
        would: the limit's message, located at the folder."""
        files = len(self._sizes) + (path not in self._sizes)
        total = sum(self._sizes.values()) - self._sizes.get(path, 0) + size
        for name, count, noun in (
            ("written-files", files, "files to write"),
            ("written-bytes", total, "bytes to write"),
        ):
            if limit(name).exceeded(count):
                what = f"{noun} (every layout the watcher writes)"
                return f"{self.directory}: {limit(name).message(count, noun=what)}"
        return None

    def _bound_warning(self, robot: LiveRobot, past: str) -> list[str]:
        """The warning for the first layout a limit stops; nothing for the next ones."""
        if self._bounded:
            return []
        self._bounded = True
        return [
            f"no layout for {shown(robot.namespace)} (nor for later robots: the watcher's "
            f"layouts reached a limit): {shown(past, limit=None)}"
        ]


def _warnings(layout: RobotLayout) -> list[str]:
    return [shown(str(warning), limit=None) for warning in layout.warnings]
