// The teaching page: controls -> one call into the WebAssembly solver -> drawings and tables.
//
// A state machine runs the solves: at any time the page is idle, has one solve scheduled for
// the next frame (inputs arriving meanwhile only update the values it will read), or runs one
// loading history. Every input, a preset, a tab switch or the "stop" button cancels a history
// in flight (a generation counter: the history's loop stops at its next step and never draws
// again). The table's caption always says what it shows: one solve of the controls' set-up, or
// which step of which history; the published values whenever the controls sit on a published
// set-up. Scenes are entries of SCENES (scenes_paper.js, scenes_generic.js); URL state in url.js,
// drawing in chart.js, the explanation panel in explain.js, the solver's thread in solver.js,
// the figure and CSV export in export.js.
import init, { bundled_json } from "./pkg/contact2d_web.js";
import { PAPER_SCENES, PRESETS, flagshipParams, flagshipSteps } from "./scenes_paper.js";
import { GENERIC_SCENES, readUserFiles } from "./scenes_generic.js";
import { chart, drawMesh, lastCharts, setFontPx } from "./chart.js";
import { makePlayer } from "./player.js";
import { installExport } from "./export.js";
import { Cancelled, makeSolver } from "./solver.js";
import { installExercises } from "./exercises.js";
import { readUrl, urlOf } from "./url.js";
import { EXPLAIN } from "./explain.js";

const $ = (id) => document.getElementById(id);
// The ball on a plate (a body of revolution) beside the plane Hertz tab.
const { flagship: plate, hertz, ...paperRest } = PAPER_SCENES;
const SCENES = { flagship: plate, hertz, ball_on_plate: GENERIC_SCENES.ball_on_plate, ...paperRest, ...GENERIC_SCENES };
const COMMON = [
  { key: "mag", id: "mag", label: "displacement magnification β", kind: "range", min: 0, max: 3, step: 0.1, value: 1,
    show: (v) => Number(v).toFixed(1) },
  { key: "projector", id: "projector", label: "projector mode (large type, figures first)", kind: "checkbox", value: "0" },
];
const HISTORY_STEPS = 10;

// The page's state for tests and for people who open the console.
const page = { ready: null, view: null, timings: [], updates: 0, error: null, run: "idle", shows: null, history: [],
  solvesStarted: 0, solveWindows: [] };
window.contact2dPage = page;
page.charts = lastCharts;

const state = { scene: "flagship", values: {}, view: null, generation: 0, frame: 0, history: [], userFiles: null };
// The player of a finished history's or cycle's steps (player.js).
const player = makePlayer({ state, page, draw: (...args) => draw(...args),
  drawFlagship: (view, ui, values) => SCENES.flagship.draw(view, ui, values) });

// ---------------------------------------------------------------------------------------------
// Controls: built from each scene's list; values live in state.values (strings, as in the URL).

function controlElement(c) {
  const label = document.createElement("label");
  label.dataset.key = c.key;
  let input;
  if (c.kind === "select") {
    input = document.createElement("select");
    for (const [value, text] of c.options) input.add(new Option(text, value));
  } else {
    input = document.createElement("input");
    input.type = c.kind === "checkbox" ? "checkbox" : "range";
    if (c.kind === "range") Object.assign(input, { min: c.min, max: c.max, step: c.step });
  }
  input.id = c.id;
  const out = document.createElement("output");
  out.id = `${c.id}-out`;
  if (c.kind === "checkbox") label.append(input, ` ${c.label}`);
  else label.append(`${c.label} `, out, input);
  return label;
}

const allControls = () => [...SCENES[state.scene].controls, ...COMMON];

function setControl(c, value) {
  const el = $(c.id);
  if (c.kind === "checkbox") el.checked = value === "1";
  else el.value = value;
  const out = $(`${c.id}-out`);
  if (out && c.show) out.textContent = c.show(value);
}

function readControl(c) {
  const el = $(c.id);
  return c.kind === "checkbox" ? (el.checked ? "1" : "0") : el.value;
}

function showValues() {
  for (const c of allControls()) setControl(c, state.values[c.key]);
  document.body.classList.toggle("projector", state.values.projector === "1");
  setFontPx(state.values.projector === "1" ? 22 : 16);
  history.replaceState(null, "", urlOf(state.scene, state.values));
}

// ---------------------------------------------------------------------------------------------
// The solver's thread (solver.js); Cancel also stops a history and drops a queued solve.

const solver = makeSolver(page);
const solveInWorker = (request) => solver.solve(request);

function cancelSolve() {
  state.queued = false;
  cancelHistory();
  solver.cancel();
}

// ---------------------------------------------------------------------------------------------
// The run state machine.

const HISTORY_LABEL = "Loading history: step w from 0 and draw l(w), b(w)";
const CYCLE_LABEL = "Mindlin–Deresiewicz cycle: +A → −A → +A";

/** Stops a history or cycle in flight: its loop sees the new generation and never draws again. */
function cancelHistory() {
  state.generation += 1;
  player.stop();
  if (page.run === "history" || page.run === "cycle") page.run = "idle";
  $("history").textContent = HISTORY_LABEL;
  $("cycle").textContent = CYCLE_LABEL;
}

/** Any input: cancel a history, schedule one solve for the next frame (coalescing inputs). While
 * a solve runs, one more is queued: it reads the controls when it starts, so a newer slider
 * value replaces a queued one. */
function schedule() {
  cancelHistory();
  player.clear();
  state.history = [];
  if (page.run === "solving") { state.queued = true; return; }
  if (!state.frame) {
    page.run = "scheduled";
    state.frame = requestAnimationFrame(() => { state.frame = 0; solveNow(); });
  }
}

function setError(message) {
  page.error = message;
  $("error").hidden = !message;
  $("error").textContent = message ? `not solved: ${message}` : "";
  // A failed solve leaves nothing of the previous one on screen (no stale numbers or banner).
  if (message) {
    clearFigures("Nothing to show: the last set-up was not solved (the reason is under the controls).");
    $("banner").hidden = true;
    $("pair-counts").textContent = "";
    $("profile-caption").textContent = "";
  }
}

/** Runs the scheduled solve; `state.inflight` is its promise while it runs (a history or cycle
 * waits for it, see settle()). */
function solveNow() {
  const run = solveScheduled().finally(() => { if (state.inflight === run) state.inflight = null; });
  state.inflight = run;
  return run;
}

/** Before a history or cycle starts: no solve of the controls may run, be scheduled or queued
 * (its answer would be drawn over the run's steps, or its end would reschedule a solve that
 * cancels the run). A solve in flight is awaited; a scheduled or queued one is run now (its
 * view gives the published case the run's steps show). Loops until nothing is pending, as a
 * finished solve may reschedule a queued one. */
async function settle() {
  for (;;) {
    if (state.inflight) { await state.inflight; continue; }
    if (state.frame) { cancelAnimationFrame(state.frame); state.frame = 0; await solveNow(); continue; }
    if (state.queued) { state.queued = false; await solveNow(); continue; }
    return;
  }
}

async function solveScheduled() {
  page.run = "solving";
  const sceneName = state.scene;
  const scene = SCENES[sceneName];
  const values = { ...state.values };
  try {
    const t0 = performance.now();
    let answer;
    if (scene.user) {
      if (!state.userFiles) {
        setError("");
        clearFigures("Nothing solved yet: choose or drop a scene .toml and its .msh.");
        page.updates += 1;
        return;
      }
      answer = await solveInWorker({ kind: "user", files: state.userFiles });
    } else {
      answer = await solveInWorker({ kind: "scene", scene: sceneName, values });
    }
    // A tab switched meanwhile: this answer is for a scene no longer shown (the queued solve follows).
    if (sceneName !== state.scene) return;
    const view = answer.view;
    const t1 = performance.now();
    // The published case of the controls' set-up (a history's steps keep showing it).
    state.published = view.published || null;
    const shows = { kind: "solve", scene: state.scene, text: `One solve of the controls' set-up: ${scene.user
      ? `${state.userFiles.sceneName} on ${state.userFiles.meshName}` : scene.describe(values)}.` };
    draw(view, values, shows);
    if (scene.user) playUserSteps(view, values);
    const t2 = performance.now();
    record(view, { scene: state.scene, solve_ms: t1 - t0, draw_ms: t2 - t1, total_ms: t2 - t0 });
    $("timing").textContent = `last update ${(t2 - t0).toFixed(1)} ms: solve in WebAssembly ` +
      `${answer.ms.toFixed(1)} ms (mesh ${view.mesh_file}), drawing ${(t2 - t1).toFixed(1)} ms`;
  } catch (e) {
    setError(e instanceof Cancelled ? "cancelled (the controls' set-up was not solved)" : String(e.message || e));
    page.updates += 1;
  } finally {
    page.run = "idle";
    if (state.queued) { state.queued = false; schedule(); }
  }
}

/** A user's scene of several load steps: every step (view.frames, one per step of its schedule)
 * into the player, all at one scale, and the last one shown. */
function playUserSteps(view, values) {
  const frames = view.frames || [];
  if (frames.length < 2) return;
  const name = `${state.userFiles.sceneName} on ${state.userFiles.meshName}`;
  const runFrames = frames.map((f, k) => {
    const row = view.summary.steps[k];
    const factors = row ? Object.entries(row.factors).map(([p, v]) => `${p} = ${+v.toPrecision(6)}`).join(", ") : "";
    return {
      view: { ...view, mesh: { ...view.mesh, displacement: f.displacement }, pairs: f.pairs,
        summary: { ...view.summary, contacts: f.contacts, status: row ? row.status : view.summary.status } },
      shows: { kind: "steps", scene: "user", step: k + 1,
        text: `Your scene, load step ${k + 1} of ${frames.length}${factors ? ` (${factors})` : ""}: ${name}.` },
    };
  });
  player.set({ kind: "user", values, frames: runFrames, first: 1, last: frames.length, interval: 400,
    drawFrame: (v, ui, vals) => SCENES.user.draw(v, ui, vals) });
  player.show(frames.length);
}

function record(view, timing) {
  state.view = view;
  page.view = view;
  page.timings.push(timing);
  page.updates += 1;
  setError("");
}

// Steps w from 0 to the slider's value in ten equal steps; with clearance and friction each point
// is the history of k equal steps (the zones depend on the path). The button is "stop" while it
// runs; any input, preset or tab switch stops it too.
async function runHistory() {
  if (page.run === "history") { cancelHistory(); return; }
  // A click while a solve of the controls runs or is scheduled is not lost: the history starts
  // when that solve has been drawn (a second click meanwhile is the same request).
  if (state.starting) return;
  state.starting = true;
  try { await settle(); } finally { state.starting = false; }
  const generation = ++state.generation;
  player.clear();
  const frames = [];
  page.run = "history";
  $("history").textContent = "Stop the loading history";
  const values = { ...state.values }, w = Number(values.load);
  const published = state.published;
  state.history = [];
  page.history = state.history;
  for (let k = 1; k <= HISTORY_STEPS; k++) {
    const load = String(+((w * k) / HISTORY_STEPS).toFixed(4));
    const base = flagshipParams({ ...values, load });
    const steps = base.eps > 0 && base.friction > 0 ? k : undefined;
    try {
      const t0 = performance.now();
      const { view } = await solveInWorker({ kind: "scene", scene: "flagship", values: { ...values, load }, steps });
      const t1 = performance.now();
      if (generation !== state.generation) return;
      state.history.push({ w: Number(load), l: view.summary.paper.l, b: view.summary.paper.b });
      const n = flagshipSteps({ ...base, steps });
      const shows = {
        kind: "history", scene: "flagship", step: k, published,
        text: `Loading history, step ${k} of ${HISTORY_STEPS}: w = ${load} reached in ${n} equal load step(s) ` +
          `(the controls: ${SCENES.flagship.describe(values)}).`,
      };
      frames.push({ view, shows });
      draw(view, values, shows);
      record(view, { scene: "history", solve_ms: t1 - t0, total_ms: performance.now() - t0 });
      $("timing").textContent = `history step ${k}/${HISTORY_STEPS} (w = ${load}): ${(t1 - t0).toFixed(1)} ms`;
    } catch (e) {
      if (generation === state.generation || e instanceof Cancelled) {
        setError(e instanceof Cancelled ? `history cancelled at step ${k}` : `history step ${k}: ${e.message || e}`);
      }
      break;
    }
    await new Promise((r) => setTimeout(r, 120));
    if (generation !== state.generation) return;
  }
  if (generation === state.generation) {
    page.run = "idle";
    $("history").textContent = "Loading history: step w from 0 and draw l(w), b(w)";
    // Complete: the steps can be played, stepped and scrubbed, all at the whole history's scale.
    if (frames.length === HISTORY_STEPS) {
      player.set({ kind: "history", values, frames, first: 1, last: HISTORY_STEPS, interval: 400 });
      player.show(HISTORY_STEPS);
    }
  }
}

// The Mindlin–Deresiewicz cycle: one solve of the whole path, then its steps played one per
// 150 ms; stopped like a history.
async function runCycle() {
  if (page.run === "cycle") { cancelHistory(); return; }
  if (state.starting) return;
  state.starting = true;
  try { await settle(); } finally { state.starting = false; }
  const generation = ++state.generation;
  page.run = "cycle";
  $("cycle").textContent = "Stop the cycle";
  const values = { ...state.values };
  let view;
  try {
    const t0 = performance.now();
    view = (await solveInWorker({ kind: "cycle", values })).view;
    if (generation !== state.generation) return;
    record(view, { scene: "cycle", solve_ms: performance.now() - t0, total_ms: performance.now() - t0 });
    $("timing").textContent = `cycle of ${view.summary.steps.length} load steps solved in ` +
      `${(performance.now() - t0).toFixed(1)} ms (mesh ${view.mesh_file})`;
  } catch (e) {
    if (generation === state.generation || e instanceof Cancelled) {
      setError(e instanceof Cancelled ? "cycle cancelled" : `cycle: ${e.message || e}`);
      cancelHistory();
    }
    return;
  }
  page.cycle = view;
  // Played once through (150 ms a step); then, or when paused, the player steps and scrubs it.
  player.set({ kind: "cycle", values, view, first: 1, last: view.summary.steps.length - 1, interval: 150 });
  await player.play();
  if (generation === state.generation) cancelHistory();
}

// ---------------------------------------------------------------------------------------------
// Drawing the view: the scene draws through `ui`.

function clearFigures(message) {
  for (const id of ["mesh", "profile"]) {
    const c = $(id);
    c.getContext("2d").clearRect(0, 0, c.width, c.height);
  }
  $("summary").tBodies[0].innerHTML = "";
  $("keynums").replaceChildren();
  $("table-caption").textContent = message;
}

const fmt = (v) => (v === null || v === undefined ? "—" : typeof v !== "number" ? String(v) : Number.isInteger(v) ? String(v)
  : Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(4) : v.toPrecision(5));

function draw(view, values, shows, custom = null) {
  state.lastDraw = [view, values, shows, custom];
  page.shows = shows;
  const published = shows.kind === "history" ? shows.published : view.published;
  const ui = {
    mesh: (v, focus) => {
      const fixed = shows.step && state.player ? state.player.fixed : null;
      const { counts, beta } = drawMesh($("mesh"), v, Number(values.mag), focus, fixed && fixed.mesh);
      page.beta = beta;
      const slip = (counts["slip+"] || 0) + (counts["slip-"] || 0);
      $("pair-counts").textContent = `— ${counts.stick || 0} stick, ${slip} slip (${counts["slip+"] || 0} +, ` +
        `${counts["slip-"] || 0} −), ${counts.contact || 0} contact, ` +
        `${counts.free || 0} free pairs; β = ${beta.toPrecision(3)}`;
      Object.assign($("mesh").dataset, { stick: counts.stick || 0, slip, free: counts.free || 0,
        slipPlus: counts["slip+"] || 0, slipMinus: counts["slip-"] || 0 });
    },
    chart: (spec, caption) => {
      const fixed = shows.step && state.player ? state.player.fixed : null;
      if (fixed) spec = { ...spec, yrange: fixed.yrange.profile };
      // Comparison mode: the pinned curves (same tab) drawn dashed under the live ones.
      if (state.pinned && state.pinned.scene === shows.scene) {
        spec = { ...spec, series: [...spec.series, ...state.pinned.series] };
        state.pinned.shown = true;
      }
      chart($("profile"), spec);
      $("profile-caption").textContent = caption;
    },
    output: (id, value, text) => { const o = $(id); if (o) { o.textContent = text; o.dataset.value = String(value); } },
    banner: (text) => { $("banner").hidden = !text; $("banner").textContent = text || ""; },
    table: (rows) => {
      const body = $("summary").tBodies[0];
      body.innerHTML = "";
      for (const [name, key, live] of rows) {
        const tr = body.insertRow();
        tr.insertCell().textContent = name;
        const cell = tr.insertCell();
        cell.textContent = fmt(live);
        cell.dataset.key = key;
        cell.dataset.value = live === null || live === undefined ? "" : String(live);
        const pub = published ? published.values.find(([k]) => k === key) : null;
        tr.insertCell().textContent = pub ? fmt(pub[1]) : "";
      }
      $("published-head").textContent = published ? "published" : "";
      let note = "";
      if (published) {
        note = `On a published set-up: ${published.label} (Solodovnikov 1998, on a finer mesh; ` +
          `scenes/${published.scene}.toml).`;
        if (shows.kind === "history") {
          note += " The paper's values are for its own load steps; this row is a step of the loading history, " +
            "so b (which depends on the load steps) and, before the last step, every value may differ.";
        } else if (published.scene.includes("gap") && !published.scene.endsWith("mu0")) {
          note += " With clearance and friction b depends on the load steps: the page solves 3 equal steps.";
        }
      }
      $("published-label").textContent = note;
      $("table-caption").textContent = shows.text;
      $("summary").dataset.shows = shows.kind;
      // The key numbers in large type over the figure (projector mode): the scene's `keys`,
      // else the table's first three rows.
      const keys = SCENES[shows.scene].keys;
      const chosen = keys ? keys.map((k) => rows.find((r) => r[1] === k)).filter(Boolean) : rows.slice(0, 3);
      $("keynums").replaceChildren(...chosen.map(([name, key, live]) => {
        const d = document.createElement("div");
        d.dataset.key = key;
        d.textContent = `${name.split(",")[0]} = ${String(fmt(live)).split(":")[0]}`;
        return d;
      }));
    },
  };
  $("banner").hidden = true;
  if (custom) { custom(ui); return; }
  SCENES[shows.scene].draw(view, ui, values);
  if (shows.scene === "flagship") drawHistory(values, shows);
  if (shows.scene === "cattaneo_mindlin") {
    chart($("history-plot"), { series: [{ x: [], y: [], colour: "#6b4c9a", label: "Q(δ): run the cycle" }],
      xlabel: "δ: sideways displacement of the roller's top, mm", ylabel: "Q, N/mm" });
  }
}

/** l(w), b(w) of the history so far, or up to the step shown (the player), on its fixed axes. */
function drawHistory(values, shows) {
  const h = shows.kind === "history" ? state.history.slice(0, shows.step) : state.history;
  const fixed = shows.kind === "history" && state.player ? state.player.fixed.yrange["history-plot"] : undefined;
  chart($("history-plot"), {
    yrange: fixed,
    series: [
      { x: h.map((p) => p.w), y: h.map((p) => p.l), colour: "#d62728", label: "l(w)", points: h.length < 2 },
      { x: h.map((p) => p.w), y: h.map((p) => p.b), colour: "#1f77b4", label: "b(w)", points: h.length < 2 },
    ],
    xlabel: "load w", ylabel: "η", xrange: [0, Math.max(1e-9, Number(values.load))],
  });
}

// ---------------------------------------------------------------------------------------------
// Comparison mode: "Pin the curves" keeps the profile chart's curves of the set-up shown; every
// later set-up of the same tab is drawn over them (dashed, "pinned: …" in the legend) until
// "Unpin" or a tab switch.

function togglePin() {
  if (state.pinned) {
    state.pinned = null;
  } else {
    const last = lastCharts.profile;
    if (!last) return;
    const what = (SCENES[state.scene].describe ? SCENES[state.scene].describe(state.values) : state.scene)
      .split(",").slice(0, 3).join(",");
    state.pinned = { scene: state.scene, what, series: last.series.filter((s) => !s.pinned && !s.points).map((s) => ({
      x: [...s.x], y: [...s.y], colour: s.colour, label: `${s.label}, pinned (${what})`, dash: true, pinned: true })) };
  }
  page.pinned = state.pinned;
  $("pin").textContent = state.pinned ? "Unpin the curves" : "Pin the curves";
  if (state.lastDraw) draw(...state.lastDraw);
}

// ---------------------------------------------------------------------------------------------
// Scenes, presets, URL, reset, projector, files (the export: export.js).

function showScene(name, values, push = false) {
  cancelHistory();
  if (state.pinned && name !== state.pinned.scene) { state.pinned = null; page.pinned = null; $("pin").textContent = "Pin the curves"; }
  // A tab chosen on the page is a new history entry (Back returns to the last tab).
  if (push && name !== state.scene) history.pushState(null, "", urlOf(name, values));
  state.scene = name;
  state.values = values;
  document.querySelectorAll("#scenes button").forEach((b) => b.classList.toggle("active", b.dataset.scene === name));
  document.querySelectorAll("[data-for]").forEach((el) => {
    el.hidden = !el.dataset.for.split(" ").includes(name);
  });
  $("explain-body").innerHTML = EXPLAIN[name] || "";
  $("history-caption").textContent = name === "flagship"
    ? "Loading history: contact end l(w) and stick end b(w) on η = 1 − φ/π."
    : "Mindlin–Deresiewicz cycle: the tangential force Q against the top's sideways displacement δ (the hysteresis loop).";
  $("banner").hidden = true;
  showValues();
  schedule();
}

const defaults = (name) => Object.fromEntries([...SCENES[name].controls, ...COMMON].map((c) => [c.key, String(c.value)]));

function applyPreset(name) {
  const p = PRESETS[name];
  Object.assign(state.values, { mu: p.mu, ratio: "1", eps: p.eps, load: p.load, variant: p.variant });
  showValues();
  schedule();
}

async function takeFiles(files) {
  try {
    state.userFiles = await readUserFiles([...files]);
    $("user-files").textContent = `${state.userFiles.sceneName} + ${state.userFiles.meshName}`;
    if (state.scene !== "user") showScene("user", defaults("user"));
    else schedule();
  } catch (e) {
    setError(String(e.message || e));
  }
}

function build() {
  const nav = $("scenes");
  for (const [name, scene] of Object.entries(SCENES)) {
    const b = document.createElement("button");
    b.dataset.scene = name;
    // The full title, and a short one for one row of tabs in projector mode.
    const long = document.createElement("span"), short = document.createElement("span");
    long.className = "long"; long.textContent = scene.title;
    short.className = "short"; short.textContent = scene.short || scene.title;
    b.append(long, short);
    b.title = scene.title;
    b.addEventListener("click", () => showScene(name, defaultsFor(name), true));
    nav.append(b);
    const block = document.createElement("div");
    block.dataset.for = name;
    block.hidden = true;
    for (const c of scene.controls) block.append(controlElement(c));
    $("scene-controls").append(block);
  }
  for (const c of COMMON) $("common-controls").append(controlElement(c));
  // Flagship extras: published set-ups and the history button.
  const presets = $("presets");
  for (const [name, p] of Object.entries(PRESETS)) {
    const b = document.createElement("button");
    b.dataset.preset = name;
    b.textContent = p.label;
    b.addEventListener("click", () => applyPreset(name));
    presets.append(b);
  }
  for (const scene of Object.values(SCENES)) {
    for (const c of scene.controls) {
      $(c.id).addEventListener("input", () => { state.values[c.key] = readControl(c); showValues(); schedule(); });
    }
  }
  $("mag").addEventListener("input", () => { state.values.mag = readControl(COMMON[0]); showValues(); schedule(); });
  $("explain-toggle").addEventListener("click", () => { $("explain").open = !$("explain").open; });
  $("explain").addEventListener("toggle", () => {
    $("explain-toggle").textContent = $("explain").open ? "Close the explanation" : "Explain";
  });
  $("projector").addEventListener("input", () => {
    state.values.projector = readControl(COMMON[1]);
    // Projector mode: the explanation is a toggle over the figure, closed to begin with.
    $("explain").open = state.values.projector !== "1";
    showValues();
    schedule();
  });
  $("history").addEventListener("click", runHistory);
  $("cancel").addEventListener("click", cancelSolve);
  $("cycle").addEventListener("click", runCycle);
  player.wire();
  // Reset: the scene's defaults, in the same display mode (projector stays on or off).
  $("reset").addEventListener("click", () => {
    $("url-notes").hidden = true;
    showScene(state.scene, { ...defaults(state.scene), projector: state.values.projector });
  });
  // Back / Forward: the set-up of that history entry (its tab and controls).
  window.addEventListener("popstate", () => {
    const { scene, values } = readUrl(location.search, SCENES, COMMON, "flagship");
    showScene(scene, values);
  });
  installExport({ state, page, scenes: SCENES });
  $("pin").addEventListener("click", togglePin);
  // Exercises (exercises.js): the page's hooks to open a set-up and to make a change.
  installExercises(page, {
    open: (ex) => {
      const name = ex.scene || "flagship";
      showScene(name, { ...defaults(name), ...ex.start, mag: state.values.mag, projector: state.values.projector },
        state.scene !== name);
    },
    change: (values) => { Object.assign(state.values, values); showValues(); schedule(); },
    // The solve of the set-up on screen is done (none running, scheduled or queued).
    solved: async () => {
      while (state.inflight || state.frame || state.queued || page.run !== "idle") await new Promise((r) => setTimeout(r, 50));
    },
  });
  $("user-input").addEventListener("change", (e) => takeFiles(e.target.files));
  document.addEventListener("dragover", (e) => e.preventDefault());
  document.addEventListener("drop", (e) => { e.preventDefault(); takeFiles(e.dataTransfer.files); });
  // A new window size redraws what is shown (the canvases follow their CSS size); nothing is solved.
  window.addEventListener("resize", () => { if (state.lastDraw) draw(...state.lastDraw); });
}

// Switching tabs keeps the common controls (β, projector) and starts the scene at its defaults.
function defaultsFor(name) {
  return { ...defaults(name), mag: state.values.mag, projector: state.values.projector };
}

async function main() {
  await init();
  solver.start();
  const bundled = JSON.parse(bundled_json());
  $("user-limits").textContent = `limits: scene ≤ ${bundled.max_scene_bytes} bytes, mesh ≤ ${bundled.max_mesh_bytes} bytes`;
  // The bundled scenes' files (web/build.sh copies them to pkg/examples) as examples to download.
  for (const [i, { name, mesh_file: mesh }] of bundled.generic.entries()) {
    for (const [j, file] of [`${name}.toml`, mesh].entries()) {
      const a = document.createElement("a");
      Object.assign(a, { href: `pkg/examples/${file}`, download: file, textContent: file });
      $("examples").append(i || j ? (j ? " + " : "; ") : "", a);
    }
  }
  build();
  const { scene, values, notes } = readUrl(location.search, SCENES, COMMON, "flagship");
  if (notes.length) {
    $("url-notes").hidden = false;
    $("url-notes").textContent = `The link's parameters were not all usable: ${notes.join("; ")}.`;
  }
  page.urlNotes = notes;
  if (values.projector === "1") $("explain").open = false;
  $("timing").textContent = "solver loaded";
  showScene(scene, values);
}

page.ready = main().catch((e) => {
  $("timing").textContent = "";
  setError(`the page could not start: ${e.message || e}`);
});
