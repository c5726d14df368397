"""The message-path parser accepts exactly what Lichtblick's own grammar accepts.

``data/message_paths.json`` holds paths and the parts Lichtblick's grammar gives them: every
path of Lichtblick's ``parseMessagePath.test.ts`` and 4,000 generated ones, each parsed by the
real ``grammar.ne`` (v1.19.0) compiled by nearleyc and run by nearley in node, as
``parseMessagePath.ts`` does. ``tools/lichtblick_check.md`` says how to make it again.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest

from solver.layouts.checks import MessagePathError, parse_message_path
from solver.layouts.checks.messagepath import Filter, MessagePath, Name, Slice

CORPUS = json.loads(
    (Path(__file__).parent / "data" / "message_paths.json").read_text(encoding="utf-8")
)


def _value(value: Any) -> Any:
    if isinstance(value, tuple):
        return {"variable": value[0]}
    if isinstance(value, float) and math.isinf(value):
        return "inf"
    return value


def _as_lichtblick_gives_it(path: MessagePath) -> list[Any]:
    parts: list[Any] = []
    for part in path.parts:
        if isinstance(part, Name):
            parts.append(["name", part.name])
        elif isinstance(part, Slice):
            parts.append(["slice", _value(part.start), _value(part.end)])
        elif isinstance(part, Filter):
            parts.append(["filter", list(part.path), part.operator, _value(part.value)])
    return [path.topic, parts, path.modifier]


def _parsed(text: str) -> list[Any] | None:
    try:
        return _as_lichtblick_gives_it(parse_message_path(text))
    except MessagePathError:
        return None


def test_the_corpus_holds_lichtblicks_own_test_paths_and_both_verdicts() -> None:
    cases = CORPUS["cases"]
    assert CORPUS["upstream_test_paths"] == 54
    assert len(cases) > 4000
    valid = sum(1 for _, parts in cases if parts is not None)
    assert 500 < valid < len(cases) - 500


def test_every_path_parses_as_lichtblicks_grammar_parses_it() -> None:
    differ = [
        (text, expected, _parsed(text))
        for text, expected in CORPUS["cases"]
        # Compared as JSON text: True and 1 are equal in Python, not in a path.
        if json.dumps(_parsed(text)) != json.dumps(expected)
    ]
    assert differ == []


@pytest.mark.parametrize(
    ("text", "topic"),
    [
        ("/robot1/wrench.wrench.force.x", "/robot1/wrench"),
        ("robot1/points", "robot1/points"),  # parses: but no ROS 2 topic has this name
        ('"/with space".data', "/with space"),
        ("/diag.status[:]{level>=2}.name", "/diag"),
    ],
)
def test_the_topic_is_what_precedes_the_first_field(text: str, topic: str) -> None:
    assert parse_message_path(text).topic == topic


def test_a_template_placeholder_is_a_syntax_error_at_its_first_character() -> None:
    with pytest.raises(MessagePathError) as caught:
        parse_message_path("<robot>/wrench.wrench.force.x")
    assert caught.value.position == 0
    assert "unexpected '<'" in str(caught.value)


@pytest.mark.parametrize("text", ["/topic.", "/topic.foo{}", "/topic.foo{bar}", "/t.a[$]"])
def test_a_half_written_path_parses_but_is_incomplete(text: str) -> None:
    assert parse_message_path(text).incomplete


def test_a_whole_path_is_complete() -> None:
    assert not parse_message_path("/t.a[0]{id==$v}.b.@derivative").incomplete


def test_a_long_hostile_path_ends_at_once() -> None:
    with pytest.raises(MessagePathError):
        parse_message_path("/t" + ".a[0]" * 100_000 + "[")
