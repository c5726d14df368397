"""Identification profiles that extend another: a few lines on top of the shipped profile.

A profile with ``extends: shipped`` (or ``extends: PATH`` to another profile, relative to the
file) is read on top of that one, so a user writes only what differs::

    extends: shipped
    structures:
      - {name: Quadruped, kinematic_types: [Legged Robot]}    # an existing structure's mapping
      - {name: Hexapod, when: {legs: 6}, kinematic_types: [Hexapod], confidence: 0.9}

How the two are put together (:func:`compose`):

* mappings merge key by key, at every depth (``characteristics``, ``patterns``, ``limbs``,
  ``sensor_types``, ``motion.velocity.by_structure``, ...): the extending file's value wins,
  the others stay;
* ``structures``: an entry named as a structure of the base changes that structure field by
  field and keeps its place; an entry with a new name is added *before* the base's structures
  (the first whose ``when`` holds wins, so a new, more specific body is tried first);
* the lists of rules (``sensors.elements``, ``sensors.plugins``, ``topics.sensors``,
  ``topics.controls``): the extending file's rules come first (first match wins), then the
  base's; ``topics.stream_segments`` gains the new segments;
* any other value (a list of names, a number, a pattern) is replaced whole;
* ``name`` and ``description`` are the extending file's own (its file name without one).

The result is validated as one profile, and every problem is located where the value was
written: in the extending file for what it says, in the base for what it kept
(:class:`ComposedDocument`). Chains (a profile extending one that extends the shipped one) are
followed up to :data:`MAX_CHAIN` files; a file extending itself, directly or not, is an error
at its ``extends``.

Not here: reading a profile (:mod:`solver.identify.profile`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Final

from solver.errors import Fault, InputError, Location, SolverError
from solver.files.reader import Reader
from solver.files.yamlio import Document, PathPart, load_document
from solver.untrusted import shown

__all__ = ["EXTENDS", "MAX_CHAIN", "SHIPPED", "ComposedDocument", "compose"]

EXTENDS: Final = "extends"
# ``extends: shipped`` names the profile installed with the package.
SHIPPED: Final = "shipped"
# At most this many profiles in one chain of ``extends``.
MAX_CHAIN: Final = 8

YPath = tuple[PathPart, ...]
# Lists whose entries are rules tried in order: the extending file's come first.
_RULE_LISTS: Final = {
    ("sensors", "elements"),
    ("sensors", "plugins"),
    ("sensors", "frames"),
    ("topics", "sensors"),
    ("topics", "controls"),
}
_UNION_LISTS: Final = {("topics", "stream_segments")}
_STRUCTURES: Final = ("structures",)
# What describes a file, not what it identifies: never inherited.
_OWN_KEYS: Final = {"name", "description", EXTENDS}


@dataclass(frozen=True)
class ComposedDocument(Document):
    """The merged data of a profile and the one it extends; each value is located in the file
    that wrote it (``origins``: a merged path -> the document and path it came from)."""

    origins: dict[YPath, tuple[Document, YPath]] = field(default_factory=dict, repr=False)

    def location(self, path: Sequence[PathPart] = (), *, key: bool = False) -> Location:
        path = tuple(path)
        prefix = path
        while prefix not in self.origins:
            if not prefix:
                return super().location(path, key=key)
            prefix = prefix[:-1]
        document, origin = self.origins[prefix]
        return document.location((*origin, *path[len(prefix) :]), key=key)


def compose(document: Document, *, shipped: Path, chain: tuple[str, ...] = ()) -> Document:
    """``document`` on top of the profile it ``extends`` (see the module docstring); the
    document itself when it extends nothing. :class:`InputError` located at ``extends`` when
    the base cannot be read, is the document itself, or the chain is too long."""
    data = document.data
    if not isinstance(data, dict) or EXTENDS not in data:
        return document
    base = _base(document, data[EXTENDS], shipped, chain)
    merger = _Merger(base, document)
    merged = merger.mapping(base.data if isinstance(base.data, dict) else {}, (), data, (), ())
    return ComposedDocument(document.file, merged, origins=merger.origins)


def _base(document: Document, value: Any, shipped: Path, chain: tuple[str, ...]) -> Document:
    where = document.location((EXTENDS,))
    if not isinstance(value, str) or not value.strip():
        raise InputError(
            Fault(
                where,
                f"extends names the profile this one adds to: '{SHIPPED}' or a file, "
                f"got {shown(str(value), quoted=True)}",
            )
        )
    text = value.strip()
    path = shipped if text == SHIPPED else Path(document.file).parent / Path(text).expanduser()
    identity = str(path.resolve())
    own = str(Path(document.file).resolve())
    if identity in (*chain, own) or len(chain) + 1 >= MAX_CHAIN:
        why = (
            f"more than {MAX_CHAIN} profiles extend one another"
            if identity not in (*chain, own)
            else "a profile cannot extend itself, directly or through others"
        )
        raise InputError(Fault(where, why))
    display = str(path) if text != SHIPPED else str(shipped)
    try:
        loaded = load_document(path, display=display)
    except SolverError as error:
        raise _unreadable(where, text, error.faults) from None
    base = compose(loaded, shipped=shipped, chain=(*chain, own))
    # A base that is no profile may be any file (/etc/shadow parses as a mapping of its lines):
    # none of its keys may reach a message as an unknown profile field.
    reader = Reader(base)
    if reader.top("identification profile", needs="characteristics") is None:
        raise _unreadable(where, text, reader.faults)
    return base


def _unreadable(where: Location, text: str, faults: Sequence[Fault]) -> InputError:
    reason = "; ".join(str(fault) for fault in faults[:3])
    message = f"cannot read the profile it extends ({shown(text, quoted=True)}): {reason}"
    return InputError(Fault(where, message))


class _Merger:
    """Builds the merged data, recording where each value came from."""

    def __init__(self, base: Document, over: Document) -> None:
        self.base = base
        self.over = over
        self.origins: dict[YPath, tuple[Document, YPath]] = {(): (over, ())}

    def value(self, base: Any, base_path: YPath, over: Any, over_path: YPath, at: YPath) -> Any:
        if isinstance(base, dict) and isinstance(over, dict):
            return self.mapping(base, base_path, over, over_path, at)
        if isinstance(base, list) and isinstance(over, list):
            if at == _STRUCTURES:
                return self.structures(base, base_path, over, over_path)
            if at in _RULE_LISTS:
                return self.concatenated(base, base_path, over, over_path, at)
            if at in _UNION_LISTS:
                return self.union(base, base_path, over, over_path, at)
        self.origins[at] = (self.over, over_path)
        return over

    def mapping(
        self,
        base: dict[Any, Any],
        base_path: YPath,
        over: dict[Any, Any],
        over_path: YPath,
        at: YPath,
    ) -> dict[Any, Any]:
        self.origins[at] = (self.over, over_path)
        merged: dict[Any, Any] = {}
        for key, item in base.items():
            if at == () and str(key) in _OWN_KEYS:
                continue
            if key in over:
                merged[key] = self.value(
                    item, (*base_path, key), over[key], (*over_path, key), (*at, key)
                )
            else:
                merged[key] = item
                self.origins[(*at, key)] = (self.base, (*base_path, key))
        for key, item in over.items():
            if key not in base and not (at == () and str(key) == EXTENDS):
                merged[key] = item
                self.origins[(*at, key)] = (self.over, (*over_path, key))
        return merged

    def structures(
        self, base: list[Any], base_path: YPath, over: list[Any], over_path: YPath
    ) -> list[Any]:
        names = {
            str(item["name"]): index
            for index, item in enumerate(base)
            if isinstance(item, dict) and "name" in item
        }
        changes: dict[int, int] = {}  # base index -> over index
        new: list[int] = []
        for index, item in enumerate(over):
            name = str(item.get("name")) if isinstance(item, dict) else None
            if name in names and names[name] not in changes:
                changes[names[name]] = index
            else:
                new.append(index)
        merged: list[Any] = []
        for index in new:
            self.origins[(*_STRUCTURES, len(merged))] = (self.over, (*over_path, index))
            merged.append(over[index])
        for index, item in enumerate(base):
            at = (*_STRUCTURES, len(merged))
            if index in changes:
                change = changes[index]
                merged.append(
                    self.value(item, (*base_path, index), over[change], (*over_path, change), at)
                )
            else:
                self.origins[at] = (self.base, (*base_path, index))
                merged.append(item)
        return merged

    def concatenated(
        self, base: list[Any], base_path: YPath, over: list[Any], over_path: YPath, at: YPath
    ) -> list[Any]:
        self.origins[at] = (self.over, over_path)
        for index in range(len(over)):
            self.origins[(*at, index)] = (self.over, (*over_path, index))
        for index in range(len(base)):
            self.origins[(*at, len(over) + index)] = (self.base, (*base_path, index))
        return [*over, *base]

    def union(
        self, base: list[Any], base_path: YPath, over: list[Any], over_path: YPath, at: YPath
    ) -> list[Any]:
        self.origins[at] = (self.over, over_path)
        merged = list(base)
        for index in range(len(base)):
            self.origins[(*at, index)] = (self.base, (*base_path, index))
        for index, item in enumerate(over):
            if item not in merged:
                self.origins[(*at, len(merged))] = (self.over, (*over_path, index))
                merged.append(item)
        return merged
