"""The robot's workspace: the ROS packages around its description that use it, read as text.

A description package rarely says how its robot is commanded: a bringup package launches the
teleop node, a navigation package runs Nav2 or move_base, a MoveIt configuration plans for the
arm. Those packages sit beside the description in the workspace and name it. This module finds
them and reads their launch, configuration and script files as text; nothing in them is run,
imported or parsed as code.

* The description's *package* is the nearest folder above the file (at most
  :data:`MAX_LEVELS_UP` folders up) holding a ``package.xml``, or a rosbuild ``manifest.xml``
  (ROS 1's packages before catkin, to 2013: a ``<package>`` with no ``<name>``, the package
  named by its folder). The *workspace* is the nearest
  folder named ``src`` at most two folders above that package's folder (a colcon or catkin
  workspace, where a bringup may sit in a sibling repository); for a package colcon installed
  (``install/NAME/share/NAME``) the install space its neighbours were installed in; else the
  folder above the package (``/opt/ros/DISTRO/share``), or one the caller names.
* The workspace is walked once, the description's package first: symbolic links are never
  followed, hidden folders and the folders builds and tests write (``build``, ``install``,
  ``devel``, ``log``, ``test``, ...) are skipped (but an ``install`` folder the description
  lies in: its neighbours are installed beside it), at most :data:`MAX_DEPTH` folders deep and
  :data:`MAX_ENTRIES` entries; an install prefix (``install`` or ``install/NAME``: ``share``
  beside ``lib``, ``include`` or ``bin``) is walked in ``share`` alone. Each file belongs to
  the nearest package above it; a file in no package is nobody's, but in a workspace of one
  robot the caller names (below).
* Files are read in the order the robot's packages are likeliest: the description's, those
  named for the robot, those whose ``package.xml`` names one of them, then the rest; so a bound
  spent on a vendored library leaves the robot's own packages read. Text files
  (:data:`TEXT_SUFFIXES`, and files with no suffix in ``scripts`` and ``nodes`` folders, ROS 1
  nodes) are opened only when they are regular files (a link, a FIFO or a device is passed by,
  never opened), at most :data:`MAX_FILE_BYTES` of each, :data:`MAX_FILES` files and
  :data:`MAX_TOTAL_BYTES` in all; XML comments are removed.
* The *robot's packages*: the description's and, for a package named ``ROBOT_description`` (or
  named ``ROBOT_...`` beside a ``ROBOT_description`` package: a description kept in a control
  package), every package named ``ROBOT_...`` (the ROS convention: ``jackal_navigation`` is the
  Jackal's though it never names ``jackal_description``); then every package that *uses* one of
  them (names it as a word in its ``package.xml`` or its files: a bringup that finds the
  description); then every package one of those uses (the navigation package a bringup includes).
  A package another robot's package uses is not reached through a dependency both share (a
  vendored ``gazebo_ros`` used by every robot of the workspace), and a name most packages of the
  workspace write (``robot_description``, the parameter) is no evidence that the package of that
  name is used. A package named like that parameter is used only where a file names it as a
  package (found, launched, run: :data:`PARAMETER_NAMES`), so that a description package named
  ``robot_description`` does not take in every neighbour that sets its own robot's parameter.
  A source workspace (a ``src`` folder, or the one the caller names) walked whole in which no
  other package holds a description (a ``.urdf`` or ``.xacro`` file) is one robot's: every
  package of it is the robot's (its navigation and mission packages need name no package of
  the description's, :func:`_one_robots`). When the caller named that workspace (a
  repository, a ``src`` folder), its files in no package are the robot's too (a top-level
  ``launch`` and ``config`` beside the packages, as a repository's are:
  :func:`read_repository`), shown as :data:`NO_PACKAGE` and read last, with what the packages
  left of the bounds (a bound they reach leaves the workspace complete: the packages were read
  whole); none of them when a description among them is not named for the robot (another
  robot's, a macro file), and nothing in an install space (its setup scripts, its libraries).

* A description in *no* package (a simulator's or a learning framework's repository) is read
  with the *repository* the caller names (:func:`read_repository`; never one found around the
  file: a tool's own repository names its example robots in its code and rules): its files in
  no package are one package named for its folder, the ROS packages inside it a workspace's.
  Of a repository of several descriptions, a file in no package is the robot's only where its
  text or its path names the robot.

Past a bound the rest is not read and a note says so; the workspace is then *incomplete*, and
what it does not say is not taken as said (:mod:`solver.identify.shipped`). A workspace that
cannot be read (no such folder, no permission) is no evidence, never an error: the description
is read alone. What the files mean is :mod:`solver.identify.shipped`'s.
"""

from __future__ import annotations

import os
import re
import stat
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

__all__ = [
    "MAX_DEPTH",
    "MAX_ENTRIES",
    "MAX_FILES",
    "MAX_FILE_BYTES",
    "MAX_LEVELS_UP",
    "MAX_TOTAL_BYTES",
    "TEXT_SUFFIXES",
    "ShippedFile",
    "Workspace",
    "description_package",
    "read_repository",
    "read_workspace",
    "workspace_of",
]

# Folders above the description file searched for its package.xml (pkg/urdf/robots/x.urdf).
MAX_LEVELS_UP = 4
# Folders below the workspace walked, entries listed, files and bytes read.
MAX_DEPTH = 10
MAX_ENTRIES = 50_000
MAX_FILES = 4_000
MAX_FILE_BYTES = 256 * 1024
MAX_TOTAL_BYTES = 48 * 1024 * 1024
# A package.xml is read up to this size (its name and dependencies are at the top).
MAX_MANIFEST_BYTES = 64 * 1024
# Package names the evidence line lists before "and N more".
SHOWN_PACKAGES = 12

TEXT_SUFFIXES = (".launch", ".xml", ".yaml", ".yml", ".py", ".cpp", ".cc", ".hpp", ".sh")
# A file of these suffixes in a package is a robot's description (a URDF, a xacro).
DESCRIPTION_SUFFIXES = (".urdf", ".xacro")
# Folders whose files with no suffix are scripts (ROS 1 nodes: scripts/teleop, nodes/walker).
SCRIPT_FOLDERS = frozenset({"scripts", "nodes", "bin"})
# Folders no package ships controls in: builds, installs, logs, caches and tests.
SKIPPED_FOLDERS = frozenset(
    {"build", "devel", "install", "log", "logs", "node_modules", "__pycache__", "test", "tests"}
)
# An install space's folder name, and the folders beside share/ that tell an install prefix.
INSTALL = "install"
# What the files of a named workspace that lie in no package are shown as: a name no ROS
# package can have, so that no rule reads a package's name into it (a clone folder named
# ``quadruped_walking``) and no package of the same name is shadowed.
NO_PACKAGE = "(no package)"
_PREFIX_FOLDERS = frozenset({"lib", "include", "bin"})
# Stems too generic to name a robot (``robot_description`` beside ``robot_localization``).
GENERIC_STEMS = frozenset({"robot_", "my_robot_", "ros_", "ros2_", "test_", "my_"})
# Names a URDF gives a robot of no robot in particular: no stem of packages named for it.
GENERIC_ROBOT_STEMS = frozenset(
    {"test_robot_", "mobile_robot_", "urdf_", "model_", "base_", "arm_", "bot_"}
)
# A name written by more than this share of the workspace's packages (and by more than
# MIN_COMMON of them) is a word of every launch file, not a use.
COMMON_SHARE = 0.5
MIN_COMMON = 3
# Package names that are also a parameter every launch file writes: ``robot_description``
# holds the URDF. A package of such a name is used only where a file names it as a package
# (:data:`_AS_PACKAGE`; or where its package.xml names it), never by the parameter: a
# neighbouring robot's launch file setting its own ``robot_description`` does not use it.
PARAMETER_NAMES = frozenset({"robot_description"})
# The ROS interfaces of a simulator (Gazebo's, Gazebo Sim's), vendored into a robot's workspace
# as source: their plugins' code poses and drives any model, none of it the robot's software.
SIMULATOR_PACKAGES = frozenset(
    {
        "gazebo_dev",
        "gazebo_msgs",
        "gazebo_plugins",
        "gazebo_ros",
        "gazebo_ros_control",
        "gazebo_ros_pkgs",
        "gazebo_ros2_control",
        "gz_ros2_control",
        "ros_gz_bridge",
        "ros_gz_sim",
        "ros_ign_bridge",
        "ros_ign_gazebo",
    }
)
# A package named as one: found (``$(find P)``, ``find-pkg-share``, ``package://P``, the
# Python, C++ and CMake lookups), launched or run (``roslaunch P``, ``ros2 run P``, a node's
# ``pkg``/``package``), or given as a package argument's or variable's value (``pkg_name = 'P'``,
# ``robot_description_pkg = 'P'``, ``'description_package', default_value='P'``).
_AS_PACKAGE = re.compile(
    r"(?:\$\((?:find|find-pkg-share|find-pkg-prefix)\s+|package://|"
    r"(?:get_package_share_directory|get_package_share_path|get_package_prefix|"
    r"FindPackageShare|FindPackagePrefix|get_path|getPath|get_pkg_dir|find_package)"
    r"\(\s*(?:package\s*=\s*)?['\"]?|"
    r"(?:roslaunch|rosrun|roscd|rospack\s+find|ros2\s+(?:launch|run|pkg\s+prefix))\s+|"
    r"(?<![A-Za-z0-9_])(?:[A-Za-z0-9]+_)*(?:pkg|package)(?:_name)?['\"]?\s*[=:]\s*['\"]?|"
    r"package['\"]\s*,\s*default_value\s*=\s*['\"])"
    r"([A-Za-z0-9_]+)"
)
_NAME = re.compile(r"<name>\s*([A-Za-z0-9_.-]{1,200})\s*</name>")
# A rosbuild package's manifest (``manifest.xml``): a ``<package>`` root, after at most an XML
# declaration (comments removed first); a folder name a package may have.
ROSBUILD_MANIFEST = "manifest.xml"
_ROSBUILD_ROOT = re.compile(r"\s*(?:<\?xml[^<>]*\?>\s*)?<package[\s/>]")
_FOLDER_NAME = re.compile(r"[A-Za-z0-9_.-]{1,200}")
_MANIFESTS = frozenset({"package.xml", ROSBUILD_MANIFEST})
_WORD = re.compile(r"[A-Za-z0-9_]+")
# A metapackage exports ``<metapackage/>`` (``<metapackage />``, ``<metapackage></metapackage>``).
_EXPORT = re.compile(r"<export(?:\s[^<>]*)?>")
_EXPORT_END = re.compile(r"</export\s*>")
_METAPACKAGE = re.compile(r"<metapackage\s*/?>")


@dataclass(frozen=True, slots=True)
class ShippedFile:
    """One text file of one of the robot's packages; ``path`` is relative to the workspace."""

    package: str
    path: str
    text: str


@dataclass(frozen=True, slots=True)
class Workspace:
    """The robot's packages (the description's first) and their text files; ``notes`` say
    where a bound stopped the reading (``complete`` is then false); ``neighbours``: the names
    of the workspace's other packages, whose files are not read (a gait planner beside the
    robot's packages that names none of them)."""

    root: str
    package: str
    packages: tuple[str, ...]
    files: tuple[ShippedFile, ...]
    notes: tuple[str, ...] = ()
    neighbours: tuple[str, ...] = ()

    @property
    def complete(self) -> bool:
        """Every file was read: what the packages do not ship can be taken as not shipped
        (even with the description's package alone: of the labelled rows whose repository
        holds only it, most ship no navigation; measured, docs/identify.md)."""
        return not self.notes

    @property
    def shown_packages(self) -> str:
        """The robot's packages as a line shows them (the first few, then how many more)."""
        shown = ", ".join(self.packages[:SHOWN_PACKAGES])
        more = len(self.packages) - SHOWN_PACKAGES
        return f"{shown} and {more:,} more" if more > 0 else shown


def description_package(path: str | Path) -> Path | None:
    """The folder of the ROS package holding ``path``: the nearest folder above it (at most
    :data:`MAX_LEVELS_UP` up) with a ``package.xml`` that is a regular file, or a rosbuild
    ``manifest.xml`` (:func:`_rosbuild_manifest`); else None."""
    here = Path(os.path.abspath(path)).parent
    for _ in range(MAX_LEVELS_UP):
        if _regular(str(here / "package.xml")) or _rosbuild_manifest(str(here)) is not None:
            return here
        if here.parent == here:
            return None
        here = here.parent
    return None


def workspace_of(package: str | Path) -> Path:
    """The workspace around ``package``: the nearest folder named ``src`` at most two folders
    above the package's folder; for a package colcon installed (``install/NAME/share/NAME``),
    the install space its neighbours were installed in (``install``); else the folder above
    the package (a merged install's ``share``, as ``/opt/ros/DISTRO/share``)."""
    folder = Path(os.path.abspath(package))
    parent = folder.parent
    for above in (parent, parent.parent, parent.parent.parent):
        if above.name == "src":
            return above
    prefix = parent.parent
    if parent.name == "share" and prefix.name == folder.name and prefix.parent.name == INSTALL:
        return prefix.parent
    return parent


@dataclass(slots=True, eq=False)
class _Package:
    folder: str
    name: str
    manifest: set[str]
    paths: list[str] = field(default_factory=list)
    # The files of a named workspace that lie in no package (:data:`NO_PACKAGE`).
    loose: bool = False
    # A metapackage (``<metapackage/>`` exported): it only groups packages, uses none.
    meta: bool = False
    # Package names this package writes (its package.xml and its files), once all are known.
    mentions: set[str] = field(default_factory=set)
    files: list[ShippedFile] = field(default_factory=list)
    # The names of the robot descriptions it holds (:data:`DESCRIPTION_SUFFIXES`).
    described: list[str] = field(default_factory=list)

    @property
    def descriptions(self) -> int:
        return len(self.described)

    def describes_another(self, names: frozenset[str]) -> bool:
        """It holds a description of a robot but the one ``names`` name (:func:`_robot_name`):
        a description file whose name is not one of them (``arlobot.urdf``, the robot's own
        file made from the xacro source elsewhere, is no other robot's)."""
        return any(name.split(".", 1)[0].lower() not in names for name in self.described)


@dataclass(slots=True)
class _Budget:
    entries: int = 0
    files: int = 0
    total: int = 0
    stopped: bool = False
    notes: list[str] = field(default_factory=list)

    def note(self, why: str, *, stop: bool = True) -> None:
        """A bound was reached: say so once; ``stop``: nothing more is walked or read."""
        self.stopped = self.stopped or stop
        if why not in self.notes:
            self.notes.append(why)


def read_workspace(
    package: str | Path, root: str | Path | None = None, robot: str | None = None
) -> Workspace | None:
    """The robot's packages in the workspace around the description's ``package`` folder
    (``root``: the workspace; default: :func:`workspace_of`; ``robot``: the name its URDF
    gives the robot). None when the package has no readable ``package.xml`` (no package, no
    evidence)."""
    folder = os.path.abspath(package)
    top = os.path.abspath(root) if root is not None else str(workspace_of(folder))
    budget = _Budget()
    packages = _walk(folder, budget)
    own = packages.get(folder)
    if own is None:
        return None
    named = root is not None
    # Files in no package of the workspace the caller names (a repository): the robot's when
    # the workspace is one robot's, as a repository's are (:func:`read_repository`).
    loose = _Package(top, NO_PACKAGE, set(), loose=True)
    holding = _above(folder)
    packages.update(
        _walk(top, budget, skip=folder, holding=holding, owner=loose if named else None)
    )
    core = _core(own, list(packages.values()), robot)
    ordered = _reading_order(core, list(packages.values()))
    _read_all(ordered, top, budget)
    same = _robot_name(robot)
    if _one_robots(own, ordered, top, named=named, budget=budget, same=same):
        ours = [*ordered, *_loose_files(loose, top, budget, same)]
    else:
        ours = _robots_packages(core, ordered)
    return _workspace("workspace", top, own=own, ours=ours, ordered=ordered, budget=budget)


def _loose_files(
    loose: _Package, top: str, budget: _Budget, same: frozenset[str]
) -> list[_Package]:
    """The files of a one robot's workspace the caller named that lie in no package (a
    repository's top-level ``launch`` and ``config`` folders beside its packages, a web or
    teleop script), read after the packages as one more of the robot's (:data:`NO_PACKAGE`),
    with what the packages left of the bounds: a bound they reach stops them unsaid, the
    packages having been read whole. None when a description among them is not named for the
    robot (:meth:`_Package.describes_another`: another robot's, or a macro file)."""
    if not loose.paths or loose.describes_another(same):
        return []
    for path in loose.paths:
        if budget.files >= MAX_FILES or budget.total >= MAX_TOTAL_BYTES:
            break
        _read_into(loose, path, top, set(), budget)
    return [loose]


def _read_all(ordered: list[_Package], top: str, budget: _Budget) -> None:
    """Read the files of the ``ordered`` packages, in order, within the bounds."""
    names = {p.name for p in ordered}
    for each in ordered:
        each.mentions = each.manifest & names
        for path in each.paths:
            _read_into(each, path, top, names, budget)


def _workspace(
    what: str,
    top: str,
    *,
    own: _Package,
    ours: list[_Package],
    ordered: list[_Package],
    budget: _Budget,
) -> Workspace:
    """The robot's packages ``ours`` (``own`` the description's) of the ``ordered`` packages
    read at ``top`` (a ``what``: a workspace, a repository), with a note per bound reached; a
    simulator's ROS interface vendored beside them is none of the robot's, whatever uses it
    (:data:`SIMULATOR_PACKAGES`)."""
    ours = [p for p in ours if p is own or p.name not in SIMULATOR_PACKAGES]
    return Workspace(
        top,
        own.name,
        tuple(p.name for p in ours),
        tuple(f for p in ours for f in p.files),
        tuple(
            f"{what} {top}: {why}; the rest of it is not read "
            "(docs/identify.md, The robot's packages)"
            for why in budget.notes
        ),
        tuple(sorted({p.name for p in ordered} - {p.name for p in ours})),
    )


def read_repository(
    root: str | Path, description: str | Path, robot: str | None = None
) -> Workspace | None:
    """The robot's files in the repository at ``root`` that holds its ``description`` in no
    ROS package (a simulator's or a learning framework's repository: scripts beside the model,
    no ``package.xml``), read as one package named for the repository's folder, with the ROS
    packages inside it as a workspace's (:func:`read_workspace`). Of a repository holding more
    than one description, the files outside any package are the robot's where they name it
    (:func:`_names_robot`: its description's file name, or its URDF's or file's distinctive
    name): a repository of many robots' scripts says nothing of this one through a file that
    names none of them. None when ``root`` is no folder (no repository, no evidence)."""
    top = os.path.abspath(root)
    if not os.path.isdir(top):
        return None
    budget = _Budget()
    own = _Package(top, os.path.basename(top) or "repository", set())
    packages = _walk(top, budget, owner=own)
    own = packages.get(top, own)  # a package.xml at the root: the repository is that package
    others = [p for p in packages.values() if p is not own]
    ordered = [own, *_by_folder(others)]
    _read_all(ordered, top, budget)
    if own.descriptions > 1 and top not in packages:
        words = _robot_words(description, robot)
        folders = _robot_folders(description, robot)
        own.files = [f for f in own.files if _names_robot(f, words, folders)]
    # The packages inside are the robot's when none holds another description; no package
    # uses the repository's files by its folder's name (``main``, ``repo``: any word).
    same = _robot_name(robot)
    ours = (
        ordered if _one_robots(own, ordered, top, named=True, budget=budget, same=same) else [own]
    )
    return _workspace("repository", top, own=own, ours=ours, ordered=ordered, budget=budget)


def _robot_words(description: str | Path, robot: str | None) -> tuple[re.Pattern[str], ...]:
    """What names the robot described in ``description``: its file name (``leg.urdf``), and
    its URDF's name and its file's stem where they are distinctive (:data:`_DISTINCTIVE`:
    ``go2_arx``, ``pupper_arm``; not ``leg`` or ``robot``), each as a word of its own."""
    name = os.path.basename(str(description))
    stem = name.split(".", 1)[0]
    found = [name, *(w for w in (robot or "", stem) if _DISTINCTIVE.fullmatch(w))]
    return tuple(
        re.compile(rf"(?<![A-Za-z0-9-]){re.escape(w)}(?![A-Za-z0-9-])", re.IGNORECASE)
        for w in dict.fromkeys(found)
        if w
    )


def _robot_name(robot: str | None) -> frozenset[str]:
    """The name the URDF gives the robot, lower case, as a description file of its own is
    named (``arlobot`` for ``arlobot.urdf``); none for a name of no robot in particular
    (``robot``, ``my_robot``). Not the description's file name: ``main.urdf.xacro`` or
    ``common.urdf.xacro`` may name any robot's."""
    return frozenset({robot.lower()} if robot and _named_stem(robot) is not None else ())


def _robot_folders(description: str | Path, robot: str | None) -> frozenset[str]:
    """The names a folder or a file of the robot's is named by: its URDF's name and its
    file's stem, lower case, but a name of no robot in particular (``robot``, ``model``)."""
    stem = os.path.basename(str(description)).split(".", 1)[0]
    return frozenset(
        name.lower() for name in (robot or "", stem) if name and _named_stem(name) is not None
    )


def _names_robot(
    shipped: ShippedFile, words: tuple[re.Pattern[str], ...], folders: frozenset[str]
) -> bool:
    """``shipped`` is the robot's: its text names it (``words``), or its path does, a folder
    or the file named for it (``envs/airbot/airbot_robot.py`` for ``airbot``)."""
    *parts, name = shipped.path.lower().replace(os.sep, "/").split("/")
    named = [*parts, name.split(".", 1)[0]]
    return any(
        part == folder or part.startswith(f"{folder}_") for part in named for folder in folders
    ) or any(word.search(shipped.text) for word in words)


# A name distinctive enough to tell one robot of a repository from another: two words or a
# digit in it (``go2_arx``, ``XBot-L``, ``pupper_v2``), at least four characters.
_DISTINCTIVE = re.compile(r"(?=.{4,200}$)(?=.*[_\-0-9])[A-Za-z0-9_.\-]+")


def _one_robots(
    own: _Package,
    packages: list[_Package],
    top: str,
    *,
    named: bool,
    budget: _Budget,
    same: frozenset[str],
) -> bool:
    """The workspace is the robot's alone, every package of it the robot's: a source
    workspace (a ``src`` folder, or one the caller names) walked whole in which no package but
    the description's holds a description of another robot than the one ``same`` names
    (:meth:`_Package.describes_another`; a repository of one robot: its navigation, mission
    and arm packages need not name the description's package, as one named
    ``robot_description`` is not named as a package). An install space or a ``share`` folder
    holds every installed package, none of them the robot's for that."""
    source = named or os.path.basename(top) == "src"
    return (
        source
        and not budget.stopped
        and not any(p.describes_another(same) for p in packages if p is not own)
    )


def _stem(name: str) -> str | None:
    """``jackal_`` for ``jackal_description``: the prefix of the packages a robot's authors
    name for it (``jackal_navigation``, ``jackal_bringup``), the ROS convention; None for a
    package not named ``ROBOT_description(s)``, or named for no robot in particular."""
    for suffix in ("_descriptions", "_description"):
        if name.endswith(suffix) and len(name) > len(suffix):
            stem = name[: -len(suffix)] + "_"
            return None if stem in GENERIC_STEMS else stem
    return None


def _core(own: _Package, packages: list[_Package], robot: str | None = None) -> list[_Package]:
    """The description's package, then those named for the robot (by folder): for the stem of
    its own name (:func:`_stem`), else the longest stem its name begins with of a
    ``ROBOT_description`` package of the workspace (a description kept in ``jackal_control``
    beside ``jackal_description``; ``abb_irb_control`` is ``abb_irb_description``'s, not
    ``abb_description``'s) or of the ``robot`` its URDF names (a description kept in
    ``deliverybot_bringup`` for ``<robot name="deliverybot">``, beside
    ``deliverybot_navigation``)."""
    stems = [_named_stem(robot), *(_stem(p.name) for p in packages)]
    stem = _stem(own.name) or max(
        (found for found in stems if found is not None and _begins(own.name, found)),
        key=lambda found: (len(found), found),
        default=None,
    )
    if stem is None:
        return [own]
    return [own, *_by_folder([p for p in packages if p is not own and _begins(p.name, stem)])]


def _named_stem(robot: str | None) -> str | None:
    """``deliverybot_`` for the robot a URDF names ``deliverybot``: the stem of the packages
    named for it; None for a name of no robot in particular (``robot``, ``my_robot``)."""
    if not robot or not robot.strip():
        return None
    stem = f"{robot.strip().lower()}_"
    return None if stem in GENERIC_STEMS or stem in GENERIC_ROBOT_STEMS else stem


def _begins(name: str, stem: str) -> bool:
    """The package ``name`` is named for the robot of ``stem`` (``jackal_`` for
    ``Jackal_navigation``): it begins with the stem and goes on."""
    return len(name) > len(stem) and name.lower().startswith(stem.lower())


def _reading_order(core: list[_Package], packages: list[_Package]) -> list[_Package]:
    """The robot's core packages (:func:`_core`), those whose package.xml names one of them,
    then the rest (each group by folder)."""
    first = {p.name for p in core}
    chosen = {id(p) for p in core}
    rest = [p for p in packages if id(p) not in chosen]
    users = [p for p in rest if not first.isdisjoint(p.manifest)]
    others = [p for p in rest if first.isdisjoint(p.manifest)]
    return [*core, *_by_folder(users), *_by_folder(others)]


def _by_folder(packages: list[_Package]) -> list[_Package]:
    return sorted(packages, key=lambda p: p.folder)


def _robots_packages(core: list[_Package], packages: list[_Package]) -> list[_Package]:
    """The robot's core packages (:func:`_core`), the packages that use one of them, then the
    packages one of those uses (names compared as words; a name most packages write,
    ``robot_description`` the parameter, is no evidence that one is used, and a package of
    that name is written only where a file names it as a package: :func:`_read_into`). A
    metapackage uses nothing: it groups a repository's packages (every robot's of a vendor's
    repository), and launches none."""
    core_names = {p.name for p in core}
    chosen = {id(p) for p in core}
    users = [
        p
        for p in packages
        if id(p) not in chosen and not p.meta and not core_names.isdisjoint(p.mentions)
    ]
    chosen |= {id(p) for p in users}
    used_names = set().union(*(p.mentions for p in (*core, *users))) - _common_names(packages)
    used = [p for p in packages if id(p) not in chosen and p.name in used_names]
    return [*core, *_by_folder(users), *_by_folder(used)]


def _common_names(packages: list[_Package]) -> set[str]:
    """Names more than :data:`COMMON_SHARE` of the packages (and more than :data:`MIN_COMMON`)
    write: words every launch file has, not uses."""
    counts = Counter(name for p in packages for name in p.mentions if name != p.name)
    bound = max(MIN_COMMON, COMMON_SHARE * len(packages))
    return {name for name, count in counts.items() if count > bound}


def _above(folder: str) -> frozenset[str]:
    """The install spaces above ``folder`` (folders named ``install``): skipped elsewhere, one
    is walked when the description was installed in it, its neighbours installed beside it."""
    found = set()
    here = os.path.dirname(folder)
    while here and os.path.dirname(here) != here:
        if os.path.basename(here) == INSTALL:
            found.add(here)
        here = os.path.dirname(here)
    return frozenset(found)


def _walk(
    start: str,
    budget: _Budget,
    skip: str | None = None,
    holding: frozenset[str] = frozenset(),
    owner: _Package | None = None,
) -> dict[str, _Package]:
    """Every package under ``start`` (by folder) with its manifest's words and its text files'
    paths; a package owns the folders below it (links not followed, skipped folders but those
    in ``holding`` and ``skip`` left out); ``owner`` owns what no package below it does (a
    repository's files)."""
    packages: dict[str, _Package] = {}
    stack: list[tuple[str, int, _Package | None]] = [(start, 0, owner)]
    while stack and not budget.stopped:
        folder, level, owner = stack.pop()
        if folder == skip:
            continue
        files, subfolders = _list(folder, budget, holding)
        found = _package_in(folder, files)
        if found is not None:
            name, manifest = found
            owner = packages[folder] = _Package(
                folder,
                name,
                set(_WORD.findall(manifest)),
                meta=_exports_metapackage(_uncommented(manifest)),
            )
        # A workspace's files in no package take nothing in an install space (its setup
        # scripts, its libraries): they are no robot's.
        installed = owner is not None and owner.loose and _installed(folder, start)
        if (owner is None or installed) and _install_prefix(folder, subfolders):
            # An install prefix: its packages are in share/NAME; its libraries and headers
            # belong to none (read nothing, and would spend the walk's bound).
            subfolders = ["share"]
        elif owner is not None and not installed:
            texts = _texts(folder, files, headers=_own_headers(owner, folder))
            owner.paths += [os.path.join(folder, name) for name in texts]
            owner.described += [name for name in files if name.endswith(DESCRIPTION_SUFFIXES)]
        if level >= MAX_DEPTH and subfolders:
            budget.note(f"folders deeper than {MAX_DEPTH} levels are not walked", stop=False)
        elif subfolders:
            stack += [(os.path.join(folder, n), level + 1, owner) for n in sorted(subfolders)[::-1]]
    return packages


def _package_in(folder: str, files: list[str]) -> tuple[str, str] | None:
    """The name and manifest text of the package whose folder is ``folder`` (its files
    ``files``): its ``package.xml``'s ``<name>``; with none, a rosbuild ``manifest.xml``'s
    folder name; else None."""
    if "package.xml" in files:
        manifest = _text(_read(os.path.join(folder, "package.xml"), MAX_MANIFEST_BYTES))
        found = _NAME.search(manifest)
        return None if found is None else (found.group(1), manifest)
    if ROSBUILD_MANIFEST in files:
        rosbuild = _rosbuild_manifest(folder)
        if rosbuild is not None:
            return os.path.basename(folder), rosbuild
    return None


def _rosbuild_manifest(folder: str) -> str | None:
    """The text of the rosbuild package's manifest in ``folder`` (the package is named by the
    folder): a ``manifest.xml`` whose root is a ``<package>``, in a folder a package may be
    named by (other tools write files of that name too: an Android or .NET manifest is no ROS
    package); else None."""
    if _FOLDER_NAME.fullmatch(os.path.basename(folder)) is None:
        return None
    manifest = _text(_read(os.path.join(folder, ROSBUILD_MANIFEST), MAX_MANIFEST_BYTES))
    return manifest if _ROSBUILD_ROOT.match(_uncommented(manifest)) else None


def _exports_metapackage(manifest: str) -> bool:
    """The manifest's ``<export>`` holds ``<metapackage/>`` (an empty ``<export/>`` holds
    nothing); linear in the manifest's length (a stranger's manifest of many unclosed
    ``<export>`` tags is read through once)."""
    end = 0
    while (opening := _EXPORT.search(manifest, end)) is not None:
        if opening.group().endswith("/>"):
            end = opening.end()
            continue
        close = _EXPORT_END.search(manifest, opening.end())
        stop = len(manifest) if close is None else close.start()
        if _METAPACKAGE.search(manifest, opening.end(), stop) is not None:
            return True
        if close is None:
            return False
        end = close.end()
    return False


def _installed(folder: str, start: str) -> bool:
    """``folder`` lies in an install space at or below ``start`` (a folder named ``install``
    on the way)."""
    return INSTALL in Path(os.path.relpath(folder, os.path.dirname(start))).parts


def _install_prefix(folder: str, subfolders: list[str]) -> bool:
    """``folder`` is an install space (``install``, merged) or a prefix in one
    (``install/NAME``): ``share`` beside ``lib``, ``include`` or ``bin``. A source tree's
    folder of that shape is walked whole."""
    named = INSTALL in (os.path.basename(folder), os.path.basename(os.path.dirname(folder)))
    return named and "share" in subfolders and not _PREFIX_FOLDERS.isdisjoint(subfolders)


def _texts(folder: str, files: list[str], *, headers: bool = False) -> list[str]:
    """The names of ``files`` (in ``folder``) read as text: by suffix, and scripts with none;
    with ``headers``, C headers too (:func:`_own_headers`)."""
    script = os.path.basename(folder) in SCRIPT_FOLDERS
    return [
        name
        for name in sorted(files)
        if name not in _MANIFESTS
        and (
            name.endswith(TEXT_SUFFIXES)
            or (script and "." not in name)
            or (headers and name.endswith(_C_HEADER))
        )
    ]


# A C or C++ header: read in a package's own header folder only (:func:`_own_headers`).
_C_HEADER = ".h"


def _own_headers(owner: _Package, folder: str) -> bool:
    """``folder`` is ``owner``'s own header folder, ``include/<its name>``, or below it: where a
    ROS 1 package writes its nodes' classes (``include/legged_controllers/...Publisher.h``
    subscribing to a goal topic). A vendor's SDK keeps its ``.h`` files elsewhere
    (``include/sdk/can.h``), unread."""
    own = os.path.join(owner.folder, "include", owner.name)
    return folder == own or folder.startswith(own + os.sep)


def _list(
    folder: str, budget: _Budget, holding: frozenset[str] = frozenset()
) -> tuple[list[str], list[str]]:
    """The regular files and the folders (links and hidden or skipped names left out, but for
    a folder in ``holding``) of ``folder``; none when it cannot be listed."""
    files: list[str] = []
    subfolders: list[str] = []
    try:
        with os.scandir(folder) as entries:
            for entry in entries:
                budget.entries += 1
                if budget.entries > MAX_ENTRIES:
                    budget.note(f"more than {MAX_ENTRIES:,} entries")
                    break
                if entry.name.startswith(".") or entry.is_symlink():
                    continue
                if entry.is_dir(follow_symlinks=False):
                    if entry.name not in SKIPPED_FOLDERS or entry.path in holding:
                        subfolders.append(entry.name)
                elif entry.is_file(follow_symlinks=False):
                    files.append(entry.name)
    except OSError:
        pass
    return files, subfolders


def _read_into(owner: _Package, path: str, top: str, names: set[str], budget: _Budget) -> None:
    """Read the file ``path`` of ``owner`` within the bounds: its text and the package names
    it writes."""
    if budget.files >= MAX_FILES:
        budget.note(f"more than {MAX_FILES:,} files")
        return
    if budget.total >= MAX_TOTAL_BYTES:
        budget.note(f"more than {MAX_TOTAL_BYTES // (1024 * 1024)} MiB of files")
        return
    data = _read(path, MAX_FILE_BYTES)
    if data is None:
        return
    budget.files += 1
    budget.total += len(data)
    text = _text(data)
    if path.endswith((".launch", ".xml")):
        text = _uncommented(text)
    else:
        text = _without_comment_lines(text, "//" if path.endswith(_CPP_SUFFIXES) else "#")
    if "kill" in text:
        text = _KILLS.sub("", text)
    text = _ENCODED.sub("", text)
    written = names.intersection(_WORD.findall(text))
    if not written.isdisjoint(PARAMETER_NAMES):
        written -= PARAMETER_NAMES - set(_AS_PACKAGE.findall(text))
    owner.mentions.update(written)
    owner.files.append(ShippedFile(owner.name, os.path.relpath(path, top), text))


def _regular(path: str) -> bool:
    """``path`` is a regular file (not a link to one)."""
    try:
        return stat.S_ISREG(os.lstat(path).st_mode)
    except (OSError, ValueError):
        return False


def _text(data: bytes | None) -> str:
    """Bytes read as UTF-8 text (undecodable bytes replaced); none as empty."""
    return "" if data is None else data.decode("utf-8", errors="replace")


def _read(path: str, limit: int) -> bytes | None:
    """At most ``limit`` bytes of the regular file ``path``; None for a link, a FIFO,
    a device or a file that cannot be read (none of them is opened: the kind is asked first,
    and the file opened without following a link, waiting or taking a terminal)."""
    if not _regular(path):
        return None
    flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_NOCTTY | os.O_CLOEXEC
    try:
        descriptor = os.open(path, flags)
    except (OSError, ValueError):
        return None
    try:
        if not stat.S_ISREG(os.fstat(descriptor).st_mode):
            return None
        data = os.read(descriptor, limit)
    except OSError:
        return None
    finally:
        os.close(descriptor)
    return data


# A command that stops processes (``pkill -f "gazebo|move_group"``, ``killall``, ``rosnode
# kill``) names what a script ends, not what it runs: it is left out up to the end of the
# command (a newline, ``;``, ``&`` or ``|`` outside quotes), the rest of its line kept.
_KILLS = re.compile(r"\b(pkill|killall|rosnode[ \t]+kill)\b(?:\"[^\"\n]*\"|'[^'\n]*'|[^\n;&|\"'])*")


# A block of encoded data (three or more lines in a row of 60 characters or more, none a space,
# a full stop, a comma or a quote: base64, base85 or hex, as a vendored ``get-pip.py`` carries a
# wheel in) is data, not code: a word a pattern reads in it (``mIK``) is chance. Code and
# configuration space their words, or call, list and quote them (``pub=rospy.Publisher('/a',T)``).
_ENCODED = re.compile(r"""(?:^[^\s.,'"]{60,}(?:\r?\n|\Z)){3,}""", re.MULTILINE)


# C++ sources, whose comments open with ``//`` (``#`` opens a preprocessor line); Python,
# YAML, shell and suffixless scripts comment with ``#``.
_CPP_SUFFIXES = (".cpp", ".cc", ".hpp", ".h")


# A whole line of comment: its first text is the mark (``#!`` is an interpreter's line).
_COMMENT_LINES = {
    "#": re.compile(r"^[ \t]*#(?!!)[^\n]*(?:\n|$)", re.MULTILINE),
    "//": re.compile(r"^[ \t]*//[^\n]*(?:\n|$)", re.MULTILINE),
}


def _without_comment_lines(text: str, mark: str) -> str:
    """``text`` without its whole-line comments (a line, split at newlines only, whose first
    text is ``mark``; a ``#!`` line kept): code commented out runs nothing."""
    return _COMMENT_LINES[mark].sub("", text)


def _uncommented(text: str) -> str:
    """``text`` without XML comments, in one pass (an unclosed comment runs to the end)."""
    kept: list[str] = []
    start = 0
    while True:
        opening = text.find("<!--", start)
        if opening < 0:
            kept.append(text[start:])
            return "".join(kept)
        kept.append(text[start:opening])
        closing = text.find("-->", opening + 4)
        if closing < 0:
            return "".join(kept)
        start = closing + 3
