// Which tab an answer puts on screen, and the Tab panel's new state: the follower's decisions,
// with no DOM and no app. The follower chooses only among the tabs the team layout holds: an
// answer names a robot and a configuration, never a tab, a panel or a topic, so a forged one can
// at worst pick another of the team's tabs.

import type { Reading } from "./answer";
import { type FollowerConfig, pairKey } from "./config";

/** What an answer asks of the screen. */
export type Decision =
  /** Show `tab`: the robot's configuration has one. */
  | { readonly kind: "switch"; readonly tab: number; readonly robot: string; readonly configuration: number }
  /** Show the default tab: the pair has no tab of its own (re-import the team layout). */
  | { readonly kind: "default"; readonly tab: number; readonly robot: string; readonly configuration: number }
  /** Keep the screen: the pair has no tab and there is no default tab (re-import). */
  | { readonly kind: "missing"; readonly robot: string; readonly configuration: number }
  /** Keep the screen: no robot is active (the answer is null). */
  | { readonly kind: "none" }
  /** Keep the screen: the answer could not be read. */
  | { readonly kind: "unreadable"; readonly reason: string };

/** Finds the tab of a (robot, configuration) pair in a follower's configuration. */
export class TabIndex {
  readonly #tabs: ReadonlyMap<string, number>;
  readonly #defaultTab: number | undefined;

  public constructor(config: FollowerConfig) {
    this.#tabs = new Map(config.tabs.map((entry) => [pairKey(entry.robot, entry.configuration), entry.tab]));
    this.#defaultTab = config.defaultTab;
  }

  /** The tab of `robot`'s UI configuration `configuration`, if the team layout has one. */
  public tabOf(robot: string, configuration: number): number | undefined {
    return this.#tabs.get(pairKey(robot, configuration));
  }

  /** What `reading` asks of the screen. */
  public decide(reading: Reading): Decision {
    if (reading.kind !== "answer") {
      return reading;
    }
    const { robot, configuration } = reading.answer;
    const tab = this.tabOf(robot, configuration);
    if (tab !== undefined) {
      return { kind: "switch", tab, robot, configuration };
    }
    if (this.#defaultTab !== undefined) {
      return { kind: "default", tab: this.#defaultTab, robot, configuration };
    }
    return { kind: "missing", robot, configuration };
  }
}

/** The Tab panel's state with `tab` active, or why the panel beside the follower cannot show it. */
export type TabState =
  | { readonly kind: "switched"; readonly state: Record<string, unknown> }
  /** The panel beside is no Tab panel of a team layout (an empty or new Tab): stop following. */
  | { readonly kind: "not-beside"; readonly state: unknown }
  /** The Tab panel beside has no such tab (a team layout older than the watcher's). */
  | { readonly kind: "no-tab"; readonly state: unknown; readonly tabs: number };

function hasLayout(tab: unknown): boolean {
  return typeof tab === "object" && tab !== null && (tab as { layout?: unknown }).layout != undefined;
}

/** The state `layout.addPanel`'s `getState` returns for the sibling Tab panel's `existing` state:
 * the same state with `activeTabIdx` set, or the existing state unchanged. A Tab panel none of
 * whose tabs holds a layout is not the team's (Lichtblick opens a new, empty Tab panel beside the
 * follower when its sibling is not a Tab panel, with the app's default state). */
export function withActiveTab(existing: unknown, tab: number): TabState {
  const tabs =
    typeof existing === "object" && existing !== null ? (existing as { tabs?: unknown }).tabs : undefined;
  if (!Array.isArray(tabs) || !tabs.some(hasLayout)) {
    return { kind: "not-beside", state: existing };
  }
  if (!hasLayout(tabs[tab])) {
    return { kind: "no-tab", state: existing, tabs: tabs.length };
  }
  return { kind: "switched", state: { ...(existing as Record<string, unknown>), activeTabIdx: tab } };
}
