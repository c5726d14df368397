"""The presentation: which viewer panel presents each UI component, as data.

The shipped default is ``rules/presentation.yaml`` (a YAML file marked ``profile:
presentation``); a user passes their own copy with ``layouts --presentation``. (An
*identification profile*, :mod:`solver.identify.profile`, is another thing: how robots are
read; ``--profile`` names that one on every command.) Every problem in a presentation is
reported at once, located (file:line:col).

Not here: building layouts (:mod:`solver.layouts.foxglove`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from solver.core.ruleset import RuleSet
from solver.errors import SolverError
from solver.files.reader import Reader
from solver.files.yamlio import load_document
from solver.layouts.grammar import DEFAULT_GRAMMAR, Grammar, read_grammar
from solver.ros.names import full_topic_name_problem
from solver.untrusted import shown

__all__ = [
    "PANEL_TYPES",
    "ROBOT",
    "PanelSpec",
    "Presentation",
    "PresentationError",
    "default_presentation_path",
    "load_presentation",
]

# The presentation's placeholder for the robot's namespace in a topic template.
ROBOT = "<robot>"
# The Foxglove / Lichtblick panel types a generated layout may use (their registered ids).
PANEL_TYPES = ("3D", "Image", "Indicator", "Plot", "Publish", "RawMessages", "Teleop")


class PresentationError(SolverError, ValueError):
    """A presentation is malformed or names what the rules or the viewer do not know."""


@dataclass(frozen=True, slots=True)
class PanelSpec:
    """How one UI component is presented: a panel type, a topic template, its message types."""

    component: str
    panel: str
    topic: str
    types: tuple[str, ...]
    placeholder: bool = False


@dataclass(frozen=True, slots=True)
class Presentation:
    """Component name -> panel, in file order; the grammar that lays the panels out."""

    file: str
    panels: tuple[PanelSpec, ...]
    grammar: Grammar = field(default=DEFAULT_GRAMMAR)

    def spec(self, component: str) -> PanelSpec:
        """The component's panel; a titled placeholder for a component the presentation omits."""
        for spec in self.panels:
            if spec.component == component:
                return spec
        # Never a silent drop: an unmapped component still gets a panel, titled as a
        # placeholder. An Indicator, whose title shows (a Raw Messages panel shows only its
        # topic path, in red where the robot has no such topic: seen in the app).
        return PanelSpec(component, "Indicator", f"{ROBOT}/{_slug(component)}", (), True)


def default_presentation_path() -> Path:
    return Path(__file__).resolve().parent.parent / "rules" / "presentation.yaml"


def load_presentation(path: str | Path | None = None, rules: RuleSet | None = None) -> Presentation:
    """Read a presentation; with ``rules``, a component the rule set lacks is a located error."""
    document = load_document(path if path is not None else default_presentation_path())
    reader = Reader(document)
    panels: list[PanelSpec] = []
    known: set[str] | None = None
    if rules is not None:
        known = {
            component.name
            for characteristic in rules.characteristics
            for component in characteristic.components
        }
    top = reader.top("presentation profile", needs="components")
    if top is not None:
        components = reader.mapping(("components",), "components")
        for name in components:
            path_ = ("components", name)
            entry = reader.mapping(path_, f"component {shown(name, quoted=True)}")
            if known is not None and name not in known:
                reader.fault(
                    path_,
                    f"unknown component {shown(name, quoted=True)}",
                    key=True,
                    code="unknown-reference",
                )
            panel = reader.string((*path_, "panel"), "panel")
            if panel and panel not in PANEL_TYPES:
                reader.fault(
                    (*path_, "panel"),
                    f"unknown panel {shown(panel, quoted=True)}; known: " + ", ".join(PANEL_TYPES),
                    code="unknown-reference",
                )
            topic = reader.string((*path_, "topic"), "topic", limit=None)
            problem = _topic_problem(topic) if topic else None
            if problem:
                reader.fault(
                    (*path_, "topic"),
                    f"the topic under a robot (/robot1) {problem}",
                    code="invalid-name",
                )
            raw_types = entry.get("types") or []
            types = tuple(str(item) for item in raw_types) if isinstance(raw_types, list) else ()
            panels.append(PanelSpec(name, panel, topic, types, entry.get("placeholder") is True))
    grammar = read_grammar(reader) if top is not None else DEFAULT_GRAMMAR
    if reader.faults:
        raise PresentationError(reader.faults)
    return Presentation(document.file, tuple(panels), grammar)


def _topic_problem(template: str) -> str | None:
    """Why ``template`` is no ROS 2 topic once under a robot's namespace, or None."""
    if template.startswith(ROBOT):
        name = "/robot1" + template[len(ROBOT) :]
    elif template.startswith("/"):
        name = template
    else:
        name = "/robot1/" + template
    return full_topic_name_problem(name)


def _slug(name: str) -> str:
    """``name`` as a ROS name part: letters, digits and '_', not starting with a digit."""
    slug = "".join(char if char.isascii() and char.isalnum() else "_" for char in name.lower())
    return f"component_{slug}" if not slug or slug[0].isdigit() else slug
