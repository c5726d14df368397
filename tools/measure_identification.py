"""Measure `teleop-ui identify` against the labelled corpus (../shared/corpus/truth.csv).

Usage::

    python tools/measure_identification.py [--corpus DIR]

Each corpus robot is identified from its URDF (and SRDF when it has one) with the shipped
profile and the article's rule set, exactly as ``teleop-ui identify`` would. Printed, as
Markdown, for the whole corpus and split by source (the original 31 ROS-repository robots, rows
1-31 of truth.csv, and the newer package sources, rows 32 on): structure accuracy on the
certain labels (no trailing ``?``) per label, the structure confusion table (truth label x
reading), the lenient score (a label ending in ``?`` also accepts a structure its
``uncertainty_note`` names), descriptions refused (exit 2), warnings, sensor precision and
recall, motion controls, and every miss.

The corpus is read in place and never copied. When it is absent the script says so and exits 0.
"""

from __future__ import annotations

import argparse
import csv
import sys
from collections import Counter
from pathlib import Path

from solver.errors import SolverError
from solver.identify import Identification, identify, load_profile
from solver.rules import default_rules_path, load_rules

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_CORPUS = ROOT.parent / "shared" / "corpus"
# Truth labels spelled differently from the profile's structure names.
ALIASES = {
    "biped/lower-body": "Biped",
    "legged mobile manipulator": "Legged Mobile Manipulator",
    "aerial manipulator": "Aerial Manipulator",
}
# Readings a truth label also accepts: the corpus labels standalone grippers Hand (its README:
# "the README has no gripper label, Hand is the nearest extra label").
ACCEPTS = {"Hand": {"Gripper"}}
# truth.csv rows (1-based, header excluded) from the original ROS repositories.
ORIGINAL_ROWS = 31


def label_of(text: str, structures: tuple[str, ...]) -> str:
    clean = text.strip().rstrip("?").strip()
    lowered = clean.casefold()
    if lowered in ALIASES:
        return ALIASES[lowered]
    return next((s for s in structures if s.casefold() == lowered), clean)


def parse_counts(text: str) -> Counter[str]:
    counts: Counter[str] = Counter()
    for item in filter(None, (part.strip() for part in text.split(";"))):
        kind, _, number = item.partition(":")
        counts[kind.strip()] += int(number or 1)
    return counts


class Score:
    """Running totals over the corpus, and the misses with their reasons."""

    def __init__(self, structures: tuple[str, ...]) -> None:
        self.structures = structures
        self.robots = self.strict = self.lenient = self.sensor_exact = 0
        self.certain = self.certain_right = self.refused = self.warned = 0
        self.per_label: Counter[tuple[str, bool]] = Counter()
        self.kind_hits = self.kind_predicted = self.kind_truth = 0
        self.control_robots = self.control_exact = 0
        self.control_hits = self.control_predicted = self.control_truth = 0
        self.confusion: Counter[tuple[str, str]] = Counter()
        self.misses: list[str] = []

    def add(self, row: dict[str, str], result: Identification) -> None:
        self.robots += 1
        self.structure(row, result)
        self.sensors(row, result)
        self.controls(row, result)

    def refuse(self, row: dict[str, str], error: SolverError) -> None:
        self.robots += 1
        self.refused += 1
        self.misses.append(f"{row['robot']}: not identified (exit 2): {error}")
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
            alternatives |= {s for s in self.structures if s.casefold() in note}
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
        if got != labelled:
            missing = ", ".join(sorted(labelled - got)) or "-"
            extra = ", ".join(sorted(got - labelled)) or "-"
            self.misses.append(f"{row['robot']}: motion controls missing {missing}; extra {extra}")

    def summary(self) -> list[str]:
        """One table row: robots, certain-label accuracy, lenient, exit 2, sensor P/R."""

        def share(part: int, whole: int) -> str:
            return f"{part}/{whole} ({100 * part / whole:.0f}%)" if whole else "-"

        return [
            share(self.certain_right, self.certain),
            share(self.lenient, self.robots),
            str(self.refused),
            str(self.warned),
            share(self.kind_hits, self.kind_predicted),
            share(self.kind_hits, self.kind_truth),
        ]

    def per_label_table(self) -> list[str]:
        labels = sorted({label for label, _ in self.per_label})
        lines = ["| certain label | right | robots |", "|---|---:|---:|"]
        for label in labels:
            right = self.per_label[(label, True)]
            lines.append(f"| {label} | {right} | {right + self.per_label[(label, False)]} |")
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
            "Misses:",
            "",
        ]
        lines += [f"- {miss}" for miss in self.misses or ["(none)"]]
        return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS)
    args = parser.parse_args(argv)
    truth_file = args.corpus / "truth.csv"
    if not truth_file.is_file():
        print(f"no corpus at {args.corpus} (truth.csv missing); nothing measured")
        return 0
    profile = load_profile()
    rules = load_rules(default_rules_path())
    with truth_file.open(encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    score = Score(profile.structure_names)
    parts = {
        "original (rows 1-31)": Score(profile.structure_names),
        f"newer (rows 32-{len(rows)})": Score(profile.structure_names),
    }
    for number, row in enumerate(rows, start=1):
        part = list(parts.values())[number > ORIGINAL_ROWS]
        srdf = args.corpus / row["srdf"] if row["srdf"] else None
        try:
            result = identify(args.corpus / row["file"], srdf=srdf, rules=rules, profile=profile)
        except SolverError as error:
            score.refuse(row, error)
            part.refuse(row, error)
            continue
        score.add(row, result)
        part.add(row, result)
    print(f"Corpus: {len(rows)} descriptions ({truth_file})\n")
    print(
        "| source | structure right (certain labels) | lenient (all labels) | exit 2 | "
        "with warnings | sensor precision | sensor recall |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, part in [*parts.items(), ("all", score)]:
        print(f"| {name} | " + " | ".join(part.summary()) + " |")
    print()
    print("\n".join(score.per_label_table()) + "\n")
    print(score.report(), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
