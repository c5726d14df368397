"""Make the labelled sets' description files again from the repositories their rows name.

Usage::

    python tools/rebuild_set_files.py --repos                    # owner/name to bring, one a line
    python tools/rebuild_set_files.py --mirror DIR --out OUT     # OUT/<set>/urdf/, srdf/, ...

The rows of ``tools/identification_set``, ``tools/generalization_set`` and every
``tools/fresh_set_N`` name where each robot's file came from (the ``source`` column), but the
files of GitHub rows are not committed (the workplace's rule for fetched content: see
``tools/identification_set/README.md``). They were made on a machine that is gone; this tool
makes them again, the same way, so that ``tools/measure_identification.py`` measures the
development part on any machine:

* a row's source is read for the repository and commit (``github owner/name@commit`` or
  ``https://github.com/owner/name @commit``), the file's path in it (the first ``.urdf``,
  ``.xacro``, ``.gazebo`` or ``.xml`` after them, in any case, or such a name kept as ``.txt``
  (``robot.urdf.txt``; ``robot.urdf.bak`` is none), never a ``package.xml``; after
  the licence note in parentheses that follows the commit, when one follows it), the
  xacro arguments it names (``name:=value``, the first value of each name; ``NAME=value`` for
  an environment variable), the SRDF's path when the row has one, and the other repositories
  it names, with ``github`` or bare (their packages resolve ``$(find ...)``);
* ``DIR/owner+name/repo`` holds each repository as a git directory (the workplace's ``fetch``
  leaves them so; a clone's ``.git`` is found too); the commit's tree is written out once
  under ``OUT/trees/``;
* a ``.urdf`` is copied; a ``.xacro`` is compiled with teleop-ui's own xacro sandbox
  (:func:`solver.identify.xacro.compiler.compile_xacro`, the ``xacro`` extra) with those
  arguments and every package of those trees on the package path. An SRDF likewise;
* ``OUT/<set>/urdf/<file>`` (and ``srdf/``) are the row's files under the names its ``file``
  and ``srdf`` columns give; ``OUT/workspaces.tsv`` says where each row's tree is
  (``--workspaces`` of the measure tool: the controls its packages ship).

A row not made (no repository in its source, no such commit or file, xacro that does not
compile) is listed with why, on standard error and in the report, and the rest go on: the run
exits 0 when it went through every row (some rows' recipes can never be followed: a labeller's
own patch script, a Python 2 file), 2 on a wrong command line. Running one ``--set`` keeps the
other sets' lines of the two ``.tsv`` files. The files made need not be byte for byte those
the rows were labelled on (an argument the source only describes in words is not passed), so
``OUT/report.tsv`` lists every row and how it was made.

Then::

    PYTHONPATH=. python tools/measure_identification.py --all --split --rebuilt OUT
"""

from __future__ import annotations

import argparse
import csv
import re
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TOOLS = ROOT / "tools"
SETS = ("identification_set", "generalization_set")

REPOSITORY = re.compile(
    r"github(?:\.com/|:\s*|\s+)([\w.-]+/[\w.-]+?)(?:\.git)?\s*@\s*([0-9a-f]{7,40})\b"
)
# A second repository is often named bare: "... resolved to uuvsimulator/uuv_simulator@ed260c82".
SECOND = re.compile(r"(?<![\w./-])([\w.-]+/[\w.-]+?)(?:\.git)?\s*@\s*([0-9a-f]{7,40})\b")
DESCRIPTION = re.compile(
    r"(?<![\w/.-])((?:[\w.+-]+/)*[\w.+-]+\.(?:urdf\.xacro|xacro|urdf|gazebo|xml)(?:\.txt)?)\b(?!\.\w)",
    re.IGNORECASE,
)
# A path with a space in it, written between backquotes (`Mechanical Design/x/robot.urdf`).
QUOTED_DESCRIPTION = re.compile(r"`([^`\n]* [^`\n]*\.(?:urdf\.xacro|xacro|urdf))`", re.IGNORECASE)
# XML files a source names that are never the description.
NOT_DESCRIPTIONS = ("package.xml", "manifest.xml", "launch.xml")
SRDF = re.compile(r"(?<![\w/.-])((?:[\w.+-]+/)*[\w.+-]+\.srdf(?:\.xacro)?)\b")
# name:=value, name:='a b' or name:="a b".
ARGUMENT = re.compile(r"(?<![\w$(])([A-Za-z_][\w-]*):=(?:'([^']*)'|\"([^\"]*)\"|([^\s,;\])'\"]*))")
# How a plain URDF's recipe says it is copied: "plain" first, or first in the first bracket
# or parenthesis after the path ("[plain URDF ...]", "(plain URDF, copied ...)", "with
# config/x.srdf.xacro [plain URDF]"), not later in one ("[xacro->urdf: the plain vehicle's
# launch]", "[xacro->urdf without arguments (a plain URDF)]").
PLAIN = re.compile(r"\s*plain\b|[^\[(]*[\[(]\s*plain\b", re.IGNORECASE)
# An environment variable a source sets (``SPOT_ARM=1``): what $(optenv SPOT_ARM) reads.
ENVIRONMENT = re.compile(r"(?<![\w$(=])([A-Z][A-Z0-9_]*)=(?!=)([^\s,;\])'\"]+)")
# Placeholders the sources write in argument values: the repository's tree, the package's folder.
PLACEHOLDERS = ("<repo>", "<fetched>", "<package>")
MISSING_PACKAGE = re.compile(r"ROS package '([^']+)' not found")
# How a parenthesis changes the depth of a note's nesting.
_DEPTH = {"(": 1, ")": -1}


@dataclass(frozen=True, slots=True)
class Source:
    """Where one row's files came from, as its ``source`` column says."""

    repository: str  # owner/name
    commit: str
    path: str  # the description's path in the repository
    xacro: bool  # compiled (a .xacro, or another name the source says xacro expands)
    args: tuple[tuple[str, str], ...]
    srdf: str | None
    others: tuple[tuple[str, str], ...]  # other (repository, commit) the source names


def parse_source(text: str, *, srdf: bool) -> Source | None:
    """A row's :class:`Source`, or ``None`` when its text names no repository and file."""
    found = list(REPOSITORY.finditer(text))
    if not found:
        return None
    first = found[0]
    rest = text[first.end() :]
    # The text the description is named in: after the licence note, else the whole rest.
    named_in = _after_licence(rest)
    description = _description(named_in)
    if description is None:
        named_in, description = rest, _description(rest)
    if description is None:
        return None
    # The recipe's own arguments come first; the same name later is prose ("own:=false would
    # give ..."): the first value of each name is kept.
    args: dict[str, str] = {}
    for match in ARGUMENT.finditer(rest):
        name, quoted, double, bare = match.groups()
        given = quoted is not None or double is not None  # '' is a value
        value = quoted or double or (bare or "").rstrip(":.")
        # Placeholders other than PLACEHOLDERS ("<that package>") and elisions are words.
        unknown = "<" in _placed(value, dict.fromkeys(PLACEHOLDERS, ""))
        if (given or value) and not unknown and not any(t in value for t in ("...", "$(", "${")):
            args.setdefault(name, value)
    for name, value in ENVIRONMENT.findall(rest):
        args.setdefault(name, value.rstrip(":."))
    srdf_path = None
    if srdf:
        named = SRDF.search(rest)
        srdf_path = named.group(1) if named else None
    others = tuple(
        dict.fromkeys(
            (m.group(1), m.group(2))
            for m in (*found[1:], *SECOND.finditer(rest))
            if m.group(1).lower() != first.group(1).lower()
        )
    )
    path = description.group(1)
    # How it was made is said right after the path: "[xacro->urdf ...]", "[plain URDF ...]"
    # (:data:`PLAIN`).
    how = named_in[description.end() : description.end() + 40]
    xacro = path.endswith(".xacro") or ("xacro" in how and not PLAIN.match(how))
    return Source(
        first.group(1),
        first.group(2),
        path,
        xacro,
        tuple(args.items()),
        srdf_path,
        others,
    )


def set_folders(tools: Path = TOOLS) -> list[Path]:
    """The labelled sets whose rows this tool rebuilds, in a fixed order."""
    fresh = sorted(
        (int(path.name.removeprefix("fresh_set_")), path)
        for path in tools.glob("fresh_set_*")
        if path.name.removeprefix("fresh_set_").isdigit()
    )
    return [tools / name for name in SETS] + [path for _, path in fresh]


def rows(folder: Path) -> list[dict[str, str]]:
    with (folder / "truth.csv").open(encoding="utf-8", newline="") as stream:
        return list(csv.DictReader(stream))


def git_directory(mirror: Path, repository: str) -> Path | None:
    """The git directory of ``repository`` under ``mirror`` (``owner+name/repo[/.git]``)."""
    base = mirror / repository.replace("/", "+") / "repo"
    for candidate in (base / ".git", base):
        if (candidate / "HEAD").is_file():
            return candidate
    return None


class Trees:
    """Commits' trees written out once each under ``folder``, and which mirrored repository
    holds a ROS package of a given name (at its newest commit)."""

    def __init__(self, mirror: Path, folder: Path) -> None:
        self.mirror = mirror
        self.folder = folder
        self._packages: dict[str, str] | None = None

    def tree(self, repository: str, commit: str) -> Path:
        """The folder holding ``repository`` at ``commit`` (``HEAD``: its newest commit, named
        by its hash); :class:`LookupError` if it cannot be had."""
        git = git_directory(self.mirror, repository)
        if git is None:
            raise LookupError(f"{repository} is not under {self.mirror}")
        # Named by the full hash: one tree per commit however a source spells it.
        commit = _git(git, "rev-parse", "--verify", f"{commit}^{{commit}}").decode().strip()
        # A folder of its own above each tree: the xacro sandbox finds the packages beside a
        # package at a tree's root, and must not find another tree's.
        where = self.folder / f"{repository.replace('/', '+')}@{commit}" / "repo"
        if where.is_dir():
            return where
        partial = where.with_name("repo.part")
        shutil.rmtree(partial, ignore_errors=True)
        _write_tree(git, commit, partial)
        partial.rename(where)
        return where

    def holder(self, package: str) -> str | None:
        """The mirrored repository (owner/name) with a ``package.xml`` named ``package``: the
        shallowest copy (the package's own repository, not one that vendors it deeper down),
        then the repository whose name begins most like the package's (``uuv_simulator`` for
        ``uuv_assistants``, not a simulator that copied it), then by name."""
        if self._packages is None:
            found = sorted(
                (name, depth, -_shared(name, repository), repository)
                for folder in sorted(self.mirror.iterdir())
                if (git := git_directory(self.mirror, repository := _repository(folder)))
                for name, depth in _package_names(git)
            )
            self._packages = {}
            for name, _, _, repository in found:
                self._packages.setdefault(name, repository)
        return self._packages.get(package)


def _shared(package: str, repository: str) -> int:
    """How many leading characters the package's name and the repository's name share."""
    name = repository.split("/", 1)[1].lower().replace("-", "_")
    return next(
        (i for i, (a, b) in enumerate(zip(package.lower(), name, strict=False)) if a != b),
        min(len(package), len(name)),
    )


def _repository(folder: Path) -> str:
    """owner/name of a mirror's folder ``owner+name``."""
    return folder.name.replace("+", "/", 1)


def _git(git: Path, *args: str) -> bytes:
    """A git command's output; :class:`LookupError` with git's last word when it fails."""
    done = subprocess.run(["git", "--git-dir", str(git), *args], capture_output=True, check=False)
    if done.returncode != 0:
        message = done.stderr.decode(errors="replace").strip().splitlines()
        raise LookupError(f"{git}: {message[-1] if message else 'git failed'} ({' '.join(args)})")
    return done.stdout


def _blobs(git: Path, shas: list[str]) -> Iterator[bytes | None]:
    """Each blob's content in order (``None``: the mirror lacks it), read one at a time."""
    with tempfile.TemporaryFile() as wanted:
        wanted.write("".join(f"{sha}\n" for sha in shas).encode())
        wanted.seek(0)
        with subprocess.Popen(
            ["git", "--git-dir", str(git), "cat-file", "--batch"],
            stdin=wanted,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
        ) as batch:
            assert batch.stdout is not None
            for _ in shas:
                header = batch.stdout.readline().split()
                if not header:
                    raise LookupError(f"{git}: git cat-file ended early")
                if header[-1] == b"missing":
                    yield None
                    continue
                content = batch.stdout.read(int(header[2]))
                batch.stdout.read(1)  # the newline after each blob
                yield content


def _package_names(git: Path) -> list[tuple[str, int]]:
    """The names in the ``package.xml`` files of a git directory's newest commit, each with
    how many folders down its file is."""
    try:
        listing = _git(git, "ls-tree", "-r", "HEAD").decode(errors="replace")
        entries = [
            (line.split()[2], line.split("\t", 1)[1].count("/"))
            for line in listing.splitlines()
            if line.endswith(("/package.xml", "\tpackage.xml"))
        ]
        found = []
        for content, (_, depth) in zip(_blobs(git, [e[0] for e in entries]), entries, strict=True):
            name = re.search(rb"<name>\s*([\w.-]+)\s*</name>", content or b"")
            if name:
                found.append((name.group(1).decode(), depth))
    except LookupError:
        return []  # a mirror git cannot read holds no package to take
    return found


def _write_tree(git: Path, commit: str, folder: Path) -> None:
    """The files of ``commit`` under ``folder``; blobs the mirror lacks (its largest files,
    meshes mostly) are left out, and a symbolic link to a file of the tree is a copy of it."""
    blobs: list[tuple[str, str, bool]] = []
    for entry in _git(git, "ls-tree", "-r", "-z", commit).split(b"\0"):
        if entry:
            meta, name = entry.split(b"\t", 1)
            mode, kind, sha = meta.decode().split()
            if kind == "blob":
                blobs.append((sha, name.decode(errors="replace"), mode == "120000"))
    root = folder.resolve()
    root.mkdir(parents=True, exist_ok=True)
    links: dict[Path, Path] = {}
    contents = _blobs(git, [sha for sha, _, _ in blobs])
    for content, (_, path, link) in zip(contents, blobs, strict=True):
        target = (root / path).resolve()
        if content is None or root not in target.parents:  # no path leaves the folder
            continue
        if link:
            links[target] = (target.parent / content.decode(errors="replace")).resolve()
            continue
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(content)
    while links:  # a link to a link is copied once the link it names is
        copied = [t for t, linked in links.items() if root in linked.parents and linked.is_file()]
        if not copied:
            break  # the rest name folders, nothing, or what lies outside the tree
        for target in copied:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(links.pop(target).read_bytes())


def make(
    source: Source, trees: Trees, urdf_out: Path, srdf_out: Path | None
) -> tuple[Path, list[str]]:
    """Write the row's files; the folder of its main tree (its workspace) and notes: the
    packages taken from repositories its source does not name, the second repositories it was
    made without."""
    tree = trees.tree(source.repository, source.commit)
    roots = [tree]
    taken: list[str] = []
    for name, commit in source.others:
        # A second repository the mirror lacks may not be needed: the row is tried without
        # it (a package it held is then missing, and said so).
        try:
            roots.append(trees.tree(name, commit))
        except LookupError:
            taken.append(f"without {name} (not in the mirror)")
    for path, out, xacro in (
        (source.path, urdf_out, source.xacro),
        (source.srdf, srdf_out, (source.srdf or "").endswith(".xacro")),
    ):
        if path is None or out is None:
            continue
        file = (tree / path).resolve()
        if tree.resolve() not in file.parents or not file.is_file():
            raise LookupError(f"{source.repository}@{source.commit} has no file {path}")
        out.parent.mkdir(parents=True, exist_ok=True)
        if xacro:
            out.write_text(_compiled(file, source, trees, roots, taken), encoding="utf-8")
        else:
            out.write_bytes(file.read_bytes())
    return tree, taken


def _compiled(file: Path, source: Source, trees: Trees, roots: list[Path], taken: list[str]) -> str:
    """``file`` through teleop-ui's xacro sandbox with the source's arguments; a package no
    tree in ``roots`` has is taken from the mirrored repository that has it (its newest commit),
    as the labellers took a package their source did not name (said in ``taken``)."""
    from solver.errors import InputError
    from solver.identify.xacro.compiler import compile_xacro
    from solver.identify.xacro.packages import own_package_root

    places = {"<repo>": str(roots[0]), "<fetched>": str(roots[0])}
    places["<package>"] = str(own_package_root(file))
    args = {name: _placed(value, places) for name, value in source.args}
    for _ in range(8):
        try:
            return compile_xacro(file, args=args, package_path=roots).text
        except InputError as error:
            missing = MISSING_PACKAGE.search(str(error))
            package = missing.group(1) if missing else ""
            holder = trees.holder(package) if package else None
            if holder is None:
                raise
            added = trees.tree(holder, "HEAD")
            if added in roots:
                raise
            roots = [*roots, added]
            taken.append(f"package {package} taken from {holder}")
    raise LookupError(f"{file}: more than 8 packages from other repositories")


def _description(text: str) -> re.Match[str] | None:
    """The first description path ``text`` names (a ``package.xml`` is none): bare, or with
    spaces between backquotes."""
    description = next(
        (
            match
            for match in DESCRIPTION.finditer(text)
            if not match.group(1).lower().endswith(NOT_DESCRIPTIONS)
        ),
        None,
    )
    quoted = QUOTED_DESCRIPTION.search(text)
    if quoted is not None and (description is None or quoted.start() < description.start()):
        return quoted
    return description


def _after_licence(rest: str) -> str:
    """What follows the recipe's licence note: ``(LICENCE: where it says so)`` right after the
    commit is prose, and a file it names (``BSD in robot.urdf's header``) is not the
    description, when a file follows the note (else the note's is: the caller looks again in
    the whole text). A note left open gives nothing; a parenthesis the note quotes unpaired
    (a commit message's ``:)``) ends it early or late, as it balances."""
    stripped = rest.lstrip()
    if not stripped.startswith("("):
        return rest
    depth = 0
    for index, char in enumerate(stripped):
        depth += _DEPTH.get(char, 0)
        if depth == 0:
            return stripped[index + 1 :]
    return ""


def _placed(value: str, places: dict[str, str]) -> str:
    for placeholder in PLACEHOLDERS:
        value = value.replace(placeholder, places[placeholder])
    return value


def repositories(folders: list[Path]) -> list[str]:
    """Every repository the sets' rows name, in order of first mention."""
    found: dict[str, None] = {}
    for folder in folders:
        for row in rows(folder):
            source = parse_source(row["source"], srdf=False)
            if source is not None:
                for repository in (source.repository, *(name for name, _ in source.others)):
                    found.setdefault(repository)
            for match in REPOSITORY.finditer(row["source"]):
                found.setdefault(match.group(1))
    return list(found)


def rebuild(folders: list[Path], mirror: Path, out: Path) -> tuple[int, int]:
    """Make every row's files under ``out``: how many rows were not made, and how many of
    those could have been (their repository is under ``mirror``). ``OUT/report.tsv`` and
    ``OUT/workspaces.tsv`` keep the lines of sets not made this time."""
    trees = Trees(mirror, out / "trees")
    report: list[str] = []
    workspaces: list[str] = []
    missed = failed = 0
    for folder in folders:
        for row in rows(folder):
            name, robot = folder.name, row["robot"]
            srdf_column = row.get("srdf", "").strip()
            source = parse_source(row["source"], srdf=bool(srdf_column))
            why = note = ""
            outputs = [out / name / row["file"], *([out / name / srdf_column] * bool(srdf_column))]
            for stale in outputs:  # a row not made now keeps no file of an earlier run
                stale.unlink(missing_ok=True)
            if source is None:
                why = "its source names no GitHub repository, commit and file"
            elif srdf_column and source.srdf is None:
                why = "its source names no SRDF file"
            else:
                srdf_out = out / name / srdf_column if srdf_column else None
                try:
                    tree, taken = make(source, trees, out / name / row["file"], srdf_out)
                except (LookupError, OSError, ValueError) as error:
                    why = str(error).splitlines()[0]
                else:
                    workspaces.append(f"{name}\t{robot}\t{tree}\t{source.path}")
                    note = "; ".join(taken)
            if why:
                missed += 1
                here = source is not None and git_directory(mirror, source.repository)
                failed += bool(here)
                print(f"{name} {robot}: not made: {why}", file=sys.stderr)
            report.append(f"{name}\t{robot}\t{'no' if why else 'yes'}\t{why or note}")
    made = {folder.name for folder in folders}
    _merge(out / "report.tsv", report, made, REPORT_HEADER)
    _merge(out / "workspaces.tsv", workspaces, made)
    return missed, failed


REPORT_HEADER = "set\trobot\tmade\twhy not (or how: packages taken, repositories left out)"


def _merge(path: Path, lines: list[str], sets: set[str], header: str | None = None) -> None:
    """Write ``lines`` to ``path``, keeping its lines of sets other than ``sets``."""
    kept = []
    if path.is_file():
        kept = [
            line
            for line in path.read_text(encoding="utf-8").splitlines()
            if line != header and line.split("\t", 1)[0] not in sets
        ]
    path.parent.mkdir(parents=True, exist_ok=True)
    head = [header] if header is not None else []
    path.write_text("\n".join([*head, *kept, *lines]) + "\n", encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repos", action="store_true", help="list the repositories to bring")
    parser.add_argument("--mirror", type=Path, help="where the repositories are (owner+name/repo)")
    parser.add_argument("--out", type=Path, help="where the files go")
    parser.add_argument(
        "--set", type=Path, action="append", default=[], help="one set only (repeat for several)"
    )
    args = parser.parse_args(argv)
    folders = args.set or set_folders()
    if args.repos:
        print("\n".join(repositories(folders)))
        return 0
    if args.mirror is None or args.out is None:
        parser.error("--mirror and --out are needed to make the files (or --repos)")
    missed, failed = rebuild(folders, args.mirror, args.out)
    print(
        f"{missed} rows not made, {failed} of them with their repository here; "
        f"see {args.out / 'report.tsv'}",
        file=sys.stderr,
    )
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    sys.exit(main())
