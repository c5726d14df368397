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
    const past = [];
    const future = [];
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
    window.history.replaceState({ query: current }, "", "/?" + withView(current));

    form.addEventListener("change", (event) => {
      const target = event.target;
      if (target.matches("[data-reload]")) {
        // Another rule set has other controls: ask the server for the page.
        window.location.assign("/?" + new URLSearchParams({ rules: target.value }).toString());
        return;
      }
      if (target.matches("[data-include]")) {
        enableType(target.closest("fieldset.type"), target.checked);
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
      undo.addEventListener("click", () => step(past, future));
      redo.addEventListener("click", () => step(future, past));
    }
    document.addEventListener("keydown", (event) => {
      const typing = event.target.matches("input[type=text], input:not([type]), textarea");
      if (typing || !(event.ctrlKey || event.metaKey)) {
        return;
      }
      const key = event.key.toLowerCase();
      if (key === "z" && !event.shiftKey) {
        event.preventDefault();
        step(past, future);
      } else if ((key === "z" && event.shiftKey) || key === "y") {
        event.preventDefault();
        step(future, past);
      }
    });
    window.addEventListener("popstate", (event) => {
      const query = (event.state && event.state.query) || window.location.search.slice(1);
      apply(query);
      current = selectionQuery();
      ask(current);
    });

    function changed() {
      const query = selectionQuery();
      if (query === current) {
        return;
      }
      past.push(current);
      future.length = 0;
      current = query;
      window.history.pushState({ query }, "", "/?" + withView(query));
      ask(query);
    }

    function step(from, to) {
      if (!from.length) {
        return;
      }
      to.push(current);
      const query = from.pop();
      if (new URLSearchParams(query).get("rules") !== form.elements.rules.value) {
        window.location.assign("/?" + query);
        return;
      }
      apply(query);
      current = selectionQuery();
      window.history.pushState({ query: current }, "", "/?" + withView(current));
      ask(current);
    }

    function buttons() {
      if (undo && redo) {
        undo.disabled = past.length === 0;
        redo.disabled = future.length === 0;
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
      const mine = ++asked;
      const types = new URLSearchParams(query).getAll("type");
      if (!types.length) {
        clearTotals();
        return;
      }
      let response;
      try {
        response = await fetch("/api/solve?" + query, { headers: { accept: "application/json" } });
      } catch (error) {
        showFaults([{ file: "<studio>", path: "", message: "the studio does not answer: " + error }]);
        return;
      }
      const data = await response.json();
      if (mine !== asked) {
        return;
      }
      if (!response.ok) {
        showFaults(data.faults && data.faults.length ? data.faults : [{ file: "<studio>", path: "", message: data.error }]);
        return;
      }
      showFaults([]);
      showTotals(data);
      redraw(query);
    }

    function keepLinks(query) {
      for (const link of document.querySelectorAll("a[data-keep-selection]")) {
        const url = new URL(link.href, window.location.href);
        link.href = url.pathname + "?" + query;
      }
      for (const link of document.querySelectorAll("a[data-view-link]")) {
        link.href = "/?" + query + "&view=" + encodeURIComponent(link.dataset.viewLink);
      }
      for (const upload of document.querySelectorAll("form.upload[action^='/team']")) {
        upload.action = "/team?" + query;
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
          `published: ${p.valid_robots} valid robots / ${p.ui_configurations} UI configurations${source}: `,
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

    let drawing = null;
    function redraw(query) {
      const image = document.getElementById("radar");
      if (!image) {
        return;
      }
      // Charts take longer than counts: draw the one the clicking stopped at.
      clearTimeout(drawing);
      drawing = setTimeout(() => {
        image.src = "/api/charts/radar.svg?" + query;
      }, 300);
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
    const events = new EventSource(live.dataset.liveEvents);
    let fetching = false;
    let again = false;
    events.onmessage = (message) => {
      const event = JSON.parse(message.data);
      const item = document.createElement("li");
      const detail = event.robot ? ` ${event.robot}` : "";
      const error = event.error ? `: ${event.error}` : "";
      item.textContent = `#${event.seq} ${event.event}${detail}${error}`;
      log.prepend(item);
      while (log.children.length > 100) {
        log.lastElementChild.remove();
      }
      refresh();
    };

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
