// Issue 43 item 5 on the teaching page: the ball on a plate, a body of revolution beside the
// plane Hertz tab, in headless Chromium at 1366×768, 1024×768 and 390×844:
//   * the tab's contact radius a and peak pressure p0 against Hertz's sphere, computed HERE from
//     the scene's constants (not read from the page): E* = [(1 − ν1²)/E1 + (1 − ν2²)/E2]⁻¹,
//     a = (3PR/(4E*))^(1/3), p0 = 3P/(2πa²), P the total force;
//   * the same set-up solved by the native CLI (`contact2d run scenes/generic/ball_on_plate.toml
//     --json --set …`, the page's own override strings) gives the page's numbers.
// Usage: node web/tests/browser_ball.mjs (after web/build.sh and a release build of the CLI).
import { execFileSync } from "node:child_process";
import { join } from "node:path";
import { check, failures, launch, newPage, out, serve, web } from "./harness.mjs";

const VIEWPORTS = [{ width: 1366, height: 768 }, { width: 1024, height: 768 }, { width: 390, height: 844 }];
const root = join(web, "..");
const cli = join(root, process.env.CARGO_TARGET_DIR || "target", "release", "contact2d");
// The scene's constants (scenes/generic/ball_on_plate.toml).
const R = 10, E1 = 210000, E2 = 70000, NU = 0.3;
const eStar = 1 / ((1 - NU * NU) / E1 + (1 - NU * NU) / E2);
const hertz = (P) => { const a = Math.cbrt((3 * P * R) / (4 * eStar)); return { a, p0: (3 * P) / (2 * Math.PI * a * a) }; };
// Tolerances. a: the computed contact ends between two pairs, so it is placed to one node
// spacing at the contact edge: h/2 = 0.054 mm for the mesh's Q9 elements of h = a(5 kN)/8
// (meshes/generic/ball_on_plate.geo). p0: 2 %, as the plane Hertz roller with the same 8
// quadratic elements across a holds p0 to 1.6 % (docs/verification.md, L1).
const A_TOL = 0.108 / 2, P0_TOL = 0.02;
// Page = native: the ball is held only by the contact; its rigid motion is found by a Newton
// iteration whose stop may differ by an iteration between platforms (web/tests/
// wasm_matches_native.mjs: floating cases agree to 1e-8).
const SAME = 1e-8;

const { base, server } = await serve();
const browser = await launch();
const errors = [];
const close = (x, y, tol) => Math.abs(x - y) <= tol * Math.max(Math.abs(x), Math.abs(y), 1e-300);

try {
  for (const viewport of VIEWPORTS) {
    const tag = `${viewport.width}×${viewport.height}`;
    const page = await newPage(browser, errors, viewport);
    const forces = viewport.width === 1366 ? [5000, 2000, 10000] : [5000];
    for (const [i, P] of forces.entries()) {
      const projector = viewport.width > 900 ? "&projector=1" : "";
      await page.goto(`${base}/index.html?scene=ball_on_plate&force=${P}&mu=0${projector}`, { waitUntil: "load" });
      await page.waitForFunction(() => window.contact2dPage && window.contact2dPage.view
        && window.contact2dPage.run === "idle" && window.contact2dPage.view.scene === "ball_on_plate", { timeout: 60000 });
      const r = await page.evaluate(() => {
        const cell = (k) => Number(document.querySelector(`td[data-key="${k}"]`).dataset.value);
        const tabs = [...document.querySelectorAll("#scenes button")].map((b) => b.dataset.scene);
        const v = window.contact2dPage.view;
        return { a: cell("a"), p0: cell("p_max"), P: cell("normal_force"), tabs, status: v.summary.status,
          kinematics: v.summary.kinematics, contact: v.summary.contacts.ball, ms: window.contact2dPage.timings.at(-1).solve_ms };
      });
      const cf = hertz(P);
      if (i === 0) {
        check(r.tabs.indexOf("ball_on_plate") === r.tabs.indexOf("hertz") + 1, `${tag}: the ball tab is beside the Hertz tab`);
      }
      check(r.status === "converged" && r.kinematics === "axisymmetric" && Math.abs(r.P / P - 1) < 1e-9,
        `${tag} P = ${P} N: converged, axisymmetric, Σλ = ${r.P} = P (statics of the ball, 1e-9)`);
      check(Math.abs(r.a - cf.a) <= A_TOL, `${tag} P = ${P} N: a = ${r.a.toFixed(4)} mm, Hertz ${cf.a.toFixed(4)} ` +
        `(${(100 * (r.a / cf.a - 1)).toFixed(2)} %; within ${A_TOL} mm)`);
      check(Math.abs(r.p0 / cf.p0 - 1) <= P0_TOL, `${tag} P = ${P} N: p0 = ${r.p0.toFixed(1)} MPa, Hertz ${cf.p0.toFixed(1)} ` +
        `(${(100 * (r.p0 / cf.p0 - 1)).toFixed(2)} %; within ${100 * P0_TOL} %); solve ${r.ms.toFixed(0)} ms`);
      if (viewport.width !== 1366 && i === 0) continue;
      // The native CLI on the repository's files with the page's override strings.
      const json = JSON.parse(execFileSync(cli, ["run", join(root, "scenes/generic/ball_on_plate.toml"), "--json",
        "--set", `load.ball_top.force=[0, ${-P}]`, "--set", "contact.ball.friction=0"], { encoding: "utf8" }));
      const n = json.contacts.ball;
      const pMax = Math.max(...n.profile.pressure.map(Math.abs));
      const profileSame = n.profile.pressure.length === r.contact.profile.pressure.length
        && n.profile.pressure.every((p, k) => Math.abs(p - r.contact.profile.pressure[k]) <= SAME * pMax);
      check(json.status === r.status && close(n.contact_length, r.contact.contact_length, SAME)
        && close(n.max_pressure, r.contact.max_pressure, SAME) && close(n.normal_force, r.contact.normal_force, SAME) && profileSame,
        `${tag} P = ${P} N: the native CLI gives the page's numbers (contact length ${n.contact_length}, p0 ${n.max_pressure}, ` +
        `${n.profile.pressure.length} profile pressures; to ${SAME})`);
    }
    await page.screenshot({ path: join(out, `ball_on_plate_${viewport.width}.png`) });
    await page.close();
  }
  check(errors.length === 0, `no console or page error${errors.length ? ": " + errors.join("; ").slice(0, 300) : ""}`);
} finally {
  await browser.close();
  server.kill();
}
if (failures.length) {
  console.error(`${failures.length} ball-on-plate checks failed`);
  process.exit(1);
}
console.log("ball on a plate: ok");
