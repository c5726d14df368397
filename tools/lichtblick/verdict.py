"""Judge what ``drive.py`` saw of each layout in the real Lichtblick, against the bag played.

usage: python verdict.py BAG_DIR NAMESPACE REPORT.json ...

For each report (``shots/NAME.report.json``) and the layout it names, one line: ``ok`` and
what its panels showed, or each fault. A layout passes when

- the import showed no error (``snackbars``), the layout list shows no unsaved-changes dot
  beside it and the app's own export adds nothing to it (``export_diff``);
- every topic the app advertised once the layout was imported lies under NAMESPACE;
- no panel shows an error ("does not exist", "not available", "error"), and the app logged no
  message-path syntax error (its "X is not available" warnings are not judged: a settings
  tree built before the topic list arrived logs them on a loaded machine for topics whose
  data the panel then shows; a topic the bag lacks is found below);
- every message path a panel reads resolves in the bag: its topic is there and each field of
  the path is a field of the topic's first message (``/robot1/wrench.wrench.force.x``), and the
  panel shows that data: an Image or a point cloud at least 3 hues of colour (``hues``, from
  ``drive.py``), a Plot one hue per series, a Raw Messages panel the message's type. A topic
  the bag lacks is a fault unless no robot publishes it: a command the layout itself sends (a
  Teleop pad's, a Publish panel's or a goal panel's topic, or an Indicator standing for a
  Publish button) or a placeholder's (its title says so);
- the panels of a Tab panel's other tabs (the app mounts the active tab only) are named ``in
  a tab not shown``, unless ``drive.py --tabs`` clicked them open: then they are judged as
  the others.

Exit status 1 when a layout fails. Needs rosbags and numpy.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

STORE = get_typestore(Stores.ROS2_JAZZY)
STORE.register(get_types_from_msg("uint8[] data", "audio_common_msgs/msg/AudioData"))
ERRORS = ("does not exist", "not available", "error")


def first_messages(bag: Path) -> dict[str, tuple[str, Any]]:
    """Each topic of the bag: its type and its first message, decoded."""
    first: dict[str, tuple[str, Any]] = {}
    with Reader(bag) as reader:
        for connection, _, data in reader.messages():
            if connection.topic not in first:
                message = STORE.deserialize_cdr(bytes(data), connection.msgtype)
                first[connection.topic] = (connection.msgtype, message)
    return first


def reads(kind: str, config: dict[str, Any]) -> list[str]:
    """The message paths a panel subscribes to."""
    if kind == "Image":
        return [config.get("imageMode", {}).get("imageTopic", "")]
    if kind == "3D":
        return sorted(config.get("topics", {}))
    if kind == "Plot":
        return [series["value"] for series in config.get("paths", [])]
    if kind == "RawMessages":
        return [config.get("topicPath", "")]
    if kind == "Indicator":
        return [config.get("path", "")]
    return []


def sends(config: dict[str, Any]) -> set[str]:
    """The topics a panel publishes on (Teleop, Publish, a 3D goal panel's pose tool)."""
    topics = {config.get("topic", "")}
    publish = config.get("publish", {})
    if publish.get("type") == "pose":
        topics.add(publish.get("poseTopic", ""))
    return topics - {""}


def resolve(path: str, bag: dict[str, tuple[str, Any]]) -> str | None:
    """Why ``path`` does not resolve in the bag (None when it does)."""
    topic, *fields = path.split(".")
    if topic not in bag:
        return f"{topic} is not in the bag"
    value = bag[topic][1]
    for field in fields:
        if not hasattr(value, field):
            return f"{path}: {bag[topic][0]} has no field {field!r} there"
        value = getattr(value, field)
    return None


def judge_panel(
    panel_id: str, config: dict[str, Any], seen: dict[str, Any], context: dict[str, Any]
) -> tuple[str, list[str]]:
    """What the panel showed (``data``, ``no data expected``, ``control``) and its faults."""
    kind = panel_id.split("!", maxsplit=1)[0]
    bag, commands = context["bag"], context["commands"]
    if not seen.get("present"):
        return "missing", [f"{panel_id}: not on the screen"]
    text = seen.get("text") or ""
    faults = [f"{panel_id}: shows {word!r}" for word in ERRORS if word in text.lower()]
    paths = [path for path in reads(kind, config) if path]
    if not paths:
        return "control", faults
    missing = [why for why in (resolve(path, bag) for path in paths) if why]
    if missing:
        title = config.get("lichtblickPanelTitle", "")
        topics = {path.split(".")[0] for path in paths}
        if "placeholder" in title or "no Publish button" in title or topics <= commands:
            return "no data expected", faults
        if kind == "3D" and len(missing) < len(paths):
            return "data", faults  # a goal panel of points also shows its own goal topic
        return "missing", [*faults, *(f"{panel_id}: {why}" for why in missing)]
    hues = seen.get("hues", 0)
    if kind in ("Image", "3D") and hues < 3:
        faults.append(f"{panel_id}: {hues} hues: no image or point cloud drawn")
    if kind == "Plot" and hues < len(paths):
        faults.append(f"{panel_id}: {hues} hues for {len(paths)} series: lines not drawn")
    if kind == "RawMessages" and not text.startswith(bag[paths[0]][0]):
        faults.append(f"{panel_id}: no {bag[paths[0]][0]} message shown")
    return "data", faults


def judge(report: dict[str, Any], name: str, bag: dict[str, Any], namespace: str) -> list[str]:
    layout = json.loads(Path(report["layout"]).read_text(encoding="utf-8"))
    faults = [f"import: {text}" for text in report.get("snackbars", [])]
    if name in report.get("unsaved_changes", []):
        faults.append("the layout list marks it as having unsaved changes")
    faults += [f"export adds {where}" for _, where, _ in report.get("export_diff", [])]
    outside = [t for t in report.get("advertised", []) if not t.startswith(f"{namespace}/")]
    faults += [f"advertises {topic}, outside {namespace}" for topic in outside]
    faults += [
        f"console: {line}"
        for line in report.get("console", [])
        if "Error parsing message path" in line
    ]
    configs = layout["configById"]
    commands = set().union(*(sends(config) for config in configs.values()))
    context = {"bag": bag, "commands": commands}
    shown: dict[str, int] = {}
    hidden = inactive_tabs(configs)
    for panel_id, config in configs.items():
        if panel_id.startswith("Tab!"):
            continue  # a container: the panels of its tabs are judged
        seen = report["panels"].get(panel_id, {})
        if panel_id in hidden and not seen.get("present"):
            state, panel_faults = "in a tab not shown", []  # the app mounts the active tab only
        else:
            state, panel_faults = judge_panel(panel_id, config, seen, context)
        shown[state] = shown.get(state, 0) + 1
        faults += panel_faults
    summary = ", ".join(f"{count} {state}" for state, count in sorted(shown.items()))
    return [f"{sum(shown.values())} panels: {summary}", *faults]


def inactive_tabs(configs: dict[str, Any]) -> set[str]:
    """The panels in the tabs a Tab panel does not show on opening (not its activeTabIdx)."""
    hidden: set[str] = set()
    for panel_id, config in configs.items():
        if not panel_id.startswith("Tab!"):
            continue
        active = config.get("activeTabIdx", 0)
        for index, tab in enumerate(config.get("tabs", [])):
            stack = [tab.get("layout")] if index != active else []
            while stack:
                node = stack.pop()
                if isinstance(node, str):
                    hidden.add(node)
                elif isinstance(node, dict):
                    stack += [node.get("first"), node.get("second")]
    return hidden


def main() -> None:
    bag, namespace = first_messages(Path(sys.argv[1])), sys.argv[2].rstrip("/")
    failed = 0
    for item in sys.argv[3:]:
        report = json.loads(Path(item).read_text(encoding="utf-8"))
        name = Path(item).name.removesuffix(".report.json")
        summary, *faults = judge(report, name, bag, namespace)
        failed += bool(faults)
        print(f"{name}: {'FAIL' if faults else 'ok'}: {summary}")
        for fault in faults:
            print(f"    {fault}")
    print(f"{len(sys.argv) - 3 - failed} of {len(sys.argv) - 3} layouts pass")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
