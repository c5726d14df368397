"""Layouts checked against the viewers' own rules, kept as data the project owns (issue 26).

The rules were read from Lichtblick's TypeScript and RViz2's C++ (each data file names the
repository and commit) and confirmed in the running Lichtblick (``tools/lichtblick_check.md``).
They live in the package, not only in the tests, so that a layout written with a presentation
of one's own (``layouts --presentation``) can be checked the same way, and so that a writer
can refuse a layout before it reaches an operator.

=================  ======================================================================
``lichtblick.yaml``  layout shape, panel types, each panel's config keys and value types,
                     what the app fills in on opening, the Publish panel's sample messages
``rviz2.yaml``       file sections, display classes and the messages they show, tools and
                     their topics, properties
``data``             loading the data files; their small type language
``messagepath``      Lichtblick's message-path grammar (``/topic.field[0]{id==1}``)
``lichtblick``       :func:`check_lichtblick`: a Lichtblick layout, every problem at once
``rviz``             :func:`check_rviz`: an RViz2 document, every problem at once
``quality.yaml``     the project's own limits for a layout an operator reads (issue 39)
``quality``          a layout's figures (primary view, smallest tile, tiles on a screen)
                     and a team's consistency, measured on the split tree
=================  ======================================================================

ROS 2 topic names are checked by :func:`solver.ros.names.full_topic_name_problem` (rmw's
rules). Not here: writing layouts (:mod:`solver.layouts.foxglove`, :mod:`solver.layouts.rviz`).
"""

from solver.layouts.checks.lichtblick import check_lichtblick
from solver.layouts.checks.messagepath import MessagePath, MessagePathError, parse_message_path
from solver.layouts.checks.rviz import check_rviz

__all__ = [
    "MessagePath",
    "MessagePathError",
    "check_lichtblick",
    "check_rviz",
    "parse_message_path",
]
