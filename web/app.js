// The teaching page: sliders -> one call into the WebAssembly solver -> drawings and tables.
// Each scene is one entry of SCENES (params from the controls, solve, draw); a new scene is one
// more entry, one more exported solve function in crates/web, and one
// more nav button and control block in index.html.
import init, { solve_flagship_json, solve_hertz_json, solve_cattaneo_mindlin_json, bundled_json } from "./pkg/contact2d_web.js";

const $ = (id) => document.getElementById(id);
const COLOURS = { stick: "#1f77b4", "slip+": "#d62728", "slip-": "#d62728", contact: "#2ca02c", free: "#969696" };
const RATIOS = [0.25, 0.5, 1, 2, 4, 8, 16];
const state = { scene: "flagship", bundled: null, view: null, history: [], busy: false, pending: false };

// The page's state for tests and for people who open the console.
const page = { ready: null, view: null, timings: [], updates: 0, error: null };
window.contact2dPage = page;

// Values in the URL (?scene=hertz&mu=0.3&eps=0.05&load=0.3838&variant=insert_master&N=32&ratio=2)
// set the controls before the first solve: the page can be checked without moving a slider.
function applyUrl() {
  const q = new URLSearchParams(location.search);
  if (q.has("scene")) state.scene = q.get("scene");
  if (q.has("mu")) $("mu").value = q.get("mu");
  if (q.has("ratio")) $("ratio").value = Math.max(0, RATIOS.indexOf(Number(q.get("ratio"))));
  if (q.has("eps")) $("eps").value = Math.max(0, state.bundled.flagship_eps.indexOf(Number(q.get("eps"))));
  if (q.has("load")) $("load").value = q.get("load");
  if (q.has("variant")) $("variant").value = q.get("variant");
  if (q.has("N")) $("refinement").value = q.get("N");
  if (q.has("force")) $("force").value = q.get("force");
  if (q.has("level")) $("level").value = q.get("level");
  if (q.has("mag")) $("mag").value = q.get("mag");
  if (q.has("press")) $("cm-press").value = q.get("press");
  if (q.has("shear")) $("cm-shear").value = q.get("shear");
}

const round4 = (v) => Number(Number(v).toFixed(4));

function flagshipParams() {
  return {
    friction: round4($("mu").value),
    stiffness_ratio: RATIOS[Number($("ratio").value)],
    eps: state.bundled.flagship_eps[Number($("eps").value)],
    refinement: Number($("refinement").value),
    load: round4($("load").value),
    variant: $("variant").value,
  };
}

const PRESETS = {
  nogap_mu0: { mu: 0, eps: 0, load: 1, variant: "hole_master" },
  nogap_mu03: { mu: 0.3, eps: 0, load: 1, variant: "hole_master" },
  gap_v1_mu03: { mu: 0.3, eps: 0.05, load: 0.3838, variant: "hole_master" },
  gap_v2_mu03: { mu: 0.3, eps: 0.05, load: 0.3838, variant: "insert_master" },
  gap_v2_mu0: { mu: 0, eps: 0.05, load: 0.3838, variant: "insert_master" },
};

function applyPreset(name) {
  const p = PRESETS[name];
  $("mu").value = p.mu;
  $("ratio").value = RATIOS.indexOf(1);
  $("eps").value = state.bundled.flagship_eps.indexOf(p.eps);
  $("load").value = p.load;
  $("variant").value = p.variant;
  state.history = [];
  update();
}

const SCENES = {
  flagship: {
    solve: (params) => JSON.parse(solve_flagship_json(JSON.stringify(params))),
    params: flagshipParams,
    draw: drawFlagship,
  },
  hertz: {
    solve: (params) => JSON.parse(solve_hertz_json(JSON.stringify(params))),
    params: () => ({ force: Number($("force").value), level: $("level").value }),
    draw: drawHertz,
  },
  cattaneo_mindlin: {
    solve: (params) => JSON.parse(solve_cattaneo_mindlin_json(JSON.stringify(params))),
    params: () => ({ press: round4($("cm-press").value), shear: round4($("cm-shear").value), level: $("cm-level").value }),
    draw: drawCattaneoMindlin,
  },
};

// The scene's press and shear displacements of the roller's top at factor 1, mm.
const CM_PRESS_MM = 0.0142, CM_SHEAR_MM = 0.01;

function showLabels() {
  $("mu-out").textContent = round4($("mu").value).toFixed(2);
  $("ratio-out").textContent = RATIOS[Number($("ratio").value)];
  const eps = state.bundled.flagship_eps[Number($("eps").value)];
  $("eps-out").textContent = `${eps} (c = ${+(eps * state.bundled.clearance_per_eps).toPrecision(6)})`;
  $("load-out").textContent = round4($("load").value).toFixed(4);
  $("force-out").textContent = Number($("force").value).toLocaleString("en");
  $("mag-out").textContent = Number($("mag").value).toFixed(1);
  const press = round4($("cm-press").value), shear = round4($("cm-shear").value);
  $("cm-press-out").textContent = `${+(press * CM_PRESS_MM).toPrecision(4)} mm (${press.toFixed(2)} × the scene's)`;
  $("cm-shear-out").textContent = `${+(shear * CM_SHEAR_MM).toPrecision(4)} mm (factor ${shear.toFixed(3)})`;
}

// Solves the current scene and draws it; slider moves during a solve are coalesced.
function update() {
  showLabels();
  if (state.busy) { state.pending = true; return; }
  state.busy = true;
  try {
    const scene = SCENES[state.scene];
    const t0 = performance.now();
    const view = scene.solve(scene.params());
    const t1 = performance.now();
    state.view = view;
    scene.draw(view);
    const t2 = performance.now();
    const timing = { scene: state.scene, solve_ms: t1 - t0, draw_ms: t2 - t1, total_ms: t2 - t0 };
    page.timings.push(timing);
    page.view = view;
    page.updates += 1;
    page.error = null;
    $("error").hidden = true;
    $("timing").textContent = `last update ${timing.total_ms.toFixed(1)} ms: solve in WebAssembly ` +
      `${timing.solve_ms.toFixed(1)} ms (mesh ${view.mesh_file}), drawing ${timing.draw_ms.toFixed(1)} ms`;
  } catch (e) {
    page.error = String(e);
    $("error").hidden = false;
    $("error").textContent = `not solved: ${e}`;
  } finally {
    state.busy = false;
  }
  if (state.pending) { state.pending = false; requestAnimationFrame(update); }
}

// ---------------------------------------------------------------------------------------------
// Drawing

function frame(canvas, bounds, pad = 30) {
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const [x0, y0, x1, y1] = bounds;
  const scale = Math.min((canvas.width - 2 * pad) / (x1 - x0), (canvas.height - 2 * pad) / (y1 - y0));
  const ox = pad + 0.5 * (canvas.width - 2 * pad - scale * (x1 - x0));
  const oy = pad + 0.5 * (canvas.height - 2 * pad - scale * (y1 - y0));
  return { ctx, at: (x, y) => [ox + scale * (x - x0), canvas.height - (oy + scale * (y - y0))] };
}

// The deformed mesh X = x + β u (β from the slider times the scale that makes the largest
// displacement 5 % of the drawing), edges through their mid nodes, pairs as dots.
function drawMesh(view, bounds) {
  const m = view.mesh;
  const n = m.points.length / 2;
  const umax = m.displacement.reduce((a, v) => Math.max(a, Math.abs(v)), 0);
  const [x0, y0, x1, y1] = bounds;
  const beta = umax > 0 ? Number($("mag").value) * 0.05 * Math.max(x1 - x0, y1 - y0) / umax : 0;
  const X = new Float64Array(2 * n);
  for (let i = 0; i < 2 * n; i++) X[i] = m.points[i] + beta * m.displacement[i];
  const { ctx, at } = frame($("mesh"), bounds);
  ctx.save();
  ctx.beginPath();
  ctx.rect(0, 0, $("mesh").width, $("mesh").height);
  ctx.clip();
  const bodyColour = ["#555", "#8a6d3b", "#333"];
  for (let e = 0; e < m.edges.length / 3; e++) {
    const [a, mid, b] = [m.edges[3 * e], m.edges[3 * e + 1], m.edges[3 * e + 2]];
    const pa = at(X[2 * a], X[2 * a + 1]), pm = at(X[2 * mid], X[2 * mid + 1]), pb = at(X[2 * b], X[2 * b + 1]);
    ctx.strokeStyle = bodyColour[m.edge_body[e] % bodyColour.length];
    ctx.lineWidth = 0.7;
    ctx.beginPath();
    ctx.moveTo(...pa);
    // The quadratic through a, m, b at ξ = −1, 0, 1 has the Bézier control point 2m − (a + b)/2.
    ctx.quadraticCurveTo(2 * pm[0] - 0.5 * (pa[0] + pb[0]), 2 * pm[1] - 0.5 * (pa[1] + pb[1]), ...pb);
    ctx.stroke();
  }
  const counts = {};
  view.pairs.master.forEach((node, k) => {
    const s = view.pairs.state[k];
    counts[s] = (counts[s] || 0) + 1;
    const [px, py] = at(X[2 * node], X[2 * node + 1]);
    ctx.fillStyle = COLOURS[s];
    ctx.beginPath();
    ctx.arc(px, py, 3.5, 0, 2 * Math.PI);
    ctx.fill();
  });
  ctx.restore();
  const slip = (counts["slip+"] || 0) + (counts["slip-"] || 0);
  $("pair-counts").textContent = `— ${counts.stick || 0} stick, ${slip} slip, ${counts.contact || 0} contact, ` +
    `${counts.free || 0} free pairs; β = ${beta.toPrecision(3)}`;
  $("mesh").dataset.stick = counts.stick || 0;
  $("mesh").dataset.slip = slip;
  $("mesh").dataset.free = counts.free || 0;
}

// A line chart: series {x, y, colour, label, points?}, vertical markers {x, label}.
function chart(canvas, { series, markers = [], xlabel, ylabel, xrange }) {
  const ctx = canvas.getContext("2d");
  const W = canvas.width, H = canvas.height, L = 70, R = 150, T = 15, B = 40;
  ctx.clearRect(0, 0, W, H);
  const xs = series.flatMap((s) => s.x.filter((_, i) => s.y[i] !== null));
  const ys = series.flatMap((s) => s.y.filter((v) => v !== null));
  let [xa, xb] = xrange || [Math.min(...xs), Math.max(...xs)];
  let [ya, yb] = [Math.min(0, ...ys), Math.max(0, ...ys)];
  if (!(yb > ya)) { ya -= 1; yb += 1; }
  if (!(xb > xa)) { xa -= 1; xb += 1; }
  const margin = 0.05 * (yb - ya);
  ya -= margin; yb += margin;
  const px = (x) => L + (W - L - R) * (x - xa) / (xb - xa);
  const py = (y) => T + (H - T - B) * (yb - y) / (yb - ya);
  ctx.strokeStyle = "#000"; ctx.lineWidth = 1; ctx.font = "12px sans-serif"; ctx.fillStyle = "#000";
  ctx.strokeRect(L, T, W - L - R, H - T - B);
  ctx.strokeStyle = "#bbb"; ctx.beginPath(); ctx.moveTo(L, py(0)); ctx.lineTo(W - R, py(0)); ctx.stroke();
  for (let i = 0; i <= 4; i++) {
    const x = xa + (xb - xa) * i / 4, y = ya + (yb - ya) * i / 4;
    ctx.fillText(+x.toPrecision(3), px(x) - 10, H - B + 15);
    ctx.fillText(+y.toPrecision(3), 5, py(y) + 4);
  }
  ctx.fillText(xlabel, L + (W - L - R) / 2 - 20, H - 5);
  ctx.save(); ctx.translate(12, T + (H - T - B) / 2 + 30); ctx.rotate(-Math.PI / 2); ctx.fillText(ylabel, 0, 0); ctx.restore();
  markers.forEach((mk, k) => {
    if (mk.x === null || mk.x === undefined) return;
    ctx.strokeStyle = "#444"; ctx.setLineDash([4, 4]); ctx.beginPath();
    ctx.moveTo(px(mk.x), T); ctx.lineTo(px(mk.x), H - B); ctx.stroke(); ctx.setLineDash([]);
    ctx.fillText(mk.label, px(mk.x) + 3, T + 12 + 14 * k);
  });
  series.forEach((s, k) => {
    ctx.strokeStyle = ctx.fillStyle = s.colour; ctx.lineWidth = 1.8;
    if (s.points) {
      s.x.forEach((x, i) => { if (s.y[i] !== null) { ctx.beginPath(); ctx.arc(px(x), py(s.y[i]), 3, 0, 2 * Math.PI); ctx.fill(); } });
    } else {
      ctx.beginPath();
      let pen = false;
      s.x.forEach((x, i) => {
        if (s.y[i] === null) { pen = false; return; }
        pen ? ctx.lineTo(px(x), py(s.y[i])) : ctx.moveTo(px(x), py(s.y[i]));
        pen = true;
      });
      ctx.stroke();
    }
    ctx.fillRect(W - R + 10, T + 8 + 18 * k, 14, 3);
    ctx.fillText(s.label, W - R + 28, T + 13 + 18 * k);
  });
  ctx.fillStyle = "#000";
}

const fmt = (v) => (v === null || v === undefined ? "—" : typeof v !== "number" ? String(v) : Number.isInteger(v) ? String(v)
  : Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0)
  ? v.toExponential(4) : v.toPrecision(5));

// The summary table; each live cell keeps the exact value in data-value (for the tests).
function table(rows, published) {
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
  $("published-label").textContent = published
    ? `On a published set-up: ${published.label} (Solodovnikov 1998, on a finer mesh; scenes/${published.scene}.toml).`
    : "";
}

function drawFlagship(view) {
  drawMesh(view, [-2.5, 0, 5, 2.5]);
  const s = view.summary.paper, hole = view.hole, run = view.summary;
  chart($("profile"), {
    series: [
      { x: hole.eta, y: hole.p, colour: "#d62728", label: "p (hole edge)" },
      { x: hole.eta, y: hole.q, colour: "#1f77b4", label: "q (hole edge)" },
      { x: hole.eta, y: hole.hoop, colour: "#2ca02c", label: "hoop stress σφφ" },
    ],
    markers: [{ x: s.l, label: "l" }, { x: s.b !== s.l ? s.b : null, label: "b" }],
    xlabel: "η = 1 − φ/π", ylabel: "stress / E1", xrange: [0, 1],
  });
  $("profile-caption").textContent = "Along the hole edge: contact pressure p (< 0 in compression), shear q, " +
    "hoop stress; l = contact end, b = stick end (on η).";
  table([
    ["contact end l", "l", s.l], ["stick end b", "b", s.b], ["pulling force P", "P", s.P],
    ["Φ_E1 (plate)", "Phi_E1", s.Phi_E1], ["Φ_E2 (insert)", "Phi_E2", s.Phi_E2], ["Φ_f (dissipated)", "Phi_f", s.Phi_f],
    ["σ* (max hoop)", "sigma_star", s.sigma_star], ["K = H σ*/P", "K", s.K],
    ["status", "status", run.status], ["iterations", "iterations", run.iterations], ["pairs", "pairs", run.pairs],
  ], view.published);
  drawHistory();
}

function drawHistory() {
  const h = state.history;
  chart($("history-plot"), {
    series: [
      { x: h.map((p) => p.w), y: h.map((p) => p.l), colour: "#d62728", label: "l(w)", points: h.length < 2 },
      { x: h.map((p) => p.w), y: h.map((p) => p.b), colour: "#1f77b4", label: "b(w)", points: h.length < 2 },
    ],
    xlabel: "load w", ylabel: "η", xrange: [0, Math.max(1e-9, round4($("load").value))],
  });
}

// Steps w from 0 to the slider's value in 10 equal steps; with clearance and friction each point
// is the history of k equal steps (the zones depend on the path), otherwise one solve.
async function runHistory() {
  const K = 10, params = flagshipParams(), w = params.load;
  state.history = [];
  for (let k = 1; k <= K; k++) {
    const p = { ...params, load: round4((w * k) / K) };
    if (p.eps > 0 && p.friction > 0) p.steps = k;
    const t0 = performance.now();
    try {
      const view = SCENES.flagship.solve(p);
      const t1 = performance.now();
      state.history.push({ w: p.load, l: view.summary.paper.l, b: view.summary.paper.b });
      drawFlagship(view);
      page.timings.push({ scene: "history", solve_ms: t1 - t0, total_ms: performance.now() - t0 });
      $("timing").textContent = `history step ${k}/${K} (w = ${p.load}): ${(t1 - t0).toFixed(1)} ms`;
    } catch (e) {
      $("error").hidden = false;
      $("error").textContent = `history step ${k}: ${e}`;
      return;
    }
    await new Promise((r) => setTimeout(r, 120));
  }
}

function drawHertz(view) {
  const s = view.summary, c = s.contacts.hertz, cf = view.closed_form;
  const z = $("zoom").checked ? Math.max(4 * cf.a, 10) : null;
  drawMesh(view, z ? [0, -0.5 * z, z, 0.5 * z] : [0, -100, 100, 100]);
  const profile = c.profile;
  const keep = profile.x.map((x) => x <= 2.5 * cf.a);
  chart($("profile"), {
    series: [
      { x: profile.x.filter((_, i) => keep[i]), y: profile.pressure.filter((_, i) => keep[i]), colour: "#d62728",
        label: "computed p", points: true },
      { x: cf.x, y: cf.pressure, colour: "#000", label: "Hertz closed form" },
    ],
    markers: [{ x: cf.a, label: "a (Hertz)" }, { x: c.contact_length, label: "a (FE)" }],
    xlabel: "x along the block, mm", ylabel: "pressure, MPa", xrange: [0, 2.5 * cf.a],
  });
  $("profile-caption").textContent = "Contact pressure along the roller (master nodes) beside Hertz's " +
    "p(x) = p0 √(1 − x²/a²).";
  table([
    ["half-width a (FE), mm", "a", c.contact_length], ["a (Hertz), mm", "a_hertz", cf.a],
    ["largest pressure (FE), MPa", "p_max", c.max_pressure], ["p0 (Hertz), MPa", "p0_hertz", cf.p0],
    ["normal force Σλ (half model), N/mm", "normal_force", c.normal_force],
    ["status", "status", s.status], ["pairs", "pairs", s.pairs],
  ], null);
}

// Cattaneo–Mindlin: the contact zone of the deformed mesh, q/(μp0) and p/p0 along x/a beside the
// closed form at the measured P and Q, the stick half-width c/a computed and closed-form.
function drawCattaneoMindlin(view) {
  const s = view.summary, c = s.contacts.roller, cf = view.closed_form, m = view.measured;
  const z = 6 * cf.a;
  drawMesh(view, [-z, -0.45 * z, z, 0.45 * z]);
  const p = c.profile;
  const keep = p.x.map((x) => Math.abs(x) <= 1.5 * cf.a);
  const xs = p.x.filter((_, i) => keep[i]).map((x) => x / cf.a);
  const mp0 = cf.friction * cf.p0;
  chart($("profile"), {
    series: [
      { x: xs, y: p.shear.filter((_, i) => keep[i]).map((q) => (m.shear_sign * q) / mp0), colour: "#1f77b4",
        label: "computed q/(μp0)", points: true },
      { x: cf.x.map((x) => x / cf.a), y: cf.shear.map((q) => q / mp0), colour: "#000", label: "Cattaneo–Mindlin" },
      { x: xs, y: p.pressure.filter((_, i) => keep[i]).map((v) => v / cf.p0), colour: "#d62728",
        label: "computed p/p0", points: true },
      { x: cf.x.map((x) => x / cf.a), y: cf.pressure.map((v) => v / cf.p0), colour: "#888", label: "Hertz p/p0" },
    ],
    markers: [{ x: -m.c / cf.a, label: "−c (FE)" }, { x: m.c / cf.a, label: "c (FE)" },
      { x: cf.c / cf.a, label: "c (closed form)" }],
    xlabel: "x / a (a: closed form at the measured P)", ylabel: "traction / (p0 or μp0)", xrange: [-1.5, 1.5],
  });
  $("profile-caption").textContent = "Along the contact: shear q/(μp0) and pressure p/p0 at the roller's " +
    "nodes beside q(x) = μp0[√(1 − x²/a²) − (c/a)√(1 − x²/c²)] and Hertz's p, evaluated at the measured P and Q. In the slip zones q = μp, so q/(μp0) lies on p/p0.";
  $("cm-ratio-out").textContent = m.ratio.toFixed(3);
  $("cm-ratio-out").dataset.value = String(m.ratio);
  table([
    ["Q/(μP)", "ratio", m.ratio], ["c/a (FE: half the stick length / a)", "c_over_a", m.c / cf.a],
    ["c/a (closed form √(1 − Q/μP))", "c_over_a_closed", cf.c / cf.a],
    ["half-width a (FE), mm", "a", m.a], ["a (Hertz at P), mm", "a_hertz", cf.a],
    ["P (normal reaction), N/mm", "P", m.p], ["Q (tangential reaction), N/mm", "Q", m.q],
    ["p0 (Hertz), MPa", "p0", cf.p0], ["status", "status", s.status], ["pairs", "pairs", s.pairs],
  ], null);
}

function showScene(name) {
  state.scene = name;
  document.querySelectorAll("#scenes button").forEach((b) => b.classList.toggle("active", b.dataset.scene === name));
  document.querySelectorAll("[data-for]").forEach((el) => { el.hidden = el.dataset.for !== name; });
  update();
}

async function main() {
  await init();
  state.bundled = JSON.parse(bundled_json());
  $("eps").max = state.bundled.flagship_eps.length - 1;
  applyUrl();
  for (const id of ["mu", "ratio", "eps", "load", "variant", "refinement", "force", "level", "zoom", "cm-press", "cm-shear", "cm-level"]) {
    $(id).addEventListener("input", () => { state.history = []; update(); });
  }
  $("mag").addEventListener("input", () => { showLabels(); if (state.view) SCENES[state.scene].draw(state.view); });
  $("history").addEventListener("click", runHistory);
  document.querySelectorAll("#scenes button").forEach((b) => b.addEventListener("click", () => showScene(b.dataset.scene)));
  document.querySelectorAll("[data-preset]").forEach((b) => b.addEventListener("click", () => applyPreset(b.dataset.preset)));
  showScene(state.scene);
}

page.ready = main();
