"""Make ``tests/layouts/checks/data/message_paths.json``: message paths as Lichtblick parses them.

usage: python message_paths.py CHECKOUT > tests/layouts/checks/data/message_paths.json

CHECKOUT is a Lichtblick checkout with its node_modules installed (``tools/lichtblick_check.md``).
The paths are every string ``packages/message-path/src/parseMessagePath.test.ts`` parses and
5,000 generated ones (a fixed seed); each is parsed in node by the real grammar
(``grammar.ne`` compiled by the checkout's nearleyc) as ``parseMessagePath.ts`` does: the first
result, or none. The test compares :func:`solver.layouts.checks.parse_message_path` with them.
"""

from __future__ import annotations

import json
import random
import re
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

PARSE_JS = """
const nearley = require(process.argv[2] + "/node_modules/nearley");
const grammar = nearley.Grammar.fromCompiled(require(process.argv[3]));
const paths = JSON.parse(require("fs").readFileSync(0, "utf8"));
const out = paths.map((path) => {
  let result;
  try {
    result = new nearley.Parser(grammar).feed(path).results[0];
  } catch (e) {
    result = undefined;
  }
  return { path, result: result === undefined ? null : result };
});
process.stdout.write(JSON.stringify(out, (k, v) =>
  typeof v === "bigint" ? Number(v) : v === Infinity ? "Infinity" : v));
"""
TOKENS = ["/", "/", "a", "b_1", "x-y", "7", "-", ".", ".", "[", "]", ":", "{", "}", "==", "!=",
          ">=", "<=", "<", ">", "'", '"', "\\", "$", "@", ".@", "0", "-1", "true", "false", " ",
          "<robot>", "~", "é"]  # fmt: skip
TOPICS = ["/robot1/points", "robot1/cmd_vel", "/a", "/", "//x", '"/q t"', "<robot>/wrench",
          "/r/cam_2", "/x/", "~/x", "/1a"]  # fmt: skip
FIELDS = [".wrench", ".force", ".x", '."a b"', ".", ".data", ".1"]
SLICES = ["[0]", "[1:3]", "[:]", "[$i]", "[$a:$b]", "[-2:]", "[]", "[a]", "[0][1]"]
FILTERS = ["{id==3}", "{a.b!='x'}", "{}", "{a}", "{==1}", "{a==$}", "{a==$v}", "{a=1}",
           "{a==true}", '{a=="q"}', "{a.==1}", "{a<=-4}"]  # fmt: skip
ENDS = [".", ".@derivative", ".@", "..@x", ".@a.b"]


def upstream(checkout: Path) -> list[str]:
    text = (checkout / "packages/message-path/src/parseMessagePath.test.ts").read_text()
    operators = {"${equal}": "==", "${notEqual}": "!=", "${greaterThan}": ">="}
    found = []
    pattern = r'parseMessagePath\(\s*(String\.raw`([^`]*)`|`([^`]*)`|"((?:[^"\\]|\\.)*)")'
    for match in re.finditer(pattern, text):
        raw, template, plain = match.group(2), match.group(3), match.group(4)
        path = raw if raw is not None else template
        if path is None:
            path = json.loads(f'"{plain}"')
        elif template is not None:
            for name, operator in operators.items():
                path = path.replace(name, operator)
        if "${" not in path:
            found.append(path)
    return list(dict.fromkeys(found))


def generated(seed: int = 26) -> list[str]:
    rng = random.Random(seed)
    paths = ["".join(rng.choice(TOKENS) for _ in range(rng.randint(1, 9))) for _ in range(2500)]
    for _ in range(2500):
        path = rng.choice(TOPICS)
        for _ in range(rng.randint(0, 4)):
            path += rng.choice(rng.choices([FIELDS, SLICES, FILTERS, ENDS], [8, 4, 5, 3])[0])
        paths.append(path)
    return paths


def normal(value: Any) -> Any:
    if isinstance(value, dict) and "variableName" in value:
        return {"variable": value["variableName"]}
    return "inf" if value == "Infinity" else value


def compact(result: Any) -> Any:
    if result is None:
        return None
    parts: list[Any] = []
    for part in result["messagePath"]:
        if part["type"] == "name":
            parts.append(["name", part["name"]])
        elif part["type"] == "slice":
            parts.append(["slice", normal(part["start"]), normal(part["end"])])
        else:
            value = normal(part.get("value"))
            parts.append(["filter", part["path"], part.get("operator"), value])
    return [result["topicName"], parts, result["modifier"]]


def main() -> None:
    checkout = Path(sys.argv[1]).resolve()
    ours = upstream(checkout)
    paths = list(dict.fromkeys(ours + generated()))
    with tempfile.TemporaryDirectory() as scratch:
        compiled = Path(scratch) / "grammar.js"
        nearleyc = checkout / "node_modules/.bin/nearleyc"
        grammar = checkout / "packages/message-path/src/grammar.ne"
        subprocess.run([nearleyc, grammar, "-o", compiled], check=True, capture_output=True)
        script = Path(scratch) / "parse.js"
        script.write_text(PARSE_JS, encoding="utf-8")
        parsed = subprocess.run(
            ["node", script, checkout, compiled],
            input=json.dumps(paths),
            capture_output=True,
            text=True,
            check=True,
        )
    commit = subprocess.run(
        ["git", "-C", checkout, "rev-parse", "HEAD"], capture_output=True, text=True, check=True
    ).stdout.strip()
    document = {
        "source": f"lichtblick-suite/lichtblick {commit} packages/message-path/src/grammar.ne, "
        "compiled by nearleyc and run by nearley as parseMessagePath.ts does (first result, or "
        "none)",
        "upstream_test_paths": len(ours),
        "cases": [[item["path"], compact(item["result"])] for item in json.loads(parsed.stdout)],
    }
    json.dump(document, sys.stdout, ensure_ascii=False, separators=(",", ":"))


if __name__ == "__main__":
    main()
