// The follower's configuration, as the team layout holds it (src/config.ts).
import { strict as assert } from "node:assert";
import { test } from "node:test";

import { TABS_READ, loopbackProblem, readConfig } from "../src/config";

// configById["teleop-ui.follower!follower"] as docs/live.md's team layout has it.
const WRITTEN = {
  answerUrl: "http://127.0.0.1:8770/answer/events",
  answerTopic: "/teleop_ui/ui_configuration",
  tabs: [
    { robot: "/uav1", configuration: 1, tab: 0 },
    { robot: "/ugv1", configuration: 15, tab: 1 },
    { robot: "/ugv1", configuration: 20, tab: 2 },
  ],
  defaultTab: null,
};

test("the configuration teleop-ui writes is read whole, with no problem", () => {
  assert.deepEqual(readConfig(WRITTEN), {
    config: {
      answerUrl: "http://127.0.0.1:8770/answer/events",
      answerTopic: "/teleop_ui/ui_configuration",
      tabs: WRITTEN.tabs,
      defaultTab: undefined,
    },
    problems: [],
  });
});

test("a panel with no configuration says it was not written by teleop-ui, and follows nothing", () => {
  const { config, problems } = readConfig(undefined);
  assert.deepEqual(config, { answerUrl: undefined, answerTopic: undefined, tabs: [], defaultTab: undefined });
  assert.deepEqual(problems, [
    "no configuration: this panel was not written by teleop-ui",
    "tabs: missing (a list of {robot, configuration, tab})",
    "neither answerTopic nor answerUrl: there are no answers to follow",
  ]);
});

test("answers are read only from this machine, over http or https", () => {
  for (const url of [
    "http://127.0.0.1:8770/answer/events",
    "https://127.0.0.1/answer/events",
    "http://127.3.4.5:1/",
    "http://localhost:8770/answer/events",
    "http://[::1]:8770/answer/events",
    "http://2130706433:8770/answer/events",
    "http://0x7f.1:8770/answer/events",
  ]) {
    assert.equal(loopbackProblem(url), undefined, url);
  }
  const refused = {
    "http://example.com/answer/events": "is not on this machine (loopback: 127.0.0.1, [::1], localhost)",
    "http://127.0.0.1.example.com/answer/events": "is not on this machine (loopback: 127.0.0.1, [::1], localhost)",
    "http://10.0.0.7:8770/answer/events": "is not on this machine (loopback: 127.0.0.1, [::1], localhost)",
    "http://[::ffff:10.0.0.7]/": "is not on this machine (loopback: 127.0.0.1, [::1], localhost)",
    "file:///etc/passwd": "is not an http or https address",
    "javascript:alert(1)": "is not an http or https address",
    "ws://127.0.0.1:8770/": "is not an http or https address",
    "http://operator:secret@127.0.0.1:8770/": "carries a user name or password",
    "/answer/events": "is not an address",
  };
  for (const [url, problem] of Object.entries(refused)) {
    assert.equal(loopbackProblem(url), problem, url);
  }
});

test("an answer stream elsewhere is refused with a problem naming the field, and the topic still followed", () => {
  const { config, problems } = readConfig({ ...WRITTEN, answerUrl: "http://example.com/answer/events" });
  assert.equal(config.answerUrl, undefined);
  assert.equal(config.answerTopic, "/teleop_ui/ui_configuration");
  assert.deepEqual(problems, [
    "answerUrl is not on this machine (loopback: 127.0.0.1, [::1], localhost): " +
      "answers are read only from a watcher on this machine",
  ]);
});

test("a topic that is no full topic name is refused", () => {
  for (const answerTopic of ["teleop_ui/ui_configuration", 7, "/" + "t".repeat(5000)]) {
    const { config, problems } = readConfig({ ...WRITTEN, answerTopic });
    assert.equal(config.answerTopic, undefined);
    assert.deepEqual(problems, ["answerTopic: not a full topic name (a string starting with /)"]);
  }
});

test("a flawed tab entry is a located problem and the other entries are read", () => {
  const tabs = [
    { robot: "/uav1", configuration: 1, tab: 0 },
    { robot: "/uav2", configuration: "2", tab: 1 },
    "tab 2",
    { robot: "", configuration: 3, tab: 2 },
    { robot: "/uav4", configuration: 4, tab: -1 },
    { robot: "/uav5", configuration: 5, tab: 2.5 },
    { robot: "/uav1", configuration: 1, tab: 6 },
    { robot: "/uav7", configuration: 7, tab: 7 },
  ];
  const { config, problems } = readConfig({ ...WRITTEN, tabs });
  assert.deepEqual(config.tabs, [
    { robot: "/uav1", configuration: 1, tab: 0 },
    { robot: "/uav7", configuration: 7, tab: 7 },
  ]);
  assert.deepEqual(problems, [
    "tabs[1].configuration: not a whole number",
    "tabs[2]: not an object",
    "tabs[3].robot: not a robot name (a string)",
    "tabs[4].tab: not a tab index (a whole number from 0)",
    "tabs[5].tab: not a tab index (a whole number from 0)",
    "tabs[6]: the same robot and configuration as an earlier entry; ignored",
  ]);
});

test("at most 10,000 tabs are read, and the panel says so", () => {
  const tabs = Array.from({ length: 25_000 }, (_, index) => ({ robot: `/r${index}`, configuration: 1, tab: index }));
  const { config, problems } = readConfig({ ...WRITTEN, tabs });
  assert.equal(config.tabs.length, TABS_READ);
  assert.deepEqual(problems, ["tabs: 25000 entries; the first 10000 are read"]);
});

test("a default tab is a tab index or null", () => {
  assert.equal(readConfig({ ...WRITTEN, defaultTab: 3 }).config.defaultTab, 3);
  const { config, problems } = readConfig({ ...WRITTEN, defaultTab: "3" });
  assert.equal(config.defaultTab, undefined);
  assert.deepEqual(problems, ["defaultTab: not a tab index (a whole number from 0) or null"]);
});
