"""The presentation (solver.layouts.presentation): which viewer panel presents each UI component,
read from a file whose every problem is located, with a titled placeholder for a component it
omits."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver import load_team, solve
from solver.layouts.presentation import (
    PANEL_TYPES,
    PresentationError,
    default_presentation_path,
    load_presentation,
)


def test_the_shipped_presentation_is_the_default_and_names_known_panels_only() -> None:
    assert default_presentation_path().name == "presentation.yaml"
    shipped = load_presentation(None, solve(load_team("case3")).rules)
    assert shipped.file.endswith("presentation.yaml")
    assert shipped.panels
    assert {spec.panel for spec in shipped.panels} <= set(PANEL_TYPES)


def test_every_problem_of_a_presentation_is_reported_at_once(tmp_path: Path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(
        "profile: presentation\ncomponents:\n  Flight:\n    panel: Dial\n    topic: cmd_vel\n"
        "  visual display:\n    panel: Image\n    topic: <robot>/a b\n"
    )
    with pytest.raises(PresentationError) as caught:
        load_presentation(path)
    assert [fault.location.line for fault in caught.value.faults] == [4, 8]


def test_profile_with_unknown_component_and_panel_is_a_located_error(tmp_path: Path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text("profile: presentation\ncomponents:\n  smell:\n    panel: Nose\n    topic: x\n")
    with pytest.raises(PresentationError) as caught:
        load_presentation(path, solve(load_team("case1")).rules)
    message = str(caught.value)
    assert f"{path}:3:3: components.smell: unknown component 'smell'" in message
    assert "unknown panel 'Nose'" in message


def test_a_presentation_topic_that_is_no_ros2_name_is_a_located_error(tmp_path: Path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(
        "profile: presentation\ncomponents:\n  visual display:\n    panel: Image\n"
        "    topic: <robot>/front-camera\n"
    )
    with pytest.raises(PresentationError) as caught:
        load_presentation(path)
    assert str(caught.value) == (
        f"{path}:5:12: components.visual display.topic: the topic under a robot (/robot1) has a "
        "character other than a letter, a digit, '_' or '/' at 14"
    )


def test_a_component_the_presentation_omits_gets_a_topic_that_is_a_ros2_name() -> None:
    assert load_presentation().spec("360 microphone").topic == "<robot>/component_360_microphone"
