"""Pick few layouts of a folder that, together, hold every distinct panel of all of them.

usage: python cover.py LAYOUT_DIR ...

A panel is distinct by its type, title and topics (a team's 795 layouts have 45 distinct
panels; 7 layouts hold them all). The default configuration's layout comes first, then,
greedily, the layout holding most panels not yet held. Prints one path a line, to drive each
with ``drive.py``; a line to stderr per folder says how many of how many.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

Panel = tuple[str, str, tuple[str, ...]]


def panel(panel_id: str, config: dict[str, Any]) -> Panel:
    topics = [str(config[key]) for key in ("topicPath", "path", "topic") if key in config]
    topics += sorted(config.get("topics", {}))
    topics += [config.get("imageMode", {}).get("imageTopic", "")]
    topics += [series["value"] for series in config.get("paths", [])]
    kind = panel_id.split("!", maxsplit=1)[0]
    return kind, config.get("lichtblickPanelTitle", ""), tuple(topics)


def cover(folder: Path) -> list[Path]:
    files = sorted(folder.glob("*.json"))
    panels = {
        file: {panel(k, c) for k, c in json.loads(file.read_text())["configById"].items()}
        for file in files
    }
    chosen = [file for file in files if file.name.endswith("-default.json")]
    held = set().union(*(panels[file] for file in chosen))
    every = set().union(*panels.values())
    while held != every:
        best = max(files, key=lambda file: len(panels[file] - held))
        chosen.append(best)
        held |= panels[best]
    print(
        f"{folder}: {len(chosen)} of {len(files)} layouts hold its {len(every)} panels",
        file=sys.stderr,
    )
    return chosen


def main() -> None:
    for folder in sys.argv[1:]:
        for file in cover(Path(folder)):
            print(file)


if __name__ == "__main__":
    main()
