// The watcher's answer, read the way every reader of it must read a stranger's text (docs/live.md:
// any participant of the graph can write `/teleop_ui/ui_configuration`): bounded before the JSON
// decoder runs (1 MiB, 64 levels, as the watcher and teleop-ui's operator station read it), then
// only the fields the follower needs, each checked. Nothing in an answer is code, markup or an
// address the follower visits: the team layout's path is kept as text to show, its URL is
// never read.

/** The longest answer read, in characters (the watcher's bound: 1 MiB). */
export const ANSWER_CHARS = 1_048_576;
/** The deepest answer read, in nested arrays and objects (the watcher's bound). */
export const ANSWER_LEVELS = 64;
/** The longest robot name, team-layout path or value kept from an answer. */
export const FIELD_CHARS = 4096;
/** How many values of the answer's combination are kept (to show). */
export const VALUES_KEPT = 16;
/** How many of the answer's reasons and notes are kept (to show). */
export const NOTES_KEPT = 4;

/** What the follower needs of an answer. */
export type Answer = {
  readonly robot: string;
  readonly configuration: number;
  /** The team's default configuration, given because the robot's own could not be. */
  readonly isDefault: boolean;
  /** The combination's values, in the answer's order (shown beside the robot). */
  readonly values: readonly string[];
  /** The watcher's team layout (`layouts.team`): where it is, and its tab for this answer
   * (none when its team layout has none: a configuration that is not one of the robot's own
   * combinations); undefined when the answer names no team layout. */
  readonly team: { readonly path: string | undefined; readonly tab: number | undefined } | undefined;
  /** Where the watcher wrote the robot's own layout of this configuration (`layouts.foxglove`). */
  readonly ownLayout: string | undefined;
  /** Why the default, and what the watcher noted (`reasons`, then `notes`), at most 4. */
  readonly notes: readonly string[];
};

/** An answer read: one, none (`null`: no active robot), or one that cannot be read, and why. */
export type Reading =
  | { readonly kind: "answer"; readonly answer: Answer }
  | { readonly kind: "none" }
  | { readonly kind: "unreadable"; readonly reason: string };

/** Whether `text` nests arrays and objects deeper than `limit`, found without decoding it (the
 * JSON decoder recurses, so `"[".repeat(200000)` must never reach it). */
export function nestedDeeper(text: string, limit: number): boolean {
  let depth = 0;
  let inString = false;
  for (let at = 0; at < text.length; at += 1) {
    const char = text[at];
    if (inString) {
      if (char === "\\") {
        at += 1;
      } else if (char === '"') {
        inString = false;
      }
    } else if (char === '"') {
      inString = true;
    } else if (char === "[" || char === "{") {
      depth += 1;
      if (depth > limit) {
        return true;
      }
    } else if (char === "]" || char === "}") {
      depth -= 1;
    }
  }
  return false;
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

function fieldText(value: unknown): string | undefined {
  if (typeof value === "string" && value.length > 0 && value.length <= FIELD_CHARS) {
    return value;
  }
  if (typeof value === "number" && Number.isFinite(value)) {
    return String(value);
  }
  return undefined;
}

function combinationValues(combination: unknown): string[] {
  if (!isRecord(combination)) {
    return [];
  }
  const values: string[] = [];
  for (const value of Object.values(combination)) {
    const text = fieldText(value);
    if (text !== undefined && values.length < VALUES_KEPT) {
      values.push(text);
    }
  }
  return values;
}

function pathOf(value: unknown): string | undefined {
  return typeof value === "string" && value.length > 0 && value.length <= FIELD_CHARS ? value : undefined;
}

function teamOf(layouts: unknown): Answer["team"] {
  if (!isRecord(layouts) || !isRecord(layouts["team"])) {
    return undefined;
  }
  const tab = layouts["team"]["tab"];
  return {
    path: pathOf(layouts["team"]["path"]),
    tab: Number.isSafeInteger(tab) && (tab as number) >= 0 ? (tab as number) : undefined,
  };
}

function ownLayoutOf(layouts: unknown): string | undefined {
  return isRecord(layouts) && isRecord(layouts["foxglove"]) ? pathOf(layouts["foxglove"]["path"]) : undefined;
}

function notesOf(value: Record<string, unknown>): string[] {
  const notes: string[] = [];
  for (const key of ["reasons", "notes"]) {
    const list = value[key];
    for (const item of Array.isArray(list) ? list : []) {
      if (typeof item === "string" && item.length > 0 && notes.length < NOTES_KEPT) {
        notes.push(item.slice(0, FIELD_CHARS));
      }
    }
  }
  return notes;
}

/** The answer in a decoded JSON value. */
export function answerOf(value: unknown): Reading {
  if (value === null) {
    return { kind: "none" };
  }
  if (!isRecord(value)) {
    return { kind: "unreadable", reason: "not a JSON object or null" };
  }
  const robot = value["robot"];
  if (typeof robot !== "string" || robot.length === 0 || robot.length > FIELD_CHARS) {
    return { kind: "unreadable", reason: "no robot name (a string) in it" };
  }
  const configuration = value["configuration"];
  if (!Number.isSafeInteger(configuration) || (configuration as number) < 0) {
    return { kind: "unreadable", reason: "its configuration is not a whole number" };
  }
  return {
    kind: "answer",
    answer: {
      robot,
      configuration: configuration as number,
      isDefault: value["default"] === true,
      values: combinationValues(value["combination"]),
      team: teamOf(value["layouts"]),
      ownLayout: ownLayoutOf(value["layouts"]),
      notes: notesOf(value),
    },
  };
}

/** The answer in `text` (a `std_msgs/String`'s data, or an event stream's `data:`), bounded. */
export function readAnswer(text: string): Reading {
  if (text.length > ANSWER_CHARS) {
    return { kind: "unreadable", reason: `longer than ${ANSWER_CHARS.toLocaleString("en-US")} characters` };
  }
  if (nestedDeeper(text, ANSWER_LEVELS)) {
    return { kind: "unreadable", reason: `nested deeper than ${ANSWER_LEVELS} levels` };
  }
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch {
    return { kind: "unreadable", reason: "not JSON" };
  }
  return answerOf(value);
}

/** The text of an answer topic's message (`std_msgs/String`: `{data: "..."}`), if it has one. */
export function messageText(message: unknown): string | undefined {
  return isRecord(message) && typeof message["data"] === "string" ? message["data"] : undefined;
}
