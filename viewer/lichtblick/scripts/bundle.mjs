// Writes dist/extension.js, the one file Lichtblick loads, from the CommonJS modules tsc wrote to
// build/src/. The app runs that file as `new Function("module", "require", source)`: there is no
// `exports` and `require` knows only react and react-dom, so each module is wrapped in a function
// of its own (module, exports, require), and a require of another module of src/ is answered from
// those functions; a require of anything else (a package) is refused here. Modules in name order,
// no dates, no paths: the same sources give the same bytes.
import { existsSync, mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const root = join(dirname(fileURLToPath(import.meta.url)), "..");
const built = join(root, "build", "src");

// The modules extension.js needs, found by following its requires (a file tsc left from a
// source since removed is not one of them), in name order.
const sources = new Map();
const wanted = ["./extension"];
while (wanted.length > 0) {
  const name = wanted.pop();
  if (sources.has(name)) {
    continue;
  }
  const file = join(built, `${name.slice(2)}.js`);
  if (!/^\.\/[A-Za-z0-9_-]+$/.test(name) || !existsSync(file)) {
    throw new Error(`${name}: no module of src/ (build/src/${name.slice(2)}.js); run tsc first`);
  }
  const source = readFileSync(file, "utf8").replace(/\r\n/g, "\n").trimEnd();
  sources.set(name, source);
  for (const [, required] of source.matchAll(/\brequire\("([^"]+)"\)/g)) {
    wanted.push(required);
  }
}
const modules = [...sources.keys()]
  .sort()
  .map((name) => `${JSON.stringify(name)}: function (module, exports, require) {\n${sources.get(name)}\n}`);

const bundle = `// teleop-ui follower: a Lichtblick extension (viewer/lichtblick), written by scripts/bundle.mjs
// from tsc's output. Do not edit: edit src/ and run \`npm run build\`.
(function () {
"use strict";
const sources = {
${modules.join(",\n")}
};
const loaded = {};
function load(name) {
  if (!(name in loaded)) {
    const module = { exports: {} };
    loaded[name] = module;
    sources[name].call(module.exports, module, module.exports, load);
  }
  return loaded[name].exports;
}
module.exports = load("./extension");
})();
`;
mkdirSync(join(root, "dist"), { recursive: true });
writeFileSync(join(root, "dist", "extension.js"), bundle);
