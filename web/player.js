// The player: play / pause / step / scrub through the steps of a finished loading history, a
// Mindlin–Deresiewicz cycle or a user's multi-step scene (its schedule's steps), every step drawn at ONE scale taken from the whole run (the mesh's
// β and box, the charts' y axes), so that frames are comparable and the deformation grows with
// the load. The run's steps live in ctx.state.player; the page (app.js) clears it on any input.
import { chart, fixedMeshScale } from "./chart.js";
import { drawCycleStep } from "./cycle.js";

const $ = (id) => document.getElementById(id);

/** Draws step k of a history or cycle with a recording `ui`: the scene's chart specs and the
 * mesh's focus, without drawing. */
function specsOf(ctx, p, k) {
  const got = { focus: null, charts: {} };
  const add = (id, spec) => { (got.charts[id] = got.charts[id] || []).push(...spec.series.flatMap((s) => s.y.filter((v) => v !== null))); };
  const ui = { mesh: (v, focus) => { got.focus = focus; }, chart: (spec) => add("profile", spec), output() {}, banner() {}, table() {} };
  if (p.kind === "cycle") drawCycleStep(p.view, k, ui, { id: "history-plot" }, (c, spec) => add(c.id, spec));
  else (p.drawFrame || ctx.drawFlagship)(p.frames[k - 1].view, ui, p.values);
  return got;
}

/** The player over ctx = {state, page, draw(view, values, shows, custom), drawFlagship(view,
 * ui, values)}: {set(run), clear(), show(k), stop(), play(), wire()}. A run is {kind: "history"
 * | "cycle" | "user", values, frames: [{view, shows}] or view, first, last, interval (ms a step),
 * drawFrame(view, ui, values) (a user's scene: its tab's drawing; the flagship's by default)}. */
export function makePlayer(ctx) {
  function set(p) {
    p.k = p.last;
    p.token = 0;
    const views = p.kind === "cycle" ? [p.view] : p.frames.map((f) => f.view);
    const ys = {};
    let focus = null;
    for (let k = p.first; k <= p.last; k++) {
      const got = specsOf(ctx, p, k);
      focus = got.focus;
      for (const [id, y] of Object.entries(got.charts)) (ys[id] = ys[id] || []).push(...y);
    }
    if (p.kind === "history") ys["history-plot"] = ctx.state.history.flatMap((h) => [h.l, h.b]);
    const yrange = Object.fromEntries(Object.entries(ys).map(([id, y]) => [id, [Math.min(...y), Math.max(...y)]]));
    p.fixed = { mesh: fixedMeshScale(views, Number(p.values.mag), focus), yrange };
    ctx.state.player = p;
    const scrub = $("scrub");
    Object.assign(scrub, { min: p.first, max: p.last, step: 1 });
    scrub.value = p.k;
    $("player").hidden = false;
    $("player-what").textContent = { cycle: "the cycle's steps:", history: "the history's steps:",
      user: "your scene's load steps:" }[p.kind];
    ctx.page.player = { kind: p.kind, k: p.k, first: p.first, last: p.last, playing: false, fixed: p.fixed };
  }

  function clear() {
    stop();
    ctx.state.player = null;
    ctx.page.player = null;
    $("player").hidden = true;
  }

  /** Shows step k (clamped to the run's steps) at the run's fixed scale. */
  function show(k) {
    const p = ctx.state.player;
    if (!p) return;
    k = Math.min(p.last, Math.max(p.first, k));
    p.k = k;
    $("scrub").value = k;
    $("scrub-out").textContent = `step ${k} of ${p.last}`;
    ctx.page.player.k = k;
    if (p.kind === "cycle") {
      const view = p.view, values = p.values;
      const shows = { kind: "cycle", scene: "cattaneo_mindlin", step: k,
        text: `Mindlin–Deresiewicz cycle, step ${k} of ${p.last}: the top at δ = ${view.cycle_shear[k]} × 0.01 mm ` +
          `(press ${values.press}, amplitude ${values.amp}); the mesh's shape is the last step's.` };
      ctx.draw(view, values, shows, (ui) => drawCycleStep(view, k, ui, $("history-plot"), (c, spec) =>
        chart(c, { ...spec, yrange: p.fixed.yrange[c.id] })));
      ctx.page.cycleStep = k;
    } else {
      const { view, shows } = p.frames[k - 1];
      ctx.draw(view, p.values, shows);
      ctx.page.view = view;
    }
  }

  function stop() {
    const p = ctx.state.player;
    if (!p) return;
    p.token += 1;
    if (ctx.page.player) ctx.page.player.playing = false;
    $("play").textContent = "Play";
  }

  /** Plays from the step after the current one (from the first at the end) to the last; resolves
   * true when it reached the last step, false when paused or stopped. */
  async function play() {
    const p = ctx.state.player;
    if (!p) return false;
    const token = ++p.token;
    ctx.page.player.playing = true;
    $("play").textContent = "Pause";
    for (let k = p.k >= p.last ? p.first : p.k + 1; k <= p.last; k++) {
      show(k);
      if (k < p.last) await new Promise((r) => setTimeout(r, p.interval));
      if (token !== p.token || ctx.state.player !== p) return false;
    }
    stop();
    return true;
  }

  /** The buttons and the scrub bar of #player. */
  function wire() {
    $("play").addEventListener("click", () => {
      if (ctx.page.player && ctx.page.player.playing) stop(); else play();
    });
    $("step-back").addEventListener("click", () => { stop(); show(ctx.state.player.k - 1); });
    $("step-fwd").addEventListener("click", () => { stop(); show(ctx.state.player.k + 1); });
    $("scrub").addEventListener("input", () => { stop(); show(Number($("scrub").value)); });
  }

  return { set, clear, show, stop, play, wire };
}
