"""Layouts an operator tool can open, one per UI configuration (issue 17).

==================  ===============================================================
``presentation``    the presentation: component -> panel, topic template
``grammar``         the presentation grammar: roles, their regions and cuts (issue 39)
``tiling``          the sensor-count arrangement: sensors shown, Equation (2)'s cluster size
``ordering``        the order of a cluster's sensors: alphabetical, priority, data rate
``plan``            what a layout shows for a robot (or a template): panels, names, topics
``design``          a plan laid out by the grammar: tiles, roles, splits (every target's)
``samples``         the whole message a Publish panel holds
``foxglove``        Foxglove / Lichtblick layout JSON; its validation
``rviz``            RViz2 ``.rviz`` YAML; its validation
``targets``         the table of targets (foxglove, rviz): extension, how made and checked
``writer``          writing every configuration's layout into a folder, as one unit
``robot``           one robot's layout under its namespace, fed by its real topics
``team``            the team layout: a tab per (robot, configuration) beside the
                    follower panel that switches them (``watch --layouts``)
``identified``      a real robot's layout from its description: identified, given its
                    configuration, laid out (``layouts --robot``)
``topics``          a robot's real topics in place of the templates
``preview``         a layout's panel tree as an SVG thumbnail
``checks``          layouts against the viewers' own rules, kept as data (issue 26), and
                    the layout quality for an operator (``checks.quality``, issue 39)
==================  ===============================================================

Not here: solving (:mod:`solver.solving.solution`); UVL export (:mod:`solver.reporting.uvl`).
"""

from __future__ import annotations

from solver.layouts.foxglove import (
    LayoutError,
    foxglove_layout,
    layout_filename,
    validate_foxglove,
)
from solver.layouts.plan import Robot
from solver.layouts.presentation import PanelSpec, Presentation, load_presentation
from solver.layouts.rviz import rviz_layout, validate_rviz
from solver.layouts.writer import write_layouts
from solver.ros.joints import JointStart

__all__ = [
    "JointStart",
    "LayoutError",
    "PanelSpec",
    "Presentation",
    "Robot",
    "foxglove_layout",
    "layout_filename",
    "load_presentation",
    "rviz_layout",
    "validate_foxglove",
    "validate_rviz",
    "write_layouts",
]
