// The Mindlin–Deresiewicz cycle on the Cattaneo–Mindlin tab: the roller pressed, its top moved
// sideways to +A, back to −A and up to +A again (ten steps each way), solved in one call (every
// step carries the interface's profile). The page then plays the steps: the pairs' states along
// the contact (reverse slip growing in from the edges after each reversal), the shear beside
// ±μp, and the Q–δ hysteresis loop drawn up to the current step.
import { solve_cattaneo_mindlin_json } from "./pkg/contact2d_web.js";
import { COLOURS, globalSlip } from "./chart.js";

export const CYCLE_STEPS = 10;
const SHEAR_MM = 0.01;
const round4 = (v) => Math.round(v * 1e4) / 1e4;

/** The shear factors after the first loading to `a`: down to −a and back up, ten steps each. */
export function cyclePath(a) {
  const down = Array.from({ length: CYCLE_STEPS }, (_, i) => round4(a - (2 * a * (i + 1)) / CYCLE_STEPS));
  const up = Array.from({ length: CYCLE_STEPS }, (_, i) => round4(-a + (2 * a * (i + 1)) / CYCLE_STEPS));
  return [...down, ...up];
}

/** Solves the whole cycle; returns the view (steps[0] is the press, steps[1] the loading to a). */
export function solveCycle(values) {
  const a = round4(Number(values.amp));
  const params = { press: round4(Number(values.press)), shear: a, level: values.level, cycle: cyclePath(a) };
  const view = JSON.parse(solve_cattaneo_mindlin_json(JSON.stringify(params)));
  view.cycle_shear = [0, a, ...params.cycle];
  return view;
}

/** Draws step `k` (1 ..= 2·CYCLE_STEPS + 1) of a solved cycle through the page's `ui`. */
export function drawCycleStep(view, k, ui, loopCanvas, chart) {
  const steps = view.summary.steps;
  const mu = view.closed_form.friction;
  const profile = steps[k].contacts.roller.profile;
  const Q = steps.map((s) => s.reactions.cylinder_top[0]);
  const P = -steps[1].reactions.cylinder_top[1];
  // The loading's slip sign (its first step with slip); the other sign is reverse slip.
  const loading = steps[1].contacts.roller.profile.state.find((s) => s.startsWith("slip")) || "slip+";
  const reverse = loading === "slip+" ? "slip-" : "slip+";
  // Their colours and names as the mesh shows them: by the global direction of the sliding
  // (the flat contact has one tangent).
  const tangent = (view.pairs.tangent || [])[0];
  const [gLoading, gReverse] = [globalSlip(loading, tangent), globalSlip(reverse, tangent)];
  // The pairs coloured by this step's states (matched on the master nodes' x); the deformed
  // shape drawn is the last step's.
  const stateAt = new Map(profile.x.map((x, i) => [x.toFixed(9), profile.state[i]]));
  const m = view.mesh;
  const pairs = { ...view.pairs, state: view.pairs.master.map((n, i) => stateAt.get(m.points[2 * n].toFixed(9)) ?? view.pairs.state[i]) };
  const a = view.closed_form.a, z = 6 * a;
  ui.mesh({ ...view, pairs }, [-z, -0.45 * z, z, 0.45 * z]);
  const pick = (cond) => profile.x.map((x, i) => (cond(profile.state[i]) ? profile.shear[i] : null));
  const xs = profile.x.map((x) => x / a);
  ui.chart({
    series: [
      { x: xs, y: profile.pressure.map((p) => mu * p), colour: "#888", label: "+μp" },
      { x: xs, y: profile.pressure.map((p) => -mu * p), colour: "#bbb", label: "−μp" },
      { x: xs, y: pick((s) => s === "stick"), colour: "#1f77b4", label: "q, stick", points: true },
      { x: xs, y: pick((s) => s === loading), colour: COLOURS[gLoading.key], label: `q, ${gLoading.name} (as first loaded)`,
        points: true },
      { x: xs, y: pick((s) => s === reverse), colour: COLOURS[gReverse.key], label: `q, ${gReverse.name} (the other way)`,
        points: true },
    ],
    xlabel: "x / a", ylabel: "shear q, MPa", xrange: [-1.5, 1.5],
  }, `Mindlin–Deresiewicz cycle, step ${k} of ${steps.length - 1}: the shear q along the contact between ±μp; ` +
    "after each reversal, slip in the new direction grows in " +
    "from both edges while the middle sticks.");
  const delta = view.cycle_shear.map((s) => s * SHEAR_MM);
  chart(loopCanvas, {
    series: [
      { x: delta.slice(0, 2), y: Q.slice(0, 2), colour: "#999", label: "first loading 0 → +A (one step)" },
      { x: delta.slice(1, k + 1), y: Q.slice(1, k + 1), colour: "#6b4c9a", label: "Q(δ), computed",
        fill: "rgba(107, 76, 154, 0.25)" },
      { x: [delta[k]], y: [Q[k]], colour: "#d62728", label: "now", points: true },
    ],
    xlabel: "δ: sideways displacement of the roller's top, mm", ylabel: "Q, N/mm",
    // Fixed axes: the whole cycle's δ and Q, so the loop grows inside a frame that stays put.
    xrange: [-1.1 * Math.abs(delta[1]), 1.1 * Math.abs(delta[1])], yrange: [Math.min(...Q), Math.max(...Q)],
  });
  const count = (s) => profile.state.filter((t) => t === s).length;
  // The ratio beside the slider follows the cycle (not the slider's own solve).
  ui.output("cm-ratio-out", Q[k] / (mu * P), `${(Q[k] / (mu * P)).toFixed(3)} (cycle step ${k})`);
  ui.banner(null);
  ui.table([
    ["step of the cycle", "cycle_step", k], ["δ, mm", "delta", delta[k]], ["Q, N/mm", "Q", Q[k]],
    ["Q/(μP)", "ratio", Q[k] / (mu * P)], ["stick pairs", "stick", count("stick")],
    ["pairs slipping as first loaded", "slip", count(loading)], ["pairs slipping the other way", "reverse", count(reverse)],
    ["status", "status", view.summary.status],
  ]);
}
