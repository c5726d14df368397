// What the follower says (src/messages.ts), for answers as the watcher writes them
// (`layouts.team.tab` only where its team layout has a tab for the answer).
import { strict as assert } from "node:assert";
import { test } from "node:test";

import { type Answer, answerOf } from "../src/answer";
import * as say from "../src/messages";

const answer = (fields: Record<string, unknown>): Answer => {
  const reading = answerOf({ robot: "/uav1", configuration: 6, ...fields });
  assert.equal(reading.kind, "answer");
  return (reading as { answer: Answer }).answer;
};

test("what is on screen names the robot and the configuration", () => {
  assert.equal(say.onScreen("/ugv1", 20), "/ugv1 · UI configuration 20");
  assert.equal(
    say.detail(answer({ combination: { k: "UGV", m: "Waypoint" } }), 4),
    "UGV, Waypoint · tab 5 of the team layout",
  );
  assert.equal(say.detail(answer({ default: true }), 0), " (the team's default configuration) · tab 1 of the team layout");
  assert.equal(say.detail(undefined, 2), "tab 3 of the team layout");
});

test("a mode the robot does not offer: no tab anywhere, so no re-import, and its own layout named", () => {
  const asked = answer({
    notes: ["/uav1 does not offer motion_control 'Waypoint' (it has Flight); using it as asked"],
    layouts: {
      foxglove: { path: "/srv/lay/uav1/config-006.json" },
      team: { path: "/srv/lay/team.json" },
    },
  });
  assert.equal(
    say.noTab("/uav1", 6, asked),
    "No tab for /uav1, UI configuration 6: the team layout holds each robot's own combinations, " +
      "and this is not one of them. The screen is unchanged. Its own layout: /srv/lay/uav1/config-006.json",
  );
  assert.equal(say.notes(asked), "/uav1 does not offer motion_control 'Waypoint' (it has Flight); using it as asked");
});

test("a pair the watcher's team layout has and this one lacks: re-import it, from where it is", () => {
  const newer = answer({ robot: "/uav2", layouts: { team: { path: "/srv/lay/team.json", tab: 7 } } });
  assert.equal(
    say.noTab("/uav2", 6, newer),
    "No tab for /uav2, UI configuration 6 in this team layout; the watcher's team layout has one " +
      "(tab 8): the screen is unchanged. Re-import the team layout: /srv/lay/team.json",
  );
});

test("an answer that names no layouts: the screen is unchanged, re-import if robots changed", () => {
  assert.equal(
    say.noTab("/uav9", 4, answer({})),
    "No tab for /uav9, UI configuration 4 in this team layout: the screen is unchanged. If robots " +
      "joined or changed since it was written, re-import it.",
  );
});

test("a hostile robot name is shown escaped and cut, a path escaped and never cut", () => {
  const path = `/srv/${"deep/".repeat(40)}team\n.json`;
  const text = say.noTab(`/uav1\nERROR: forged\u202e${"x".repeat(100)}`, 2, answer({ layouts: { team: { path, tab: 3 } } }));
  assert.ok(text.startsWith(`No tab for /uav1\\nERROR: forged\\u202e${"x".repeat(40)}... (cut from 120 characters), `));
  assert.ok(text.endsWith(`Re-import the team layout: /srv/${"deep/".repeat(40)}team\\n.json`));
  assert.doesNotMatch(text, /[\n\u202e]/);
});

test("the watcher's notes are shown one after another, each escaped and cut to 200 characters", () => {
  const long = answer({ reasons: ["why\nthe default"], notes: ["n".repeat(300)] });
  assert.equal(say.notes(long), `why\\nthe default · ${"n".repeat(200)}... (cut from 300 characters)`);
  assert.equal(say.notes(undefined), "");
});

test("not beside the Tab panel, a short Tab panel, the default tab, null and unreadable answers", () => {
  assert.equal(
    say.notBeside("/srv/lay/team.json"),
    "This panel is not beside the team layout's Tab panel, so it cannot switch tabs (Lichtblick " +
      "lets a panel change only the panel beside it). Re-import the team layout: /srv/lay/team.json " +
      "Leave this panel where the team layout puts it.",
  );
  assert.equal(
    say.tabMissing(3, 7, "/uav1", 2, undefined),
    "The Tab panel beside this one has 3 tabs, and this layout's tab for /uav1, UI configuration 2 " +
      "is number 8: the screen is unchanged. Re-import the team layout.",
  );
  assert.equal(
    say.defaultShown(undefined),
    "This team layout has no tab of its own for it: the default tab is shown. Re-import the team layout.",
  );
  assert.equal(say.NO_ROBOT, "No active robot (the watcher's answer is null): the screen is unchanged.");
  assert.equal(say.unreadable("not JSON"), "An answer could not be read (not JSON): ignored.");
});
