// What the follower shows of a stranger's string (src/text.ts).
import { strict as assert } from "node:assert";
import { test } from "node:test";

import { shown } from "../src/text";

test("a line break in a robot name is shown escaped, never as a line of its own", () => {
  assert.equal(shown("/uav1\nERROR: forged"), "/uav1\\nERROR: forged");
  assert.equal(shown("a\r\tb"), "a\\r\\tb");
});

test("controls, bidirectional overrides and zero-width characters are shown as escapes", () => {
  assert.equal(shown("\u001b[2J/uav1"), "\\x1b[2J/uav1");
  assert.equal(shown("/uav\u202e1vau"), "/uav\\u202e1vau");
  assert.equal(shown("/u\u200dav1\u00ad"), "/u\\u200dav1\\xad");
  assert.equal(shown("tag\u{e0041}"), "tag\\U000e0041");
  assert.equal(shown("nbsp\u00a0here"), "nbsp\\xa0here");
});

test("characters a screen draws as nothing are shown as escapes", () => {
  assert.equal(shown("a\u3164b"), "a\\u3164b");
  assert.equal(shown("a\ufe0fb\u2800"), "a\\ufe0fb\\u2800");
});

test("a lone surrogate is shown as an escape", () => {
  assert.equal(shown("a\ud800b"), "a\\ud800b");
});

test("names in other scripts and plain spaces are shown as written", () => {
  assert.equal(shown("Ünïcödé 机器人 /uav 1"), "Ünïcödé 机器人 /uav 1");
});

test("a long value is cut to 60 characters with a mark saying how long it was", () => {
  assert.equal(shown("x".repeat(9000)), `${"x".repeat(60)}... (cut from 9,000 characters)`);
  assert.equal(shown("x".repeat(60)), "x".repeat(60));
  assert.equal(shown("abcdef", 3), "abc... (cut from 6 characters)");
});

test("characters are counted as code points, not UTF-16 units", () => {
  assert.equal(shown("🤖".repeat(60)), "🤖".repeat(60));
  assert.equal(shown("🤖".repeat(61)), `${"🤖".repeat(60)}... (cut from 61 characters)`);
});

test("with no limit a value is escaped but never cut", () => {
  const path = `/home/operator/${"deep/".repeat(100)}team.json`;
  assert.equal(shown(path, null), path);
});
