"""Printing a :class:`~solver.check.runner.Report`: text, parsable, JSON and SARIF 2.1.0.

* ``text``: one line per finding, ``file:line:col: [level] message (check-id)``, sorted by
  location, then a summary line (``2 files checked: 1 error, 0 warnings, 1 info``).
* ``parsable``: the same findings in the compiler form editors and CI problem matchers read,
  ``file:line:col: level: message [check-id]``, and nothing else.
* ``json``: the findings and the summary as data (the shape is in the README).
* ``sarif``: a SARIF 2.1.0 log for code-scanning tools; every check is a rule of the driver
  (id, short and full description, default level), ``info`` becomes SARIF's ``note``, and the
  constraints behind a conflict are ``relatedLocations``.

Output is deterministic: findings in location order, no timestamps, no absolute paths that
the user did not give.

Not here: running the checks (:mod:`solver.check.runner`).
"""

from __future__ import annotations

import re
from pathlib import Path, PurePosixPath
from typing import Any
from urllib.parse import quote

from solver import __version__
from solver.check.finding import LEVELS, Finding
from solver.check.registry import ALL_CHECKS
from solver.check.runner import Report
from solver.errors import Location
from solver.files.output import dumps
from solver.untrusted import shown

__all__ = ["FORMATS", "json_data", "render", "sarif_data", "sarif_text", "summary_line"]

FORMATS = ("text", "parsable", "json", "sarif")
SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
_SARIF_LEVELS = {"error": "error", "warning": "warning", "info": "note"}


def summary_line(report: Report) -> str:
    files = len(report.files)
    counts = report.counts
    parts = [
        f"{counts['error']} error{'' if counts['error'] == 1 else 's'}",
        f"{counts['warning']} warning{'' if counts['warning'] == 1 else 's'}",
        f"{counts['info']} info",
    ]
    return f"{files} file{'' if files == 1 else 's'} checked: {', '.join(parts)}"


def render(report: Report, format: str = "text") -> str:
    """The report in ``format`` (one of :data:`FORMATS`), ending with a newline."""
    if format == "text":
        return "".join(f"{finding}\n" for finding in report.findings) + summary_line(report) + "\n"
    if format == "parsable":
        # One line per finding, read by editors and CI: no name may start another.
        return "".join(
            f"{shown(f.location.file, limit=None)}:{f.line}:{f.column}: {f.level}: "
            f"{shown(f.message, limit=None)} [{f.check}]\n"
            for f in report.findings
        )
    if format == "json":
        return dumps(json_data(report))
    if format == "sarif":
        return dumps(sarif_data(report))
    raise ValueError(f"unknown format {format!r}; choose from {', '.join(FORMATS)}")


def _location_data(location: Location) -> dict[str, Any]:
    return {
        "file": location.file,
        "line": location.line or 1,
        "column": location.column or 1,
        "path": location.path,
    }


def _finding_data(finding: Finding) -> dict[str, Any]:
    return {
        **_location_data(finding.location),
        "level": finding.level,
        "check": finding.check,
        "message": finding.message,
        "related": [{**_location_data(r.location), "message": r.message} for r in finding.related],
    }


def json_data(report: Report) -> dict[str, Any]:
    """The JSON shape of ``teleop-ui check --format json``."""
    return {
        "files": list(report.files),
        "summary": {level: report.count(level) for level in LEVELS},
        "findings": [_finding_data(finding) for finding in report.findings],
    }


def _uri(file: str) -> str:
    path = Path(file)
    if path.is_absolute():
        return path.as_uri()
    return quote(str(PurePosixPath(*path.parts)), safe="/")


def _physical(location: Location) -> dict[str, Any]:
    return {
        "artifactLocation": {"uri": _uri(location.file)},
        "region": {"startLine": location.line or 1, "startColumn": location.column or 1},
    }


# In a SARIF plain-text message "[text](target)" is an embedded link (SARIF 2.1.0 section
# 3.11.6); a literal bracket must be written "\[" / "\]", and a backslash before a bracket
# doubled, or a name such as "[x](javascript:...)" from a rule file would become a link.
_SARIF_BRACKET = re.compile(r"(\\*)([\[\]])")


def sarif_text(text: str) -> str:
    """``text`` as a SARIF plain-text message: one line of printable characters (a viewer may
    be a terminal: :func:`~solver.untrusted.shown`), brackets escaped, so it holds no link."""
    return _SARIF_BRACKET.sub(lambda m: m.group(1) * 2 + "\\" + m.group(2), shown(text, limit=None))


def sarif_data(report: Report) -> dict[str, Any]:
    """A SARIF 2.1.0 log with one run: every check as a rule, every finding as a result."""
    index = {check.id: i for i, check in enumerate(ALL_CHECKS)}
    rules = [
        {
            "id": check.id,
            "shortDescription": {"text": check.summary},
            "fullDescription": {"text": check.description},
            "help": {"text": check.description},
            "defaultConfiguration": {"level": _SARIF_LEVELS[check.level]},
        }
        for check in ALL_CHECKS
    ]
    results = []
    for finding in report.findings:
        location: dict[str, Any] = {"physicalLocation": _physical(finding.location)}
        if finding.location.path:
            location["logicalLocations"] = [{"fullyQualifiedName": finding.location.path}]
        result: dict[str, Any] = {
            "ruleId": finding.check,
            "ruleIndex": index[finding.check],
            "level": _SARIF_LEVELS[finding.level],
            "message": {"text": sarif_text(finding.message)},
            "locations": [location],
        }
        if finding.related:
            result["relatedLocations"] = [
                {
                    "id": number,
                    "physicalLocation": _physical(related.location),
                    "message": {"text": sarif_text(related.message)},
                }
                for number, related in enumerate(finding.related, start=1)
            ]
        results.append(result)
    return {
        "$schema": SARIF_SCHEMA,
        "version": "2.1.0",
        "runs": [
            {
                "tool": {
                    "driver": {"name": "teleop-ui check", "version": __version__, "rules": rules}
                },
                "columnKind": "unicodeCodePoints",
                "artifacts": [{"location": {"uri": _uri(file)}} for file in report.files],
                "results": results,
            }
        ],
    }
