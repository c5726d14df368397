"""Solving a team: the engines (:mod:`solver.engines`) applied to a team of the model
(:mod:`solver.core`), and what is made of the answer.

===============  ==============================================================
``solution``     :func:`solve` a team -> :class:`Solution`
``assignment``   :func:`assign` one combination -> :class:`Assignment`
``contracts``    the JSON shapes of a solution and an assignment (``--format json``)
``symbolic``     counts as formulas of a type's maximum sensor count (sympy)
``reproduce``    the article's published figures beside the computed ones
``teamfile``     a team (and its counts) written back as a team file
===============  ==============================================================

The model imports nothing from here, and the engines nothing but the model: the layers run
model, engines, solving (``tests/test_architecture.py`` keeps it so).
"""
