"""Every size a command accepts, in one table: the limit, who obeys it, and the refusal.

An input sized to stall (a team of 5,000 kinematic types on a chart, 200 topic lists, a rule
set whose layouts are 50,000 files) is refused before the work starts, with a message that
names where the size comes from, the size, the limit and this table's name for it::

    rules.yaml:3:1: characteristics: 1001 characteristics; at most 1000 are accepted (limit
    'characteristics', docs/security.md)

Below each limit, every command ends within seconds (``benchmarks/`` measures the edges).
docs/security.md shows this table; a test keeps the two in step. The ``-seconds`` entries are
time budgets of work that sizes do not bound: a call stops when its budget is spent
(:mod:`solver.deadline`), not before it starts.

Not here: the bounds of the file reader (bytes per file, YAML values and nesting, name
lengths: :mod:`solver.files`), of robot descriptions and bags (:mod:`solver.identify`) and of
the live graph (:mod:`solver.live`); docs/security.md lists those beside these.
"""

from __future__ import annotations

from dataclasses import dataclass

from solver.errors import Fault, Location, TooLargeError

__all__ = ["LIMITS", "Limit", "limit", "readable", "table"]


@dataclass(frozen=True, slots=True)
class Limit:
    """One documented size limit.

    ``noun`` counts the thing (``"characteristics"``), ``where`` says what holds it (``"a rule
    set"``), ``commands`` who obey the limit.
    """

    name: str
    value: int
    noun: str
    where: str
    commands: str

    def message(self, size: int, *, noun: str | None = None, bound: bool = False) -> str:
        """``1200 characteristics; at most 1000 are accepted (limit 'characteristics', ...)``;
        ``bound``: ``size`` is an upper bound (``up to 1200 ...``)."""
        return (
            f"{'up to ' if bound else ''}{readable(size)} {noun or self.noun}; "
            f"at most {readable(self.value)} "
            f"are accepted (limit '{self.name}', docs/security.md)"
        )

    def exceeded(self, size: int) -> bool:
        return size > self.value

    def fault(
        self, location: Location, size: int, *, noun: str | None = None, bound: bool = False
    ) -> Fault:
        return Fault(location, self.message(size, noun=noun, bound=bound), "too-large")

    def check(
        self,
        size: int,
        file: str,
        *,
        line: int | None = None,
        column: int | None = None,
        path: str = "",
        noun: str | None = None,
    ) -> None:
        """Raise :class:`~solver.errors.TooLargeError` at that location when ``size`` is over."""
        if size > self.value:
            raise TooLargeError(self.fault(Location(file, line, column, path), size, noun=noun))


_RULES = "every command that reads a rule set"
_TEAMS = "every command that reads a team"
_SOLVING = (
    "every command that solves a team (solve, assign, robots, report, layouts, batch, watch, "
    "identify --team)"
)

LIMITS: tuple[Limit, ...] = (
    # Rule sets and teams, checked as they are read: what follows from a file is bounded here.
    Limit("characteristics", 1_000, "characteristics", "a rule set", _RULES),
    Limit("values", 100_000, "values", "one characteristic (a list or a range)", _RULES),
    Limit("all-values", 250_000, "values", "all characteristics of a rule set", _RULES),
    Limit("components", 20_000, "components", "all characteristics of a rule set", _RULES),
    Limit("constraints", 2_000, "constraints", "a rule set", _RULES),
    Limit(
        "condition-values",
        1_000_000,
        "values named by conditions",
        "all constraints of a rule set (a range counts its values)",
        _RULES,
    ),
    Limit("kinematic-types", 20_000, "kinematic types", "a team", _TEAMS),
    Limit(
        "conflicts",
        # The rule sets shipped and benchmarked need at most about 1,000 conflicts; a hostile
        # pigeonhole (16 characteristics, 1,800 constraints) spends this many in about 5 s CPU.
        50_000,
        "conflicts of the SAT search",
        "all questions about one rule set (live values, conflicts, redundancy)",
        "check, and solve's warnings about excluded selections",
    ),
    # Time budgets (solver.deadline): work that sizes do not bound, stopped when spent.
    Limit(
        "check-seconds",
        30,
        "seconds of checking",
        "one check run (--time-limit sets it)",
        "check",
    ),
    Limit(
        "symbolic-seconds",
        30,
        "seconds of building formulas",
        "one team (--time-limit sets it)",
        "count --symbolic",
    ),
    Limit(
        "cover-seconds",
        10,
        "seconds of proving a minimum cover (HiGHS)",
        "one cover of overlapping components",
        _SOLVING + ", count",
    ),
    # Solving: the engines refuse before enumerating.
    Limit(
        "robots",
        100_000_000,
        "robots to enumerate",
        "one kinematic type (--max-robots lowers or raises it)",
        _SOLVING,
    ),
    Limit(
        "csp-robots",
        100_000,
        "robots to enumerate with python-constraint",
        "one kinematic type (solve --engine csp)",
        "solve, count, robots with --engine csp",
    ),
    Limit(
        "fast-rows",
        5_000_000,
        "value-class combinations to enumerate",
        "one kinematic type (the fast engine's rows)",
        "solve, count, robots with --engine fast or auto",
    ),
    Limit(
        "configurations",
        500_000,
        "UI configurations to list",
        "a team (counting them has no limit: --count-only)",
        _SOLVING,
    ),
    # Charts and reports.
    Limit(
        "chart-types",
        100,
        "kinematic types to draw",
        "one chart or report",
        "solve --plot, report, batch --report",
    ),
    Limit(
        "chart-characteristics",
        100,
        "characteristics to draw",
        "one chart or report (a spoke or a column group each)",
        "solve --plot, report, batch --report",
    ),
    Limit(
        "chart-robots",
        10**300,
        "robots",
        "one kinematic type drawn (a bar's height is a float)",
        "solve --plot, report, batch --report",
    ),
    # Robot identification.
    Limit("topic-lists", 64, "topic lists", "one command (--topics)", "identify, layouts"),
    Limit(
        "topics",
        100_000,
        "topic lines",
        "all topic lists of one command",
        "identify, layouts",
    ),
    Limit("bags", 64, "bags", "one command (--bag)", "identify, layouts"),
    Limit(
        "description-entries",
        1_000,
        "motion controls and sensors",
        "a teleoperation description",
        "identify, check, watch, assign",
    ),
    Limit(
        "description-bytes",
        1_048_576,
        "characters",
        "a teleoperation description on a live graph (<ns>/teleop_description)",
        "watch, assign",
    ),
    # Many files at once.
    Limit("check-files", 1_000, "files", "one check run", "check"),
    Limit("batch-teams", 10_000, "team files", "one batch", "batch"),
    Limit("batch-jobs", 64, "worker processes", "one batch (--jobs)", "batch"),
    # What a command writes.
    Limit(
        "written-files",
        2_000,
        "files to write",
        "one command (a layout per UI configuration and the default's; watch --layouts: every "
        "layout it writes while it runs)",
        "layouts, watch --layouts",
    ),
    Limit(
        "written-bytes",
        256 * 1024 * 1024,
        "bytes to write",
        "the files one command writes together (batch: a team's JSON; its report with its "
        "charts; watch --layouts: every layout it writes while it runs)",
        "every command that writes files (layouts, report, batch, fleet -o, solve --plot, "
        "watch --layouts)",
    ),
)

_BY_NAME = {entry.name: entry for entry in LIMITS}


def limit(name: str) -> Limit:
    """The limit called ``name``; :class:`KeyError` for any other name."""
    return _BY_NAME[name]


def table() -> str:
    """The limits as the Markdown table docs/security.md shows (a test compares the two)."""
    rows = [
        "| limit | value | counts | in | obeyed by |",
        "| --- | ---: | --- | --- | --- |",
    ]
    rows += [
        f"| `{entry.name}` | {_shown(entry.value)} | {entry.noun} | {entry.where} | "
        f"{entry.commands} |"
        for entry in LIMITS
    ]
    return "\n".join(rows) + "\n"


def _shown(value: int) -> str:
    """``1,000,000``, or ``10^300`` for a number too long to read."""
    plain = readable(value)
    return plain if "^" in plain else f"{value:,}"


def readable(value: int) -> str:
    """A size in a message: ``1000000`` as it is; past 16 digits ``10^300`` for a power of
    ten, else its first digits (``about 1.37 x 10^2999``): a refusal stays one short line
    however large the input made the number."""
    text = str(value)
    if len(text) <= 16:
        return text
    if text == "1" + "0" * (len(text) - 1):
        return f"10^{len(text) - 1}"
    return f"about {text[0]}.{text[1:3]} x 10^{len(text) - 1}"
