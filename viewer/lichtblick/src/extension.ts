// teleop-ui's Lichtblick extension: one panel, `follower`, whose type in a layout is
// `teleop-ui.follower` (the extension's displayName, then the panel's name: Lichtblick's
// buildContributionPoints). The app loads dist/extension.js with
// `new Function("module", "require", source)` and calls `module.exports.activate`; `require` gives
// only react and react-dom, which this extension does not use.

import type { ExtensionContext } from "@lichtblick/suite";

import { initFollower } from "./panel";

/** The panel's name; its type in a layout is `teleop-ui.follower`. */
export const PANEL_NAME = "follower";

export function activate(extensionContext: ExtensionContext): void {
  extensionContext.registerPanel({ name: PANEL_NAME, initPanel: initFollower });
}
