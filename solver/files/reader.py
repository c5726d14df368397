"""Typed access to a loaded YAML document that collects located faults instead of stopping.

The rule-set and team loaders validate a whole file and report every problem at once; this is
the small toolkit they share: "give me a mapping here", "a list of strings there", "which keys
are unknown", each recording a :class:`~solver.errors.Fault` on a mismatch and returning a
harmless placeholder so validation can continue.

Not here: the meaning of any key (see :mod:`solver.core.rules` and :mod:`solver.core.team`).
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from typing import Any

from solver.errors import Fault, TooLargeError, did_you_mean
from solver.files.yamlio import Document, PathPart
from solver.limits import Limit
from solver.untrusted import shown

__all__ = ["MAX_NAME_CHARS", "Reader", "type_name"]

# Names and labels (of a team, a characteristic, a value, a component, a constraint) are at
# most this long: they end up in tables, charts and file names. docs/security.md says so.
MAX_NAME_CHARS = 200
Path = tuple[PathPart, ...]


def type_name(value: Any) -> str:
    """How a YAML user would call the type of ``value``."""
    if value is None:
        return "nothing (null)"
    if isinstance(value, bool):
        return f"a boolean ({str(value).lower()})"
    if isinstance(value, int | float):
        return f"a number ({value})"
    if isinstance(value, str):
        return f"a string ({shown(value, quoted=True)})"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a mapping"
    return type(value).__name__


class Reader:
    """Reads one document, remembering every fault it finds."""

    def __init__(self, document: Document) -> None:
        self.document = document
        self.faults: list[Fault] = []

    @property
    def file(self) -> str:
        return self.document.file

    def fault(
        self, path: Sequence[PathPart], message: str, *, key: bool = False, code: str = "invalid"
    ) -> None:
        location = self.document.location(path, key=key)
        self.faults.append(Fault(location, message, code))

    def within(
        self,
        limit: Limit,
        size: int,
        path: Sequence[PathPart],
        *,
        key: bool = False,
        noun: str | None = None,
    ) -> None:
        """Refuse the whole file at once (:class:`~solver.errors.TooLargeError`, located at
        ``path``) when ``size`` is over ``limit``: nothing past it is read or built."""
        if limit.exceeded(size):
            location = self.document.location(path, key=key)
            raise TooLargeError(limit.fault(location, size, noun=noun))

    def get(self, path: Sequence[PathPart]) -> Any:
        """The raw value at ``path`` (``None`` when absent)."""
        value: Any = self.document.data
        for part in path:
            if isinstance(part, int):
                if not isinstance(value, list) or part >= len(value):
                    return None
            elif not isinstance(value, dict):
                return None
            value = value[part] if isinstance(part, int) else _lookup(value, part)
        return value

    def top(self, what: str, *, needs: str | None = None) -> dict[str, Any] | None:
        """The document's top-level mapping, or ``None`` after a fault (empty file, a list...).

        ``needs``: a field without which the file is not a ``what`` at all. Such a file (and
        one that is no mapping) may be anything, ``/etc/passwd`` say: its fault names the
        file and the problem and quotes nothing of it.
        """
        data = self.document.data
        a_what = f"{'an' if what[:1] in 'aeiou' else 'a'} {what}"
        if data is None:
            self.fault((), f"the file is empty; expected {a_what}", code="missing-field")
            return None
        if not isinstance(data, dict):
            kind = "a list" if isinstance(data, list) else "a single value"
            self.fault(
                (),
                f"not {a_what}: expected a mapping of fields at the top level, got {kind}",
                code="wrong-type",
            )
            return None
        if needs is not None and not any(str(key) == needs for key in data):
            self.fault((), f"not {a_what}: it has no '{needs}:' field", code="missing-field")
            return None
        return {str(key): item for key, item in data.items()}

    def mapping(self, path: Path, what: str, *, required: bool = True) -> dict[str, Any]:
        """The mapping at ``path``; its keys converted to strings."""
        value = self.get(path)
        if value is None:
            if required:
                self.missing(path, what)
            return {}
        if not isinstance(value, dict):
            self.fault(path, f"{what} must be a mapping, got {type_name(value)}", code="wrong-type")
            return {}
        return {str(key): item for key, item in value.items()}

    def missing(self, path: Path, what: str) -> None:
        self.fault(path, f"missing {what}", code="missing-field")

    def string(
        self,
        path: Path,
        what: str,
        *,
        required: bool = True,
        default: str = "",
        limit: int | None = MAX_NAME_CHARS,
    ) -> str:
        """A string (a name unless ``limit`` says otherwise: ``None`` for free text, which the
        YAML reader already bounds)."""
        value = self.get(path)
        if value is None:
            if required:
                self.missing(path, what)
            return default
        if isinstance(value, bool) or not isinstance(value, str | int | float):
            self.fault(path, f"{what} must be a string, got {type_name(value)}", code="wrong-type")
            return default
        text = str(value).strip()
        if required and not text:
            self.fault(path, f"{what} must not be empty", code="wrong-type")
        if limit is not None and len(text) > limit:
            self.fault(path, f"{what} is longer than {limit} characters", code="too-large")
            return default
        return text

    def integer(self, path: Path, what: str, *, required: bool = True) -> int | None:
        value = self.get(path)
        if value is None:
            if required:
                self.missing(path, what)
            return None
        if isinstance(value, bool) or not isinstance(value, int):
            self.fault(
                path, f"{what} must be a whole number, got {type_name(value)}", code="wrong-type"
            )
            return None
        return value

    def names(self, path: Path, what: str) -> list[tuple[Path, str]]:
        """A list of strings (or one string), each with its own path."""
        value = self.get(path)
        if value is None:
            self.missing(path, what)
            return []
        if isinstance(value, str | int) and not isinstance(value, bool):
            if len(str(value)) > MAX_NAME_CHARS:
                self.fault(
                    path,
                    f"{what}: a name longer than {MAX_NAME_CHARS} characters",
                    code="too-large",
                )
                return []
            return [(path, str(value))]
        if not isinstance(value, list):
            self.fault(
                path, f"{what} must be a list of names, got {type_name(value)}", code="wrong-type"
            )
            return []
        found: list[tuple[Path, str]] = []
        for index, item in enumerate(value):
            item_path = (*path, index)
            if isinstance(item, bool) or not isinstance(item, str | int | float):
                self.fault(
                    item_path, f"{what} must be names, got {type_name(item)}", code="wrong-type"
                )
                continue
            name = str(item).strip()
            if len(name) > MAX_NAME_CHARS:
                self.fault(
                    item_path,
                    f"{what}: a name longer than {MAX_NAME_CHARS} characters",
                    code="too-large",
                )
                continue
            found.append((item_path, name))
        return found

    def unknown_keys(
        self, path: Path, mapping: dict[str, Any], allowed: Collection[str], what: str
    ) -> None:
        """A fault for every key of ``mapping`` that is not in ``allowed``."""
        for key in mapping:
            if key not in allowed:
                hint = did_you_mean(key, allowed)
                self.fault(
                    (*path, key),
                    f"unknown {what} {shown(key, quoted=True)}{hint}; "
                    f"allowed: {', '.join(sorted(allowed))}",
                    key=True,
                    code="unknown-field",
                )


def _lookup(mapping: dict[Any, Any], key: str) -> Any:
    if key in mapping:
        return mapping[key]
    for candidate, value in mapping.items():
        if str(candidate) == key:
            return value
    return None
