// What the follower says: every sentence it shows, made from a decision and the answer, with
// every string from an answer or a layout passed through `shown` (escaped; a robot name or a
// value cut to 60 characters; a path an operator must copy escaped but never cut). The panel
// puts them on screen with `textContent` only.

import type { Answer } from "./answer";
import { shown } from "./text";

/** How many characters of a reason or note from the watcher are shown. */
export const NOTE_CHARS = 200;

/** `/uav1 · UI configuration 3`: what is on screen. */
export function onScreen(robot: string, configuration: number): string {
  return `${shown(robot)} · UI configuration ${configuration}`;
}

/** The combination's values, whether it is the team's default, and the tab. */
export function detail(answer: Answer | undefined, tab: number): string {
  const values = (answer?.values ?? []).map((value) => shown(value)).join(", ");
  const isDefault = answer?.isDefault === true ? " (the team's default configuration)" : "";
  const separator = values === "" && isDefault === "" ? "" : " · ";
  return `${values}${isDefault}${separator}tab ${tab + 1} of the team layout`;
}

/** The watcher's reasons and notes for the answer, one after another. */
export function notes(answer: Answer | undefined): string {
  return (answer?.notes ?? []).map((note) => shown(note, NOTE_CHARS)).join(" · ");
}

/** How to get a team layout that has the tab: import it again (from where, when known). */
export function reimport(path: string | undefined): string {
  return path === undefined
    ? "Re-import the team layout."
    : `Re-import the team layout: ${shown(path, null)}`;
}

/** Why an answer's robot and configuration have no tab here, and what to do, if anything. */
export function noTab(robot: string, configuration: number, answer: Answer | undefined): string {
  const pair = `${shown(robot)}, UI configuration ${configuration}`;
  const team = answer?.team;
  if (team !== undefined && team.tab === undefined) {
    // The watcher's own team layout has no tab for it either: it holds the robots' own
    // combinations, and this one is not (a mode the robot was asked for and does not offer).
    const own = answer?.ownLayout === undefined ? "" : ` Its own layout: ${shown(answer.ownLayout, null)}`;
    return (
      `No tab for ${pair}: the team layout holds each robot's own combinations, and this is ` +
      `not one of them. The screen is unchanged.${own}`
    );
  }
  if (team !== undefined && team.tab !== undefined) {
    return (
      `No tab for ${pair} in this team layout; the watcher's team layout has one (tab ` +
      `${team.tab + 1}): the screen is unchanged. ${reimport(team.path)}`
    );
  }
  return (
    `No tab for ${pair} in this team layout: the screen is unchanged. If robots joined or ` +
    `changed since it was written, re-import it.`
  );
}

/** Said beside the default tab, shown for a pair with no tab of its own. */
export function defaultShown(answer: Answer | undefined): string {
  const again = reimport(answer?.team?.path);
  return `This team layout has no tab of its own for it: the default tab is shown. ${again}`;
}

/** The answer is null. */
export const NO_ROBOT = "No active robot (the watcher's answer is null): the screen is unchanged.";

/** An answer that could not be read. */
export function unreadable(reason: string): string {
  return `An answer could not be read (${reason}): ignored.`;
}

/** The Tab panel beside has fewer tabs than this layout's tab for the pair. */
export function tabMissing(
  tabs: number,
  tab: number,
  robot: string,
  configuration: number,
  path: string | undefined,
): string {
  return (
    `The Tab panel beside this one has ${tabs} tabs, and this layout's tab for ` +
    `${shown(robot)}, UI configuration ${configuration} is number ${tab + 1}: the screen is ` +
    `unchanged. ${reimport(path)}`
  );
}

/** The follower is not beside the team's Tab panel: it stops switching. */
export function notBeside(path: string | undefined): string {
  return (
    "This panel is not beside the team layout's Tab panel, so it cannot switch tabs " +
    "(Lichtblick lets a panel change only the panel beside it). " +
    `${reimport(path)} Leave this panel where the team layout puts it.`
  );
}
