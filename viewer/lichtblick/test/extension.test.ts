// dist/extension.js loads as Lichtblick v1.19.0 loads an extension
// (packages/suite-base/src/providers/helpers/buildContributionPoints.ts): its source run as
// `new Function("module", "require", source)`, with no `exports`, a `require` that knows only
// react and react-dom, and then `module.exports.activate(context)`.
import { strict as assert } from "node:assert";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { test } from "node:test";

const SOURCE = readFileSync(join(__dirname, "..", "..", "dist", "extension.js"), "utf8");

test("the built extension registers one panel, follower, and asks the app for no module", () => {
  const required: string[] = [];
  const module: { exports: { activate?: (context: unknown) => void } } = { exports: {} };
  // eslint-disable-next-line @typescript-eslint/no-implied-eval
  const load = new Function("module", "require", SOURCE) as (m: unknown, r: (name: string) => unknown) => void;
  load(module, (name: string) => {
    required.push(name);
    return undefined;
  });
  const registered: { name: string; initPanel: unknown }[] = [];
  const context = {
    mode: "production",
    registerPanel: (registration: { name: string; initPanel: unknown }) => registered.push(registration),
  };
  assert.equal(typeof module.exports.activate, "function");
  module.exports.activate?.(context);
  assert.deepEqual(
    registered.map((each) => [each.name, typeof each.initPanel]),
    [["follower", "function"]],
  );
  assert.deepEqual(required, []);
});

test("the built extension names no path of the machine it was built on", () => {
  assert.doesNotMatch(SOURCE, /\/(home|root|tmp|work|Users)\//);
  assert.doesNotMatch(SOURCE, /sourceMappingURL/);
});
