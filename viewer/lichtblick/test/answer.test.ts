// Reading the watcher's answer, bounded (src/answer.ts). The answers are written here as the
// watcher writes them (docs/live.md, "The /teleop_ui parameter convention"), and as strangers may.
import { strict as assert } from "node:assert";
import { test } from "node:test";

import { ANSWER_CHARS, answerOf, messageText, readAnswer } from "../src/answer";

const WATCHERS = JSON.stringify({
  robot: "/uav1",
  team: "Case 3",
  configuration: 1,
  default: false,
  default_configuration: 103,
  kinematic_type: "UAV",
  combination: {
    kinematic_type: "UAV",
    motion_control: "Flight",
    sensor_type: "2D Camera",
    sensor_count: "1",
  },
  components: [{ characteristic: "kinematic_type", component: "UAV", values: ["UAV"] }],
  notes: ["/uav1 has several sensor_type values: using 2D Camera"],
  reasons: [],
  layouts: {
    foxglove: { path: "/srv/lay/uav1/config-001.json", url: "http://127.0.0.1:8770/layouts/uav1/config-001.json" },
    team: { path: "/srv/lay/team.json", url: "http://127.0.0.1:8770/layouts/team.json", tab: 0 },
  },
  watcher: "/teleop_ui_watch_1_0123456789abcdef0123456789abcdef",
});

test("a watcher's answer gives its robot, configuration, values, layouts and notes", () => {
  assert.deepEqual(readAnswer(WATCHERS), {
    kind: "answer",
    answer: {
      robot: "/uav1",
      configuration: 1,
      isDefault: false,
      values: ["UAV", "Flight", "2D Camera", "1"],
      team: { path: "/srv/lay/team.json", tab: 0 },
      ownLayout: "/srv/lay/uav1/config-001.json",
      notes: ["/uav1 has several sensor_type values: using 2D Camera"],
    },
  });
});

test("a default configuration's answer says so", () => {
  const reading = readAnswer('{"robot": "/ghost", "configuration": 103, "default": true}');
  assert.equal(reading.kind, "answer");
  assert.equal(reading.kind === "answer" && reading.answer.isDefault, true);
  assert.equal(reading.kind === "answer" && reading.answer.team, undefined);
});

test("null is no active robot", () => {
  assert.deepEqual(readAnswer("null"), { kind: "none" });
  assert.deepEqual(readAnswer(" null\n"), { kind: "none" });
});

test("an answer nested 200,000 levels deep is refused before the JSON decoder sees it", () => {
  assert.deepEqual(readAnswer("[".repeat(200_000)), {
    kind: "unreadable",
    reason: "nested deeper than 64 levels",
  });
  assert.deepEqual(readAnswer(`{"robot": ${"{\"a\":".repeat(100_000)}1`), {
    kind: "unreadable",
    reason: "nested deeper than 64 levels",
  });
});

test("64 levels are read and 65 are not", () => {
  const nested = (levels: number) =>
    `{"robot": "/uav1", "configuration": 2, "x": ${"[".repeat(levels - 1)}${"]".repeat(levels - 1)}}`;
  assert.equal(readAnswer(nested(64)).kind, "answer");
  assert.deepEqual(readAnswer(nested(65)), { kind: "unreadable", reason: "nested deeper than 64 levels" });
});

test("brackets and escaped quotes inside strings are not nesting", () => {
  const robot = `/r${"[{".repeat(100)}\\"${"[".repeat(100)}`;
  const reading = readAnswer(`{"robot": "${robot}", "configuration": 4}`);
  assert.equal(reading.kind, "answer");
  assert.equal(reading.kind === "answer" && reading.answer.robot, `/r${"[{".repeat(100)}"${"[".repeat(100)}`);
});

test("an answer longer than 1 MiB is refused unread", () => {
  const long = `{"robot": "/uav1", "configuration": 1, "pad": "${"x".repeat(ANSWER_CHARS)}"}`;
  assert.deepEqual(readAnswer(long), { kind: "unreadable", reason: "longer than 1,048,576 characters" });
});

test("text that is not JSON is unreadable", () => {
  assert.deepEqual(readAnswer("{robot: /uav1}"), { kind: "unreadable", reason: "not JSON" });
  assert.deepEqual(readAnswer(""), { kind: "unreadable", reason: "not JSON" });
});

test("an answer without a robot name or a whole configuration number is unreadable", () => {
  const unreadable = (text: string) => {
    const reading = readAnswer(text);
    return reading.kind === "unreadable" ? reading.reason : reading.kind;
  };
  assert.equal(unreadable('[1, 2]'), "not a JSON object or null");
  assert.equal(unreadable('"/uav1"'), "not a JSON object or null");
  assert.equal(unreadable('{"configuration": 3}'), "no robot name (a string) in it");
  assert.equal(unreadable('{"robot": 7, "configuration": 3}'), "no robot name (a string) in it");
  assert.equal(unreadable('{"robot": "", "configuration": 3}'), "no robot name (a string) in it");
  assert.equal(unreadable('{"robot": "/uav1", "configuration": "3"}'), "its configuration is not a whole number");
  assert.equal(unreadable('{"robot": "/uav1", "configuration": -1}'), "its configuration is not a whole number");
  assert.equal(unreadable('{"robot": "/uav1", "configuration": 1.5}'), "its configuration is not a whole number");
  assert.equal(unreadable('{"robot": "/uav1", "configuration": 1e300}'), "its configuration is not a whole number");
  assert.equal(unreadable('{"robot": "/uav1"}'), "its configuration is not a whole number");
});

test("a robot name longer than 4,096 characters is unreadable", () => {
  const reading = answerOf({ robot: `/${"r".repeat(4096)}`, configuration: 1 });
  assert.equal(reading.kind, "unreadable");
});

test("at most 16 values of a combination are kept, and only strings and numbers", () => {
  const combination = Object.fromEntries(
    Array.from({ length: 10_000 }, (_, index) => [`c${index}`, index % 2 === 0 ? `v${index}` : { nested: index }]),
  );
  const reading = answerOf({ robot: "/uav1", configuration: 1, combination });
  assert.equal(reading.kind, "answer");
  const values = reading.kind === "answer" ? reading.answer.values : [];
  assert.deepEqual(values, Array.from({ length: 16 }, (_, index) => `v${index * 2}`));
});

test("a team layout path that is not a short string, or a tab that is no index, is not kept", () => {
  const team = (path: unknown, tab: unknown) => {
    const reading = answerOf({ robot: "/uav1", configuration: 1, layouts: { team: { path, tab } } });
    return reading.kind === "answer" ? reading.answer.team : "unreadable";
  };
  assert.deepEqual(team(`/${"d".repeat(5000)}`, 2), { path: undefined, tab: 2 });
  assert.deepEqual(team(["/a"], -1), { path: undefined, tab: undefined });
  assert.deepEqual(team("", "2"), { path: undefined, tab: undefined });
  assert.deepEqual(team("/srv/lay/team.json", 1.5), { path: "/srv/lay/team.json", tab: undefined });
  const reading = answerOf({ robot: "/uav1", configuration: 1, layouts: { team: "here" } });
  assert.equal(reading.kind === "answer" && reading.answer.team, undefined);
});

test("the reasons come before the notes, at most four, strings only", () => {
  const reading = answerOf({
    robot: "/uav1",
    configuration: 103,
    reasons: ["no robot /uav1 on the graph", 7],
    notes: Array.from({ length: 1000 }, (_, index) => `note ${index}`),
  });
  assert.deepEqual(reading.kind === "answer" && reading.answer.notes, [
    "no robot /uav1 on the graph",
    "note 0",
    "note 1",
    "note 2",
  ]);
});

test("the answer topic's text is a std_msgs/String's data, and nothing else", () => {
  assert.equal(messageText({ data: "null" }), "null");
  assert.equal(messageText({ data: 5 }), undefined);
  assert.equal(messageText({}), undefined);
  assert.equal(messageText(null), undefined);
  assert.equal(messageText("null"), undefined);
});
