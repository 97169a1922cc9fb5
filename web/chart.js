// Drawing on canvases at the device's pixel ratio: the deformed mesh (fitted to its canvas) and
// line charts whose labels never overprint (tick labels, axis titles, markers and legend each
// get their own band; marker labels are stacked where they would collide).
//
// Sizes are CSS pixels; the canvas backing store is CSS size × devicePixelRatio, so text and
// lines are sharp on high-density screens. FONT_PX is the chart text size (≥ 14 CSS px; larger
// in projector mode).

// Slip in the two global directions in two colours: "slip+" (red) is sliding towards +x (+y on a
// surface steeper than 45°), "slip-" (orange) towards −x (−y); after a reversal (the
// Mindlin–Deresiewicz cycle) the slip the other way is seen growing from the edges.
export const COLOURS = { stick: "#1f77b4", "slip+": "#d62728", "slip-": "#ff7f0e", contact: "#2ca02c", free: "#969696" };

/** A pair's state named in the global frame. The solver's `slip+` is the master node sliding
 * along the pair's tangent `+t` relative to the slave surface (`slip-` along −t); the page names
 * it by the global axis nearest to t (x unless the surface is steeper than 45°) and the sign of
 * the motion along it: returns {key: "slip+" | "slip-" (towards + / − of that axis), name:
 * "slip +x" ...}. Other states are returned as they are. */
export function globalSlip(state, tangent) {
  if (!state.startsWith("slip") || !tangent) return { key: state, name: state };
  const axis = Math.abs(tangent[0]) >= Math.abs(tangent[1]) ? 0 : 1;
  const sign = (state === "slip+" ? 1 : -1) * Math.sign(tangent[axis] || 1);
  return { key: sign > 0 ? "slip+" : "slip-", name: `slip ${sign > 0 ? "+" : "−"}${axis ? "y" : "x"}` };
}

let fontPx = 16;
/** Sets the chart text size in CSS px (16 normally, 22 in projector mode). */
export function setFontPx(px) { fontPx = px; }

/** Resizes the canvas's backing store to its CSS box × devicePixelRatio; returns a context
 * whose unit is the CSS pixel, and the CSS width and height. */
export function prepare(canvas) {
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(50, canvas.clientWidth), h = Math.max(50, canvas.clientHeight);
  if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
  }
  const ctx = canvas.getContext("2d");
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return { ctx, W: w, H: h };
}

// The last chart drawn on each canvas (its spec), for the CSV and the SVG figure's vector charts.
export const lastCharts = {};

/** The deformed mesh X = x + β u fitted to the canvas: the drawing's bounds are those of the
 * deformed nodes (and `focus`, a box [x0, y0, x1, y1] to zoom on, when given: then only the
 * focus is framed and the rest is clipped). β is `magnification` times the scale that makes
 * the largest displacement 5 % of the undeformed drawing; `fixed` (fixedMeshScale) gives one β
 * and box for all steps of a history instead. Returns the pair counts and β. */
export function drawMesh(canvas, view, magnification, focus = null, fixed = null) {
  const m = view.mesh;
  const n = m.points.length / 2;
  const { ctx, W, H } = prepare(canvas);
  if (n === 0) return { counts: {}, beta: 0 };
  const beta = fixed ? fixed.beta : meshBeta([view], magnification, focus);
  const X = new Float64Array(2 * n);
  for (let i = 0; i < 2 * n; i++) X[i] = m.points[i] + beta * m.displacement[i];
  const bounds = focus || (fixed ? fixed.bounds : meshBounds([view], beta));
  const pad = 8;
  const [bx0, by0, bx1, by1] = bounds;
  const scale = Math.min((W - 2 * pad) / Math.max(bx1 - bx0, 1e-300), (H - 2 * pad) / Math.max(by1 - by0, 1e-300));
  const ox = pad + 0.5 * (W - 2 * pad - scale * (bx1 - bx0));
  const oy = pad + 0.5 * (H - 2 * pad - scale * (by1 - by0));
  const at = (x, y) => [ox + scale * (x - bx0), H - (oy + scale * (y - by0))];
  ctx.save();
  ctx.beginPath();
  ctx.rect(0, 0, W, H);
  ctx.clip();
  const bodyColour = ["#555", "#8a6d3b", "#333", "#6b4c9a"];
  // 1.5 CSS px: thinner lines vanish on a projector.
  ctx.lineWidth = 1.5;
  // One path (one stroke) per body colour: a stroke per edge made large meshes slow to draw on
  // the page's thread.
  for (let colour = 0; colour < bodyColour.length; colour++) {
    ctx.strokeStyle = bodyColour[colour];
    ctx.beginPath();
    let any = false;
    for (let e = 0; e < m.edges.length / 3; e++) {
      if (m.edge_body[e] % bodyColour.length !== colour) continue;
      any = true;
      const [a, mid, b] = [m.edges[3 * e], m.edges[3 * e + 1], m.edges[3 * e + 2]];
      const pa = at(X[2 * a], X[2 * a + 1]), pm = at(X[2 * mid], X[2 * mid + 1]), pb = at(X[2 * b], X[2 * b + 1]);
      ctx.moveTo(...pa);
      // The quadratic through a, m, b at ξ = −1, 0, 1 has the Bézier control point 2m − (a + b)/2.
      ctx.quadraticCurveTo(2 * pm[0] - 0.5 * (pa[0] + pb[0]), 2 * pm[1] - 0.5 * (pa[1] + pb[1]), ...pb);
    }
    if (any) ctx.stroke();
  }
  const counts = {};
  view.pairs.master.forEach((node, k) => {
    const s = globalSlip(view.pairs.state[k], (view.pairs.tangent || [])[k]).key;
    counts[s] = (counts[s] || 0) + 1;
    const [px, py] = at(X[2 * node], X[2 * node + 1]);
    ctx.fillStyle = COLOURS[s];
    ctx.beginPath();
    ctx.arc(px, py, 4, 0, 2 * Math.PI);
    ctx.fill();
  });
  ctx.restore();
  return { counts, beta };
}

/** β for the views drawn together: `magnification` times the scale that makes the largest
 * displacement of all of them 5 % of the undeformed drawing (of `focus` when given). */
function meshBeta(views, magnification, focus) {
  const pts = views[0].mesh.points;
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let i = 0; i < pts.length / 2; i++) {
    x0 = Math.min(x0, pts[2 * i]); x1 = Math.max(x1, pts[2 * i]);
    y0 = Math.min(y0, pts[2 * i + 1]); y1 = Math.max(y1, pts[2 * i + 1]);
  }
  const umax = views.reduce((a, v) => v.mesh.displacement.reduce((b, u) => Math.max(b, Math.abs(u)), a), 0);
  const size = focus ? Math.max(focus[2] - focus[0], focus[3] - focus[1]) : Math.max(x1 - x0, y1 - y0);
  return umax > 0 ? magnification * 0.05 * size / umax : 0;
}

/** The box [x0, y0, x1, y1] holding every view's undeformed and deformed (X = x + β u) nodes. */
function meshBounds(views, beta) {
  const b = [Infinity, Infinity, -Infinity, -Infinity];
  for (const { mesh: m } of views) {
    const p = m.points, u = m.displacement;
    for (let i = 0; i < p.length; i += 2) {
      const x = p[i], y = p[i + 1], X = x + beta * u[i], Y = y + beta * u[i + 1];
      b[0] = Math.min(b[0], x, X); b[2] = Math.max(b[2], x, X); b[1] = Math.min(b[1], y, Y); b[3] = Math.max(b[3], y, Y);
    }
  }
  return b;
}

/** One drawing scale for the steps of a history or cycle (frames comparable: the deformation
 * grows with the load): β from the largest displacement of all `views`, the bounds of all of
 * them. Pass the result to drawMesh as `fixed`. */
export function fixedMeshScale(views, magnification, focus = null) {
  const beta = meshBeta(views, magnification, focus);
  return { beta, bounds: focus || meshBounds(views, beta) };
}

/** Round tick values: the multiples of a step 1, 2, 2.5 or 5 × 10^k in [a, b], the step the
 * smallest of these giving at most `most` intervals over [a, b]; labels with the step's decimals. */
export function niceTicks(a, b, most = 5) {
  const raw = (b - a) / most;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((st) => st >= raw * (1 - 1e-9));
  const digits = Math.max(0, -Math.floor(Math.log10(step) + 1e-9) + (step / mag === 2.5 ? 1 : 0));
  const ticks = [];
  for (let k = Math.ceil(a / step - 1e-9); k * step <= b + 1e-9 * step; k++) {
    ticks.push({ v: k * step, label: String(+(k * step).toFixed(Math.min(digits, 20)) || 0) });
  }
  return ticks;
}

/** A line chart: series {x, y, colour, label, points?, fill?, dash?}, vertical markers {x, label},
 * optional xrange / yrange [a, b] (fixed axes); every
 * label sits in a band of its own: tick labels under/left of the plot, axis titles outside
 * them, the legend above the plot, marker labels in a strip above the plot stacked into rows
 * so that no two overlap. */
export function chart(canvas, spec) {
  const { series, markers = [], xlabel, ylabel, xrange, yrange } = spec;
  const { ctx, W, H } = prepare(canvas);
  lastCharts[canvas.id] = spec;
  const f = fontPx, line = Math.round(1.3 * f);
  ctx.font = `${f}px sans-serif`;
  const xs = series.flatMap((s) => s.x.filter((_, i) => s.y[i] !== null));
  const ys = series.flatMap((s) => s.y.filter((v) => v !== null));
  let [xa, xb] = xrange || [Math.min(...xs), Math.max(...xs)];
  // yrange: a fixed y axis (a history's frames share one), else the series' extent and 0.
  let [ya, yb] = yrange ? [Math.min(0, yrange[0]), Math.max(0, yrange[1])] : [Math.min(0, ...ys), Math.max(0, ...ys)];
  if (!(yb > ya)) { ya -= 1; yb += 1; }
  if (!(xb > xa)) { xa -= 1; xb += 1; }
  const margin = 0.05 * (yb - ya);
  ya -= margin; yb += margin;
  const yticks = niceTicks(ya, yb);
  const tickWidth = Math.max(...yticks.map((t) => ctx.measureText(t.label).width));
  // The legend: entries laid out left to right, wrapping into rows across the top.
  const legend = [];
  let lx = 0, lrow = 0;
  for (const s of series) {
    const w = 22 + ctx.measureText(s.label).width + 16;
    if (lx + w > W - 10 && lx > 0) { lx = 0; lrow += 1; }
    legend.push({ s, x: 10 + lx, row: lrow });
    lx += w;
  }
  // Marker labels: rows so that no two overlap horizontally (placed once the x scale is known).
  const shown = markers.filter((mk) => mk.x !== null && mk.x !== undefined && Number.isFinite(mk.x));
  const L = 6 + line + 6 + tickWidth + 6, R = 12, B = 6 + line + 4 + line;
  const legendH = (lrow + 1) * line;
  const px0 = (x) => L + (W - L - R) * (x - xa) / (xb - xa);
  const rows = [];
  const placed = shown.map((mk) => {
    const w = ctx.measureText(mk.label).width;
    const left = Math.min(Math.max(px0(mk.x) - w / 2, L), W - R - w);
    let r = 0;
    while ((rows[r] || []).some(([a, b]) => left < b + 6 && a < left + w + 6)) r += 1;
    (rows[r] = rows[r] || []).push([left, left + w]);
    return { mk, left, row: r };
  });
  const T = 6 + legendH + 4 + rows.length * line + 4;
  const px = px0;
  const py = (y) => T + (H - T - B) * (yb - y) / (yb - ya);
  ctx.textBaseline = "alphabetic";
  ctx.fillStyle = "#000";
  ctx.strokeStyle = "#000"; ctx.lineWidth = 1;
  ctx.strokeRect(L, T, W - L - R, H - T - B);
  ctx.strokeStyle = "#bbb"; ctx.beginPath(); ctx.moveTo(L, py(0)); ctx.lineTo(W - R, py(0)); ctx.stroke();
  // x tick labels: centred under their ticks, skipped where they would touch the previous one.
  let lastRight = -Infinity;
  for (const { v: x, label } of niceTicks(xa, xb)) {
    const w = ctx.measureText(label).width;
    const left = Math.min(Math.max(px(x) - w / 2, L - w / 2), W - w - 2);
    if (left > lastRight + 8) { ctx.fillText(label, left, H - B + 4 + f); lastRight = left + w; }
  }
  yticks.forEach(({ v: y, label }) => {
    ctx.fillText(label, L - 6 - ctx.measureText(label).width, py(y) + 0.35 * f);
  });
  ctx.fillText(xlabel, L + (W - L - R) / 2 - ctx.measureText(xlabel).width / 2, H - 6);
  ctx.save();
  ctx.translate(6 + f, T + (H - T - B) / 2 + ctx.measureText(ylabel).width / 2);
  ctx.rotate(-Math.PI / 2); ctx.fillText(ylabel, 0, 0); ctx.restore();
  placed.forEach(({ mk, left, row }) => {
    ctx.strokeStyle = "#444"; ctx.setLineDash([5, 4]); ctx.beginPath();
    ctx.moveTo(px(mk.x), T - 2 - (rows.length - 1 - row) * line); ctx.lineTo(px(mk.x), H - B); ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = "#000";
    ctx.fillText(mk.label, left, T - 4 - (rows.length - 1 - row) * line - 0.25 * f);
  });
  ctx.save();
  ctx.beginPath(); ctx.rect(L, T, W - L - R, H - T - B); ctx.clip();
  series.forEach((s) => {
    // The SVG export's context (svgcontext.js) groups each series' elements.
    if (ctx.svgSeries) ctx.svgSeries(s.label);
    ctx.strokeStyle = ctx.fillStyle = s.colour; ctx.lineWidth = 2;
    if (s.fill && s.x.length > 2) {
      // A closed polygon filled (the hysteresis loop's area).
      ctx.fillStyle = s.fill;
      ctx.beginPath();
      s.x.forEach((x, i) => (i ? ctx.lineTo(px(x), py(s.y[i])) : ctx.moveTo(px(x), py(s.y[i]))));
      ctx.closePath();
      ctx.fill();
      ctx.fillStyle = s.colour;
    }
    if (s.points) {
      s.x.forEach((x, i) => { if (s.y[i] !== null) { ctx.beginPath(); ctx.arc(px(x), py(s.y[i]), 3.5, 0, 2 * Math.PI); ctx.fill(); } });
    } else {
      ctx.setLineDash(s.dash ? [7, 5] : []);
      ctx.beginPath();
      let pen = false;
      s.x.forEach((x, i) => {
        if (s.y[i] === null) { pen = false; return; }
        pen ? ctx.lineTo(px(x), py(s.y[i])) : ctx.moveTo(px(x), py(s.y[i]));
        pen = true;
      });
      ctx.stroke();
      ctx.setLineDash([]);
    }
  });
  if (ctx.svgSeries) ctx.svgSeries(null);
  ctx.restore();
  legend.forEach(({ s, x, row }) => {
    const y = 6 + row * line + f;
    ctx.fillStyle = s.colour;
    ctx.fillRect(x, y - 0.4 * f, 16, 4);
    ctx.fillStyle = "#000";
    ctx.fillText(s.label, x + 22, y);
  });
}

/** The CSV of the last chart on `canvasId`: one block per series (x, y columns). */
export function chartCsv(canvasId) {
  const c = lastCharts[canvasId];
  if (!c) return "";
  const quote = (s) => `"${String(s).replaceAll('"', '""')}"`;
  const lines = [];
  for (const s of c.series) {
    lines.push(`${quote("series")},${quote(s.label)}`);
    lines.push(`${quote(c.xlabel)},${quote(c.ylabel)}`);
    s.x.forEach((x, i) => { if (s.y[i] !== null) lines.push(`${x},${s.y[i]}`); });
    lines.push("");
  }
  return lines.join("\n");
}
