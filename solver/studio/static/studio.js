// teleop-ui studio: small progressive scripts over server-rendered pages.
// Without this file every page still works (forms submit, links navigate); with it the
// selection answers as you click (GET /api/solve, the JSON of `teleop-ui solve --format json`),
// the last change's cost is shown, undo and redo work, and the live page follows its events.
// Nothing is loaded from elsewhere; text from the server is set with textContent.
"use strict";

(function () {
  const form = document.querySelector("form[data-selection]");
  if (form) {
    selectionPage(form);
  }
  const live = document.getElementById("live");
  if (live) {
    livePage(live);
  }

  function selectionPage(form) {
    let current = selectionQuery();
    let shown = null; // the totals last shown, to say what a change cost
    let asked = 0; // answers to older questions are dropped
    // Undo and Redo walk the browser's history of this page's changes, as Back and Forward do:
    // one history, whichever way a step is taken. Each change is an entry numbered "index";
    // Undo stops at the entry the page was loaded at, Redo at the newest change.
    // A change to the rule set (what-if's) loads the page anew: the entry it pushed says where
    // Undo stops (floor) and Redo (top), so Undo walks back into the rule set before.
    const state = window.history.state;
    let index = state && Number.isInteger(state.index) ? state.index : 0;
    const floor = state && Number.isInteger(state.floor) ? state.floor : index;
    let top = state && Number.isInteger(state.top) ? state.top : index;
    const undo = document.getElementById("undo");
    const redo = document.getElementById("redo");
    const historyButtons = document.querySelector("[data-history]");
    if (historyButtons) {
      historyButtons.hidden = false;
    }
    const initial = readTotals();
    if (initial) {
      shown = initial;
    }
    window.history.replaceState(entry(current), "", "/?" + withView(current));
    buttons(); // a page loaded by a change to the rule set may step back at once

    // What each part of the page shows, by the selection it answers: the totals, the radar
    // chart and the check's findings. When all three answer the selection the page holds, the
    // form says so (data-settled) and the document hears "studio:settled"; until then a part
    // still answering an older selection says so itself (the chart is marked as being redrawn).
    const answered = { totals: current, chart: null, findings: null };
    const figure = document.getElementById("radar-figure");
    // The radar chart is drawn into the page (inline SVG, not an image): each type's values on
    // each spoke and each legend entry is a stop of the keyboard, and what the pointer is over
    // or the keyboard is on is said below the chart (#radar-value).
    const holder = document.getElementById("radar");
    let drawing = 0;
    const summary = document.getElementById("check-summary");
    if (summary && summary.dataset.query) {
      answered.findings = current;
    }
    if (figure && holder) {
      const say = (event) => {
        const stop = event.target.closest && event.target.closest("[aria-label]");
        if (stop && holder.contains(stop) && stop !== holder) {
          setText("radar-value", stop.getAttribute("aria-label"));
        }
      };
      holder.addEventListener("focusin", say);
      holder.addEventListener("mouseover", say);
      if (figure.hidden) {
        answered.chart = current;
      } else {
        chartState("drawing", "Drawing the chart…");
        draw(figure.dataset.query);
      }
    } else {
      answered.chart = current;
    }
    settle();

    form.addEventListener("change", (event) => {
      const target = event.target;
      if (target.matches("[data-reload]")) {
        // Another rule set has other controls: ask the server for the page.
        window.location.assign("/?" + new URLSearchParams({ rules: target.value }).toString());
        return;
      }
      if (target.matches("[data-include]")) {
        enableType(target.closest("fieldset.type"), target.checked);
        startSmall(target.closest("fieldset.type"), target.checked);
      }
      if (target.type === "range") {
        keepOrder(target);
        showRange(target);
      }
      changed();
    });
    form.addEventListener("input", (event) => {
      if (event.target.type === "range") {
        showRange(event.target);
      }
    });
    form.addEventListener("submit", (event) => {
      event.preventDefault();
      changed();
    });
    if (undo && redo) {
      undo.addEventListener("click", () => step(-1));
      redo.addEventListener("click", () => step(1));
    }
    // A what-if suggestion applied is a change like any other: one entry of the history.
    const suggestions = document.getElementById("whatif");
    if (suggestions) {
      suggestions.addEventListener("click", (event) => {
        const rulesChange = event.target.closest("button[data-apply-rules]");
        if (rulesChange) {
          event.preventDefault();
          applyRules(rulesChange.dataset.applyRules);
          return;
        }
        const link = event.target.closest("a[data-apply]");
        if (!link) {
          return;
        }
        event.preventDefault();
        const query = link.dataset.apply;
        if (new URLSearchParams(query).get("rules") !== form.elements.rules.value) {
          window.location.assign("/?" + query);
          return;
        }
        apply(query);
        changed();
      });
    }
    document.addEventListener("keydown", (event) => {
      const typing = event.target.matches("input[type=text], input:not([type]), textarea");
      if (typing || !(event.ctrlKey || event.metaKey)) {
        return;
      }
      const key = event.key.toLowerCase();
      if (key === "z" && !event.shiftKey) {
        event.preventDefault();
        step(-1);
      } else if ((key === "z" && event.shiftKey) || key === "y") {
        event.preventDefault();
        step(1);
      }
    });
    window.addEventListener("popstate", (event) => {
      const entry = event.state || {};
      const query = entry.query || window.location.search.slice(1);
      if (Number.isInteger(entry.index)) {
        index = entry.index;
      }
      if (new URLSearchParams(query).get("rules") !== form.elements.rules.value) {
        window.location.reload(); // this entry, under its own rule set (its state kept)
        return;
      }
      apply(query);
      current = selectionQuery();
      ask(current);
    });

    function entry(query) {
      return { query, index, floor, top };
    }

    // What-if's change to the rule set: the studio keeps the changed rule set (as an upload)
    // and answers the same selection under it; that is one new entry of the history, and the
    // page is loaded anew under it (Back and Undo come back to this entry).
    async function applyRules(query) {
      let data = null;
      try {
        const response = await fetch("/api/whatif/apply?" + query, {
          method: "POST",
          headers: { accept: "application/json" },
        });
        data = await response.json();
        if (!response.ok) {
          setText("whatif-summary", "Not applied: " + (data.error || response.status));
          return;
        }
      } catch (error) {
        setText("whatif-summary", "Not applied: the studio did not answer");
        return;
      }
      top = index + 1;
      window.history.replaceState(entry(current), "", "/?" + withView(current));
      index = top;
      window.history.pushState(entry(data.query), "", "/?" + withView(data.query));
      window.location.reload();
    }

    function changed() {
      const query = selectionQuery();
      if (query === current) {
        return;
      }
      current = query;
      index += 1;
      top = index;
      window.history.pushState(entry(query), "", "/?" + withView(query));
      ask(query);
    }

    // One step back (-1) or forward (1) through the changes: the browser's own, so Back,
    // Forward, Undo and Redo agree; popstate applies the selection it comes to.
    function step(delta) {
      if (delta < 0 ? index <= floor : index >= top) {
        return;
      }
      window.history.go(delta);
    }

    function buttons() {
      if (undo && redo) {
        undo.disabled = index <= floor;
        redo.disabled = index >= top;
      }
    }

    function withView(query) {
      const view = form.elements.view ? form.elements.view.value : "all";
      return view && view !== "all" ? query + "&view=" + encodeURIComponent(view) : query;
    }

    // The selection as the address holds it: a characteristic with every value ticked is left
    // out (every value), one with none ticked is "T.c=" (none), a full range is left out.
    function selectionQuery() {
      const params = new URLSearchParams();
      params.append("rules", form.elements.rules.value);
      const name = form.elements.name.value.trim();
      if (name) {
        params.append("name", name);
      }
      const types = form.querySelectorAll("input[data-include]");
      for (const box of types) {
        if (box.checked) {
          params.append("type", box.value);
        }
      }
      for (const box of types) {
        if (!box.checked) {
          continue;
        }
        const type = box.closest("fieldset.type");
        // A type this page does not draw carries its part of the selection as it came.
        for (const carried of type.querySelectorAll("input[data-carried]")) {
          params.append(carried.name, carried.value);
        }
        for (const group of type.querySelectorAll("fieldset.characteristic")) {
          const key = group.dataset.key;
          if (group.dataset.kind === "integer") {
            const low = group.querySelector("input[data-low]");
            const high = group.querySelector("input[data-high]");
            const lowest = low.min;
            const highest = high.max;
            if (low.value === lowest && high.value === highest) {
              continue;
            }
            if (low.value !== lowest) {
              params.append(key + ".min", low.value);
            }
            params.append(key + ".max", high.value);
            continue;
          }
          const boxes = [...group.querySelectorAll("input[type=checkbox]")];
          const kept = [...group.querySelectorAll("input[type=hidden]")].filter((h) => h.value !== "");
          const open = boxes.filter((b) => !b.disabled);
          if (kept.length === 0 && open.every((b) => b.checked)) {
            continue;
          }
          const chosen = [...open.filter((b) => b.checked).map((b) => b.value), ...kept.map((h) => h.value)];
          if (!chosen.length) {
            params.append(key, "");
          }
          for (const value of chosen) {
            params.append(key, value);
          }
        }
      }
      return params.toString();
    }

    function apply(query) {
      const params = new URLSearchParams(query);
      form.elements.name.value = params.get("name") || "";
      const types = params.getAll("type");
      for (const box of form.querySelectorAll("input[data-include]")) {
        box.checked = types.includes(box.value);
        enableType(box.closest("fieldset.type"), box.checked);
      }
      for (const group of form.querySelectorAll("fieldset.characteristic")) {
        const key = group.dataset.key;
        if (group.dataset.kind === "integer") {
          const low = group.querySelector("input[data-low]");
          const high = group.querySelector("input[data-high]");
          low.value = params.get(key + ".min") || low.min;
          high.value = params.get(key + ".max") || high.max;
          showRange(low);
          showRange(high);
          continue;
        }
        const present = params.has(key);
        const values = params.getAll(key).filter((v) => v !== "");
        for (const box of group.querySelectorAll("input[type=checkbox]")) {
          if (!box.disabled) {
            box.checked = !present || values.includes(box.value);
          }
        }
      }
    }

    // A type ticked starts from a small selection, not everything: the first value the rules
    // allow it of each characteristic and the counts of the first arrangement; the page says
    // which, and every other value is a tick away.
    function startSmall(fieldset, on) {
      const note = fieldset.querySelector(".start-note");
      if (!on) {
        if (note) {
          note.hidden = true;
        }
        return;
      }
      const parts = [];
      for (const group of fieldset.querySelectorAll("fieldset.characteristic")) {
        const name = group.querySelector("legend .name");
        const label = name ? name.textContent.replace(/[()]/g, "") : group.dataset.key;
        if (group.dataset.kind === "integer") {
          const low = group.querySelector("input[data-low]");
          const high = group.querySelector("input[data-high]");
          low.value = low.min;
          high.value = high.dataset.startMost || high.max;
          showRange(low);
          showRange(high);
          parts.push(`${label} ${low.value}..${high.value}`);
          continue;
        }
        const boxes = [...group.querySelectorAll("input[type=checkbox]")].filter((b) => !b.disabled);
        const first = boxes.find((b) => b.hasAttribute("data-start"));
        if (!first) {
          continue;
        }
        for (const box of boxes) {
          box.checked = box === first;
        }
        parts.push(`${label} ${first.value}`);
      }
      if (note && parts.length) {
        note.textContent = `Started from a small selection: ${parts.join("; ")}. Tick more values to widen it.`;
        note.hidden = false;
      }
    }

    function enableType(fieldset, on) {
      fieldset.classList.toggle("included", on);
      for (const group of fieldset.querySelectorAll("fieldset.characteristic")) {
        group.disabled = !on;
      }
    }

    function keepOrder(range) {
      const group = range.closest("fieldset.characteristic");
      const low = group.querySelector("input[data-low]");
      const high = group.querySelector("input[data-high]");
      if (Number(low.value) > Number(high.value)) {
        if (range === low) {
          high.value = low.value;
          showRange(high);
        } else {
          low.value = high.value;
          showRange(low);
        }
      }
    }

    function showRange(range) {
      const output = document.getElementById(range.id + "-out");
      if (output) {
        output.textContent = range.value;
      }
    }

    async function ask(query) {
      buttons();
      keepLinks(query);
      // The header names the team as the page now has it (renamed, or undone).
      setText("context-team", form.elements.name.value.trim() || "studio team");
      const mine = ++asked;
      stale(query);
      findings(query);
      whatIf(query);
      const types = new URLSearchParams(query).getAll("type");
      if (!types.length) {
        clearTotals();
        answer("totals", query);
        if (figure) {
          figure.hidden = true;
          chartState("none", "");
        }
        answer("chart", query);
        return;
      }
      let response;
      let data;
      try {
        response = await fetch("/api/solve?" + query, { headers: { accept: "application/json" } });
        data = await response.json();
      } catch (error) {
        if (mine === asked) {
          showFaults([{ file: "<studio>", path: "", message: "the studio does not answer: " + error }]);
          unanswered(query);
        }
        return;
      }
      if (mine !== asked) {
        return;
      }
      if (!response.ok) {
        showFaults(data.faults && data.faults.length ? data.faults : [{ file: "<studio>", path: "", message: data.error }]);
        unanswered(query);
        return;
      }
      showFaults([]);
      showTotals(data);
      document.getElementById("totals").dataset.query = query;
      answer("totals", query);
      redraw(query);
    }

    // A change was made: every part still shows the selection before it until it answers.
    function stale(query) {
      delete form.dataset.settled;
      form.dataset.current = query;
      if (figure && !figure.hidden) {
        chartState("stale", "Redrawing the chart for this selection…");
      }
      if (summary) {
        summary.closest("section").setAttribute("aria-busy", "true");
        form.dataset.findingsStale = "";
      }
    }

    // The selection cannot be solved: the totals and the chart keep the last one that could,
    // and say so.
    function unanswered(query) {
      const totals = document.getElementById("totals");
      if (totals.dataset.query) {
        totals.dataset.stale = "";
        setText("change", "Not updated: the selection has problems; the counts are the last ones without.");
      }
      answer("totals", query);
      if (figure && !figure.hidden) {
        chartState("stale", "Not redrawn: the selection has problems; the chart shows the last one without.");
      }
      answer("chart", query);
    }

    function redraw(query) {
      if (!figure || !holder) {
        answer("chart", query);
        return;
      }
      figure.hidden = false;
      if (figure.dataset.query === query && figure.dataset.state === "drawn" && holder.querySelector("svg")) {
        answer("chart", query); // the chart on show already is this selection's (undo)
        return;
      }
      chartState(figure.dataset.query ? "stale" : "drawing", "Redrawing the chart for this selection…");
      draw(query);
    }

    // The panel's radar chart of `query`, fetched and put in the page (the studio escapes
    // every text in it; the page's policy runs no script from it); a newer one replaces it.
    async function draw(query) {
      const mine = ++drawing;
      let svg = null;
      try {
        const response = await fetch("/api/charts/panel.svg?" + query);
        if (response.ok) {
          const parsed = new DOMParser().parseFromString(await response.text(), "image/svg+xml");
          if (parsed.documentElement.localName === "svg") {
            svg = document.importNode(parsed.documentElement, true);
          }
        }
      } catch (error) {
        svg = null;
      }
      if (mine !== drawing) {
        return; // an older chart, replaced since
      }
      figure.dataset.query = query;
      if (svg) {
        // Sized by the page (its viewBox keeps its shape), not in points.
        svg.removeAttribute("width");
        svg.removeAttribute("height");
        holder.replaceChildren(svg);
        setText("radar-value", "");
        chartState("drawn", "");
      } else {
        chartState("failed", "The chart could not be drawn (the studio's console says why).");
      }
      answer("chart", query);
    }

    function chartState(state, text) {
      if (!figure) {
        return;
      }
      figure.dataset.state = state;
      figure.setAttribute("aria-busy", state === "stale" || state === "drawing" ? "true" : "false");
      setText("radar-state", text);
    }

    function answer(part, query) {
      answered[part] = query;
      settle();
    }

    function settle() {
      form.dataset.current = current;
      if (answered.totals === current && answered.chart === current && answered.findings === current) {
        if (form.dataset.settled !== current) {
          form.dataset.settled = current;
          document.dispatchEvent(new CustomEvent("studio:settled", { detail: { query: current } }));
        }
      } else {
        delete form.dataset.settled;
      }
    }

    // What-if for the selection: the single changes that save configurations, each with an
    // Apply link (a change of this page, so undo holds it; without scripts the link opens it).
    // Asked for only once the selection has rested WHATIF_REST ms (a few quick ticks ask once),
    // after the page's load (never with it), and in a slot of the studio's own, so the totals
    // never wait for it; an answer "superseded" (a newer what-if was asked) is dropped.
    const WHATIF_REST = 400;
    let wondering = 0;
    let resting = null;
    // Never part of the page's load: asked for once the page has loaded (unless the page came
    // with it, asked for by whatif=1).
    const wanted = document.getElementById("whatif-section");
    if (wanted && !wanted.dataset.query) {
      whatIf(current);
    }
    function whatIf(query) {
      const section = document.getElementById("whatif-section");
      if (!section) {
        return;
      }
      const mine = ++wondering;
      section.setAttribute("aria-busy", "true");
      section.dataset.state = "waiting";
      window.clearTimeout(resting);
      resting = window.setTimeout(() => wonder(query, mine), WHATIF_REST);
    }

    async function wonder(query, mine) {
      const section = document.getElementById("whatif-section");
      const list = document.getElementById("whatif");
      section.dataset.state = "asking";
      let data = null;
      if (new URLSearchParams(query).getAll("type").length) {
        try {
          const response = await fetch("/api/whatif?" + query, { headers: { accept: "application/json" } });
          if (response.status === 409 && mine === wondering) {
            whatIf(query); // dropped for another page's newer what-if: this page asks again
            return;
          }
          data = response.ok ? await response.json() : null;
        } catch (error) {
          data = null;
        }
      }
      if (mine !== wondering) {
        return;
      }
      list.replaceChildren();
      const left = document.getElementById("whatif-left");
      if (left) {
        left.replaceChildren();
      }
      let text = "";
      if (data) {
        text = whatIfSummary(data);
        for (const found of data.suggestions) {
          list.append(suggestionItem(found));
        }
        for (const found of data.left_out) {
          const item = document.createElement("li");
          item.textContent = `${found.change}: ${found.reason}`;
          left.append(item);
        }
      }
      setText("whatif-summary", text);
      section.dataset.query = data ? query : "";
      section.dataset.state = data ? "answered" : "none";
      section.setAttribute("aria-busy", "false");
    }

    function whatIfSummary(data) {
      let text = `${data.tried} of ${data.total} changes tried`;
      if (data.stopped) {
        text += ` (the rest not: ${data.stopped})`;
      }
      if (data.left_out_count) {
        text += `; ${data.left_out_count} not counted (below, why)`;
      }
      return data.suggestions.length
        ? `Single changes that save UI configurations, most saved first (counted exactly; ${text}):`
        : `No single change saves a UI configuration (${text}).`;
    }

    // A change of a count as the suggestions show it: -32, +12 (removing a constraint gains).
    function signed(change) {
      return change > 0 ? `+${change}` : change < 0 ? `-${-change}` : "0";
    }

    function suggestionItem(found) {
      const item = document.createElement("li");
      item.dataset.saved = String(found.ui_configurations_saved);
      item.dataset.lost = String(found.valid_robots_lost);
      const change = document.createElement("span");
      change.className = "whatif-change";
      change.textContent = found.change;
      const saved = document.createElement("strong");
      saved.textContent = `${signed(-found.ui_configurations_saved)} configurations`;
      let link;
      if (found.rules_change) {
        // A change to the rule set is kept by the studio: a form, posted (or by applyRules).
        link = document.createElement("form");
        link.className = "whatif-apply";
        link.method = "post";
        link.action = "/whatif/apply?" + found.query;
        const button = document.createElement("button");
        button.type = "submit";
        button.dataset.applyRules = found.query;
        button.setAttribute("aria-label", "Apply: " + found.change);
        button.textContent = "Apply";
        link.append(button);
      } else {
        link = document.createElement("a");
        link.href = "/?" + found.query;
        link.dataset.apply = found.query;
        link.setAttribute("aria-label", "Apply: " + found.change);
        link.textContent = "Apply";
      }
      item.append(change, ": ", saved, `, ${signed(-found.valid_robots_lost)} valid robots `, link);
      return item;
    }

    let checking = 0;
    async function findings(query) {
      const mine = ++checking;
      let data = null;
      try {
        const response = await fetch("/api/findings?" + query, { headers: { accept: "application/json" } });
        if (response.ok) {
          data = await response.json();
        }
      } catch (error) {
        data = null;
      }
      if (mine !== checking) {
        return;
      }
      placeFindings(data, query);
      delete form.dataset.findingsStale;
      if (summary) {
        summary.closest("section").setAttribute("aria-busy", "false");
        summary.dataset.query = data ? query : "";
      }
      answer("findings", query);
    }

    // Each finding at the controls it concerns (a value of the rules: that value in every type;
    // nothing in particular: the general list), as the server draws them (templates/findings.html).
    function placeFindings(data, query) {
      const slots = [...document.querySelectorAll("ul[data-findings]")];
      for (const slot of slots) {
        slot.replaceChildren();
      }
      if (!summary) {
        return;
      }
      if (!data) {
        summary.textContent = "The check could not run on this selection (see its problems above).";
        return;
      }
      data.findings.forEach((finding, index) => {
        const places = finding.places.length ? finding.places : [{ type: "", characteristic: "", value: "" }];
        const here = slots.filter((slot) => places.some((place) => fits(slot.dataset, place)));
        for (const slot of here) {
          slot.append(findingItem(finding, index, data.rules, query));
        }
      });
      const counts = data.summary;
      const code = document.createElement("code");
      code.textContent = "teleop-ui check";
      const all = document.createElement("a");
      all.href = "/check?" + query;
      all.textContent = "all on the Check page";
      summary.replaceChildren(
        code,
        `: ${many(counts.error, "error")}, ${many(counts.warning, "warning")}, ${many(counts.info, "note")}; each is shown at the value, characteristic or type it concerns (`,
        all,
        ").",
      );
    }

    function fits(slot, place) {
      return (
        slot.placeCharacteristic === place.characteristic &&
        slot.placeValue === place.value &&
        (slot.placeType === place.type || (place.type === "" && place.characteristic !== ""))
      );
    }

    function findingItem(finding, index, rules, query) {
      const item = document.createElement("li");
      item.className = "finding " + finding.level;
      const level = document.createElement("span");
      level.className = "level";
      level.textContent = finding.level;
      const id = document.createElement("code");
      id.className = "check-id";
      id.textContent = finding.check;
      const where = document.createElement("a");
      where.className = "where";
      if (finding.file === "<selection>") {
        where.href = "/check?" + query + "#finding-" + index;
        where.textContent = "<selection>: " + (finding.path || "the selection");
      } else {
        where.href = "/rules/source?" + new URLSearchParams({ rules }).toString() + "#L" + finding.line;
        where.textContent = `${finding.file}:${finding.line}:${finding.column}`;
      }
      item.append(level, " ", id, " " + finding.message + " ", where);
      return item;
    }

    function keepLinks(query) {
      for (const link of document.querySelectorAll("a[data-keep-selection]")) {
        const url = new URL(link.href, window.location.href);
        link.href = url.pathname + "?" + query;
      }
      for (const link of document.querySelectorAll("a[data-view-link]")) {
        link.href = "/?" + query + "&view=" + encodeURIComponent(link.dataset.viewLink);
      }
      // An upload that fails leads back to the selection under way.
      for (const upload of document.querySelectorAll("form.upload[action^='/team'], form.upload[action^='/rules']")) {
        upload.action = new URL(upload.action, window.location.href).pathname + "?" + query;
      }
    }

    function readTotals() {
      const robots = document.getElementById("total-robots");
      const configurations = document.getElementById("total-configurations");
      if (!robots || !configurations || !document.querySelector("#by-type tr")) {
        return null;
      }
      return { robots: Number(robots.textContent), configurations: Number(configurations.textContent) };
    }

    function clearTotals() {
      document.getElementById("by-type").replaceChildren();
      setText("total-robots", "0");
      setText("total-configurations", "0");
      setText("total-ratio", "-");
      setText("bound", "-");
      setText("default", "-");
      setText("published", "none for this selection");
      document.getElementById("warnings").replaceChildren();
      for (const span of document.querySelectorAll("[data-type-counts]")) {
        span.textContent = "";
      }
      setText("change", "No kinematic type selected yet: include one to start.");
      shown = null;
      showFaults([]);
    }

    function showTotals(data) {
      delete document.getElementById("totals").dataset.stale;
      const body = document.getElementById("by-type");
      body.replaceChildren(
        ...data.by_type.map((t) =>
          row([t.kinematic_type, t.valid_robots, t.ui_configurations, ratio(t.reduction_ratio)]),
        ),
      );
      for (const span of document.querySelectorAll("[data-type-counts]")) {
        const found = data.by_type.find((t) => t.kinematic_type === span.dataset.typeCounts);
        span.textContent = found ? `${found.valid_robots} valid robots, ${found.ui_configurations} UI configurations` : "";
      }
      setText("total-robots", String(data.totals.valid_robots));
      setText("total-configurations", String(data.totals.ui_configurations));
      setText("total-ratio", ratio(data.totals.reduction_ratio));
      setText("bound", `${data.bound} (${Object.values(data.bound_factors).join(" x ")})`);
      const every = Object.values(data.default_components).reduce((n, names) => n + names.length, 0);
      setText("default", `${data.default_configuration} (every component: ${every})`);
      const published = document.getElementById("published");
      if (data.published) {
        const p = data.published;
        const agrees = p.valid_robots === data.totals.valid_robots && p.ui_configurations === data.totals.ui_configurations;
        const source = p.source ? ` (${p.source})` : "";
        const verdict = document.createElement("strong");
        verdict.textContent = agrees
          ? "reproduced"
          : `NOT reproduced: these rules give ${data.totals.valid_robots} / ${data.totals.ui_configurations}`;
        published.replaceChildren(
          `${p.valid_robots} valid robots / ${p.ui_configurations} UI configurations${source}: `,
          verdict,
        );
      } else {
        published.textContent = "none for this selection";
      }
      document.getElementById("warnings").replaceChildren(
        ...data.warnings.map((w) => {
          const item = document.createElement("li");
          item.textContent = w;
          return item;
        }),
      );
      const now = { robots: data.totals.valid_robots, configurations: data.totals.ui_configurations };
      setText("change", shown ? cost(shown, now) : "");
      shown = now;
    }

    function cost(before, after) {
      const parts = [];
      const configurations = after.configurations - before.configurations;
      const robots = after.robots - before.robots;
      if (configurations) {
        parts.push(`${configurations > 0 ? "+" : ""}${configurations} configuration${Math.abs(configurations) === 1 ? "" : "s"}`);
      }
      if (robots) {
        parts.push(`${robots > 0 ? "+" : ""}${robots} valid robot${Math.abs(robots) === 1 ? "" : "s"}`);
      }
      return "Last change: " + (parts.length ? parts.join(", ") : "no change in the counts");
    }
  }

  function showFaults(faults) {
    const region = document.getElementById("faults");
    if (!region) {
      return;
    }
    for (const slot of document.querySelectorAll("[data-faults-for]")) {
      slot.textContent = "";
    }
    if (!faults.length) {
      region.replaceChildren();
      return;
    }
    const section = document.createElement("section");
    section.className = "faults";
    const title = document.createElement("h2");
    title.textContent = `${faults.length} problem${faults.length === 1 ? "" : "s"}`;
    const list = document.createElement("ul");
    for (const fault of faults) {
      const item = document.createElement("li");
      item.className = "fault";
      item.dataset.path = fault.path || "";
      const where = document.createElement("code");
      where.textContent = fault.file + (fault.path ? ": " + fault.path : "");
      item.append(where, ": " + fault.message);
      list.append(item);
      for (const slot of document.querySelectorAll("[data-faults-for]")) {
        if (fault.path && (fault.path === slot.dataset.faultsFor || fault.path.startsWith(slot.dataset.faultsFor + "["))) {
          slot.textContent = fault.message;
        }
      }
    }
    section.append(title, list);
    region.replaceChildren(section);
  }

  function row(cells) {
    const tr = document.createElement("tr");
    cells.forEach((cell, index) => {
      const td = document.createElement(index === 0 ? "th" : "td");
      if (index === 0) {
        td.scope = "row";
      }
      td.textContent = String(cell);
      tr.append(td);
    });
    return tr;
  }

  function many(count, noun) {
    return `${count} ${noun}${count === 1 ? "" : "s"}`;
  }

  function ratio(value) {
    return value === null || value === undefined ? "-" : Number(value).toFixed(2);
  }

  function setText(id, text) {
    const element = document.getElementById(id);
    if (element) {
      element.textContent = text;
    }
  }

  function livePage(live) {
    const log = document.getElementById("event-log");
    const status = document.getElementById("switch-status");
    const events = new EventSource(live.dataset.liveEvents);
    let fetching = false;
    let again = false;
    // A click on a robot or one of its values: the switch as JSON (the form posts it without
    // this script), the answer said in the status line, the table redrawn by the events.
    live.addEventListener("submit", (submitted) => {
      const form = submitted.target;
      if (!form.matches("form[data-switch]")) {
        return;
      }
      submitted.preventDefault();
      const button = submitted.submitter;
      const values = {};
      if (button && button.name === "value") {
        const split = button.value.indexOf("=");
        values[button.value.slice(0, split)] = button.value.slice(split + 1);
      }
      switchTo(form.elements.robot.value, values);
    });
    events.onmessage = (message) => {
      const event = JSON.parse(message.data);
      const item = document.createElement("li");
      item.dataset.event = event.event;
      // The studio's own sentence for the event, every value from the graph escaped.
      item.textContent = `#${event.seq} ${event.summary || event.event}`;
      log.prepend(item);
      while (log.children.length > 100) {
        log.lastElementChild.remove();
      }
      refresh();
    };
    events.onerror = () => {
      // Refused (too many live views open) or the studio stopped: the browser will not try
      // again by itself, so say so where the log is.
      if (events.readyState === EventSource.CLOSED) {
        const item = document.createElement("li");
        item.textContent =
          "Live events stopped: the studio refused this view (too many live views open) " +
          "or stopped. Close other live views and reload.";
        log.prepend(item);
      }
    };

    async function switchTo(robot, values) {
      const asked = [robot, ...Object.values(values)].join(" ");
      status.textContent = `Switching to ${asked}: waiting for the watcher's answer...`;
      try {
        const response = await fetch(live.dataset.liveSwitch, {
          method: "POST",
          headers: { "content-type": "application/json" },
          body: JSON.stringify({ robot, values }),
        });
        const data = await response.json();
        if (response.status === 200) {
          const answer = data.answer;
          status.textContent =
            `${asked}: UI configuration ${answer.configuration}` +
            (answer.default ? " (the default)" : "") +
            ` (answered by ${answer.watcher})`;
        } else if (response.status === 202) {
          status.textContent = `${asked}: selected, but no watcher answered in time`;
        } else {
          const faults = (data.faults || []).map((fault) => fault.message);
          status.textContent = `${asked}: refused: ${faults.join("; ") || data.error}`;
        }
      } catch (error) {
        status.textContent = `${asked}: the studio did not answer (${error})`;
      }
      refresh();
    }

    async function refresh() {
      if (fetching) {
        again = true;
        return;
      }
      fetching = true;
      try {
        const response = await fetch(live.dataset.liveBody);
        if (response.ok) {
          // The studio's own page fragment, every value escaped by its templates.
          live.innerHTML = await response.text();
        }
      } finally {
        fetching = false;
        if (again) {
          again = false;
          refresh();
        }
      }
    }
  }
})();
