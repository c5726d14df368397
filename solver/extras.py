"""Optional dependencies: which extra brings each one, and the error when it is missing.

``pip install teleop-ui`` is enough for ``solve``, ``assign``, ``check``, ``count``, ``robots``
and ``reproduce``. Heavier parts come as extras (``pyproject.toml``): ``plots`` (matplotlib) for
``solve --plot``, ``report`` and ``batch --report``; ``ros`` (lxml, rosbags) for ``identify``,
``fleet`` and the descriptions of ``watch``; ``xacro`` for ``--trust-xacro``; ``all`` for every
one. A library function that needs one calls :func:`require` before importing it, so a missing
package is a :class:`~solver.errors.MissingExtraError` naming the feature and the extra to
install (the CLI prints it and exits 2), never an ``ImportError`` traceback.

Not here: importing the packages for use (each module imports where it uses them).
"""

from __future__ import annotations

import importlib.util

from solver.errors import Fault, Location, MissingExtraError

__all__ = ["EXTRAS", "require"]

# The extra that installs each optional top-level module (kept in step with pyproject.toml).
EXTRAS: dict[str, str] = {
    "matplotlib": "plots",
    "lxml": "ros",
    "rosbags": "ros",
    "xacro": "xacro",
    "cyclonedds": "ros2",
    "starlette": "studio",
    "uvicorn": "studio",
    "jinja2": "studio",
}


def require(module: str, *, feature: str) -> None:
    """Raise :class:`MissingExtraError` when ``module`` cannot be imported for ``feature``."""
    try:
        found = importlib.util.find_spec(module) is not None
    except (ImportError, ValueError):
        # A module blocked with sys.modules[name] = None raises ValueError here.
        found = False
    if found:
        return
    extra = EXTRAS[module]
    raise MissingExtraError(
        Fault(
            Location(feature),
            f"needs {module}, which is not installed; install the {extra!r} extra: "
            f"pip install 'teleop-ui[{extra}]' (or 'teleop-ui[all]')",
            "missing-extra",
        )
    )
