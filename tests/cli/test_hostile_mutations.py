"""Random mutations of valid files given to the commands that read them: rule files and team
files to every command that solves (also onto an output that fails as a closed descriptor or
a full disk does), bags to ``identify --bag``; each ends with a result or a located error,
never a traceback (bounded numbers of examples, so the suite stays quick).
"""

from __future__ import annotations

import errno
import io
import os
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.cli.hostile import run_main, team_file, with_paper_rules
from tests.conftest import RULES, TEAMS
from tests.hostile import FUZZ, mutations


def _fuzz_commands(folder: Path, team: Path) -> list[list[str | Path]]:
    """Every command that reads a team and its rules, its outputs in ``folder``."""
    return [
        ["solve", team],
        ["count", team],
        ["robots", team, "--max-robots", "100000"],
        ["check", team],
        ["report", team, "-o", folder / "r.md"],
        ["batch", team, "-o", folder / "out"],
    ]


# ---- rule and team files ---------------------------------------------------------------------


@FUZZ
@given(data=mutations((RULES / "paper.yaml").read_bytes()))
def test_mutated_rule_files_never_reach_a_traceback(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    folder = tmp_path_factory.mktemp("rules")
    (folder / "rules.yaml").write_bytes(data)
    team = team_file(folder)
    for args in _fuzz_commands(folder, team):
        assert run_main(*args) in (0, 1, 2), args


@FUZZ
@given(
    data=mutations(
        (TEAMS / "case3.yaml").read_bytes().replace(b"rules: ../paper.yaml", b"rules: rules.yaml")
    )
)
def test_mutated_team_files_never_reach_a_traceback(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    folder = tmp_path_factory.mktemp("team")
    with_paper_rules(folder)
    team = folder / "team.yaml"
    team.write_bytes(data)
    for args in _fuzz_commands(folder, team):
        assert run_main(*args) in (0, 1, 2), args


class _FailingStream(io.StringIO):
    """Standard output that fails as a closed descriptor or a full disk does."""

    def __init__(self, error: int) -> None:
        super().__init__()
        self.error = error

    def write(self, text: str) -> int:  # noqa: ARG002 (nothing is written)
        raise OSError(self.error, os.strerror(self.error))

    def flush(self) -> None:
        raise OSError(self.error, os.strerror(self.error))


@FUZZ
@given(
    data=mutations(
        (TEAMS / "case3.yaml").read_bytes().replace(b"rules: ../paper.yaml", b"rules: rules.yaml")
    ),
    error=st.sampled_from([errno.EBADF, errno.ENOSPC, errno.EPIPE]),
)
def test_mutated_team_files_onto_a_failing_output_never_reach_a_traceback(
    tmp_path_factory: pytest.TempPathFactory,
    monkeypatch: pytest.MonkeyPatch,
    data: bytes,
    error: int,
) -> None:
    folder = tmp_path_factory.mktemp("team")
    with_paper_rules(folder)
    team = folder / "team.yaml"
    team.write_bytes(data)
    for args in _fuzz_commands(folder, team):
        with monkeypatch.context() as patched:
            patched.setattr(sys, "stdout", _FailingStream(error))
            status = run_main(*args)
        # A broken pipe ends quietly (0); a closed or full output ends with status 2; a
        # command that wrote nothing to standard output ends as it would have.
        assert status in (0, 1, 2), args


def _corpus_urdf() -> bytes:
    from tests.identify import builders

    return builders.ugv().text().encode()


# ---- bags -------------------------------------------------------------------------------------

# Bags (issue 23.3): length fields made huge or zero, bytes flipped, a region repeated (as the
# repeated chunk index was), the end cut off. Each mutated bag goes through `identify --bag`:
# its topics or a located refusal, never a traceback; the reader's own bounds end it.
BAG_HOSTILE = [
    b"\xff\xff\xff\xff",
    b"\xff" * 8,
    b"\x00\x00\x00\x00",
    b"\x7f\xff\xff\xff",
    b"\x00" * 9,
    b"op=\x07",
    b"op=\x06",
    b"zstd",
    b"lz4",
    b"\x89MCAP0\r\n",
    b"#ROSBAG V2.0\n",
]


@st.composite
def bag_mutations(draw: st.DrawFn, original: bytes) -> bytes:
    data = bytearray(original)
    for _ in range(draw(st.integers(1, 3))):
        start = draw(st.integers(0, len(data)))
        how = draw(st.sampled_from(["overwrite", "repeat", "cut"]))
        if how == "overwrite":
            insert = draw(st.sampled_from(BAG_HOSTILE) | st.binary(min_size=1, max_size=8))
            data[start : start + len(insert)] = insert
        elif how == "repeat":
            piece = data[start : start + draw(st.integers(1, 256))]
            data[start:start] = piece * draw(st.integers(1, 40))
        else:
            del data[start:]
    return bytes(data)


def _small_bag(kind: str) -> bytes:
    """A real small bag of ``kind`` (``.bag``, ``.db3``, ``.mcap``) written with rosbags."""
    import tempfile

    from rosbags.rosbag2 import StoragePlugin

    from tests.identify.readers import bagfiles

    with tempfile.TemporaryDirectory() as folder:
        if kind == ".bag":
            return bagfiles.ros1(Path(folder) / "run.bag").read_bytes()
        plugin = StoragePlugin.SQLITE3 if kind == ".db3" else StoragePlugin.MCAP
        return bagfiles.ros2(Path(folder) / "run", plugin).read_bytes()


BAG_FUZZ = settings(FUZZ, max_examples=15)


def _identify_with_bag(folder: Path, data: bytes, suffix: str) -> None:
    urdf = folder / "rover.urdf"
    urdf.write_bytes(_corpus_urdf())
    bag = folder / f"run{suffix}"
    bag.write_bytes(data)
    assert run_main("identify", urdf, "--bag", bag) in (0, 2)


@BAG_FUZZ
@given(data=bag_mutations(_small_bag(".bag")))
def test_mutated_ros1_bags_are_read_or_refused(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    _identify_with_bag(tmp_path_factory.mktemp("bag"), data, ".bag")


@BAG_FUZZ
@given(data=bag_mutations(_small_bag(".db3")))
def test_mutated_ros2_databases_are_read_or_refused(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    _identify_with_bag(tmp_path_factory.mktemp("bag"), data, ".db3")


@BAG_FUZZ
@given(data=bag_mutations(_small_bag(".mcap")))
def test_mutated_mcaps_are_read_or_refused(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    _identify_with_bag(tmp_path_factory.mktemp("bag"), data, ".mcap")
