"""ROS 2 topic names against rmw's and rcl's own rules, with the cases of their own tests.

The valid and invalid names are those of ros2/rmw ``rmw/test/test_validate_full_topic_name.cpp``
(commit 33118c9d4dc2) and ros2/rcl ``rcl/test/rcl/test_validate_topic_name.cpp`` (commit
c19dab55e6a6): the expected verdicts are theirs, not this project's.
"""

from __future__ import annotations

import pytest

from solver.ros.names import (
    TOPIC_MAX_CHARS,
    common_namespace,
    full_topic_name_problem,
    in_namespace,
    topic_name_problem,
)

RMW_VALID = ["/basename_only", "/with_one/namespace", "/" + "a" * (TOPIC_MAX_CHARS - 1)]
RMW_INVALID = [
    "",
    "not_absolute",
    "not/absolute",
    "/ends/with/",
    "/",
    "/~/unexpanded_tilde",
    "/unexpanded_sub/{node}",
    "/question?",
    "/with spaces",
    "/repeated//slashes",
    "/9starts_with_number",
    "/starts/42with/number",
    "/" + "a" * TOPIC_MAX_CHARS,
]
RCL_VALID = [
    "foo", "abc123", "_foo", "Foo", "BAR", "~", "foo/bar", "~/foo", "{foo}_bar",
    "foo/{ping}/bar", "foo/_bar", "foo_/bar", "foo_", "/foo", "/bar/baz", "/_private/thing",
    "/public_namespace/_private/thing", "{foo1}", "{foo_bar}", "{_bar}",
]  # fmt: skip
RCL_INVALID = [
    "123abc", "123", " ", "foo bar", "/~", "~foo", "foo~", "foo~/bar", "foo/~bar", "foo/~/bar",
    "foo/", "", "foo/123bar", "foo/bar}/baz", "foo/{bar", "{$}", "{{bar}_baz}", "foo/{bar/baz}",
    "{1foo}",
]  # fmt: skip


@pytest.mark.parametrize("name", RMW_VALID)
def test_rmw_accepts_a_full_topic_name(name: str) -> None:
    assert full_topic_name_problem(name) is None


@pytest.mark.parametrize("name", RMW_INVALID)
def test_rmw_refuses_what_its_own_tests_refuse(name: str) -> None:
    assert full_topic_name_problem(name) is not None


@pytest.mark.parametrize("name", RCL_VALID)
def test_rcl_accepts_relative_names_tildes_and_substitutions(name: str) -> None:
    assert topic_name_problem(name) is None


@pytest.mark.parametrize("name", RCL_INVALID)
def test_rcl_refuses_what_its_own_tests_refuse(name: str) -> None:
    assert topic_name_problem(name) is not None


def test_a_template_placeholder_is_no_ros_name_of_either_kind() -> None:
    assert full_topic_name_problem("<robot>/cmd_vel") == (
        "is not absolute (a ROS 2 topic name starts with '/')"
    )
    assert topic_name_problem("<robot>/cmd_vel") is not None
    # Relative: a node expands it; an operator's tool that names full topics cannot.
    assert topic_name_problem("robot1/cmd_vel") is None
    assert full_topic_name_problem("robot1/cmd_vel") is not None


def test_a_problem_names_where_it_is_but_not_the_strangers_character() -> None:
    problem = full_topic_name_problem("/robot1/\x1b[2Jx")
    assert problem == "has a character other than a letter, a digit, '_' or '/' at 9"


def test_common_namespace_is_the_shared_leading_names() -> None:
    assert common_namespace(["/robot1/cmd_vel", "/robot1/front/points"]) == "/robot1"
    assert common_namespace(["/a/b/c", "/a/b/d"]) == "/a/b"
    assert common_namespace(["<robot>/cmd_vel", "<robot>/points"]) == "<robot>"
    assert common_namespace(["/cmd_vel", "/scan"]) is None
    assert common_namespace([]) is None


def test_a_namespace_holds_its_own_names_only() -> None:
    assert in_namespace("/robot1/cmd_vel", "/robot1")
    assert not in_namespace("/robot10/cmd_vel", "/robot1")
    assert not in_namespace("/clicked_point", "/robot1")
