// The WebAssembly module returns the native library's numbers.
//
// Reference: web/out/reference.json, written in the same run by the native binary
// `web_reference` (crates/web/src/bin/web_reference.rs): every bundled case solved natively from
// the mesh files through `contact2d run`'s own path. Here the same parameters go through the
// module built by web/build.sh (meshes compiled in, parsed from bytes) and every value of the
// returned view is compared:
//   * strings (status, pair states, mesh file) exactly: a pair changing state would be a
//     different solution, not round-off; integers (iterations, pair counts, mesh indices) fall
//     under the numbers' rule, which for them means exactly;
//   * numbers to 1e-12 relative, each relative to the size of the quantity it belongs to:
//     - an array relative to its largest magnitude (a field's round-off is relative to the
//       field, not to a value that happens to cross zero inside it);
//     - a contour's tractions p and q relative to the largest of both: they are the two
//       components of one traction vector (without friction q is round-off of p, ~1e-17);
//     - an interface's normal_force Σλ and tangential_force Στ relative to the larger of both:
//       they are the two components of one interface force (pressed without shear, Στ is
//       round-off of Σλ, ~1e-5 of it on an asymmetric mesh);
//     - the bodies' strain energies relative to the work W of the same step: the library
//       certifies energies by the balance W = Σ Φ + Φ_f, relative to W; a floating body's
//       energy ½ uᵀK u is computed from a displacement dominated by its rigid motion, whose
//       cancellation is relative to the energy put in, not to the body's share of it;
//     - any other number relative to itself;
//     - reactions_total, the sum of every support's reaction, relative to the largest group
//       reaction it sums (balanced loads make it round-off of those, ~1e-12 of them);
//   * a case with a body held only by contact (summary.floating_bodies not empty) to 1e-8: its
//     rigid motion is found by a Newton iteration that stops when the pins' force is below 1e-10
//     of the force scale (crates/contact/src/floating.rs), and two platforms whose round-off
//     differs by an ulp may stop one iteration apart, their answers then agreeing to that
//     tolerance; its iteration counts (iterations, kkt.floating_iterations) are not compared.
//     A body with more free modes amplifies that stop: the incline's rubber block (E = 10 MPa,
//     held by friction alone, all three rigid modes free, loads of 4e-3 N) agrees to 4.1e-9 at
//     the block's corner (its largest pressure), the pin in a lug to 1.4e-10, Hertz to 1.7e-12
//     (measured 26 November 2026); floating cases are therefore held to 1e-8, not 1e-10;
//   * a generic interface's pressure and shear relative to the larger of both (one traction),
//     its gap and slip relative to the case's largest displacement (displacements), supports'
//     reactions relative to the largest interface force (an interference fit has no load: its
//     reactions are round-off of the contact force), dissipation relative to the largest work;
//   * KKT residuals (kkt.*) are not compared by value: they are round-off, or the termination
//     residual of the floating bodies' proximal iterations, ~1e-7 N against loads of 1e4 N;
//     their meaning, the certified status, is compared as a string, and the iteration counts
//     exactly;
//   * wall-clock times (time_s, solve_time_s, times.*) are skipped.
// Why 1e-12 and not bit equality: native faer picks AVX2/FMA kernels at run time, wasm32 runs
// scalar code, and the two libm implementations (glibc, Rust's libm) may differ in the last bit
// of sin/cos/atan2, so sums are rounded in a different order; a condition number of the
// stiffness of ~1e4 turns 1e-16 differences into ~1e-12 at worst.
//
// Usage: node web/tests/wasm_matches_native.mjs [reference.json]
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { dirname, join } from "node:path";

const here = dirname(fileURLToPath(import.meta.url));
const web = join(here, "..");
const { initSync, solve_flagship_json, solve_hertz_json, solve_cattaneo_mindlin_json, solve_generic_json } = await import(join(web, "pkg/contact2d_web.js"));
initSync({ module: readFileSync(join(web, "pkg/contact2d_web_bg.wasm")) });

const RELATIVE = 1e-12;
// The floating bodies' Newton tolerance (see above).
const FLOATING_RELATIVE = 1e-8;
let tolerance = RELATIVE;
// Per case: the largest displacement, interface force and work (the scales of round-off above).
let caseScales = { displacement: 0, force: 0, work: 0, length: 1 };
// A moment about a centre (reaction_moments, reaction_moment_total, an interface's moment,
// rigid_moment, couple) is a sum over a group's or an interface's nodes of arm × nodal force:
// each term carries the forces' 1e-12 of the force scale times an arm up to the model's size, and
// the sum cancels (a balanced group's moment is small beside its terms), so its round-off is
// bounded by the number of terms × 1e-12 × force × length; these meshes' groups and interfaces
// have at most ~10² nodes.
const MOMENT_TERMS = 100;
const MOMENT_KEYS = new Set(["reaction_moments", "reaction_moment_total", "moment", "rigid_moment", "couple"]);
let floating = false;
const referencePath = process.argv[2] || join(web, "out/reference.json");
const reference = JSON.parse(readFileSync(referencePath, "utf8"));

const failures = [];
let compared = 0;
let worst = { rel: 0, path: "" };
const worstByScene = {};

function isTime(key) {
  return key === "time_s" || key === "solve_time_s" || key === "times";
}

function compareNumber(path, a, b, scale) {
  compared += 1;
  const diff = Math.abs(a - b);
  const ref = Math.max(scale, Math.abs(a), Math.abs(b));
  const rel = ref === 0 ? 0 : diff / ref;
  if (rel > worst.rel) worst = { rel, path };
  const scene = path.slice(0, path.indexOf("{"));
  worstByScene[scene] = Math.max(worstByScene[scene] || 0, rel);
  if (!(rel <= tolerance)) failures.push(`${path}: native ${a}, wasm ${b} (relative ${rel.toExponential(2)})`);
}

function compare(path, a, b, scale = 0) {
  if (a !== null && typeof a === "object" && !Array.isArray(a) && scale > 0) {
    // An object under a common scale (the energies per body): each entry relative to it.
    if (b === null || typeof b !== "object") {
      failures.push(`${path}: object vs ${JSON.stringify(b)}`);
      return;
    }
    for (const k of new Set([...Object.keys(a), ...Object.keys(b)])) compare(`${path}.${k}`, a[k], b[k], scale);
    return;
  }
  if (Array.isArray(a)) {
    if (!Array.isArray(b) || a.length !== b.length) {
      failures.push(`${path}: length ${a.length} vs ${b?.length}`);
      return;
    }
    const numbers = a.filter((v) => typeof v === "number");
    const arrayScale = numbers.reduce((m, v) => Math.max(m, Math.abs(v)), 0);
    a.forEach((v, i) => compare(`${path}[${i}]`, v, b[i], Math.max(scale, arrayScale)));
    return;
  }
  if (a !== null && typeof a === "object") {
    if (b === null || typeof b !== "object") {
      failures.push(`${path}: object vs ${JSON.stringify(b)}`);
      return;
    }
    const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
    const magnitude = (...arrays) => arrays.flat().reduce((m, v) => (typeof v === "number" ? Math.max(m, Math.abs(v)) : m), 0);
    for (const k of keys) {
      if (isTime(k)) continue;
      if (path.endsWith(".kkt") && (k !== "floating_iterations" || floating)) continue;
      if (floating && k === "iterations") continue;
      let scale = 0;
      if ((k === "p" || k === "q") && Array.isArray(a.p) && Array.isArray(a.q)) scale = magnitude(a.p, a.q);
      if ((k === "normal_force" || k === "tangential_force") && typeof a.normal_force === "number"
        && typeof a.tangential_force === "number") scale = magnitude([a.normal_force, a.tangential_force]);
      const work = typeof a.work === "number" ? a.work : Array.isArray(a.steps) ? a.steps.at(-1)?.work : undefined;
      if (k === "energies" && typeof work === "number") scale = Math.abs(work);
      if (k === "reactions_total" && a.reactions && typeof a.reactions === "object") {
        scale = magnitude(...Object.values(a.reactions).map((r) => (Array.isArray(r) ? r : [])));
      }
      // A generic interface's profile: pressure and shear are the two components of one
      // traction (frictionless, the shear is round-off of the pressure); gap and slip are
      // displacements, round-off of the case's largest displacement where they vanish.
      if ((k === "pressure" || k === "shear") && Array.isArray(a.pressure) && Array.isArray(a.shear)) {
        scale = magnitude(a.pressure, a.shear);
      }
      if ((k === "gap" || k === "slip") && Array.isArray(a[k])) scale = caseScales.displacement;
      // Supports' reactions balance the contact forces (an interference fit has no load at all:
      // its symmetry reactions are round-off of the contact force), and dissipation is part of
      // the work W = Σ Φ + Φ_f, certified relative to W (as the energies above).
      if (k === "reactions" || k === "reactions_total") scale = Math.max(scale, caseScales.force);
      if (k === "dissipated" || k === "dissipation") scale = caseScales.work;
      if (MOMENT_KEYS.has(k)) scale = Math.max(scale, MOMENT_TERMS * caseScales.force * caseScales.length);
      // path_error is itself a relative difference of two runs' forces and dissipations, each
      // equal between wasm and native to 1e-12 of its scale, summed over the halved run's steps:
      // it is compared in absolute terms, to 1e-9 (a value of 1e-11 is round-off, not an
      // estimate; the note that reads it starts at 1e-2).
      if (k === "path_error") scale = 1e3;
      compare(`${path}.${k}`, a[k], b[k], scale);
    }
    return;
  }
  if (typeof a === "number" && typeof b === "number") {
    compareNumber(path, a, b, scale);
    return;
  }
  compared += 1;
  if (a !== b) failures.push(`${path}: native ${JSON.stringify(a)}, wasm ${JSON.stringify(b)}`);
}

const solvers = {
  flagship: solve_flagship_json, hertz: solve_hertz_json, cattaneo_mindlin: solve_cattaneo_mindlin_json,
  generic: solve_generic_json,
};
for (const [scene, cases] of Object.entries(reference)) {
  for (const { params, view } of cases) {
    const t0 = performance.now();
    floating = (view.summary?.floating_bodies?.length ?? 0) > 0;
    const largest = (xs) => xs.reduce((m, v) => (typeof v === "number" ? Math.max(m, Math.abs(v)) : m), 0);
    const steps = view.summary?.steps ?? [];
    caseScales = {
      displacement: largest(view.mesh?.displacement ?? []),
      force: largest(steps.flatMap((st) => Object.values(st.contacts ?? {}).map((c) => c.normal_force))),
      work: largest(steps.map((st) => st.work)),
      // The model's size: the largest coordinate of the groups' bounding boxes.
      length: largest(Object.values(view.summary?.groups ?? {}).flatMap((g) => (g.bbox ?? []).flat())) || 1,
    };
    tolerance = floating ? FLOATING_RELATIVE : RELATIVE;
    const wasm = JSON.parse(solvers[scene](JSON.stringify(params)));
    const ms = performance.now() - t0;
    compare(`${scene}${JSON.stringify(params)}`, view, wasm);
    console.log(`${scene} ${JSON.stringify(params)}: ${ms.toFixed(1)} ms in node`);
  }
}

console.log(`${compared} values compared; largest relative difference ${worst.rel.toExponential(2)} at ${worst.path}`);
for (const [scene, rel] of Object.entries(worstByScene)) console.log(`  ${scene}: largest relative difference ${rel.toExponential(2)}`);
if (failures.length > 0) {
  console.error(`${failures.length} values differ:\n` + failures.slice(0, 30).join("\n"));
  process.exit(1);
}
console.log("wasm matches native to 1e-12 relative (1e-8 with a floating body): ok");
