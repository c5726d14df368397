// The follower panel in the app: reads the watcher's answers (the answer topic through the data
// source, and/or the watcher's event stream on loopback), and puts the answer's tab of the team
// layout on screen by rewriting the Tab panel beside it (`context.layout.addPanel` with
// `updateIfExists`: Lichtblick's only layout action for an extension, which rewrites the config of
// the panel on the other branch of the caller's split when it has the given type). Plain DOM;
// every string from an answer or a layout reaches the screen through `textContent` and `shown`.

import type {
  Immutable,
  MessageEvent,
  PanelExtensionContext,
  RenderState,
} from "@lichtblick/suite";

import { type Answer, type Reading, messageText, readAnswer } from "./answer";
import { type FollowerConfig, readConfig } from "./config";
import { type Decision, TabIndex, withActiveTab } from "./follow";
import * as say from "./messages";
import { shown } from "./text";

/** What the follower records of each answer, in `window.__teleopUi.timings`, for the measuring
 * tool (tools/lichtblick/follow.py); times are the page's `performance.now()`. */
export type Timing = {
  readonly source: "topic" | "url";
  /** When the answer reached the follower. */
  readonly received: number;
  /** What came of it: a decision's kind, then the Tab panel's answer (`switched`, `not-beside`,
   * `no-tab`), or `repeated` (the same text as the answer before: nothing to do). */
  outcome: string;
  robot?: string;
  configuration?: number;
  tab?: number;
  /** When the follower asked the app to rewrite the Tab panel. */
  requested?: number;
  /** When the app took the Tab panel's new state (its panels are drawn from it next). */
  applied?: number;
};

/** How many timings are kept. */
export const TIMINGS_KEPT = 200;
/** How long the follower waits before opening an event stream the server closed again. */
export const REOPEN_MS = 5000;

declare global {
  interface Window {
    __teleopUi?: { timings: Timing[] };
  }
}

function record(timing: Timing): void {
  const store = (window.__teleopUi ??= { timings: [] });
  store.timings.push(timing);
  if (store.timings.length > TIMINGS_KEPT) {
    store.timings.splice(0, store.timings.length - TIMINGS_KEPT);
  }
}

const WARNING_COLOR = "#e8a33d";

function line(parent: HTMLElement, role: string, style: string): HTMLElement {
  const element = document.createElement("div");
  element.dataset["teleopUi"] = role;
  element.style.cssText = style;
  parent.appendChild(element);
  return element;
}

/** The follower panel on `context.panelElement`; `close()` ends its streams. */
export class Follower {
  readonly #context: PanelExtensionContext;
  readonly #config: FollowerConfig;
  readonly #index: TabIndex;
  readonly #screen: HTMLElement;
  readonly #detail: HTMLElement;
  readonly #warning: HTMLElement;
  readonly #notes: HTMLElement;
  readonly #sources: HTMLElement;
  #topicState = "waiting for it on the data source";
  #streamState = "connecting";
  #subscribed = false;
  #stream: EventSource | undefined;
  #reopen: ReturnType<typeof setTimeout> | undefined;
  #lastText: string | undefined;
  /** Where the watcher's team layout is, as the last answer that said so said. */
  #teamPath: string | undefined;
  /** Why the follower stopped switching (it is not beside the team's Tab panel). */
  #stopped: string | undefined;
  #closed = false;

  public constructor(context: PanelExtensionContext) {
    this.#context = context;
    const { config, problems } = readConfig(context.initialState);
    this.#config = config;
    this.#index = new TabIndex(config);
    const root = document.createElement("div");
    root.style.cssText =
      "box-sizing:border-box;height:100%;overflow:auto;padding:8px 10px;" +
      "font:12px/1.45 system-ui,sans-serif;overflow-wrap:anywhere";
    this.#screen = line(root, "screen", "font-size:15px;font-weight:600");
    this.#detail = line(root, "detail", "margin-top:2px");
    this.#warning = line(root, "warning", `margin-top:6px;color:${WARNING_COLOR}`);
    this.#notes = line(root, "notes", "margin-top:4px;opacity:0.85");
    this.#sources = line(root, "sources", "margin-top:8px;opacity:0.7");
    const faults = line(root, "problems", `margin-top:6px;color:${WARNING_COLOR}`);
    for (const problem of problems) {
      line(faults, "problem", "").textContent = `layout: ${shown(problem, null)}`;
    }
    this.#screen.textContent = "Waiting for the watcher's answer";
    context.panelElement.replaceChildren(root);
    context.setDefaultPanelTitle("teleop-ui follower");
    if (config.answerTopic !== undefined) {
      context.watch("topics");
      context.watch("currentFrame");
      context.onRender = (state, done) => {
        this.#render(state);
        done();
      };
    }
    if (config.answerUrl !== undefined) {
      this.#open(config.answerUrl);
    }
    this.#showSources();
  }

  public close(): void {
    this.#closed = true;
    this.#stream?.close();
    clearTimeout(this.#reopen);
    this.#context.unsubscribeAll();
  }

  #render(state: Immutable<RenderState>): void {
    const topic = this.#config.answerTopic;
    if (topic === undefined) {
      return;
    }
    if (!this.#subscribed && state.topics?.some((each) => each.name === topic) === true) {
      this.#context.subscribe([{ topic }]);
      this.#subscribed = true;
      this.#topicState = "subscribed";
      this.#showSources();
    }
    let last: Immutable<MessageEvent> | undefined;
    for (const event of state.currentFrame ?? []) {
      if (event.topic === topic) {
        last = event;
      }
    }
    if (last !== undefined) {
      const text = messageText(last.message);
      this.#receive(text ?? "", "topic", text === undefined ? "not a std_msgs/String" : undefined);
    }
  }

  #open(url: string): void {
    const stream = new EventSource(url);
    this.#stream = stream;
    stream.onopen = () => {
      this.#streamState = "connected";
      this.#showSources();
    };
    stream.onmessage = (event: globalThis.MessageEvent<unknown>) => {
      this.#receive(typeof event.data === "string" ? event.data : "", "url", undefined);
    };
    stream.onerror = () => {
      if (stream.readyState === EventSource.CLOSED) {
        // Refused (an HTTP error, not an event stream, or no CORS for this page's origin): the
        // browser does not retry by itself.
        this.#streamState = `refused; trying again every ${REOPEN_MS / 1000} s`;
        if (!this.#closed) {
          this.#reopen = setTimeout(() => this.#open(url), REOPEN_MS);
        }
      } else {
        this.#streamState = "not reachable; retrying";
      }
      this.#showSources();
    };
  }

  #receive(text: string, source: Timing["source"], unreadable: string | undefined): void {
    const received = performance.now();
    if (unreadable === undefined && text === this.#lastText) {
      record({ source, received, outcome: "repeated" });
      return;
    }
    this.#lastText = text;
    const reading: Reading =
      unreadable === undefined ? readAnswer(text) : { kind: "unreadable", reason: unreadable };
    const decision = this.#index.decide(reading);
    const timing: Timing = { source, received, outcome: decision.kind };
    record(timing);
    const answer = reading.kind === "answer" ? reading.answer : undefined;
    this.#teamPath = answer?.team?.path ?? this.#teamPath;
    this.#notes.textContent = say.notes(answer);
    this.#act(decision, answer, timing);
  }

  #act(decision: Decision, answer: Answer | undefined, timing: Timing): void {
    switch (decision.kind) {
      case "switch":
      case "default":
        timing.robot = shown(decision.robot, 200);
        timing.configuration = decision.configuration;
        timing.tab = decision.tab;
        this.#switchTo(decision, answer, timing);
        return;
      case "missing":
        this.#warn(say.noTab(decision.robot, decision.configuration, answer));
        return;
      case "none":
        this.#warn(say.NO_ROBOT);
        return;
      case "unreadable":
        this.#warn(say.unreadable(decision.reason));
        return;
    }
  }

  #switchTo(
    decision: Decision & { kind: "switch" | "default" },
    answer: Answer | undefined,
    timing: Timing,
  ): void {
    if (this.#stopped !== undefined) {
      timing.outcome = "not-beside";
      this.#warn(this.#stopped);
      return;
    }
    timing.requested = performance.now();
    this.#context.layout.addPanel({
      position: "sibling",
      type: "Tab",
      updateIfExists: true,
      getState: (existing?: unknown) => {
        const result = withActiveTab(existing, decision.tab);
        timing.applied = performance.now();
        timing.outcome = result.kind;
        if (result.kind === "switched") {
          this.#showScreen(decision, answer);
        } else if (result.kind === "no-tab") {
          const { robot, configuration, tab } = decision;
          this.#warn(say.tabMissing(result.tabs, tab, robot, configuration, this.#teamPath));
        } else {
          this.#stopped = say.notBeside(this.#teamPath);
          this.#warn(this.#stopped);
        }
        return result.state;
      },
    });
  }

  #showScreen(
    decision: Decision & { kind: "switch" | "default" },
    answer: Answer | undefined,
  ): void {
    this.#screen.textContent = say.onScreen(decision.robot, decision.configuration);
    this.#detail.textContent = say.detail(answer, decision.tab);
    this.#warn(decision.kind === "default" ? say.defaultShown(answer) : "");
  }

  #warn(text: string): void {
    this.#warning.textContent = text;
  }

  #showSources(): void {
    const parts: string[] = [];
    if (this.#config.answerTopic !== undefined) {
      parts.push(`topic ${shown(this.#config.answerTopic, null)}: ${this.#topicState}`);
    }
    if (this.#config.answerUrl !== undefined) {
      parts.push(`${shown(this.#config.answerUrl, null)}: ${this.#streamState}`);
    }
    this.#sources.textContent = parts.length === 0 ? "" : `Answers from ${parts.join("; ")}`;
  }
}

/** `initPanel` of the follower panel. */
export function initFollower(context: PanelExtensionContext): () => void {
  const follower = new Follower(context);
  return () => {
    follower.close();
  };
}
