"""The exception root: located faults, and every exception the package defines under it."""

from __future__ import annotations

import importlib
import inspect
import pkgutil

import pytest

import solver
from solver.errors import Fault, InputError, Location, SolverError, did_you_mean

# Exceptions that never leave the module that defines them, each with why.
PRIVATE_SIGNALS = {
    # Raised inside the sandboxed xacro child process and reported by the parent as text.
    "solver.identify.xacro.child.Refused",
    # Raised by the expression guard inside that child, reported the same way.
    "solver.identify.xacro.expressions.GuardError",
    # Raised inside the bag-reading child process and reported by the parent as text.
    "solver.identify.readers.bag_child.Refused",
    # Raised by the RE2 compile helper and turned into a located fault by the profile reader.
    "solver.identify.profile.PatternError",
    # Raised by the bounded XML-RPC transport, turned into MasterError (ReplyTooLarge) by the
    # master client that called it.
    "solver.live.sources.ros1.rpc.OversizedReply",
    # Raised by the command line's output streams when they fail (closed, full, a pipe whose
    # reader left) and ended by solver.cli.main: no SolverError, which commands may catch.
    "solver.cli._terminal.OutputFailed",
    # SIGTERM while files are written, as KeyboardInterrupt is for SIGINT: not an input error,
    # a BaseException so that no `except Exception` keeps a temporary (solver/files/atomic.py).
    "solver.errors.Terminated",
}
# Modules whose import needs an optional extra that may be absent.
OPTIONAL = ("solver.live.sources.ros2",)


def defined_exceptions() -> list[type[BaseException]]:
    found: list[type[BaseException]] = []
    for module_info in pkgutil.walk_packages(solver.__path__, "solver."):
        if module_info.name.endswith("__main__"):
            continue  # importing it runs the command line
        try:
            module = importlib.import_module(module_info.name)
        except ImportError:
            if module_info.name.startswith(OPTIONAL):
                continue
            raise
        found.extend(
            value
            for value in vars(module).values()
            if inspect.isclass(value)
            and issubclass(value, BaseException)
            and value.__module__ == module.__name__
        )
    return found


def test_every_exception_the_package_defines_is_a_solver_error() -> None:
    found = defined_exceptions()
    outside = [
        f"{error.__module__}.{error.__qualname__}"
        for error in found
        if not issubclass(error, SolverError)
        # A leading underscore: a private signal caught in its own module.
        and not error.__name__.startswith("_")
        and f"{error.__module__}.{error.__qualname__}" not in PRIVATE_SIGNALS
    ]
    assert outside == []
    assert {"TooLargeError", "StructureTooComplex", "ProfileError", "MasterError"} <= {
        error.__name__ for error in found if issubclass(error, SolverError)
    }


def test_a_fault_reads_file_line_column_path_message() -> None:
    fault = Fault(Location("rules.yaml", 14, 5, "team.UAV.sensor_type[1]"), "unknown value")
    assert str(fault) == "rules.yaml:14:5: team.UAV.sensor_type[1]: unknown value"
    assert str(Fault(Location("team.yaml"), "empty")) == "team.yaml: empty"


def test_faults_are_reported_top_to_bottom() -> None:
    error = InputError(
        [Fault(Location("a.yaml", 9, 1), "late"), Fault(Location("a.yaml", 2, 3), "early")]
    )
    assert [fault.message for fault in error.faults] == ["early", "late"]
    assert str(error) == "a.yaml:2:3: early\na.yaml:9:1: late"


def test_an_error_without_faults_is_refused() -> None:
    with pytest.raises(ValueError, match="needs at least one fault"):
        SolverError([])


def test_did_you_mean_names_the_closest_choice_or_nothing() -> None:
    assert did_you_mean("Camra", ["Camera", "Lidar"]) == " (did you mean 'Camera'?)"
    assert did_you_mean("Mic", ["Microphone", "Lidar"]) == " (did you mean 'Microphone'?)"
    assert did_you_mean("zzz", ["Camera"]) == ""
