"""Optional dependencies: a command that needs a missing extra says which one to install."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from solver.errors import MissingExtraError, SolverError
from solver.extras import EXTRAS, require
from tests.conftest import ROOT


def _run_without(module: str, *args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter where ``import module`` fails, as if not installed."""
    code = (
        f"import sys; sys.modules[{module!r}] = None\n"
        "from solver.cli import main\n"
        f"sys.exit(main({list(args)!r}))\n"
    )
    return subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        cwd=cwd,
        check=False,
        timeout=300,
    )


def test_solve_with_a_plot_and_no_matplotlib_names_the_plots_extra(tmp_path: Path) -> None:
    result = _run_without("matplotlib", "solve", "case1", "--plot", "radar.png", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == (
        "drawing plots (solve --plot, report, batch --report): needs matplotlib, which is not "
        "installed; install the 'plots' extra: pip install 'teleop-ui[plots]' "
        "(or 'teleop-ui[all]')"
    )
    assert "Traceback" not in result.stderr
    assert not (tmp_path / "radar.png").exists()


def test_solve_without_matplotlib_still_works(tmp_path: Path) -> None:
    result = _run_without("matplotlib", "solve", "case1", cwd=tmp_path)
    assert result.returncode == 0
    assert "30" in result.stdout


def test_identify_without_lxml_names_the_ros_extra(tmp_path: Path) -> None:
    urdf = tmp_path / "robot.urdf"
    urdf.write_text('<robot name="r"><link name="base"/></robot>\n', encoding="utf-8")
    result = _run_without("lxml", "identify", "robot.urdf", cwd=tmp_path)
    assert result.returncode == 2
    assert (
        "needs lxml, which is not installed; install the 'ros' extra: "
        "pip install 'teleop-ui[ros]'" in result.stderr
    )
    assert "Traceback" not in result.stderr


def test_a_missing_extra_is_an_error_under_the_root_and_an_import_error(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setitem(sys.modules, "rosbags", None)
    with pytest.raises(MissingExtraError) as caught:
        require("rosbags", feature="reading bag files")
    assert isinstance(caught.value, SolverError)
    assert isinstance(caught.value, ImportError)
    (fault,) = caught.value.faults
    assert (fault.location.file, fault.code) == ("reading bag files", "missing-extra")


def test_every_optional_module_is_in_the_extra_pyproject_gives_it() -> None:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    extras = project["optional-dependencies"]
    for module, extra in EXTRAS.items():
        names = [
            requirement.split(">")[0].split("=")[0].strip().lower() for requirement in extras[extra]
        ]
        assert module in names, (module, extra)
    core = " ".join(project["dependencies"]).lower()
    assert [module for module in EXTRAS if module in core] == []
    assert set(extras["all"][0].split("[")[1].rstrip("]").split(",")) >= set(EXTRAS.values())


def test_the_readme_shows_the_message_a_missing_extra_gives(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    from solver.reporting.plot import _FEATURE

    with pytest.raises(MissingExtraError) as caught:
        require("matplotlib", feature=_FEATURE)
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert f"\n{caught.value}\n" in readme


def test_the_test_command_installs_into_a_project_venv_with_every_extra() -> None:
    script = (ROOT / "tools" / "test.sh").read_text(encoding="utf-8")
    commands = [
        line.strip()
        for line in script.splitlines()
        if line.strip() and not line.lstrip().startswith("#")
    ]
    # Never the system interpreter's pip (PEP 668 refuses it on Debian 12 / Ubuntu 24.04).
    assert not any(line.startswith(("python3 -m pip", "pip ")) for line in commands)
    assert 'python3 -m venv "$venv"' in commands
    assert "\"$python\" -m pip install -q -e '.[test,all]'" in commands
    assert ".venv/" in (ROOT / ".gitignore").read_text(encoding="utf-8").splitlines()


def test_fleet_without_lxml_names_the_ros_extra_once(tmp_path: Path) -> None:
    for name in ("one", "two"):
        (tmp_path / f"{name}.urdf").write_text(
            f'<robot name="{name}"><link name="base"/></robot>\n', encoding="utf-8"
        )
    result = _run_without("lxml", "fleet", ".", "-o", "team.yaml", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.count("needs lxml") == 1
    assert result.stderr.splitlines()[-1].endswith(
        "needs lxml, which is not installed; install the 'ros' extra: "
        "pip install 'teleop-ui[ros]' (or 'teleop-ui[all]')"
    )
    assert "Traceback" not in result.stderr
    assert not (tmp_path / "team.yaml").exists()


def test_batch_with_a_report_and_no_matplotlib_is_refused_before_solving(tmp_path: Path) -> None:
    result = _run_without(
        "matplotlib", "batch", "case1", "case2", "--report", "html", "-o", "out", cwd=tmp_path
    )
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == (
        "drawing plots (solve --plot, report, batch --report): needs matplotlib, which is not "
        "installed; install the 'plots' extra: pip install 'teleop-ui[plots]' "
        "(or 'teleop-ui[all]')"
    )
    assert not (tmp_path / "out").exists()
