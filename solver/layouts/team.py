"""The team layout: every robot's screens in one Lichtblick layout that follows the operator's
switch (issue 38; written by ``watch --layouts DIR`` as ``DIR/team.json``).

Lichtblick's extension API cannot load, select or replace a layout; an extension panel can
only rewrite the config of the panel beside it in its split (``context.layout.addPanel``
with ``position: "sibling"``, ``updateIfExists``). So the team layout is that pair::

    {"direction": "row", "first": "teleop-ui.follower!follower", "second": "Tab!robots",
     "splitPercentage": 15}

* ``Tab!robots``, Lichtblick's own Tab panel, holds one tab per (robot, UI configuration)
  the operator can select for that robot: each tab is that robot's layout of that
  configuration as written for it alone (its panels on its own topics), the panel ids
  renamed so that they are unique across tabs (``Image!p02`` of the third tab is
  ``Image!t3-p02``), every panel's config in the layout's ``configById`` as the Tab panel
  keeps nested panels. The app mounts the active tab only.
* ``teleop-ui.follower!follower``, the panel of this project's extension (viewer/lichtblick/):
  its config maps each (robot, configuration) to its tab, and says where the answer comes
  from (``answerTopic`` on the viewer's data source, ``answerUrl`` an EventSource of
  ``watch --serve``, or ``null``); on each answer it sets the Tab panel's ``activeTabIdx``.

A team without robots has one empty tab that says so (a Tab panel with no tab is replaced by
the app's default). The layout is checked for its shape before it is returned
(:func:`solver.layouts.checks.lichtblick.tree_faults`); every rule of the viewer holds for it
as for each robot's layout (:func:`solver.layouts.checks.check_lichtblick`, which checks each
tab as a screen of its own).

Not here: which robots and configurations, and writing the file (:mod:`solver.live.layouts`);
one robot's layout (:mod:`solver.layouts.robot`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from solver.errors import Fault, Location
from solver.layouts.checks.lichtblick import tree_faults
from solver.layouts.foxglove import NOTE_VARIABLE, LayoutError

__all__ = [
    "FOLLOWER_ID",
    "FOLLOWER_PANEL",
    "TABS_ID",
    "TEAM_FILE",
    "TeamTab",
    "tab_title",
    "team_layout",
]

# The follower's panel type: "<extension displayName>.<panel name>", as Lichtblick names an
# extension's panel (checks/lichtblick.yaml extension_panels).
FOLLOWER_PANEL = "teleop-ui.follower"
FOLLOWER_ID = f"{FOLLOWER_PANEL}!follower"
TABS_ID = "Tab!robots"
TEAM_FILE = "team.json"
# The follower's share of the screen's width: a narrow status column.
_FOLLOWER_PERCENT = 15
_NO_ROBOT = "no robot yet: import this layout again once robots are on the graph"


@dataclass(frozen=True, slots=True)
class TeamTab:
    """One tab: the robot (its namespace), the UI configuration, the tab's title and the
    robot's layout of that configuration (Lichtblick JSON, as written for the robot alone)."""

    robot: str
    configuration: int
    title: str
    layout: Mapping[str, Any]


def tab_title(robot: str, configuration: int, values: Sequence[str], *, default: bool) -> str:
    """``/uav1: 3 (UAV, Flight, 2D Camera, 1)``: what the tab's toolbar shows."""
    which = f"{configuration} (default)" if default else str(configuration)
    return f"{robot}: {which} ({', '.join(values)})"


def team_layout(
    tabs: Sequence[TeamTab],
    *,
    answer_topic: str,
    answer_url: str | None = None,
    note: str = "",
    file: str = "<team layout>",
) -> dict[str, Any]:
    """The team layout of ``tabs`` (in their order; see the module docstring); a located
    :class:`~solver.layouts.foxglove.LayoutError` if its shape is wrong (two tabs of one
    robot and configuration, a tab's layout that is not one)."""
    configs: dict[str, Any] = {}
    entries: list[dict[str, Any]] = []
    mapping: list[dict[str, Any]] = []
    for index, tab in enumerate(tabs):
        renamed = {old: _renamed(old, index) for old in tab.layout.get("configById", {})}
        configs.update(
            {
                renamed[old]: _rename_tabs(config, renamed) if old.startswith("Tab!") else config
                for old, config in tab.layout["configById"].items()
            }
        )
        entry: dict[str, Any] = {"title": tab.title}
        if tab.layout.get("layout") is not None:
            entry["layout"] = _rename_tree(tab.layout["layout"], renamed)
        entries.append(entry)
        mapping.append({"robot": tab.robot, "configuration": tab.configuration, "tab": index})
    configs[TABS_ID] = {"activeTabIdx": 0, "tabs": entries or [{"title": _NO_ROBOT}]}
    configs[FOLLOWER_ID] = {
        "answerUrl": answer_url,
        "answerTopic": answer_topic,
        "tabs": mapping,
        "defaultTab": None,
    }
    layout = {
        "configById": configs,
        "globalVariables": {NOTE_VARIABLE: note} if note else {},
        "userNodes": {},
        "playbackConfig": {"speed": 1},
        "layout": {
            "direction": "row",
            "first": FOLLOWER_ID,
            "second": TABS_ID,
            "splitPercentage": _FOLLOWER_PERCENT,
        },
    }
    _check(layout, mapping, file)
    return layout


def _renamed(panel_id: str, index: int) -> str:
    kind, _, own = panel_id.partition("!")
    return f"{kind}!t{index + 1}-{own}"


def _rename_tabs(config: Any, renamed: Mapping[str, str]) -> Any:
    """A robot layout's Tab panel (a cluster of sensors) with the ids in its tabs renamed."""
    tabs = config.get("tabs") if isinstance(config, dict) else None
    if not isinstance(tabs, list):
        return config
    return {
        **config,
        "tabs": [
            {**tab, "layout": _rename_tree(tab["layout"], renamed)}
            if isinstance(tab, dict) and "layout" in tab
            else tab
            for tab in tabs
        ],
    }


def _rename_tree(node: Any, renamed: Mapping[str, str]) -> Any:
    """A panel tree with its ids renamed (the robot layouts' trees hold a split per tile: a
    few dozen deep at most, :mod:`solver.layouts.tiling`)."""
    if isinstance(node, str):
        return renamed.get(node, node)
    if isinstance(node, dict):
        return {
            key: _rename_tree(value, renamed) if key in ("first", "second") else value
            for key, value in node.items()
        }
    return node


def _check(layout: dict[str, Any], mapping: list[dict[str, Any]], file: str) -> None:
    faults = list(tree_faults(layout, file))
    pairs = [(entry["robot"], entry["configuration"]) for entry in mapping]
    if len(set(pairs)) != len(pairs):
        twice = sorted({pair for pair in pairs if pairs.count(pair) > 1})
        where = Location(file, path=f"configById.{FOLLOWER_ID}.tabs")
        faults.append(Fault(where, f"a robot's configuration has two tabs: {twice}"))
    if faults:
        raise LayoutError(faults)
