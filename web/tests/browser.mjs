// The page in a real browser: headless Chromium (Debian's `chromium`) driven by puppeteer-core.
//
// Serves web/ with `python3 -m http.server` (the documented way), loads the page, moves the μ
// slider from 0 to 0.3 with the keyboard (six steps of 0.05, each an input event and a solve),
// and checks that
//   * at μ = 0 no pair sticks, at μ = 0.3 a stick zone appears (pairs drawn as stick) and b < l;
//   * l, b and P shown on the page (the cells' exact values) equal the native library's to
//     1e-12 relative (web/out/reference.json, written in the same run by `web_reference`; see
//     wasm_matches_native.mjs for why 1e-12 and not bit equality);
//   * the Hertz scene solves and its half-width equals the native one likewise;
//   * the Cattaneo–Mindlin scene: the shear slider moved from 0 to 0.3 with the keyboard (twenty
//     steps, each a solve), a slip zone appears at both ends of the contact (pairs drawn as slip
//     at x < 0 and at x > 0) and c/a on the page equals the native value to 1e-12;
//   * each bundled generic scene (pin in a lug, interference fit, incline, two blocks) opened at
//     its defaults shows the native interface forces and contact length;
//   * no console error and no page error.
// It measures the update times (performance.now() around solve + drawing, as the page shows
// them) for each scene and mesh, and saves screenshots to web/out/.
//
// Usage: node web/tests/browser.mjs [reference.json]   (CHROMIUM=/path overrides the browser)
import { readFileSync, mkdirSync } from "node:fs";
import { join } from "node:path";
import { check, failures, launch, out, serve } from "./harness.mjs";

mkdirSync(out, { recursive: true });
const reference = JSON.parse(readFileSync(process.argv[2] || join(out, "reference.json"), "utf8"));
const RELATIVE = 1e-12;
const close = (a, b) => Math.abs(a - b) <= RELATIVE * Math.max(Math.abs(a), Math.abs(b));

function findCase(scene, params) {
  const found = reference[scene].find((c) => Object.entries(params).every(([k, v]) => c.params[k] === v)
    && Object.keys(c.params).length === Object.keys(params).length);
  if (!found) throw new Error(`no reference case ${JSON.stringify(params)}`);
  return found.view;
}

const { base, server } = await serve();
const browser = await launch();
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1500, height: 1150 });
  const errors = [];
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("pageerror", (e) => errors.push(String(e)));
  await page.goto(`${base}/index.html`, { waitUntil: "load" });
  await page.waitForFunction(() => window.contact2dPage && window.contact2dPage.updates >= 1, { timeout: 60000 });

  const cell = (key) => page.$eval(`td[data-key="${key}"]`, (td) => td.dataset.value);
  const stick = () => page.$eval("#mesh", (c) => Number(c.dataset.stick));
  const updates = () => page.evaluate(() => window.contact2dPage.updates);

  check((await page.$eval("#mu", (s) => s.value)) === "0" && (await stick()) === 0, "μ = 0: no pair sticks");

  // Move the μ slider with the keyboard: six steps of 0.05, each an input event and a solve.
  await page.focus("#mu");
  for (let i = 0; i < 6; i++) {
    const before = await updates();
    await page.keyboard.press("ArrowRight");
    await page.waitForFunction((n) => window.contact2dPage.updates > n, { timeout: 30000 }, before);
  }
  check((await page.$eval("#mu", (s) => s.value)) === "0.3", "the μ slider reads 0.3");
  const stuck = await stick();
  check(stuck > 0, `μ = 0.3: a stick zone appears (${stuck} pairs drawn as stick)`);
  const native = findCase("flagship", {
    friction: 0.3, stiffness_ratio: 1, eps: 0, refinement: 16, load: 1, variant: "hole_master",
  }).summary.paper;
  const live = { l: Number(await cell("l")), b: Number(await cell("b")), P: Number(await cell("P")) };
  for (const k of ["l", "b", "P"]) {
    check(close(live[k], native[k]), `page ${k} = ${live[k]} equals native ${native[k]} to 1e-12`);
  }
  check(live.b < live.l, `b = ${live.b.toFixed(4)} < l = ${live.l.toFixed(4)}`);
  check((await page.$eval("#published-label", (p) => p.textContent)).includes("no gap, μ = 0.3"),
    "the published no-gap μ = 0.3 values are shown beside the live ones");
  await page.screenshot({ path: join(out, "flagship_mu03.png"), fullPage: true });

  // Update times: a few slider moves per mesh, as the page measures them.
  const timings = {};
  const measure = async (label, moves) => {
    const start = await page.evaluate(() => window.contact2dPage.timings.length);
    for (const move of moves) {
      const before = await updates();
      await move();
      await page.waitForFunction((n) => window.contact2dPage.updates > n, { timeout: 60000 }, before);
    }
    const t = await page.evaluate((s) => window.contact2dPage.timings.slice(s), start);
    const median = (xs) => xs.slice().sort((a, b) => a - b)[Math.floor(xs.length / 2)];
    timings[label] = { solve_ms: median(t.map((x) => x.solve_ms)), total_ms: median(t.map((x) => x.total_ms)), n: t.length };
  };
  const key = (id, k) => async () => { await page.focus(id); await page.keyboard.press(k); };
  const muMoves = [key("#mu", "ArrowLeft"), key("#mu", "ArrowRight"), key("#mu", "ArrowLeft"), key("#mu", "ArrowRight"), key("#mu", "ArrowLeft")];
  await measure("flagship N=16, eps = 0", muMoves);
  await page.select("#refinement", "32");
  await page.waitForFunction(() => document.querySelector("#timing").textContent.includes("N32"), { timeout: 60000 });
  await measure("flagship N=32, eps = 0", muMoves);
  await page.select("#refinement", "16");
  await page.click('[data-preset="gap_v1_mu03"]');
  await page.waitForFunction(() => document.querySelector("#timing").textContent.includes("eps0.05_N16"), { timeout: 60000 });
  await measure("flagship N=16, eps = 0.05 (3 steps)", muMoves);
  await page.select("#refinement", "32");
  await page.waitForFunction(() => document.querySelector("#timing").textContent.includes("eps0.05_N32"), { timeout: 60000 });
  await measure("flagship N=32, eps = 0.05 (3 steps)", muMoves);

  // Hertz: the benchmark's force on L1 equals the native half-width.
  await page.click('[data-scene="hertz"]');
  await page.waitForFunction(() => window.contact2dPage.view && window.contact2dPage.view.closed_form, { timeout: 60000 });
  const hertz = findCase("hertz", { force: 35000, level: "L1" }).summary.contacts.hertz;
  const a = Number(await cell("a"));
  check(close(a, hertz.contact_length), `Hertz L1: page a = ${a} equals native ${hertz.contact_length} to 1e-12`);
  await page.screenshot({ path: join(out, "hertz_L1.png"), fullPage: true });
  const forceMoves = [key("#force", "ArrowLeft"), key("#force", "ArrowRight"), key("#force", "ArrowLeft"), key("#force", "ArrowRight"), key("#force", "ArrowLeft")];
  await measure("hertz L1", forceMoves);

  // Cattaneo–Mindlin: shear from 0 to 0.3 (twenty steps of 0.015); slip at both ends; c/a = native.
  await page.click('[data-scene="cattaneo_mindlin"]');
  await page.waitForFunction(() => window.contact2dPage.view && window.contact2dPage.view.measured, { timeout: 60000 });
  await page.focus("#cm-shear");
  {
    const before = await updates();
    await page.keyboard.press("Home");
    await page.waitForFunction((n) => window.contact2dPage.updates > n, { timeout: 30000 }, before);
  }
  const slipEnds = () => page.evaluate(() => {
    const v = window.contact2dPage.view;
    const ends = { left: 0, right: 0, stick: 0 };
    v.pairs.master.forEach((node, k) => {
      const s = v.pairs.state[k];
      if (s === "stick") ends.stick += 1;
      if (s.startsWith("slip")) ends[v.mesh.points[2 * node] < 0 ? "left" : "right"] += 1;
    });
    return ends;
  });
  const atZero = await slipEnds();
  check((await page.$eval("#cm-shear", (s) => s.value)) === "0", `shear 0: ${atZero.stick} stick, ` +
    `${atZero.left} + ${atZero.right} slip pairs (left + right)`);
  for (let i = 0; i < 20; i++) {
    const before = await updates();
    await page.keyboard.press("ArrowRight");
    await page.waitForFunction((n) => window.contact2dPage.updates > n, { timeout: 30000 }, before);
  }
  check((await page.$eval("#cm-shear", (s) => s.value)) === "0.3", "the shear slider reads 0.3");
  const sheared = await slipEnds();
  check(sheared.left > 0 && sheared.right > 0 && sheared.stick > 0,
    `shear 0.3: slip at both ends (${sheared.left} left, ${sheared.right} right) around ${sheared.stick} stick pairs`);
  const cm = findCase("cattaneo_mindlin", { press: 1, shear: 0.3, level: "L0" });
  // c/a on the page: the computed stick length over the computed contact length (≤ 1).
  const cNative = cm.measured.c / cm.measured.a;
  const cPage = Number(await cell("c_over_a"));
  check(close(cPage, cNative), `Cattaneo–Mindlin L0: page c/a = ${cPage} equals native ${cNative} to 1e-12`);
  const ratio = Number(await page.$eval("#cm-ratio-out", (o) => o.dataset.value));
  check(close(ratio, cm.measured.ratio), `the page shows Q/(μP) = ${ratio.toFixed(4)} (native ${cm.measured.ratio.toFixed(4)})`);
  console.log(`  c/a: FE ${cPage.toFixed(4)}, closed form ${Number(await cell("c_over_a_closed")).toFixed(4)}`);
  await page.screenshot({ path: join(out, "cattaneo_mindlin_L0.png"), fullPage: true });
  const shearMoves = [key("#cm-shear", "ArrowLeft"), key("#cm-shear", "ArrowRight"), key("#cm-shear", "ArrowLeft"), key("#cm-shear", "ArrowRight"), key("#cm-shear", "ArrowLeft")];
  await measure("cattaneo_mindlin L0 (press + shear: 2 steps)", shearMoves);

  // The bundled generic scenes, each opened at its defaults: the interface's normal force and
  // contact length on the page equal the native ones (the same override strings; 1e-8 for a
  // body held only by contact, see wasm_matches_native.mjs), then five slider moves timed.
  const GENERIC = { pin_lug: ["bore", "mu"], interference_fit: ["fit", "delta"], incline_push: ["incline", "push"],
    two_blocks_press_slide: ["joint", "slide"] };
  for (const [scene, [iface, slider]] of Object.entries(GENERIC)) {
    await page.click(`[data-scene="${scene}"]`);
    await page.waitForFunction((s) => window.contact2dPage.view && window.contact2dPage.view.scene === s
      && window.contact2dPage.run === "idle", { timeout: 60000 }, scene);
    const overrides = reference.generic.find((c) => c.params.scene === scene).params.overrides;
    const native = findCase("generic", { scene, overrides }).summary;
    const tol = native.floating_bodies.length ? 1e-8 : RELATIVE;
    for (const key of ["normal_force", "contact_length"]) {
      const live = Number(await cell(key)), want = native.contacts[iface][key];
      check(Math.abs(live - want) <= tol * Math.max(Math.abs(want), 1e-300),
        `${scene}: page ${key} = ${live} equals native ${want} to ${tol}`);
    }
    await page.screenshot({ path: join(out, `${scene}.png`), fullPage: true });
    const id = `#${scene}-${slider}`;
    await measure(scene, [key(id, "ArrowLeft"), key(id, "ArrowRight"), key(id, "ArrowLeft"), key(id, "ArrowRight"),
      key(id, "ArrowLeft")]);
  }

  // The loading history mode draws l(w), b(w) over ten steps.
  await page.click('[data-scene="flagship"]');
  await page.select("#refinement", "16");
  await page.click('[data-preset="gap_v1_mu03"]');
  await page.click("#history");
  // Waits on the state the page exposes (the run over, its last step shown), not on a text
  // that a later solve could replace; then the timing line must name that step.
  await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.shows
    && window.contact2dPage.shows.kind === "history" && window.contact2dPage.shows.step === 10, { timeout: 120000 });
  check((await page.$eval("#timing", (p) => p.textContent)).includes("step 10/10"),
    "the loading history after a preset ran to step 10/10 (the click is not lost to the preset's solve)");
  await page.screenshot({ path: join(out, "history.png"), fullPage: true });

  check(errors.length === 0, `no console or page error${errors.length ? ": " + errors.join("; ") : ""}`);
  console.log("update times in Chromium (median; solve = the WebAssembly call, total = solve + drawing):");
  for (const [label, t] of Object.entries(timings)) {
    console.log(`  ${label}: solve ${t.solve_ms.toFixed(1)} ms, total ${t.total_ms.toFixed(1)} ms (${t.n} updates)`);
  }
  console.log(`screenshots: ${join(out, "flagship_mu03.png")}, hertz_L1.png, cattaneo_mindlin_L0.png, history.png`);
} finally {
  await browser.close();
  server.kill();
}
if (failures.length) {
  console.error(`${failures.length} browser checks failed`);
  process.exit(1);
}
console.log("browser test: ok");
