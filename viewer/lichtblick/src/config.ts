// The follower panel's configuration, as teleop-ui's watcher writes it into the team layout
// (`configById["teleop-ui.follower!..."]`):
//
//   {"answerUrl": "http://127.0.0.1:8770/answer/events" | null,
//    "answerTopic": "/teleop_ui/ui_configuration" | null,
//    "tabs": [{"robot": "/uav1", "configuration": 3, "tab": 0}, ...],
//    "defaultTab": null | 5}
//
// The layout is a file the operator imported, so it is read as one: a flaw in one entry is a
// located problem the panel shows, and the follower goes on with the rest. The answer stream
// must be on this machine (loopback: the watcher serves it there), over http or https.

/** The most (robot, configuration) tabs read from one follower's configuration. */
export const TABS_READ = 10_000;
/** The longest robot name or topic read from the configuration. */
export const NAME_CHARS = 4096;

/** One (robot, UI configuration) pair the team layout has a tab for. */
export type TabEntry = { readonly robot: string; readonly configuration: number; readonly tab: number };

/** The follower's configuration, read. */
export type FollowerConfig = {
  readonly answerUrl: string | undefined;
  readonly answerTopic: string | undefined;
  readonly tabs: readonly TabEntry[];
  /** The tab shown for an answer whose pair has no tab of its own; none when undefined. */
  readonly defaultTab: number | undefined;
};

/** The configuration and what was wrong with it, each problem naming its field. */
export type ConfigReading = { readonly config: FollowerConfig; readonly problems: readonly string[] };

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

function isIndex(value: unknown): value is number {
  return Number.isSafeInteger(value) && (value as number) >= 0;
}

const LOOPBACK_HOSTS = new Set(["localhost", "[::1]"]);

/** Why `text` is no address of an answer stream on this machine, or undefined when it is. */
export function loopbackProblem(text: string): string | undefined {
  let url: URL;
  try {
    url = new URL(text);
  } catch {
    return "is not an address";
  }
  if (url.protocol !== "http:" && url.protocol !== "https:") {
    return "is not an http or https address";
  }
  if (url.username !== "" || url.password !== "") {
    return "carries a user name or password";
  }
  // The URL parser writes every IPv4 spelling (0x7f.1, 2130706433) as dotted decimal.
  if (!LOOPBACK_HOSTS.has(url.hostname) && !/^127\.\d+\.\d+\.\d+$/.test(url.hostname)) {
    return "is not on this machine (loopback: 127.0.0.1, [::1], localhost)";
  }
  return undefined;
}

function readUrl(value: unknown, problems: string[]): string | undefined {
  if (value === undefined || value === null) {
    return undefined;
  }
  if (typeof value !== "string" || value.length > NAME_CHARS) {
    problems.push("answerUrl: not an address (a string)");
    return undefined;
  }
  const problem = loopbackProblem(value);
  if (problem !== undefined) {
    problems.push(`answerUrl ${problem}: answers are read only from a watcher on this machine`);
    return undefined;
  }
  return value;
}

function readTopic(value: unknown, problems: string[]): string | undefined {
  if (value === undefined || value === null) {
    return undefined;
  }
  if (typeof value !== "string" || !value.startsWith("/") || value.length > NAME_CHARS) {
    problems.push("answerTopic: not a full topic name (a string starting with /)");
    return undefined;
  }
  return value;
}

function readEntry(value: unknown, where: string, problems: string[]): TabEntry | undefined {
  if (!isRecord(value)) {
    problems.push(`${where}: not an object`);
    return undefined;
  }
  const { robot, configuration, tab } = value;
  if (typeof robot !== "string" || robot.length === 0 || robot.length > NAME_CHARS) {
    problems.push(`${where}.robot: not a robot name (a string)`);
    return undefined;
  }
  if (!isIndex(configuration)) {
    problems.push(`${where}.configuration: not a whole number`);
    return undefined;
  }
  if (!isIndex(tab)) {
    problems.push(`${where}.tab: not a tab index (a whole number from 0)`);
    return undefined;
  }
  return { robot, configuration, tab };
}

function readTabs(value: unknown, problems: string[]): TabEntry[] {
  if (!Array.isArray(value)) {
    problems.push("tabs: missing (a list of {robot, configuration, tab})");
    return [];
  }
  if (value.length > TABS_READ) {
    problems.push(`tabs: ${value.length} entries; the first ${TABS_READ} are read`);
  }
  const entries: TabEntry[] = [];
  const seen = new Set<string>();
  value.slice(0, TABS_READ).forEach((item: unknown, index) => {
    const entry = readEntry(item, `tabs[${index}]`, problems);
    if (entry === undefined) {
      return;
    }
    const key = pairKey(entry.robot, entry.configuration);
    if (seen.has(key)) {
      problems.push(`tabs[${index}]: the same robot and configuration as an earlier entry; ignored`);
      return;
    }
    seen.add(key);
    entries.push(entry);
  });
  return entries;
}

/** One key for a (robot, configuration) pair. */
export function pairKey(robot: string, configuration: number): string {
  return `${configuration} ${robot}`;
}

/** The follower's configuration from the panel's saved state (`context.initialState`). */
export function readConfig(state: unknown): ConfigReading {
  const problems: string[] = [];
  const fields = isRecord(state) ? state : {};
  if (!isRecord(state)) {
    problems.push("no configuration: this panel was not written by teleop-ui");
  }
  const answerUrl = readUrl(fields["answerUrl"], problems);
  const answerTopic = readTopic(fields["answerTopic"], problems);
  const tabs = readTabs(fields["tabs"], problems);
  let defaultTab: number | undefined;
  if (isIndex(fields["defaultTab"])) {
    defaultTab = fields["defaultTab"];
  } else if (fields["defaultTab"] !== undefined && fields["defaultTab"] !== null) {
    problems.push("defaultTab: not a tab index (a whole number from 0) or null");
  }
  if (answerUrl === undefined && answerTopic === undefined) {
    problems.push("neither answerTopic nor answerUrl: there are no answers to follow");
  }
  return { config: { answerUrl, answerTopic, tabs, defaultTab }, problems };
}
