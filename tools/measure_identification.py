"""Measure `teleop-ui identify` against labelled sets of robot descriptions.

Usage::

    python tools/measure_identification.py                      # the shared corpus
    python tools/measure_identification.py --set tools/identification_set
    python tools/measure_identification.py --all                # both, side by side
    python tools/measure_identification.py --set DIR --files DIR2   # files kept elsewhere
    python tools/measure_identification.py --all --profile mine.yaml  # another profile
    python tools/measure_identification.py --all --split      # development / held-out parts
    python tools/measure_identification.py --all --split --no-names   # every name removed

A labelled set is a folder with a ``truth.csv`` (the columns of ``../shared/corpus/truth.csv``:
``robot``, ``file``, ``srdf``, ``source``, ``kinematic_type``, ``sensors``,
``motion_control_kinds``, ``uncertainty_note``, ...; optionally ``family`` and ``licence``).
``file`` and ``srdf`` are paths relative to the set; a file absent there is looked up under each
``--files`` folder and then under ``../shared/<set folder name>/`` (a name that another set
measured lists too, only in the set's home ``--files`` folder, the one holding most of its other
files: two sets may label different robots under one file name), and a row whose file is nowhere
is counted as *absent* (its ``source`` says how to fetch it) and not measured.

Each robot is identified from its URDF (and SRDF when it has one) with the shipped profile and
the article's rule set, exactly as ``teleop-ui identify`` would. Printed, as Markdown, per
family and per source (the repository or package in ``source``), each set's rows side by side:
structure accuracy on the certain labels (no trailing ``?``), the lenient score (a label ending
in ``?`` also accepts a structure its ``uncertainty_note`` names, by its name or a word of
``ALIASES`` such as the brief's Snake, and the ``LENIENT_ACCEPTS`` readings of its label),
descriptions refused (exit 2), sensor precision and recall (kinds with counts), and
motion-control precision and recall (robots whose ``motion_control_kinds`` is empty are not
labelled for controls); then per set the per-label table, the structure confusion table, each
motion control's precision and recall and every miss.

Labels that name no structure of the profile are scored against the article's fallback: a
``Surface vessel`` or ``Underwater vehicle`` is right as ``Other`` until the profile has a
structure of that name. A standalone gripper read as ``Gripper`` counts for the label ``Hand``.

With ``--split`` (``tools/identification_split.csv`` by default, or a file named after it: the
split's list, made by ``tools/split_identification.py`` with a fixed seed) the rows of every set
are measured by the part the split gives them, ``development`` and ``held-out``, side by side in
place of the sets; a row the split does not list is measured as ``unsplit``. With ``--all``,
``tools/generalization_set`` and every ``tools/fresh_set_N`` folder are measured too. A fresh
set is built blind, to measure the rules once, then moved to the development part (the split
lists its rows as ``development``: ``tools/fresh_set_1``, ``tools/fresh_set_2``,
``tools/fresh_set_3``, ``tools/fresh_set_4``, ``tools/fresh_set_5``, ``tools/fresh_set_6``,
``tools/fresh_set_7``, ``tools/fresh_set_8``, ``tools/fresh_set_9``, ``tools/fresh_set_10``,
``tools/fresh_set_11``, ``tools/fresh_set_12``, ``tools/fresh_set_13``, ``tools/fresh_set_14``,
``tools/fresh_set_15`` .. ``tools/fresh_set_26``, their READMEs). The
*blind* sets are the ``fresh_set_N`` among the sets measured whose name the split does not
list at all (``split_identification.BLIND_NEXT`` and the ones built beside it, two or more at
a time): their rows are held out whole by their set, and count in ``held-out`` and again on a
line of their own, ``held-out (fresh)``, their misses counted and not listed. Moving a set to
development is listing it in the split.

With ``--no-names`` each URDF is read with every link and joint renamed to a neutral id
(``l0``, ``j0``, ... wherever the name is written: the tree, mimic joints, transmissions, Gazebo
references and plugin parameters) and the robot named ``robot``, and without its SRDF (which
names groups by them): what identification reads from what the joints do and what the plugins
and sensors are, with no word of a part's name (a CAD export's ``Revolute_3``, a team's own
language). A sensor's or a plugin's name that is also a link's or a joint's is renamed with it;
plugin files and everything else stay.

The sets are read in place and never copied. A set with no truth.csv is reported and skipped.
"""

from __future__ import annotations

import argparse
import csv
import re
import sys
import tempfile
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from solver.core.rules import default_rules_path, load_rules
from solver.errors import SolverError
from solver.identify import Identification, identify, load_profile
from solver.identify.readers.safexml import read_xml
from solver.identify.readers.workspace import description_package

ROOT = Path(__file__).resolve().parent.parent
# The labels' families, sources and the shared folder are the split's (one definition).
sys.path.insert(0, str(Path(__file__).resolve().parent))
from split_identification import (  # noqa: E402
    family_of,
    shared_folder,
    source_of,
)

OWN_SET = ROOT / "tools" / "identification_set"
ADDED_SET = ROOT / "tools" / "generalization_set"
TOOLS = ROOT / "tools"
# A fresh set's folder name: fresh_set_N (one the split does not list is blind).
FRESH_NAME = re.compile(r"fresh_set_([0-9]+)")
# The part the rows of the blind fresh sets are also reported in, within the held-out part.
FRESH_PART = "held-out (fresh)"
PART_ORDER = ("development", "held-out", FRESH_PART, "unsplit")
SPLIT = ROOT / "tools" / "identification_split.csv"
# Truth labels spelled differently from the profile's structure names.
ALIASES = {
    "mm": "Mobile Manipulator",  # the corpus README's short name for it
    "biped/lower-body": "Biped",
    "legged mobile manipulator": "Legged Mobile Manipulator",
    "aerial manipulator": "Aerial Manipulator",
    # The labelling brief's word for a snake robot (tools/labelling_brief.md), the kinematic
    # type the rule set gives its Serpentine structure.
    "snake": "Serpentine",
}
# Labels with no structure of their own in the article: the reading they are scored against
# while the profile has no structure of that name.
FALLBACKS = {"surface vessel": "Other", "underwater vehicle": "Other"}
# Readings a truth label also accepts: the corpus labels standalone grippers Hand (its README:
# "the README has no gripper label, Hand is the nearest extra label").
ACCEPTS = {"Hand": {"Gripper"}}
# Readings an uncertain label (ending in ``?``) also accepts, in the lenient score only: the
# sets have no pan/tilt label and label a pan/tilt unit alone ``Manipulator?``, the kinematic
# type the profile maps the structure to. A certain Manipulator read so is a miss.
LENIENT_ACCEPTS = {"Manipulator": {"Pan/Tilt Unit"}}


def label_of(text: str, structures: tuple[str, ...]) -> str:
    clean = text.strip().rstrip("?").strip()
    lowered = clean.casefold()
    if lowered in ALIASES:
        return ALIASES[lowered]
    named = next((s for s in structures if s.casefold() == lowered), None)
    return named or FALLBACKS.get(lowered, clean)


def parse_counts(text: str) -> Counter[str]:
    counts: Counter[str] = Counter()
    for item in filter(None, (part.strip() for part in text.split(";"))):
        kind, _, number = item.partition(":")
        counts[kind.strip()] += int(number or 1)
    return counts


def read_split(path: Path) -> dict[tuple[str, str], str]:
    """(set folder name, robot) -> part, from a split file (its ``#`` lines are its method)."""
    with path.open(encoding="utf-8", newline="") as stream:
        rows = csv.DictReader(line for line in stream if not line.startswith("#"))
        return {(row["set"], row["robot"]): row["part"] for row in rows}


def share(part: int, whole: int) -> str:
    return f"{part}/{whole} ({100 * part / whole:.0f}%)" if whole else "-"


def named_structures(note: str, structures: Sequence[str]) -> set[str]:
    """The structures ``note`` (case-folded) names, each by its words as words (a plural too,
    joined by spaces, hyphens, underscores or a slash: an ``aerial-manipulator``, ``UGVs``; no
    ``hand`` in ``handheld``, no ``other`` in ``another``), a longer name first and then out of
    the way, so that a note naming an Aerial Manipulator or a Mobile Manipulator names no
    Manipulator by it."""
    named: set[str] = set()
    for structure in sorted(structures, key=len, reverse=True):
        words = re.split(r"[\s/]+", structure.casefold())
        pattern = re.compile(
            r"(?<![a-z0-9])" + r"[\s_/-]+".join(map(re.escape, words)) + r"s?(?![a-z0-9])"
        )
        if pattern.search(note):
            named.add(structure)
            note = pattern.sub(" ", note)
    return named


@dataclass
class Score:
    """Running totals over some rows of a set, and the misses with their reasons."""

    structures: tuple[str, ...]
    robots: int = 0
    absent: int = 0
    strict: int = 0
    lenient: int = 0
    certain: int = 0
    certain_right: int = 0
    refused: int = 0
    warned: int = 0
    sensor_exact: int = 0
    kind_hits: int = 0
    kind_predicted: int = 0
    kind_truth: int = 0
    control_robots: int = 0
    control_exact: int = 0
    control_hits: int = 0
    control_predicted: int = 0
    control_truth: int = 0
    # Per motion control: (control, "hit" | "predicted" | "truth") -> robots.
    per_control: Counter[tuple[str, str]] = field(default_factory=Counter)
    per_label: Counter[tuple[str, bool]] = field(default_factory=Counter)
    confusion: Counter[tuple[str, str]] = field(default_factory=Counter)
    misses: list[str] = field(default_factory=list)
    # Misses of the blind set's rows, counted but not listed (see ``measure``).
    withheld: int = 0

    def keep_blind(self, since: int) -> None:
        """Withhold the misses listed since ``since``: they are a blind row's."""
        self.withheld += len(self.misses) - since
        del self.misses[since:]

    def add(self, row: dict[str, str], result: Identification) -> None:
        self.robots += 1
        self.structure(row, result)
        self.sensors(row, result)
        self.controls(row, result)

    def miss_file(self, row: dict[str, str], path: Path) -> None:
        self.absent += 1
        self.misses.append(f"{row['robot']}: absent ({path.name}; fetch recipe in `source`)")

    def refuse(self, row: dict[str, str], error: SolverError) -> None:
        self.robots += 1
        self.refused += 1
        message = " ".join(str(error).split())
        self.misses.append(f"{row['robot']}: not identified (exit 2): {message}")
        self.confusion[(row["kinematic_type"], "(exit 2)")] += 1
        if not row["kinematic_type"].endswith("?"):
            self.certain += 1
            self.per_label[(row["kinematic_type"], False)] += 1

    def structure(self, row: dict[str, str], result: Identification) -> None:
        label = label_of(row["kinematic_type"], self.structures)
        self.confusion[(row["kinematic_type"], result.structure)] += 1
        self.warned += bool(result.warnings)
        right = result.structure == label or result.structure in ACCEPTS.get(label, set())
        if not row["kinematic_type"].endswith("?"):
            self.certain += 1
            self.certain_right += right
            self.per_label[(row["kinematic_type"], right)] += 1
        note = row.get("uncertainty_note", "").casefold()
        alternatives = {label, *ACCEPTS.get(label, set())}
        if row["kinematic_type"].endswith("?"):
            alternatives |= named_structures(note, self.structures)
            alternatives |= {
                s for a, s in ALIASES.items() if re.search(rf"\b{re.escape(a)}\b", note)
            }
            alternatives |= LENIENT_ACCEPTS.get(label, set())
        self.strict += right
        self.lenient += result.structure in alternatives
        if not right:
            self.misses.append(
                f"{row['robot']}: structure {result.structure}, labelled {row['kinematic_type']}"
            )

    def sensors(self, row: dict[str, str], result: Identification) -> None:
        found: Counter[str] = Counter()
        for sensor in result.sensors:
            found[sensor.kind] += sensor.count
        expected = parse_counts(row["sensors"])
        self.sensor_exact += +found == +expected
        self.kind_hits += sum((found & expected).values())
        self.kind_predicted += sum(found.values())
        self.kind_truth += sum(expected.values())
        if +found != +expected:
            self.misses.append(
                f"{row['robot']}: sensors {dict(sorted(found.items()))}, "
                f"labelled {dict(sorted(expected.items()))}"
            )

    def controls(self, row: dict[str, str], result: Identification) -> None:
        labelled = {c.strip() for c in row["motion_control_kinds"].split(";") if c.strip()}
        if not labelled:
            return
        got = {c.motion_control for c in result.motion_controls}
        self.control_robots += 1
        self.control_exact += got == labelled
        self.control_hits += len(got & labelled)
        self.control_predicted += len(got)
        self.control_truth += len(labelled)
        for control in got & labelled:
            self.per_control[(control, "hit")] += 1
        for control in got:
            self.per_control[(control, "predicted")] += 1
        for control in labelled:
            self.per_control[(control, "truth")] += 1
        if got != labelled:
            missing = ", ".join(sorted(labelled - got)) or "-"
            extra = ", ".join(sorted(got - labelled)) or "-"
            self.misses.append(f"{row['robot']}: motion controls missing {missing}; extra {extra}")

    def summary(self) -> list[str]:
        """One table row: robots, certain-label accuracy, lenient, exit 2, absent, P/R."""
        return [
            str(self.robots),
            share(self.certain_right, self.certain),
            share(self.lenient, self.robots),
            str(self.refused),
            str(self.absent),
            share(self.kind_hits, self.kind_predicted),
            share(self.kind_hits, self.kind_truth),
            share(self.control_hits, self.control_predicted),
            share(self.control_hits, self.control_truth),
        ]

    def per_label_table(self) -> list[str]:
        labels = sorted({label for label, _ in self.per_label})
        lines = ["| certain label | right | robots |", "|---|---:|---:|"]
        for label in labels:
            right = self.per_label[(label, True)]
            lines.append(f"| {label} | {right} | {right + self.per_label[(label, False)]} |")
        return lines

    def per_control_table(self) -> list[str]:
        """Precision and recall of each motion control, on the robots labelled for controls."""
        controls = sorted({control for control, _ in self.per_control})
        lines = ["| motion control | precision | recall |", "|---|---:|---:|"]
        for control in controls:
            hits = self.per_control[(control, "hit")]
            predicted = share(hits, self.per_control[(control, "predicted")])
            lines.append(
                f"| {control} | {predicted} | {share(hits, self.per_control[(control, 'truth')])} |"
            )
        return lines

    def report(self) -> str:
        lines = ["Structure confusion (rows: label in truth.csv, columns: `structure` read):", ""]
        labels = sorted({t for t, _ in self.confusion})
        readings = sorted({r for _, r in self.confusion})
        lines.append("| label | " + " | ".join(readings) + " |")
        lines.append("|---|" + "---:|" * len(readings))
        for truth in labels:
            cells = [str(self.confusion[(truth, r)] or "") for r in readings]
            lines.append(f"| {truth} | " + " | ".join(cells) + " |")
        lines += [
            "",
            f"structure correct: {self.strict}/{self.robots} strict, {self.lenient}/"
            f"{self.robots} lenient ('?' labels also accept a structure their note names)",
            f"sensor kinds and counts exactly right: {self.sensor_exact}/{self.robots} robots; "
            f"per sensor: {self.kind_hits} of {self.kind_truth} labelled found, "
            f"{self.kind_hits} of {self.kind_predicted} reported correct",
            f"motion controls (description and SRDF only, {self.control_robots} robots "
            f"labelled): exact {self.control_exact}/{self.control_robots}; recall "
            f"{self.control_hits}/{self.control_truth}, precision "
            f"{self.control_hits}/{self.control_predicted}",
            "",
        ]
        if self.per_control:
            lines += [*self.per_control_table(), ""]
        lines += ["Misses:", ""]
        lines += [f"- {miss}" for miss in self.misses or ["(none)"]]
        if self.withheld:
            lines.append(
                f"- ({self.withheld} misses of the blind set withheld: --read-blind lists them, "
                "and reading them makes it development data)"
            )
        return "\n".join(lines) + "\n"


@dataclass
class Measured:
    """One labelled set, measured: the whole set and its rows grouped by family and source."""

    name: str
    truth: Path
    rows: int
    whole: Score
    families: dict[str, Score]
    sources: dict[str, Score]


# (urdf, srdf, (set, robot)) -> the identification of one row.
Runner = Callable[[Path, "Path | None", tuple[str, str]], Identification]


# The attributes that name a link or a joint (the tree, mimic, transmissions, Gazebo references).
_NAMING = ("name", "link", "joint", "reference")
_NUMBER = re.compile(r"[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?")


def without_names(urdf: Path) -> bytes:
    """The URDF with every link renamed ``l<i>`` and every joint ``j<i>`` (document order),
    wherever a ``name``, ``link``, ``joint`` or ``reference`` attribute or an element's whole
    text is such a name (not a number: a link named ``0`` leaves a ``<lower>0</lower>`` as it
    is), and the robot ``robot``. A file that cannot be read is returned as it is (its refusal
    is the measurement's)."""
    try:
        root = read_xml(urdf)
    except SolverError:
        return urdf.read_bytes()
    names: dict[str, str] = {}
    for kind, prefix in (("link", "l"), ("joint", "j")):
        found = dict.fromkeys(e.get("name") for e in root.findall(kind))
        names |= {name: f"{prefix}{i}" for i, name in enumerate(found) if name is not None}
    for name in [name for name in names if _NUMBER.fullmatch(name)]:
        del names[name]  # kept: a number is no word, and such text is mostly a quantity
    for element in root.iter():
        for key in _NAMING:
            value = element.get(key)
            if value is not None and value in names:
                element.set(key, names[value])
        if element.text is not None and element.text.strip() in names:
            element.text = names[element.text.strip()]
    root.set("name", "robot")
    return etree.tostring(root)


def locate(relative: str, folders: Iterable[Path]) -> Path:
    """The first folder holding `relative`; the first candidate when none does."""
    candidates = [folder / relative for folder in folders]
    return next((path for path in candidates if path.is_file()), candidates[0])


def shared_names(folders: Iterable[Path]) -> frozenset[str]:
    """File names (``file`` and ``srdf``) that more than one of the sets in ``folders`` lists:
    two sets may label different robots under one name (``urdf/sjtu_drone.urdf``)."""
    seen: dict[str, int] = {}
    for folder in folders:
        truth = folder / "truth.csv"
        if not truth.is_file():
            continue
        with truth.open(encoding="utf-8", newline="") as stream:
            rows = list(csv.DictReader(line for line in stream if not line.startswith("#")))
        for name in {row.get(key) or "" for row in rows for key in ("file", "srdf")} - {""}:
            seen[name] = seen.get(name, 0) + 1
    return frozenset(name for name, count in seen.items() if count > 1)


def lookup_folders(
    folder: Path, rows: list[dict[str, str]], extra_files: list[Path], shared: frozenset[str]
) -> tuple[list[Path], list[Path]]:
    """Where a set's files are looked up: every folder (its own, each ``--files`` folder, then
    ``../shared/<set>``), and for a name another set lists too (``shared``) only its own
    folder, its home among the ``--files`` folders (the one holding most of its other files;
    none when none does) and ``../shared/<set>``, so that no row is measured on another set's
    file."""
    last = shared_folder() / folder.name
    names = [row.get(key) or "" for row in rows for key in ("file", "srdf") if row.get(key) or ""]
    own = [name for name in names if name not in shared]
    held = [sum(1 for name in own if (extra / name).is_file()) for extra in extra_files]
    home = [extra_files[held.index(max(held))]] if held and max(held) > 0 else []
    return [folder, *extra_files, last], [folder, *home, last]


def fresh_number(name: str) -> int | None:
    """N of a folder named ``fresh_set_N``; None for any other name."""
    found = FRESH_NAME.fullmatch(name)
    return int(found.group(1)) if found else None


def fresh_sets(tools: Path = TOOLS) -> list[Path]:
    """The ``fresh_set_N`` folders under ``tools``, by N."""
    found = [(fresh_number(path.name), path) for path in tools.iterdir() if path.is_dir()]
    return [path for number, path in sorted((n, p) for n, p in found if n is not None)]


def blind_sets(names: Iterable[str], split: dict[tuple[str, str], str]) -> frozenset[str]:
    """The blind sets among ``names``: every ``fresh_set_N`` the split lists no row of (a fresh
    set moves to development by being listed; sets are built two or more at a time)."""
    listed = {set_name for set_name, _ in split}
    return frozenset(
        name for name in names if fresh_number(name) is not None and name not in listed
    )


def parts_of(
    set_name: str,
    robot: str,
    split: dict[tuple[str, str], str],
    blind: frozenset[str] = frozenset(),
) -> list[str]:
    """The parts a row is measured in: its part in the split (``unsplit`` when it lists none);
    a row of a blind set is held out by its set, and reported in the fresh part too."""
    if set_name in blind:
        return ["held-out", FRESH_PART]
    return [split.get((set_name, robot), "unsplit")]


@dataclass(frozen=True)
class Kept:
    """Where a row's repository was kept: the ``workspace``, the description's ``package`` in
    it (None: in no package, the workspace is read as its repository) and the description's
    file ``name`` there (what a repository's scripts name it by)."""

    workspace: Path
    package: Path | None
    name: str


def read_workspaces(path: Path) -> dict[tuple[str, str], Kept]:
    """(set, robot) -> where its repository was kept, from a --workspaces file."""
    found: dict[tuple[str, str], Kept] = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        fields = line.split("\t")
        if len(fields) == 4 and not line.startswith("#"):
            set_name, robot, workspace, inside = fields
            package = description_package(Path(workspace) / inside)
            found[(set_name, robot)] = Kept(Path(workspace), package, Path(inside).name)
    return found


def measure(
    name: str,
    folder: Path,
    extra_files: list[Path],
    structures: tuple[str, ...],
    run: Runner,
    *,
    split: dict[tuple[str, str], str] | None = None,
    parts: dict[str, Measured] | None = None,
    blind: frozenset[str] = frozenset(),
    shared: frozenset[str] = frozenset(),
    read_blind: bool = False,
) -> Measured | None:
    """Measure one set; with ``split``, each row into the Measured of its part in ``parts``
    (the rows of the sets named in ``blind`` held out whole, see ``parts_of``). A file name in
    ``shared`` (listed by another set too) is looked up only where this set keeps its files
    (``lookup_folders``). A blind set's misses are counted, not listed, unless
    ``read_blind``."""
    truth = folder / "truth.csv"
    if not truth.is_file():
        return None
    with truth.open(encoding="utf-8", newline="") as stream:
        rows = list(csv.DictReader(line for line in stream if not line.startswith("#")))
    folders, narrow = lookup_folders(folder, rows, extra_files, shared)
    own = Measured(name, truth, len(rows), Score(structures), {}, {})
    for row in rows:
        targets = [own]
        if split is not None and parts is not None:
            targets = [
                parts.setdefault(part, Measured(part, truth, 0, Score(structures), {}, {}))
                for part in parts_of(folder.name, row["robot"], split, blind)
            ]
            for measured in targets:
                measured.rows += 1
        scores: list[Score] = []
        for measured in targets:
            scores += [
                measured.whole,
                measured.families.setdefault(family_of(row), Score(structures)),
                measured.sources.setdefault(source_of(row), Score(structures)),
            ]
        hidden = name in blind and not read_blind
        since = [len(score.misses) for score in scores]
        urdf = locate(row["file"], narrow if row["file"] in shared else folders)
        srdf_name = row.get("srdf") or ""
        srdf = locate(srdf_name, narrow if srdf_name in shared else folders) if srdf_name else None
        if not urdf.is_file() or (srdf is not None and not srdf.is_file()):
            for score in scores:
                score.miss_file(row, urdf if not urdf.is_file() else srdf or urdf)
            _withhold(scores, since, hidden)
            continue
        try:
            result = run(urdf, srdf, (name, row["robot"]))
        except SolverError as error:
            for score in scores:
                score.refuse(row, error)
            _withhold(scores, since, hidden)
            continue
        for score in scores:
            score.add(row, result)
        _withhold(scores, since, hidden)
    return own


def _withhold(scores: list[Score], since: list[int], hidden: bool) -> None:
    if hidden:
        for score, start in zip(scores, since, strict=True):
            score.keep_blind(start)


HEADER = (
    "| {group} | set | robots | structure right (certain labels) | lenient (all labels) | "
    "exit 2 | absent | sensor precision | sensor recall | control precision | control recall |"
)
RULE = "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"


def side_by_side(
    group: str, sets: list[Measured], pick: Callable[[Measured], dict[str, Score]]
) -> list[str]:
    """Rows of every set for each group value, the sets of one value next to each other."""
    keys = sorted({key for measured in sets for key in pick(measured)}, key=str.casefold)
    lines = [HEADER.format(group=group), RULE]
    for key in keys:
        for measured in sets:
            score = pick(measured).get(key)
            if score is not None:
                lines.append(f"| {key} | {measured.name} | " + " | ".join(score.summary()) + " |")
    for measured in sets:
        lines.append(
            f"| **all** | {measured.name} | " + " | ".join(measured.whole.summary()) + " |"
        )
    return lines


def parser() -> argparse.ArgumentParser:
    """The command line of this tool."""
    found = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    found.add_argument(
        "--set",
        dest="sets",
        type=Path,
        action="append",
        metavar="DIR",
        help="a labelled set (a folder with truth.csv); repeat for several "
        "(default: ../shared/corpus)",
    )
    found.add_argument(
        "--all", action="store_true", help="the shared corpus and tools/identification_set"
    )
    found.add_argument(
        "--files",
        type=Path,
        action="append",
        default=[],
        metavar="DIR",
        help="another folder holding the sets' urdf/ and srdf/ files",
    )
    found.add_argument(
        "--corpus", type=Path, help="the shared corpus folder (default: ../shared/corpus)"
    )
    found.add_argument(
        "--split",
        type=Path,
        nargs="?",
        const=SPLIT,
        metavar="SPLIT.csv",
        help="measure by the parts of a split (default file: tools/identification_split.csv): "
        "development and held-out side by side; with --all, tools/generalization_set and every "
        "tools/fresh_set_N (one the split does not list is blind: held out whole, also as "
        "a part of its own, held-out (fresh))",
    )
    found.add_argument(
        "--no-names",
        action="store_true",
        help="read each URDF with every link and joint renamed to a neutral id, without its "
        "SRDF: what identification reads with no word of a part's name",
    )
    found.add_argument(
        "--read-blind",
        action="store_true",
        help="list the blind sets' misses too (withheld by default: once read, a blind set "
        "measures nothing unseen and is moved to development)",
    )
    found.add_argument(
        "--workspaces",
        type=Path,
        metavar="WORKSPACES.tsv",
        help="where rows' repositories were kept: lines 'SET<TAB>ROBOT<TAB>WORKSPACE<TAB>PATH' "
        "(PATH: the row's description inside WORKSPACE); such a row's packages are read for "
        "the controls they ship (solver/identify/readers/workspace.py), as identify reads them "
        "around a description in its package; a description in no package is read with "
        "WORKSPACE as its repository, under its file name there",
    )
    found.add_argument(
        "--rebuilt",
        type=Path,
        metavar="OUT",
        help="the folder tools/rebuild_set_files.py made: each OUT/<set> as --files and "
        "OUT/workspaces.tsv as --workspaces",
    )
    found.add_argument(
        "--profile",
        type=Path,
        help="an identification profile to measure instead of the shipped one "
        "(a copy with a rule left out measures that rule)",
    )
    return found


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    corpus = args.corpus or shared_folder() / "corpus"
    folders: list[Path] = list(args.sets or [])
    if args.all:
        added = [ADDED_SET, *fresh_sets()]
        folders = [corpus, OWN_SET, *(added if args.split else []), *folders]
    elif not folders:
        folders = [corpus]
    profile = load_profile(args.profile)
    rules = load_rules(default_rules_path())

    if args.rebuilt is not None:
        args.files += sorted(path for path in args.rebuilt.iterdir() if (path / "urdf").is_dir())
        args.workspaces = args.workspaces or args.rebuilt / "workspaces.tsv"
    kept = read_workspaces(args.workspaces) if args.workspaces else {}

    def run(urdf: Path, srdf: Path | None, row: tuple[str, str]) -> Identification:
        if args.no_names:
            with tempfile.TemporaryDirectory() as folder:
                nameless = Path(folder) / urdf.name
                nameless.write_bytes(without_names(urdf))
                return identify(
                    nameless, rules=rules, profile=profile, look_beside=False, look_around=False
                )
        where = kept.get(row)
        if where is None or where.package is not None:
            return identify(
                urdf,
                srdf=srdf,
                rules=rules,
                profile=profile,
                look_beside=False,
                look_around=False,
                package=None if where is None else where.package,
                workspace=None if where is None else where.workspace,
            )
        # In no package: read with its repository, under the file name its scripts know it by
        # (a rebuilt xacro is URDF now).
        with tempfile.TemporaryDirectory() as folder:
            named = Path(folder) / f"{where.name.split('.', 1)[0]}.urdf"
            named.write_bytes(urdf.read_bytes())
            return identify(
                named,
                srdf=srdf,
                rules=rules,
                profile=profile,
                look_beside=False,
                look_around=False,
                workspace=where.workspace,
            )

    split = read_split(args.split) if args.split else None
    blind = blind_sets((f.name for f in folders), split) if split is not None else frozenset()
    parts: dict[str, Measured] = {}
    sets: list[Measured] = []
    shared = shared_names(folders)
    for folder in folders:
        measured = measure(
            folder.name,
            folder,
            args.files,
            profile.structure_names,
            run,
            split=split,
            parts=parts,
            blind=blind,
            shared=shared,
            read_blind=args.read_blind,
        )
        if measured is None:
            print(f"no labelled set at {folder} (truth.csv missing); nothing measured there\n")
        elif split is None:
            sets.append(measured)
        else:
            print(f"Set `{measured.name}`: {measured.rows} descriptions ({measured.truth})")
    if split is not None:
        sets = [parts[p] for p in PART_ORDER if p in parts]
        print(f"Split `{args.split.name}`: " + ", ".join(f"{m.name} {m.rows}" for m in sets))
    if not sets:
        return 0
    for measured in sets:
        if split is None:
            print(f"Set `{measured.name}`: {measured.rows} descriptions ({measured.truth})")
    print("\nPer family:\n")
    print("\n".join(side_by_side("family", sets, lambda m: m.families)))
    print("\nPer source:\n")
    print("\n".join(side_by_side("source", sets, lambda m: m.sources)))
    for measured in sets:
        print(f"\n## Set `{measured.name}`\n")
        print("\n".join(measured.whole.per_label_table()) + "\n")
        print(measured.whole.report(), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
