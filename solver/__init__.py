"""Teleoperation UI configurations for heterogeneous robot teams, as a constraint problem.

After Mortimer, Horan and Seyedmahmoudian, "Building a Relationship between Robot
Characteristics and Teleoperation User Interfaces", Sensors 17(3):587 (2017). Robots are
described by characteristics (kinematic type, motion control, sensor type, number of sensors,
or any of the user's own); relationship rules map every value to the UI component that serves
it; a team selection says which values each kinematic type may take. The solver enumerates the
valid robots and partitions them into the fewest UI configurations.

The package has wings; each is a package with its own map in its docstring:

=====================  ==========================================================
``errors``             the exception root and located faults (every wing uses it)
``extras``             optional dependencies and the error when one is missing
``untrusted``          ``shown``: a stranger's string as human-readable output may
                       show it (escaped, cut to 60 characters, marked as cut); every
                       message, text output, finding and event uses it
``limits``             every size a command accepts, in one table (docs/security.md)
``deadline``           a call's time budget (``check``, ``count --symbolic``, the
                       cover), looked at in its loops; refused when spent
``lazy``               packages that load what they export on first use (PEP 562)
``collector``          Python's cycle collector held off while many acyclic values
                       are built (reading, solving)
``addresses``          whether a host names this machine only (loopback), for every
                       server and client of the tool
``files``              reading input safely (size limits, YAML with positions,
                       typed access, file kinds) and writing output atomically
``ros``                ROS vocabulary: topics, message-type names, teleoperation descriptions
``core``               the model: rule sets, constraints, team selections, the
                       constraint model, the partition into UI configurations, the
                       exact cover, the SAT questions about a rule set
``engines``            counting and enumerating: ``structure``, ``fast``, ``csp``;
                       the limits
``solving``            ``solve`` and ``assign`` with the engines, their JSON
                       contracts, symbolic counts, the article's published figures,
                       team files written back
``layouts``            UI configurations -> Foxglove/Lichtblick and RViz2 layouts
``reporting``          text/JSON/CSV/Markdown views, the robot list, plots,
                       HTML/Markdown reports, UVL export, batch runs
``check``              linting rule sets and teams: coverage, void, dead, conflicts
``identify``           real robots from ROS metadata (URDF, xacro, SRDF, topics, bags)
``live``               live UI assignment on a ROS 2 graph or a ROS 1 master (``watch``)
``cli``                the ``teleop-ui`` command line, a thin layer over the above
``studio``             the design studio: pages and a JSON API in the browser, a
                       layer over the above beside the command line
=====================  ==========================================================

Layers, lowest first; a module imports only from its own layer or lower ones, and no module
imports itself back through others (tests/test_architecture.py checks both):
``errors``, ``extras``, ``untrusted``, ``limits``, ``deadline``, ``lazy``, ``collector``,
``addresses`` ->
``files``, ``ros`` -> ``core`` -> ``engines``, ``check`` -> ``solving`` -> ``layouts``,
``identify`` -> ``reporting`` -> ``live`` -> ``cli``, ``studio``. Every import counts, those
made only for type checking too.

Every command from Python (docs/python-api.md has worked examples):

==============================  ========================================================
``teleop-ui solve TEAM``        ``solve(load_team("case3"))`` -> :class:`Solution`;
                                ``.to_dict()`` is the JSON output, ``.records()`` a table
``solve --plot``, ``report``    ``write_plot(solution, path)``, ``write_report(...)``
``assign``                      ``assign(solution, kinematic_type="UAV", ...)``
``count FILE``                  ``solve(team, count_only=True)``; a rule set's whole
                                design space: ``full_team(load_rules(path))``
``count --symbolic``            ``formulas(team)``
``robots``                      ``numbered_robots(solution)``
``reproduce``                   ``compare()``
``check FILES``                 ``check_files(paths)``; ``time_limit=``, ``partial=True``
``identify``, ``fleet``         ``identify_urdf(text, ...)``, ``identify_fleet(...)``
``watch``, ``assign --master``  ``Watcher``, ``assign_from_master(...)``; on any graph,
                                ROS 2 too: ``open_watcher(address, solution, profile)``,
                                ``assign_from_graph(open_source(address), ...)``, the
                                address from ``graph_address(ros2=True, domain=7)``
``demo ros2``                   ``emulated_fleet(domain)``; its graph: ``DdsGraph(domain)``
``switch``                      ``switch_robot(open_station(address), "/uav1", {...})``
                                -> :class:`Switched` (the watcher's answer)
``batch``                       ``solver.reporting.batch`` (``run_batch``: the steps)
``layouts``                     ``write_layouts(solution, load_presentation(), dir)``
``layouts --robot``             ``identified_layout(urdf, solution, ...)``
``export --format uvl``         ``team_to_uvl(team)``
==============================  ========================================================

Example::

    >>> from solver import load_team, solve
    >>> solution = solve(load_team("rules/teams/case1.yaml"))
    >>> solution.totals.valid_robots, solution.totals.ui_configurations
    (30, 6)
"""

# The public API is loaded lazily (PEP 562): `import solver` and the command line stay fast,
# and each name is imported from its module on first use. Keep _EXPORTS and the TYPE_CHECKING
# imports and __all__ in step (tests/test_api.py checks they match).
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from solver.lazy import load as _load
from solver.lazy import names as _names

__version__ = "0.1.0"

if TYPE_CHECKING:
    from solver.check import Finding, check_files
    from solver.core.constraints import Condition, RuleConstraint
    from solver.core.model import Robot, build_problem, robots
    from solver.core.partition import Configuration
    from solver.core.rules import default_rules_path, load_rules
    from solver.core.ruleset import Characteristic, Component, RuleSet
    from solver.core.team import Published, Team, TypeSelection, full_team, load_team
    from solver.errors import Fault, InputError, Location, RulesError, SolverError, TeamError
    from solver.identify import (
        Identification,
        IdentificationCache,
        Profile,
        identify_fleet,
        identify_urdf,
        load_profile,
    )
    from solver.layouts.identified import IdentifiedLayout, identified_layout
    from solver.layouts.presentation import load_presentation
    from solver.layouts.writer import write_layouts
    from solver.live import MasterError, Watcher, assign_from_master
    from solver.live.demo import emulated_fleet
    from solver.live.operator import Switched, open_station, switch_robot
    from solver.live.query import assign_from_graph
    from solver.live.sources import GraphAddress, graph_address, open_source
    from solver.live.sources.ros1 import MasterGraph
    from solver.live.sources.ros2 import DdsGraph
    from solver.live.watcher import open_watcher
    from solver.reporting.listing import numbered_robots
    from solver.reporting.plot import bars_figure, radar_figure, write_plot
    from solver.reporting.report import render_html, render_markdown, write_report
    from solver.reporting.uvl import team_to_uvl
    from solver.solving.assignment import Assignment, assign, parse_combination
    from solver.solving.reproduce import Comparison, compare
    from solver.solving.solution import Solution, TypeSummary, solve
    from solver.solving.symbolic import formulas

_EXPORTS = {
    "Assignment": "solver.solving.assignment",
    "Characteristic": "solver.core.ruleset",
    "Comparison": "solver.solving.reproduce",
    "Component": "solver.core.ruleset",
    "Condition": "solver.core.constraints",
    "Configuration": "solver.core.partition",
    "DdsGraph": "solver.live.sources.ros2",
    "Fault": "solver.errors",
    "Finding": "solver.check",
    "GraphAddress": "solver.live.sources",
    "Identification": "solver.identify",
    "IdentificationCache": "solver.identify",
    "IdentifiedLayout": "solver.layouts.identified",
    "InputError": "solver.errors",
    "Location": "solver.errors",
    "MasterError": "solver.live",
    "MasterGraph": "solver.live.sources.ros1",
    "Profile": "solver.identify",
    "Published": "solver.core.team",
    "Robot": "solver.core.model",
    "RuleConstraint": "solver.core.constraints",
    "RuleSet": "solver.core.ruleset",
    "RulesError": "solver.errors",
    "Solution": "solver.solving.solution",
    "SolverError": "solver.errors",
    "Switched": "solver.live.operator",
    "Team": "solver.core.team",
    "TeamError": "solver.errors",
    "TypeSelection": "solver.core.team",
    "TypeSummary": "solver.solving.solution",
    "Watcher": "solver.live",
    "assign": "solver.solving.assignment",
    "assign_from_graph": "solver.live.query",
    "assign_from_master": "solver.live",
    "bars_figure": "solver.reporting.plot",
    "build_problem": "solver.core.model",
    "check_files": "solver.check",
    "compare": "solver.solving.reproduce",
    "default_rules_path": "solver.core.rules",
    "emulated_fleet": "solver.live.demo",
    "formulas": "solver.solving.symbolic",
    "full_team": "solver.core.team",
    "graph_address": "solver.live.sources",
    "identified_layout": "solver.layouts.identified",
    "identify_fleet": "solver.identify",
    "identify_urdf": "solver.identify",
    "load_presentation": "solver.layouts.presentation",
    "load_profile": "solver.identify",
    "load_rules": "solver.core.rules",
    "load_team": "solver.core.team",
    "numbered_robots": "solver.reporting.listing",
    "open_source": "solver.live.sources",
    "open_station": "solver.live.operator",
    "open_watcher": "solver.live.watcher",
    "parse_combination": "solver.solving.assignment",
    "radar_figure": "solver.reporting.plot",
    "render_html": "solver.reporting.report",
    "render_markdown": "solver.reporting.report",
    "robots": "solver.core.model",
    "solve": "solver.solving.solution",
    "switch_robot": "solver.live.operator",
    "team_to_uvl": "solver.reporting.uvl",
    "write_layouts": "solver.layouts.writer",
    "write_plot": "solver.reporting.plot",
    "write_report": "solver.reporting.report",
}

__all__ = [
    "Assignment",
    "Characteristic",
    "Comparison",
    "Component",
    "Condition",
    "Configuration",
    "DdsGraph",
    "Fault",
    "Finding",
    "GraphAddress",
    "Identification",
    "IdentificationCache",
    "IdentifiedLayout",
    "InputError",
    "Location",
    "MasterError",
    "MasterGraph",
    "Profile",
    "Published",
    "Robot",
    "RuleConstraint",
    "RuleSet",
    "RulesError",
    "Solution",
    "SolverError",
    "Switched",
    "Team",
    "TeamError",
    "TypeSelection",
    "TypeSummary",
    "Watcher",
    "assign",
    "assign_from_graph",
    "assign_from_master",
    "bars_figure",
    "build_problem",
    "check_files",
    "compare",
    "default_rules_path",
    "emulated_fleet",
    "formulas",
    "full_team",
    "graph_address",
    "identified_layout",
    "identify_fleet",
    "identify_urdf",
    "load_presentation",
    "load_profile",
    "load_rules",
    "load_team",
    "numbered_robots",
    "open_source",
    "open_station",
    "open_watcher",
    "parse_combination",
    "radar_figure",
    "render_html",
    "render_markdown",
    "robots",
    "solve",
    "switch_robot",
    "team_to_uvl",
    "write_layouts",
    "write_plot",
    "write_report",
]


def __getattr__(name: str) -> Any:
    return _load(globals(), _EXPORTS, name)


def __dir__() -> list[str]:
    return _names(globals(), _EXPORTS)
