"""The graph sources are a family: neutral types in solver.live.graph, no source importing
another, and the watcher's machinery importing no source (but the default ROS 1 source, made
on demand when no source is given); one lookup opens the source a graph's address needs."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from solver.errors import InputError
from solver.live import sources
from solver.live.sources import GraphAddress, graph_address, open_source
from solver.live.sources.ros1 import MasterGraph
from solver.live.sources.ros2 import DdsGraph
from tests.conftest import ROOT
from tests.live.ros2_graph import next_domain, write_config
from tests.live.roscore import Roscore

LIVE = ROOT / "solver" / "live"
SOURCES = ("ros1", "ros2")


def imported(path: Path, *, top_level_only: bool = False) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    nodes = tree.body if top_level_only else list(ast.walk(tree))
    names: set[str] = set()
    for node in nodes:
        if isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
        elif isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
    return names


def source_files(source: str) -> list[Path]:
    package = LIVE / "sources" / source
    return sorted(package.rglob("*.py")) if package.is_dir() else [package.with_suffix(".py")]


def test_no_source_imports_another() -> None:
    for source in SOURCES:
        others = [f"solver.live.sources.{other}" for other in SOURCES if other != source]
        for path in source_files(source):
            crossing = {
                name for name in imported(path) for other in others if name.startswith(other)
            }
            assert crossing == set(), f"{path.relative_to(ROOT)} imports {crossing}"


def test_the_shared_machinery_imports_no_source_at_module_level() -> None:
    """(That both sources are GraphSources is checked by mypy: the lookup's ``open_source``
    returns either as one.) The package's ``__init__`` re-exports public names."""
    for path in sorted(LIVE.glob("*.py")):
        if path.name == "__init__.py":
            continue
        sources = {n for n in imported(path, top_level_only=True) if "solver.live.sources" in n}
        assert sources == set(), f"{path.relative_to(ROOT)} imports {sources}"


# -- one lookup: the source of the graph at an address --------------------------------------


def test_every_source_of_the_folder_has_its_entry_in_the_lookup() -> None:
    present = {
        path.stem
        for path in (LIVE / "sources").iterdir()
        if not path.name.startswith("_") and (path.suffix == ".py" or path.is_dir())
    }
    assert present == set(SOURCES)  # the family the checks above cover
    assert set(sources.SOURCES) == present


def test_a_master_uri_names_a_ros1_graph_checked_and_normalised() -> None:
    address = graph_address(master=" http://127.0.0.1:11311")
    assert address == GraphAddress("ros1", "http://127.0.0.1:11311/")
    assert address.label == "http://127.0.0.1:11311/"


def test_without_a_master_the_environment_names_it(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROS_MASTER_URI", "http://localhost:11411")
    assert graph_address() == GraphAddress("ros1", "http://localhost:11411/")
    monkeypatch.delenv("ROS_MASTER_URI")
    with pytest.raises(InputError, match="no ROS master given"):
        graph_address()


def test_a_dds_domain_is_the_one_given_else_the_environment_s_else_0(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.delenv("ROS_DOMAIN_ID", raising=False)
    assert graph_address(ros2=True) == GraphAddress("ros2", 0)
    monkeypatch.setenv("ROS_DOMAIN_ID", "42")
    assert graph_address(ros2=True) == GraphAddress("ros2", 42)
    assert graph_address(ros2=True, domain=232) == GraphAddress("ros2", 232)
    assert graph_address(ros2=True, domain=7).label == "ROS 2 domain 7"


@pytest.mark.parametrize("text", ["233", "-1", "seven", "\u00b2", "\u0663", "9" * 5000])
def test_a_domain_id_that_is_not_0_to_232_in_ascii_digits_is_a_located_error(
    monkeypatch: pytest.MonkeyPatch, text: str
) -> None:
    monkeypatch.setenv("ROS_DOMAIN_ID", text)
    with pytest.raises(InputError) as caught:
        graph_address(ros2=True)
    assert str(caught.value).startswith("<arguments>: DDS domain id must be 0..232, got '")


def test_a_ros2_graph_with_a_master_is_a_located_error() -> None:
    with pytest.raises(InputError) as caught:
        graph_address(ros2=True, master="http://127.0.0.1:11311")
    assert str(caught.value) == (
        "<arguments>: --ros2 reads a DDS domain: give --domain N, not --master"
    )


def test_an_address_of_no_known_family_is_a_located_error_naming_the_families() -> None:
    with pytest.raises(InputError) as caught:
        open_source(GraphAddress("ros3", 0))
    assert str(caught.value) == "<arguments>: no graph source 'ros3'; sources: ros1, ros2"


def test_a_ros1_address_opens_the_master_there(master: Roscore) -> None:
    source = open_source(graph_address(master=master.uri), timeout=5.0, push=False)
    try:
        assert isinstance(source, MasterGraph)
        assert (source.name, source.timeout) == (master.uri, 5.0)
        assert source.node_uri is None  # push=False: no node of its own
        assert source.get_pid() > 0
    finally:
        source.close()


def test_a_ros2_address_opens_a_participant_on_that_domain(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("CYCLONEDDS_URI", write_config(tmp_path))
    domain = next_domain()
    source = open_source(graph_address(ros2=True, domain=domain))
    try:
        assert isinstance(source, DdsGraph)
        assert (source.name, source.domain) == (f"ros2://domain/{domain}", domain)
    finally:
        source.close()
