"""The model: rule sets, team selections, constraints, and the partition of robots into
configurations.

===============  ==============================================================
``constraints``  constraints between characteristic values, as data
``ruleset``      rule sets as frozen values: characteristics, components, :class:`RuleSet`
``rules``        reading rule set files, :func:`load_rules`
``team``         team selections, :func:`load_team`
``forbidden``    selected values a team's constraints leave no robot for
``model``        the python-constraint model; valid robots
``partition``    robots -> UI configurations, numbering
``cover``        the exact minimum cover when components overlap (factors, HiGHS)
``analysis``     which values survive the constraints; minimal conflicting subsets
``oracle``       "is there a valid robot over these domains?", asked of a SAT solver
``regions``      the robots a constraint excludes, as boxes of value sets
===============  ==============================================================

Counting and enumerating live in :mod:`solver.engines`, above the model; solving a team with
them in :mod:`solver.solving`, above the engines; output in :mod:`solver.reporting`.
"""
