"""Teleoperation UI configurations for heterogeneous robot teams, as a constraint problem.

After Mortimer, Horan and Seyedmahmoudian, "Building a Relationship between Robot
Characteristics and Teleoperation User Interfaces", Sensors 17(3):587 (2017). Robots are
described by characteristics (kinematic type, motion control, sensor type, number of sensors,
or any of the user's own); relationship rules map every value to the UI component that serves
it; a team selection says which values each kinematic type may take. The solver enumerates the
valid robots and partitions them into the fewest UI configurations.

Modules, one concept each:

=====================  ==========================================================
``errors``             the exception root and located faults
``yamlio``             safe YAML loading with line/column for every value
``reader``             typed, fault-collecting access to a loaded document
``rules``              rule sets: characteristics, components, :func:`load_rules`
``constraints``        constraints between values, as data
``team``               team selections, :func:`load_team`
``model``              the python-constraint model; valid robots
``partition``          robots -> UI configurations, numbering, minimum cover
``solve``              :func:`solve` a team -> :class:`Solution`
``assign``             :func:`assign` one combination -> :class:`Assignment`
``reproduce``          published figures beside computed ones
``formats``            text / JSON / CSV / Markdown rendering
``cli``                the ``teleop-ui`` command line
=====================  ==========================================================

Example::

    >>> from solver import load_team, solve
    >>> solution = solve(load_team("rules/teams/case1.yaml"))
    >>> solution.totals.valid_robots, solution.totals.ui_configurations
    (30, 6)
"""

from solver.assign import Assignment, assign, parse_combination
from solver.constraints import Condition, RuleConstraint
from solver.errors import Fault, InputError, Location, RulesError, SolverError, TeamError
from solver.model import Robot, build_problem, robots
from solver.partition import Configuration
from solver.reproduce import Comparison, compare
from solver.rules import Characteristic, Component, RuleSet, default_rules_path, load_rules
from solver.solve import Solution, TypeSummary, solve
from solver.team import Published, Team, TypeSelection, load_team

__all__ = [
    "Assignment",
    "Characteristic",
    "Comparison",
    "Component",
    "Condition",
    "Configuration",
    "Fault",
    "InputError",
    "Location",
    "Published",
    "Robot",
    "RuleConstraint",
    "RuleSet",
    "RulesError",
    "Solution",
    "SolverError",
    "Team",
    "TeamError",
    "TypeSelection",
    "TypeSummary",
    "assign",
    "build_problem",
    "compare",
    "default_rules_path",
    "load_rules",
    "load_team",
    "parse_combination",
    "robots",
    "solve",
]
