// Which tab an answer puts on screen, and the Tab panel's new state (src/follow.ts).
import { strict as assert } from "node:assert";
import { test } from "node:test";

import { readAnswer } from "../src/answer";
import { readConfig } from "../src/config";
import { TabIndex, withActiveTab } from "../src/follow";

const CONFIG = readConfig({
  answerTopic: "/teleop_ui/ui_configuration",
  tabs: [
    { robot: "/uav1", configuration: 1, tab: 0 },
    { robot: "/ugv1", configuration: 15, tab: 1 },
    { robot: "/ugv1", configuration: 20, tab: 2 },
  ],
}).config;

const answer = (robot: string, configuration: number) => readAnswer(JSON.stringify({ robot, configuration }));

test("an answer shows its robot's configuration's tab", () => {
  const index = new TabIndex(CONFIG);
  assert.deepEqual(index.decide(answer("/uav1", 1)), { kind: "switch", tab: 0, robot: "/uav1", configuration: 1 });
  assert.deepEqual(index.decide(answer("/ugv1", 20)), { kind: "switch", tab: 2, robot: "/ugv1", configuration: 20 });
});

test("another motion control of the same robot is another tab", () => {
  const index = new TabIndex(CONFIG);
  assert.equal(index.tabOf("/ugv1", 15), 1);
  assert.equal(index.tabOf("/ugv1", 20), 2);
});

test("a pair the team layout lacks keeps the screen, or shows the default tab when there is one", () => {
  assert.deepEqual(new TabIndex(CONFIG).decide(answer("/uav9", 4)), {
    kind: "missing",
    robot: "/uav9",
    configuration: 4,
  });
  assert.deepEqual(new TabIndex({ ...CONFIG, defaultTab: 3 }).decide(answer("/uav9", 103)), {
    kind: "default",
    tab: 3,
    robot: "/uav9",
    configuration: 103,
  });
});

test("robot names are compared as written", () => {
  assert.equal(new TabIndex(CONFIG).decide(answer("uav1", 1)).kind, "missing");
  assert.equal(new TabIndex(CONFIG).decide(answer("/uav1 ", 1)).kind, "missing");
});

test("a null answer and an unreadable one keep the screen", () => {
  const index = new TabIndex(CONFIG);
  assert.deepEqual(index.decide(readAnswer("null")), { kind: "none" });
  assert.deepEqual(index.decide(readAnswer("[".repeat(100))), {
    kind: "unreadable",
    reason: "nested deeper than 64 levels",
  });
});

// A team layout's Tab panel: every tab holds a layout of the robot's panels.
const TEAM_TAB = {
  activeTabIdx: 0,
  tabs: [
    { title: "/uav1: 1", layout: { direction: "row", first: "Image!a", second: "Teleop!b" } },
    { title: "/ugv1: 15", layout: "3D!c" },
    { title: "/ugv1: 20", layout: "3D!d" },
  ],
};

test("the team's Tab panel gets the tab active, and keeps everything else", () => {
  const result = withActiveTab(TEAM_TAB, 2);
  assert.deepEqual(result, { kind: "switched", state: { ...TEAM_TAB, activeTabIdx: 2 } });
  assert.equal(TEAM_TAB.activeTabIdx, 0);
});

test("a new Tab panel, as Lichtblick opens one beside a panel with no Tab sibling, is not the team's", () => {
  // Lichtblick v1.19.0 util/layout.ts DEFAULT_TAB_PANEL_CONFIG, the Tab panel's defaultConfig,
  // which Panel.tsx openSiblingPanel passes to getState when it opens a new panel.
  const fresh = { activeTabIdx: 0, tabs: [{ title: "1", layout: undefined }] };
  const result = withActiveTab(fresh, 0);
  assert.equal(result.kind, "not-beside");
  assert.equal(result.state, fresh);
});

test("no state, or another panel's, is not the team's Tab panel", () => {
  assert.equal(withActiveTab(undefined, 0).kind, "not-beside");
  assert.equal(withActiveTab({ imageMode: { imageTopic: "/uav1/camera" } }, 0).kind, "not-beside");
  assert.equal(withActiveTab({ tabs: "all of them" }, 0).kind, "not-beside");
});

test("a tab the Tab panel does not have leaves it as it is, and says how many it has", () => {
  const result = withActiveTab(TEAM_TAB, 7);
  assert.deepEqual(result, { kind: "no-tab", state: TEAM_TAB, tabs: 3 });
});
