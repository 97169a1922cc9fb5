// The bundled generic scenes (scenes/generic/*.toml) and a user's own scene, all through one
// call: solve_generic_json({scene, overrides}) or solve_user_scene_json(files, overrides). The
// sliders only write `--set` overrides, exactly as `contact2d run --set` takes them; the page has
// no solve path of its own for any of these scenes. Closed forms shown beside the numbers come
// from each scene file's own comment (Lamé, the incline's Coulomb threshold, μP).
import { solve_generic_json, solve_user_scene_json } from "./pkg/contact2d_web.js";

const num = (v) => String(+Number(v).toFixed(6));

/** The request for a bundled generic scene. */
export const genericParams = (scene, overrides) => ({ scene, overrides });

// One interface's profile along its master curve: pressure and shear against arc length.
function drawInterface(view, ui, name, caption) {
  const c = view.summary.contacts[name];
  const p = c.profile;
  const stickX = [], slipX = [];
  p.state.forEach((st, i) => { (st === "stick" ? stickX : st.startsWith("slip") ? slipX : []).push(p.s[i]); });
  ui.chart({
    series: [
      { x: p.s, y: p.pressure, colour: "#d62728", label: "pressure p" },
      { x: p.s, y: p.shear, colour: "#1f77b4", label: "shear q" },
    ],
    markers: [],
    xlabel: `arc length s along ${name}'s master curve, mm`, ylabel: "traction, MPa",
  }, caption);
  return c;
}

/** The solver's status in words (the report's `status`, and its `not_held` object). */
export function statusWords(summary) {
  const n = summary.not_held;
  switch (summary.status) {
    case "converged": return "converged: every pair satisfies the contact conditions and Coulomb's law";
    case "not_held": return n
      ? `not held: at load step ${n.step} friction on “${n.contact}” cannot hold the ${n.body}; it slides away ` +
        `(the load demands ${n.ratio.toFixed(2)} × the friction force μΣλ available), so that step has no solution`
      : "not held: friction cannot hold a body held only by contact; it slides away";
    case "max_iterations": return "not converged: the iteration limit was reached";
    case "infeasible": return "infeasible: the contact conditions cannot all be met";
    case "numerical": return "numerical failure of the solver";
    case "inadmissible": return "inadmissible: a computed state breaks the contact conditions";
    case "penalised": return "penalised: held only by the stabilising springs";
    default: return String(summary.status);
  }
}

/** The banner of a run that did not converge (null when it did). */
const unsolved = (view) => (view.summary.status === "converged" ? null : `Solver: ${statusWords(view.summary)}.`);

function rows(view, name, extra = []) {
  const s = view.summary, c = s.contacts[name];
  // A run that did not converge has no equilibrium to report: its forces and lengths are not
  // shown (a dash), only the status in words.
  const ok = s.status === "converged";
  const v = (x) => (ok ? x : null);
  return [
    ...extra,
    ["contact length, mm", "contact_length", v(c.contact_length)],
    // Without friction on the interface nothing sticks: no stick length.
    ["stick length, mm", "stick_length", view.pairs.state.includes("contact") ? null : v(c.stick_length)],
    ["normal force Σλ, N/mm", "normal_force", v(c.normal_force)],
    ["tangential force Στ, N/mm", "tangential_force", v(c.tangential_force)],
    ["largest pressure, MPa", "max_pressure", v(c.max_pressure)],
    ["status", "status", statusWords(s)], ["load steps", "steps", s.steps.length], ["pairs", "pairs", s.pairs],
  ];
}

const frictionSlider = (value) => ({ key: "mu", id: "g-mu", label: "friction μ", kind: "range", min: 0, max: 0.6,
  step: 0.05, value, show: (v) => Number(v).toFixed(2) });

const pinLug = {
  title: "Pin in a lug",
  short: "Pin in a lug",
  keys: ["normal_force", "tangential_force", "max_pressure"],
  controls: [
    frictionSlider(0.2),
    { key: "force", id: "g-force", label: "pin force on the half model, N/mm", kind: "range", min: 250, max: 2000,
      step: 250, value: 1000, show: (v) => `${Number(v)} (whole pin ${2 * Number(v)})` },
  ],
  overrides: (v) => [`contact.bore.friction=${num(v.mu)}`, `load.pin_back.force=[${num(v.force)}, 0]`],
  describe: (v) => `μ = ${num(v.mu)}, F = ${num(v.force)} N/mm on the half model, 4 load steps, mesh pin_lug_L1`,
  draw(view, ui, v) {
    ui.mesh(view, null);
    drawInterface(view, ui, "bore", "Along the pin's contact arc: pressure and shear (the pin crosses the 0.1 mm " +
      "clearance, then bears on the side of the lug's end).");
    ui.banner(unsolved(view));
    ui.table(rows(view, "bore", [["pin force (half model), N/mm", "force", Number(v.force)]]));
  },
};

// Lamé: p = E δ (b² − a²) / (2 a b²) for a disk a = 500 mm in a ring b = 1000 mm of one material.
const lame = (delta) => 2e5 * delta * (1000 ** 2 - 500 ** 2) / (2 * 500 * 1000 ** 2);

const interferenceFit = {
  title: "Interference fit",
  short: "Interference fit",
  keys: ["p_lame", "max_pressure", "status"],
  controls: [
    { key: "delta", id: "g-delta", label: "radial interference δ, mm", kind: "range", min: 0.05, max: 1.2, step: 0.05,
      value: 0.65, show: (v) => Number(v).toFixed(2) },
    { ...frictionSlider(0), max: 0.3 },
  ],
  overrides: (v) => [`contact.fit.gap=${num(-v.delta)}`, `contact.fit.friction=${num(v.mu)}`],
  describe: (v) => `δ = ${num(v.delta)} mm, μ = ${num(v.mu)}, one load step`,
  draw(view, ui, v) {
    ui.mesh(view, null);
    drawInterface(view, ui, "fit", "Along the bore: the contact pressure (uniform in Lamé's solution) and shear.");
    ui.banner(unsolved(view));
    ui.table(rows(view, "fit", [["Lamé pressure E δ (b² − a²)/(2 a b²), MPa", "p_lame", lame(Number(v.delta))]]));
  },
};

// The incline's two limits (rigid-body statics with Coulomb, tan α = 0.1, a horizontal push F):
// pushed up the slope when F cos α − G sin α > μ (G cos α + F sin α), i.e.
// F/G > (tan α + μ)/(1 − μ tan α); sliding down when G sin α − F cos α > μ (G cos α + F sin α),
// i.e. F/G < (tan α − μ)/(1 + μ tan α) (only when tan α > μ: then the weight alone slides it).
const TAN_ALPHA = 0.1;
const threshold = (mu) => (TAN_ALPHA + mu) / (1 - mu * TAN_ALPHA);
export const lowerThreshold = (mu) => (TAN_ALPHA - mu) / (1 + mu * TAN_ALPHA);

const inclinePush = {
  title: "Block on an incline",
  short: "Incline",
  keys: ["threshold", "tangential_force", "status"],
  controls: [
    frictionSlider(0.3),
    { key: "push", id: "g-push", label: "push F/G (horizontal force over weight)", kind: "range", min: 0, max: 0.7,
      step: 0.01, value: 0.3, show: (v) => Number(v).toFixed(2) },
  ],
  overrides: (v) => [`contact.incline.friction=${num(v.mu)}`,
    `loading.schedule=[{weight = 1}, {weight = 1, push = ${num(v.push)}}]`],
  describe: (v) => `μ = ${num(v.mu)}, F/G = ${num(v.push)}: the weight, then the push (two load steps)`,
  draw(view, ui, v) {
    ui.mesh(view, null);
    drawInterface(view, ui, "incline", "Along the block's base: pressure and shear (the stick zone shrinks as F grows).");
    const mu = Number(v.mu), push = Number(v.push), limit = threshold(mu), lower = lowerThreshold(mu);
    const statics = `Statics (tan α = 0.1, μ = ${num(mu)}): the block holds for ` +
      `${lower > 0 ? `${lower.toFixed(4)} = (tan α − μ)/(1 + μ tan α) ≤ ` : ""}F/G ≤ (tan α + μ)/(1 − μ tan α) = ` +
      `${limit.toFixed(4)}.`;
    let why = null;
    if (TAN_ALPHA > mu && push < lower) {
      why = `F/G = ${num(push)} is below (tan α − μ)/(1 + μ tan α) = ${lower.toFixed(4)}` +
        ` (tan α = 0.1 > μ = ${num(mu)}: unpushed, the weight alone slides the block down): ` +
        "no equilibrium, the block slides down the slope.";
    } else if (push >= limit) {
      why = `F/G = ${num(push)} is at or past (tan α + μ)/(1 − μ tan α) = ${limit.toFixed(4)}: ` +
        "no equilibrium, the push slides the block up the slope.";
    }
    const status = view.summary.status;
    ui.banner(why || status !== "converged" ? `${why || statics} Solver: ${statusWords(view.summary)}.` : null);
    ui.table(rows(view, "incline", [["holds from F/G (statics)", "threshold_low", lower > 0 ? lower : 0],
      ["slides up from F/G (statics)", "threshold", limit]]));
  },
};

const twoBlocks = {
  title: "Two blocks: press, then slide",
  short: "Two blocks",
  keys: ["mu_p", "tangential_force", "status"],
  controls: [
    frictionSlider(0.3),
    { key: "slide", id: "g-slide", label: "slide of the top, × 0.01 mm", kind: "range", min: 0, max: 1.5, step: 0.05,
      value: 1, show: (v) => Number(v).toFixed(2) },
  ],
  overrides: (v) => [`contact.joint.friction=${num(v.mu)}`,
    `loading.schedule=[{press = 1}, {press = 1, slide = ${num(v.slide)}}]`],
  describe: (v) => `press 1000 N/mm, then slide ${num(v.slide)} × 0.01 mm with μ = ${num(v.mu)} (two load steps)`,
  draw(view, ui, v) {
    ui.mesh(view, null);
    const c = drawInterface(view, ui, "joint", "Along the joint: pressure and shear.");
    const slipping = view.pairs.state.every((st) => st === "free" || st.startsWith("slip"));
    ui.banner(unsolved(view) || (slipping && Number(v.mu) > 0 && Number(v.slide) > 0
      ? `Full sliding: every pair slips and Στ = μ Σλ (${Math.abs(c.tangential_force).toPrecision(5)} = ` +
        `${num(v.mu)} × ${c.normal_force.toPrecision(5)}).` : null));
    ui.table(rows(view, "joint", [["μ P (full sliding), N/mm", "mu_p", Number(v.mu) * 1000]]));
  },
};

// Hertz's sphere on a flat (Johnson 1985, eqs. 4.22-4.23): the scene's steel ball R = 10 mm on an
// aluminium plate, ν = 0.3 both; P the TOTAL force (a body of revolution: over the circumference).
//   E* = [(1 − ν1²)/E1 + (1 − ν2²)/E2]⁻¹,  a = (3PR/(4E*))^(1/3),  p0 = 3P/(2πa²),  p(r) = p0 √(1 − r²/a²)
export const BALL = { R: 10, E1: 210000, E2: 70000, nu: 0.3 };
export function hertzSphere(P) {
  const eStar = 1 / ((1 - BALL.nu ** 2) / BALL.E1 + (1 - BALL.nu ** 2) / BALL.E2);
  const a = Math.cbrt((3 * P * BALL.R) / (4 * eStar));
  return { eStar, a, p0: (3 * P) / (2 * Math.PI * a * a) };
}
// The contact radius of the computed contact: its length is an arc of the ball's surface (the
// master curve) from the axis, s = R asin(r/R), so r = R sin(s/R).
export const ballRadiusOf = (arc) => BALL.R * Math.sin(arc / BALL.R);

const ballOnPlate = {
  title: "Hertz: ball on a plate (axisymmetric)",
  short: "Sphere",
  keys: ["a", "a_hertz", "p_max", "p0_hertz"],
  controls: [
    { key: "force", id: "g-force", label: "total force P on the ball, N", kind: "range", min: 1000, max: 10000,
      step: 500, value: 5000, show: (v) => Number(v).toLocaleString("en") },
    { ...frictionSlider(0), max: 0.5 },
  ],
  overrides: (v) => [`load.ball_top.force=[0, ${num(-v.force)}]`, `contact.ball.friction=${num(v.mu)}`],
  describe: (v) => `P = ${num(v.force)} N (total), μ = ${num(v.mu)}, one load step, body of revolution`,
  draw(view, ui, v) {
    const cf = hertzSphere(Number(v.force)), c = view.summary.contacts.ball, z = 4 * cf.a;
    ui.mesh(view, [0, -0.5 * z, z, 0.5 * z]);
    const p = c.profile, keep = p.x.map((x) => x <= 2 * cf.a);
    const rs = Array.from({ length: 101 }, (_, i) => (cf.a * i) / 100);
    ui.chart({
      series: [
        { x: p.x.filter((_, i) => keep[i]), y: p.pressure.filter((_, i) => keep[i]), colour: "#d62728",
          label: "computed p(r)", points: true },
        { x: rs, y: rs.map((r) => cf.p0 * Math.sqrt(Math.max(0, 1 - (r * r) / (cf.a * cf.a)))), colour: "#000",
          label: "Hertz p0 √(1 − r²/a²)" },
      ],
      markers: [{ x: cf.a, label: "a (Hertz)" }, { x: ballRadiusOf(c.contact_length), label: "a (FE)" }],
      xlabel: "r: distance from the axis, mm", ylabel: "pressure, MPa", xrange: [0, 2 * cf.a],
    }, "Contact pressure along the ball (master nodes) beside Hertz's sphere p(r) = p0 √(1 − r²/a²), " +
      "a = (3PR/(4E*))^(1/3), p0 = 3P/(2πa²), P the total force.");
    ui.banner(unsolved(view));
    const ok = view.summary.status === "converged";
    ui.table([
      ["contact radius a (FE), mm", "a", ok ? ballRadiusOf(c.contact_length) : null], ["a (Hertz), mm", "a_hertz", cf.a],
      ["peak pressure p0 (FE), MPa", "p_max", ok ? c.max_pressure : null], ["p0 (Hertz), MPa", "p0_hertz", cf.p0],
      ["normal force Σλ (total), N", "normal_force", ok ? c.normal_force : null],
      ["E* (plane strain, combined), MPa", "e_star", cf.eStar],
      ["status", "status", statusWords(view.summary)], ["kinematics", "kinematics", view.summary.kinematics],
      ["pairs", "pairs", view.summary.pairs],
    ]);
  },
};

/** A user's scene: the files chosen or dropped on the page, solved with the CLI's limits. */
const userScene = {
  title: "Your scene (.toml + .msh)",
  short: "Your scene",
  controls: [],
  user: true,
  describe: () => "your scene as written in its file",
  draw(view, ui) {
    ui.mesh(view, null);
    const names = Object.keys(view.summary.contacts);
    if (names.length) drawInterface(view, ui, names[0], `Along interface ${names[0]}: pressure and shear.`);
    ui.banner(unsolved(view));
    ui.table(names.length ? rows(view, names[0]) : [["status", "status", statusWords(view.summary)]]);
  },
};

export const GENERIC_SCENES = {
  ball_on_plate: ballOnPlate, pin_lug: pinLug, interference_fit: interferenceFit, incline_push: inclinePush,
  two_blocks_press_slide: twoBlocks, user: userScene,
};

for (const [name, scene] of Object.entries(GENERIC_SCENES)) {
  // Element ids unique across scenes (the friction slider's spec is shared).
  scene.controls = scene.controls.map((c) => ({ ...c, id: `${name}-${c.key}` }));
  if (scene.user) continue;
  scene.solve = (v) => JSON.parse(solve_generic_json(JSON.stringify(genericParams(name, scene.overrides(v)))));
}

/** Solves the user's files ({scene: File, mesh: File} read as bytes). */
export async function readUserFiles(files) {
  const scene = files.find((f) => f.name.toLowerCase().endsWith(".toml"));
  const mesh = files.find((f) => f.name.toLowerCase().endsWith(".msh"));
  if (!scene || !mesh) throw new Error("choose (or drop) one scene .toml and its .msh together");
  return {
    sceneName: scene.name, sceneBytes: new Uint8Array(await scene.arrayBuffer()),
    meshName: mesh.name, meshBytes: new Uint8Array(await mesh.arrayBuffer()),
  };
}

export function solveUser(files) {
  return JSON.parse(solve_user_scene_json(files.sceneName, files.sceneBytes, files.meshName, files.meshBytes, "[]"));
}
