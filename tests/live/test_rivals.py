"""A watcher's and the operator's reading of the watchers' announcements."""

from __future__ import annotations

from solver.live.rivals import MAX_ANNOUNCED, WATCHERS, Announcement, announcements


def test_announcements_are_read_by_key_with_their_rule_set() -> None:
    params = {
        WATCHERS: {
            "b": {"watcher": "/watch_b", "team": "case3", "rules": "paper", "policy": "insist"},
            "a": {"watcher": "/watch_a", "fingerprint": "f" * 64},
        }
    }
    assert announcements(params) == [
        Announcement("/watch_a", None, "f" * 64, "yield"),
        Announcement("/watch_b", "case3", None, "insist", "paper"),
    ]
    assert announcements(params)[1].rules == "paper"


def test_what_is_no_announcement_is_dropped_and_at_most_a_few_are_read() -> None:
    many = {f"w{i:02d}": {"watcher": f"/w{i:02d}"} for i in range(3 * MAX_ANNOUNCED)}
    params = {WATCHERS: {**many, "0": "text", "1": {"team": "no watcher named"}}}
    found = announcements(params)
    # The first MAX_ANNOUNCED keys in order are read: "0" and "1" among them, dropped.
    assert [a.watcher for a in found] == [f"/w{i:02d}" for i in range(MAX_ANNOUNCED - 2)]
    assert announcements({WATCHERS: "not a mapping"}) == []
    assert announcements({}) == []


def test_a_policy_that_is_none_of_the_known_ones_is_yield() -> None:
    (found,) = announcements({WATCHERS: {"a": {"watcher": "/w", "policy": "conquer"}}})
    assert found.policy == "yield"
