// The three scenes with published or closed-form companions: the plate with an insert
// (Solodovnikov 1998), Hertz (NAFEMS) and Cattaneo–Mindlin. Each scene is its controls (keys are
// the URL's), the request its solve takes, and the drawing of the returned view through `ui`
// (mesh, profile chart, table, banner). See app.js for how a scene is run.
import { solve_flagship_json, solve_hertz_json, solve_cattaneo_mindlin_json } from "./pkg/contact2d_web.js";

export const RATIOS = ["0.25", "0.5", "1", "2", "4", "8", "16"];
export const EPS = ["0", "1e-6", "0.001", "0.05", "0.2"];
const round4 = (v) => Number(Number(v).toFixed(4));

// The published set-ups: the bundled scenes scenes/plate_insert_*.toml (E2/E1 = 1).
export const PRESETS = {
  nogap_mu0: { label: "no gap, μ = 0", mu: "0", eps: "0", load: "1", variant: "hole_master" },
  nogap_mu03: { label: "no gap, μ = 0.3", mu: "0.3", eps: "0", load: "1", variant: "hole_master" },
  gap_v1_mu03: { label: "Table 2 U(1)", mu: "0.3", eps: "0.05", load: "0.3838", variant: "hole_master" },
  gap_v2_mu03: { label: "Table 2 U(2)", mu: "0.3", eps: "0.05", load: "0.3838", variant: "insert_master" },
  gap_v2_mu0: { label: "Table 2 U(3)", mu: "0", eps: "0.05", load: "0.3838", variant: "insert_master" },
};

/** The flagship's request for the controls' values (`steps` for one step of a history). */
export function flagshipParams(v, steps) {
  const p = {
    friction: round4(v.mu), stiffness_ratio: Number(v.ratio), eps: Number(v.eps), refinement: Number(v.N),
    load: round4(v.load), variant: v.variant,
  };
  if (steps !== undefined) p.steps = steps;
  return p;
}

/** The flagship's default load steps (the Rust side's rule: 3 with clearance and friction). */
export const flagshipSteps = (p) => (p.steps ?? (p.eps > 0 && p.friction > 0 ? 3 : 1));

const flagship = {
  title: "Plate with an insert (Solodovnikov 1998)",
  short: "Plate + insert",
  keys: ["l", "b", "P"],
  controls: [
    { key: "mu", id: "mu", label: "friction μ", kind: "range", min: 0, max: 0.6, step: 0.05, value: 0,
      show: (v) => Number(v).toFixed(2) },
    { key: "ratio", id: "ratio", label: "stiffness ratio E2/E1", kind: "select", value: "1",
      options: RATIOS.map((r) => [r, r]) },
    { key: "eps", id: "eps", label: "clearance ε (c = ω ε, ω = 20)", kind: "select", value: "0",
      options: EPS.map((e) => [e, `${e} (c = ${+(20 * Number(e)).toPrecision(6)})`]) },
    { key: "load", id: "load", label: "load w (pulled-edge displacement)", kind: "range", min: 0.0002, max: 1,
      step: 0.0002, value: 1, show: (v) => Number(v).toFixed(4) },
    { key: "variant", id: "variant", label: "pairing variant", kind: "select", value: "hole_master",
      options: [["hole_master", "1: hole edge is master"], ["insert_master", "2: insert edge is master"]] },
    { key: "N", id: "refinement", label: "mesh N (elements on the half hole edge)", kind: "select", value: "16",
      options: [["16", "16"], ["32", "32"]] },
  ],
  history: true,
  solve: (v, steps) => JSON.parse(solve_flagship_json(JSON.stringify(flagshipParams(v, steps)))),
  describe: (v) => {
    const p = flagshipParams(v);
    return `μ = ${p.friction}, E2/E1 = ${p.stiffness_ratio}, ε = ${p.eps}, w = ${p.load}, variant ` +
      `${p.variant === "hole_master" ? 1 : 2}, N = ${p.refinement}, ${flagshipSteps(p)} load step(s)`;
  },
  draw(view, ui, v) {
    ui.mesh(view, null);
    const s = view.summary.paper, hole = view.hole, run = view.summary;
    const frictionless = Number(v.mu) === 0;
    ui.chart({
      series: [
        // The solver's normal stress is < 0 in compression; the contact pressure p = −σ_nn ≥ 0.
        { x: hole.eta, y: hole.p.map((v) => (v === null ? null : -v)), colour: "#d62728", label: "p (hole edge)" },
        { x: hole.eta, y: hole.q, colour: "#1f77b4", label: "q (hole edge)" },
        { x: hole.eta, y: hole.hoop, colour: "#2ca02c", label: "hoop stress σφφ" },
      ],
      markers: [{ x: s.l, label: "l (contact end)" }, { x: frictionless || s.b === s.l ? null : s.b, label: "b (stick end)" }],
      xlabel: "η = 1 − φ/π", ylabel: "stress / E1", xrange: [0, 1],
    }, "Along the hole edge: contact pressure p (> 0 in compression), shear q, hoop stress σφφ; " +
      "l = contact end, b = stick end (on η).");
    ui.table([
      ["contact end l", "l", s.l],
      // Without friction nothing sticks: b is not defined (the solver's b equals l there).
      ["stick end b", "b", frictionless ? null : s.b],
      ["pulling force P", "P", s.P],
      ["Φ_E1 (plate)", "Phi_E1", s.Phi_E1], ["Φ_E2 (insert)", "Phi_E2", s.Phi_E2], ["Φ_f (dissipated)", "Phi_f", s.Phi_f],
      ["σ* (max hoop)", "sigma_star", s.sigma_star], ["K = H σ*/P", "K", s.K],
      ["status", "status", run.status], ["iterations", "iterations", run.iterations], ["pairs", "pairs", run.pairs],
    ]);
  },
};

const hertz = {
  title: "Hertz: roller on a block (NAFEMS)",
  short: "Hertz",
  keys: ["a", "a_hertz", "p_max"],
  controls: [
    { key: "force", id: "force", label: "force F (N per mm of thickness, whole roller)", kind: "range", min: 2500,
      max: 70000, step: 2500, value: 35000, show: (v) => Number(v).toLocaleString("en") },
    { key: "level", id: "level", label: "mesh", kind: "select", value: "L1", options: [["L1", "L1"]] },
    { key: "zoom", id: "zoom", label: "zoom on the contact", kind: "checkbox", value: "1" },
  ],
  solve: (v) => JSON.parse(solve_hertz_json(JSON.stringify({ force: Number(v.force), level: v.level }))),
  describe: (v) => `F = ${Number(v.force).toLocaleString("en")} N/mm on mesh ${v.level}`,
  draw(view, ui, v) {
    const s = view.summary, c = s.contacts.hertz, cf = view.closed_form;
    const z = v.zoom === "1" ? Math.max(4 * cf.a, 10) : null;
    ui.mesh(view, z ? [0, -0.5 * z, z, 0.5 * z] : null);
    const profile = c.profile;
    const keep = profile.x.map((x) => x <= 2.5 * cf.a);
    ui.chart({
      series: [
        { x: profile.x.filter((_, i) => keep[i]), y: profile.pressure.filter((_, i) => keep[i]), colour: "#d62728",
          label: "computed p", points: true },
        { x: cf.x, y: cf.pressure, colour: "#000", label: "Hertz closed form" },
      ],
      markers: [{ x: cf.a, label: "a (Hertz)" }, { x: c.contact_length, label: "a (FE)" }],
      xlabel: "x along the block, mm", ylabel: "pressure, MPa", xrange: [0, 2.5 * cf.a],
    }, "Contact pressure along the roller (master nodes) beside Hertz's p(x) = p0 √(1 − x²/a²).");
    ui.table([
      ["half-width a (FE), mm", "a", c.contact_length], ["a (Hertz), mm", "a_hertz", cf.a],
      ["largest pressure (FE), MPa", "p_max", c.max_pressure], ["p0 (Hertz), MPa", "p0_hertz", cf.p0],
      ["normal force Σλ (half model), N/mm", "normal_force", c.normal_force],
      ["status", "status", s.status], ["pairs", "pairs", s.pairs],
    ]);
  },
};

// The scene's press and shear displacements of the roller's top at factor 1, mm.
const CM_PRESS_MM = 0.0142, CM_SHEAR_MM = 0.01;

const cattaneoMindlin = {
  title: "Cattaneo–Mindlin: partial slip",
  short: "Cattaneo–Mindlin",
  keys: ["ratio", "c_over_a", "c_over_a_closed"],
  controls: [
    { key: "press", id: "cm-press", label: "press: the roller's top pushed down by", kind: "range", min: 0.5,
      max: 1.5, step: 0.05, value: 1,
      show: (v) => `${+(v * CM_PRESS_MM).toPrecision(4)} mm (${Number(v).toFixed(2)} × the scene's)` },
    { key: "shear", id: "cm-shear", label: "shear: then the roller's top moved sideways by", kind: "range",
      min: 0, max: 0.9, step: 0.015, value: 0.3,
      show: (v) => `${+(v * CM_SHEAR_MM).toPrecision(4)} mm (factor ${Number(v).toFixed(3)})` },
    { key: "level", id: "cm-level", label: "mesh", kind: "select", value: "L0", options: [["L0", "L0"]] },
    // 0.75: past full sliding (0.615) at the ends of the stroke, so the loop is wide (21 % of its
    // box; 1.4 % at 0.45, partial slip only).
    { key: "amp", id: "cm-amp", label: "cycle amplitude A (shear factor)", kind: "range", min: 0.05, max: 0.9,
      step: 0.05, value: 0.75, show: (v) => `${+(v * CM_SHEAR_MM).toPrecision(3)} mm (factor ${Number(v).toFixed(2)})` },
  ],
  solve: (v) => JSON.parse(solve_cattaneo_mindlin_json(JSON.stringify({
    press: round4(v.press), shear: round4(v.shear), level: v.level,
  }))),
  describe: (v) => `press ${round4(v.press)}, then shear ${round4(v.shear)} (two load steps) on mesh ${v.level}`,
  draw(view, ui) {
    const s = view.summary, c = s.contacts.roller, cf = view.closed_form, m = view.measured;
    const z = 6 * cf.a;
    ui.mesh(view, [-z, -0.45 * z, z, 0.45 * z]);
    const p = c.profile;
    const keep = p.x.map((x) => Math.abs(x) <= 1.5 * cf.a);
    const xs = p.x.filter((_, i) => keep[i]).map((x) => x / cf.a);
    const mp0 = cf.friction * cf.p0;
    // c/a from the computed zones: the stick length over the contact length (both FE), so it
    // is a fraction of the computed contact and never above 1.
    const cOverA = m.a > 0 ? m.c / m.a : null;
    const sticking = view.pairs.state.some((st) => st === "stick");
    const touching = view.pairs.state.some((st) => st !== "free");
    ui.chart({
      series: [
        { x: xs, y: p.shear.filter((_, i) => keep[i]).map((q) => (m.shear_sign * q) / mp0), colour: "#1f77b4",
          label: "computed q/(μp0)", points: true },
        { x: cf.x.map((x) => x / cf.a), y: cf.shear.map((q) => q / mp0), colour: "#000", label: "Cattaneo–Mindlin" },
        { x: xs, y: p.pressure.filter((_, i) => keep[i]).map((val) => val / cf.p0), colour: "#d62728",
          label: "computed p/p0", points: true },
        { x: cf.x.map((x) => x / cf.a), y: cf.pressure.map((val) => val / cf.p0), colour: "#888", label: "Hertz p/p0" },
      ],
      markers: [{ x: sticking ? -m.c / m.a : null, label: "−c (FE)" }, { x: sticking ? m.c / m.a : null, label: "c (FE)" },
        { x: cf.c > 0 ? cf.c / cf.a : null, label: "c (closed form)" }],
      xlabel: "x / a (Hertz a at the measured P)", ylabel: "traction / (p0 or μp0)", xrange: [-1.5, 1.5],
    }, "Along the contact: shear q/(μp0) and pressure p/p0 at the roller's nodes beside " +
      "q(x) = μp0[√(1 − x²/a²) − (c/a)√(1 − x²/c²)] and Hertz's p, at the measured P and Q. " +
      "In the slip zones q = μp, so q/(μp0) lies on p/p0.");
    ui.output("cm-ratio-out", m.ratio, m.ratio.toFixed(3));
    ui.banner(touching && !sticking
      ? `Full sliding: no pair sticks, Q = μP (Q/(μP) = ${m.ratio.toFixed(3)}). The roller slides; ` +
        "moving its top further changes nothing but the slip."
      : null);
    ui.table([
      ["Q/(μP)", "ratio", m.ratio],
      ["c/a (FE: stick length / contact length)", "c_over_a", sticking ? cOverA : 0],
      ["c/a (closed form √(1 − Q/μP))", "c_over_a_closed", cf.c / cf.a],
      ["half-width a (FE), mm", "a", m.a], ["a (Hertz at P), mm", "a_hertz", cf.a],
      ["P (normal reaction), N/mm", "P", m.p], ["Q (tangential reaction), N/mm", "Q", m.q],
      ["p0 (Hertz), MPa", "p0", cf.p0], ["status", "status", s.status], ["pairs", "pairs", s.pairs],
    ]);
  },
};

export const PAPER_SCENES = { flagship, hertz, cattaneo_mindlin: cattaneoMindlin };
