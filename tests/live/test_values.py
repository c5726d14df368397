"""Values from a graph are bounded before they are parsed or shown (issue 23 item 6, issue 30
item 7): JSON depth and size checked before decoding, the operator's selection at most 200
characters of text, every echo cut; hypothesis feeds random values and mutations."""

from __future__ import annotations

import contextlib
import json
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from solver.errors import InputError
from solver.live.graph import MAX_DEPTH, TOO_DEEP
from solver.live.selection import Request, read_request
from solver.live.values import (
    MAX_JSON_CHARS,
    MAX_SELECTION_CHARS,
    bounded_json,
    kind_of,
    selection_text,
    shown_value,
)

# An event note may quote 60 characters of a value, escaped (up to 10 characters each) and say
# how long it was: nothing a stranger sends makes a note longer than this.
MAX_NOTE_CHARS = 1000


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("[" * 200_000, f"nested deeper than {MAX_DEPTH} levels"),
        ('{"a":' * 100_000 + "1" + "}" * 100_000, f"nested deeper than {MAX_DEPTH} levels"),
        ('"' + "x" * MAX_JSON_CHARS + '"', f"longer than {MAX_JSON_CHARS} characters"),
    ],
    ids=["brackets", "objects", "long"],
)
def test_json_too_deep_or_too_long_is_refused_before_decoding(text: str, reason: str) -> None:
    with pytest.raises(ValueError, match=reason):
        bounded_json(text)


def test_json_within_the_bounds_is_decoded_and_brackets_in_strings_do_not_count() -> None:
    nested = "[" * MAX_DEPTH + "]" * MAX_DEPTH
    assert bounded_json(nested) == json.loads(nested)
    quoted = json.dumps({"robot": "[" * 1000 + '"\\"{' * 100, "configuration": 3})
    assert bounded_json(quoted)["configuration"] == 3


def test_the_selection_is_short_text_or_ignored_with_a_short_note() -> None:
    assert selection_text("x", " /uav1 ") == ("/uav1", None)
    assert selection_text("x", "") == (None, None)
    long = "/" + "a" * 10_000_000
    value, note = selection_text("/teleop_ui/active_robot", long)
    assert value is None
    assert note == (
        f"/teleop_ui/active_robot ignored: 10,000,001 characters, longer than "
        f"{MAX_SELECTION_CHARS} (/{'a' * 59}... (cut from 10,000,001 characters))"
    )
    assert selection_text("x", TOO_DEEP) == (
        None,
        f"x ignored: expected text, got a value nested deeper than {MAX_DEPTH} levels",
    )
    unreadable = InputError.at("/teleop_ui/active_robot", "cannot be read from the master: fault")
    assert selection_text("x", unreadable)[1] == (
        "x ignored: expected text, got an unreadable value (cannot be read from the master: fault)"
    )


def test_shown_values_are_escaped_and_cut() -> None:
    assert shown_value("line\nforged\x1b[2J") == "line\\nforged\\x1b[2J"
    assert shown_value(7) == "7"
    assert shown_value([[1]]) == "(a list)"
    assert shown_value("é" * 61).endswith("... (cut from 61 characters)")
    assert kind_of({"a": 1}) == "a namespace of parameters"


# -- hypothesis: random values from a graph ---------------------------------------------------

FUZZ = settings(
    max_examples=150,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)

scalars = (
    st.text(max_size=300)
    | st.integers()
    | st.floats()
    | st.booleans()
    | st.binary(max_size=50)
    | st.just(TOO_DEEP)
)
values = st.recursive(
    scalars,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=8), inner),
    max_leaves=20,
)


@FUZZ
@given(
    params=st.dictionaries(
        st.sampled_from(
            [
                "active_robot",
                "active_motion_control",
                "active_sensor_type",
                "ui_configuration",
                "other",
            ]
        ),
        values,
    )
)
def test_any_teleop_ui_parameters_give_a_request_with_short_text_and_short_notes(
    params: dict[str, Any],
) -> None:
    request = read_request(params, ("kinematic_type", "motion_control", "sensor_type"))
    assert isinstance(request, Request)
    for chosen in (request.robot, *(value for _, value in request.values)):
        assert chosen is None or (
            isinstance(chosen, str) and len(chosen) <= MAX_SELECTION_CHARS + 1
        )
    for note in request.notes:
        assert len(note) <= MAX_NOTE_CHARS
        assert note.isprintable()


@st.composite
def mutated_json(draw: st.DrawFn) -> str:
    """A valid answer, cut, spliced, with runs of brackets and quotes put in."""
    text = json.dumps({"robot": "/uav1", "configuration": 1, "components": [{"values": ["a"]}]})
    for _ in range(draw(st.integers(1, 4))):
        at = draw(st.integers(0, len(text)))
        insert = draw(st.sampled_from(["[", "{", '"', "\\", "]", "}", ":", ","])) * draw(
            st.integers(1, 5000)
        )
        text = text[:at] + insert + text[at + draw(st.integers(0, 3)) :]
    return text


@FUZZ
@given(text=mutated_json())
def test_mutated_json_answers_decode_or_are_refused_with_value_error(text: str) -> None:
    with contextlib.suppress(ValueError):
        bounded_json(text)
