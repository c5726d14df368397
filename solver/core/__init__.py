"""The model: rule sets, team selections, constraints, and the solved partition.

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
``solution``     :func:`solve` a team -> :class:`Solution`
``assignment``   :func:`assign` one combination -> :class:`Assignment`
``contracts``    the JSON shapes of a solution and an assignment (``--format json``)
``symbolic``     counts as formulas of a type's maximum sensor count (sympy)
``reproduce``    the article's published figures beside the computed ones
===============  ==============================================================

Counting and enumerating live in :mod:`solver.engines`; output in :mod:`solver.reporting`.
"""
