// Issue 42's presentation items in headless Chromium, at 1366×768, 1024×768 and 390×844:
//
//   player (item 3)  a finished loading history, the Mindlin–Deresiewicz cycle and a user's
//                    multi-step scene play, pause, step and scrub; every step is drawn at one scale: β and the charts' axes are
//                    the same at every step, so the drawn deformation grows with the load
//   export (item 6)  one figure as PNG and SVG (every chart shown, the colour key, the key
//                    numbers); the CSV holds the history's (w, l, b) and the cycle's whole loop;
//                    the example scene files are the repository's bytes and solve as a user's scene
//   exercises (item 5) predict-then-reveal: no reveal before a committed prediction; the page's
//                    verdict against the docs' and the paper's trends; comparison mode pins a
//                    curve (μ = 0's q ≡ 0) under the next set-up
//
// What is drawn is recorded by harness.mjs's instrument (the canvas calls), not by the page.
// Usage: node web/tests/browser_present.mjs
import { mkdirSync, readdirSync, readFileSync, rmSync } from "node:fs";
import { join } from "node:path";
import { check, failures, launch, newPage, out, serve, web } from "./harness.mjs";

mkdirSync(out, { recursive: true });
const VIEWPORTS = [{ width: 1366, height: 768 }, { width: 1024, height: 768 }, { width: 390, height: 844 }];
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const { base, server } = await serve();
const browser = await launch();
const errors = [];

const open = async (page, query = "") => {
  await page.goto(`${base}/index.html${query}`, { waitUntil: "load" });
  await page.waitForFunction(() => window.contact2dPage && window.contact2dPage.updates >= 1
    && window.contact2dPage.run === "idle", { timeout: 30000 });
};
const section = async (name, body) => {
  try { await body(); } catch (e) { check(false, `${name}: ${String(e.message || e).split("\n")[0]}`); }
};
// What one step shows: the player's step, β, the mesh's drawn extent (device px) and the tick
// labels drawn on the two charts (their axes).
const frame = (page) => page.evaluate(() => {
  const mesh = window.__canvasLog("mesh"), profile = window.__canvasLog("profile"), hist = window.__canvasLog("history-plot");
  const ticks = (l) => (l ? l.texts.filter((t) => /^−?-?[\d.]+$/.test(t.text)).map((t) => t.text).sort().join(" ") : "");
  return { k: window.contact2dPage.player && window.contact2dPage.player.k, beta: window.contact2dPage.beta,
    extent: mesh ? [mesh.x1 - mesh.x0, mesh.y1 - mesh.y0] : [0, 0], profileTicks: ticks(profile), historyTicks: ticks(hist),
    caption: document.getElementById("table-caption").textContent };
});
// Clicks the buttons and returns the downloaded files' names and bytes.
async function downloads(page, buttons) {
  const dir = join(out, "downloads_present");
  rmSync(dir, { recursive: true, force: true });
  mkdirSync(dir, { recursive: true });
  const cdp = await page.createCDPSession();
  await cdp.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: dir });
  for (const b of buttons) await page.click(b);
  const done = () => readdirSync(dir).filter((f) => !f.endsWith(".crdownload"));
  for (let i = 0; i < 100 && done().length < buttons.length; i++) await sleep(100);
  return Object.fromEntries(done().map((f) => [f.replace(/^.*_/, ""), readFileSync(join(dir, f))]));
}
const scrubTo = (page, k) => page.evaluate((n) => {
  const s = document.getElementById("scrub");
  s.value = String(n);
  s.dispatchEvent(new Event("input"));
}, k);

try {
  for (const viewport of VIEWPORTS) {
    const tag = `${viewport.width}×${viewport.height}`;
    const page = await newPage(browser, errors, viewport);
    await section(`${tag} a loading history plays at one scale`, async () => {
      // Frictionless, no clearance: one solve a step (fast); the projector layout where it fits.
      await open(page, `?mu=0&load=0.5${viewport.width > 900 ? "&projector=1" : ""}`);
      check(await page.$eval("#player", (p) => p.hidden), `${tag}: no player before a run`);
      await page.click("#history");
      await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.player
        && window.contact2dPage.player.k === 10, { timeout: 60000 });
      const box = await page.$eval("#player", (p) => { const r = p.getBoundingClientRect(); return [r.top, r.bottom]; });
      // On a screen (projector mode) the player is on it without scrolling; on a phone it is
      // reached by scrolling, like every control below the sticky figure.
      check(!(await page.$eval("#player", (p) => p.hidden)) && (viewport.width < 900 || box[1] <= viewport.height),
        `${tag}: the player is shown after the history (at y ${box[0].toFixed(0)}–${box[1].toFixed(0)} px)`);
      const f10 = await frame(page);
      await page.click("#step-back");
      const f9 = await frame(page);
      await scrubTo(page, 5);
      const f5 = await frame(page);
      await scrubTo(page, 1);
      const f1 = await frame(page);
      // Fixed scale: β is the same number at every step (the whole history's largest displacement
      // sets it); the charts' tick labels (their axes) are identical; the drawn deformed mesh
      // grows with w (without friction or clearance u ∝ w: its extent beyond the undeformed
      // mesh grows with the step), strictly from step 1 to 5 to 10.
      check(f9.k === 9 && f5.k === 5 && f1.k === 1 && f9.caption.includes("step 9 of 10") && f1.caption.includes("step 1 of 10"),
        `${tag}: step back → 9, scrub → 5 and 1; the table says which step`);
      check(f1.beta === f10.beta && f5.beta === f10.beta && f9.beta === f10.beta && f10.beta > 0,
        `${tag}: one β at every step (${f10.beta.toPrecision(4)})`);
      check(f1.profileTicks === f10.profileTicks && f5.profileTicks === f10.profileTicks && f1.historyTicks === f10.historyTicks
        && f10.profileTicks.length > 0, `${tag}: the charts' axes are the same at steps 1, 5, 10 (${f10.profileTicks.split(" ").length} profile ticks)`);
      const area = (f) => f.extent[0] * f.extent[1];
      check(area(f1) < area(f5) && area(f5) < area(f10),
        `${tag}: the drawn mesh grows with the load (extent ${f1.extent.map((v) => v.toFixed(0)).join("×")} → ` +
        `${f5.extent.map((v) => v.toFixed(0)).join("×")} → ${f10.extent.map((v) => v.toFixed(0)).join("×")} px)`);
      // Play from step 1 to the end; pause holds the step.
      await page.click("#play");
      await page.waitForFunction(() => window.contact2dPage.player.k >= 3, { timeout: 10000 });
      await page.click("#play");
      const paused = await frame(page);
      await sleep(900);
      const still = await frame(page);
      check(paused.k >= 3 && paused.k < 10 && still.k === paused.k, `${tag}: play advances, pause holds step ${paused.k}`);
      await page.click("#play");
      await page.waitForFunction(() => window.contact2dPage.player.k === 10 && !window.contact2dPage.player.playing, { timeout: 10000 });
      check(true, `${tag}: play runs on to step 10 and stops`);
      await page.screenshot({ path: join(out, `present_player_${viewport.width}.png`) });
      // Any input clears the player (its steps are of another set-up).
      await page.click("#step-fwd");
      await page.evaluate(() => { const e = document.getElementById("load"); e.value = "0.4"; e.dispatchEvent(new Event("input")); });
      await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.shows.kind === "solve", { timeout: 30000 });
      check(await page.$eval("#player", (p) => p.hidden), `${tag}: a new input hides the player`);
    });
    await section(`${tag} export: one figure, the history's CSV`, async () => {
      await open(page, "?mu=0&load=0.5");
      await page.click("#history");
      await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.player
        && window.contact2dPage.player.k === 10, { timeout: 60000 });
      const shown = await page.evaluate(() => ({
        series: ["profile", "history-plot"].map((id) => window.contact2dPage.charts[id].series.map((s) => s.label)),
        canvases: ["mesh", "profile", "history-plot"].map((id) => document.getElementById(id)).map((c) => [c.width, c.height]),
        history: window.contact2dPage.history, l: document.querySelector('td[data-key="l"]').textContent,
      }));
      const files = await downloads(page, ["#export-csv", "#export-png", "#export-svg"]);
      const csv = String(files["flagship.csv"] || "");
      const rows = csv.split("\n");
      const at = rows.indexOf("w,l,b");
      const hist = rows.slice(at + 1, at + 11).map((r) => r.split(",").map(Number));
      check(at > 0 && hist.length === 10 && hist.every(([w, l, b], i) => w === shown.history[i].w && l === shown.history[i].l
        && b === shown.history[i].b), `${tag}: the CSV holds the history's 10 (w, l, b) rows exactly`);
      // The PNG: its header's size is the figure's: as wide as the widest chart, and taller
      // than the three charts stacked (title, numbers, colour key above and between them).
      const png = files["figure.png"];
      const [pw, ph] = png ? [png.readUInt32BE(16), png.readUInt32BE(20)] : [0, 0];
      const maxW = Math.max(...shown.canvases.map(([w]) => w)), sumH = shown.canvases.reduce((a, [, h]) => a + h, 0);
      check(png && png.subarray(1, 4).toString() === "PNG" && pw >= maxW && ph > sumH,
        `${tag}: one PNG figure ${pw}×${ph} px holds the three charts (${maxW} wide, ${sumH} tall)`);
      const svg = String(files["figure.svg"] || "");
      const images = (svg.match(/<image /g) || []).length;
      const key = ["stick", "slip +x", "slip −x", "contact (μ = 0)", "free"].every((n) => svg.includes(`>${n}</text>`));
      check(svg.startsWith("<svg") && images === 1 && key && svg.includes(`contact end l = ${shown.l}`),
        `${tag}: the SVG figure: the mesh as its one image, the colour key, the key numbers (l = ${shown.l})`);
      // The charts as vectors: every series of the profile and the history a group holding a
      // <polyline> (a line) or <path>s (dots), its legend entry as text, and the axes' ticks as
      // text; the document parses as SVG.
      const esc = (t) => t.replaceAll("&", "&amp;").replaceAll("<", "&lt;").replaceAll(">", "&gt;").replaceAll('"', "&quot;");
      const vector = shown.series.flat().map((label) => {
        const at = svg.indexOf(`<g class="series" data-series="${esc(label)}">`);
        const body = at < 0 ? "" : svg.slice(at, svg.indexOf("</g>", at));
        return { label, ok: /<polyline |<path /.test(body) && svg.includes(`>${esc(label)}</text>`) };
      });
      const parsed = await page.evaluate((text) => {
        const doc = new DOMParser().parseFromString(text, "image/svg+xml");
        return !doc.querySelector("parsererror") && doc.querySelectorAll("polyline").length;
      }, svg);
      const ticks = ["0", "0.1", "0.2"].every((t) => svg.includes(`>${t}</text>`));
      check(vector.length >= 4 && vector.every((v) => v.ok) && parsed > 0 && ticks,
        `${tag}: the SVG draws the charts as vectors: ${vector.length} series (${vector.map((v) => v.label).join(", ")}) ` +
        `each as <polyline>/<path> with its legend, ${parsed} polylines, tick labels as text`);
    });
    await section(`${tag} example scene files`, async () => {
      await open(page, "?scene=user");
      const links = await page.$$eval("#examples a", (as) => as.map((a) => [a.getAttribute("href"), a.download]));
      const same = await Promise.all(links.map(async ([href]) => {
        const bytes = Buffer.from(await page.evaluate(async (h) => [...new Uint8Array(await (await fetch(h)).arrayBuffer())], href));
        const name = href.split("/").pop();
        const repo = join(web, "..", name.endsWith(".toml") ? "scenes/generic" : "meshes/generic", name);
        return bytes.equals(readFileSync(repo));
      }));
      // Five bundled generic scenes (crates/web's BUNDLED_GENERIC), a .toml and a .msh each.
      check(links.length === 10 && same.every(Boolean) && links.every(([h, d]) => h.endsWith(d)),
        `${tag}: ${links.length} example files offered, each the repository's bytes`);
      if (viewport.width === 1366) {
        const input = await page.$("#user-input");
        await input.uploadFile(join(web, "../scenes/generic/pin_lug.toml"), join(web, "../meshes/generic/pin_lug_L1.msh"));
        await page.waitForFunction(() => window.contact2dPage.view && window.contact2dPage.run === "idle"
          && window.contact2dPage.shows && window.contact2dPage.shows.text.includes("pin_lug.toml"), { timeout: 60000 });
        const s = await page.evaluate(() => ({ status: window.contact2dPage.view.summary.status, error: window.contact2dPage.error }));
        check(!s.error && s.status === "converged", `the example pin_lug pair solves as a user's scene (status ${s.status})`);
      }
    });
    await section(`${tag} a user's multi-step scene plays at one scale`, async () => {
      // The example two_blocks_press_slide pair as a user's scene: its schedule presses in two
      // steps (0.5, then 1 × 1000 N/mm), then slides the top in four while the force is held.
      await open(page, "?scene=user");
      const input = await page.$("#user-input");
      await input.uploadFile(join(web, "../scenes/generic/two_blocks_press_slide.toml"), join(web, "../meshes/generic/two_blocks.msh"));
      await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.player
        && window.contact2dPage.player.kind === "user" && window.contact2dPage.player.k === 6, { timeout: 60000 });
      const normal = () => page.$eval('td[data-key="normal_force"]', (td) => Number(td.dataset.value));
      const f6 = { ...(await frame(page)), P: await normal() };
      await scrubTo(page, 1);
      const f1 = { ...(await frame(page)), P: await normal() };
      await page.click("#step-fwd");
      const f2 = { ...(await frame(page)), P: await normal() };
      check(f1.k === 1 && f2.k === 2 && f1.caption.includes("load step 1 of 6") && f2.caption.includes("load step 2 of 6"),
        `${tag}: your scene's player scrubs to step 1, steps to 2; the table says which`);
      // Statics of the upper block: the joint carries the press, Σλ = 0.5 × 1000 at step 1 and
      // 1000 from step 2 (1e-9: the solve's force balance, as crates/web's two-blocks test).
      check(Math.abs(f1.P / 500 - 1) < 1e-9 && Math.abs(f2.P / 1000 - 1) < 1e-9 && Math.abs(f6.P / 1000 - 1) < 1e-9,
        `${tag}: Σλ at steps 1, 2, 6 = ${f1.P}, ${f2.P}, ${f6.P} (the press: 500, 1000, 1000)`);
      check(f1.beta === f6.beta && f2.beta === f6.beta && f6.beta > 0 && f1.profileTicks === f6.profileTicks
        && f6.profileTicks.length > 0, `${tag}: one β (${f6.beta.toPrecision(4)}) and the profile's axes at steps 1, 2, 6`);
      await page.click("#play");
      await page.waitForFunction(() => window.contact2dPage.player.k === 6 && !window.contact2dPage.player.playing, { timeout: 10000 });
      check(true, `${tag}: play runs your scene's steps to 6 and stops`);
      if (viewport.width === 1366) await page.screenshot({ path: join(out, "present_user_steps_1366.png") });
    });
    await section(`${tag} exercises: predict, then reveal`, async () => {
      await open(page, viewport.width > 900 ? "?projector=1" : "");
      // In projector mode the "Exercises" button over the figure opens them on screen.
      if (viewport.width > 900) await page.click("#exercises-toggle");
      else await page.evaluate(() => { document.getElementById("exercises").open = true; });
      // Exercise 1: b grows with μ (docs/teaching.md on N = 16: b = 0.015 at μ = 0.1, 0.153 at
      // 0.3; the paper 0.1485 at 0.3). Exercise 4: no gap, no friction: l does not move with w
      // (the problem is linear in w, spec §5.2).
      // Once, at 1366×768, exercises 2 and 3: b falls with a stiffer insert (docs: 0.206 at
      // E2/E1 = 0.25 to 0.031 at 16), l falls with clearance (the paper's Table 2: l ≈ 0.15 at
      // ε = 0.05 against ≈ 0.47 without).
      // Exercise 5 (Cattaneo–Mindlin) and 6 (the incline): their truths are computed below from
      // the closed form and the statics, not listed here (null).
      const more = viewport.width === 1366 ? [["stiffness", "shrinks", "shrinks"], ["clearance", "stays", "shrinks"]] : [];
      const tan = 0.1, upper = (mu) => (tan + mu) / (1 - mu * tan);
      for (const [id, predict, truth] of [["friction", "grows", "grows"], ["linear", "grows", "stays"], ...more,
        ["partial_slip", "shrinks", null], ["incline", "holds", null]]) {
        await page.select("#ex-pick", id);
        await page.waitForFunction((x) => window.contact2dPage.exercise && window.contact2dPage.exercise.id === x
          && window.contact2dPage.run === "idle" && window.contact2dPage.shows.kind === "solve", { timeout: 60000 }, id);
        const early = await page.$eval("#ex-reveal", (b) => b.disabled);
        const cell = (key) => page.$eval(`td[data-key="${key}"]`, (td) => td.dataset.value);
        const closedBefore = id === "partial_slip" ? Number(await cell("c_over_a_closed")) : null;
        await page.click(`input[name="ex-choice"][value="${predict}"]`);
        await page.click("#ex-commit");
        await page.click("#ex-reveal");
        await page.waitForFunction(() => window.contact2dPage.exercise.revealed, { timeout: 60000 });
        const r = await page.evaluate(() => ({ ...window.contact2dPage.exercise.revealed, text: document.getElementById("ex-answer").textContent }));
        let expected = truth, also = true, detail = "";
        if (id === "partial_slip") {
          // Cattaneo–Mindlin: c/a = √(1 − Q/(μP)) at the measured Q/(μP) (the table's closed-form
          // row): the FE c/a must move the closed form's way, and lie within one L0 cell of it
          // (a/4 = 0.25 in c/a: L0 places a stick end to a cell, docs/teaching.md exercise 4).
          const closedAfter = Number(await cell("c_over_a_closed"));
          expected = closedAfter < closedBefore ? "shrinks" : closedAfter > closedBefore ? "grows" : "stays";
          also = Math.abs(r.before - closedBefore) <= 0.25 && Math.abs(r.after - closedAfter) <= 0.25;
          detail = `; closed form ${closedBefore.toPrecision(3)} → ${closedAfter.toPrecision(3)}`;
        } else if (id === "incline") {
          // Statics with Coulomb: the push F/G = 0.35 holds the block below (tan α + μ)/(1 − μ tan α):
          // 0.4124 at μ = 0.3 (it holds before), 0.3061 at μ = 0.2 (it slides after).
          expected = 0.35 < upper(0.2) ? "holds" : "slides";
          also = 0.35 < upper(0.3) && String(r.before).startsWith("converged");
          detail = `; statics: holds below F/G = ${upper(0.3).toFixed(4)} (μ = 0.3), ${upper(0.2).toFixed(4)} (μ = 0.2)`;
        }
        const show = (v) => (typeof v === "number" ? v.toPrecision(4) : String(v).split(":")[0]);
        check(early && also && r.moved === expected && r.right === (predict === expected) && r.text.includes(r.right ? "Right" : "Not quite"),
          `${tag} exercise ${id}: reveal locked until committed; the page finds "${r.moved}" ` +
          `(${show(r.before)} → ${show(r.after)}${detail}), the prediction "${predict}" judged ${r.right ? "right" : "wrong"}`);
      }
      if (viewport.width > 900) {
        const bottom = await page.$eval("#ex-answer", (e) => e.getBoundingClientRect().bottom);
        const scrolled = await page.evaluate(() => window.scrollY);
        check(scrolled === 0 && bottom <= viewport.height,
          `${tag} projector mode: the exercise and its answer on screen without scrolling (answer ends at y ${bottom.toFixed(0)})`);
      }
      await page.screenshot({ path: join(out, `present_exercise_${viewport.width}.png`) });
    });
    await section(`${tag} comparison mode pins a curve`, async () => {
      await open(page, "?mu=0");
      await page.click("#pin");
      await page.evaluate(() => { const e = document.getElementById("mu"); e.value = "0.3"; e.dispatchEvent(new Event("input")); });
      await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.view
        && document.getElementById("table-caption").textContent.includes("μ = 0.3"), { timeout: 60000 });
      const r = await page.evaluate(() => {
        const pinned = window.contact2dPage.pinned;
        const qPinned = pinned.series.find((s) => s.label.startsWith("q "));
        const legend = window.__canvasLog("profile").texts.map((t) => t.text).filter((t) => t.includes("pinned"));
        return { qPinnedMax: Math.max(...qPinned.y.filter((v) => v !== null).map(Math.abs)), legend,
          qLive: Math.max(...window.contact2dPage.view.hole.q.filter((v) => v !== null).map(Math.abs)) };
      });
      // Without friction the shear is zero everywhere (Coulomb: |q| ≤ μp = 0); at μ = 0.3 it is
      // not. 1e-12 × the live shear: the pinned q is zero up to round-off (the edge's q is
      // σ·n·t of the stress, a sum of terms of order 1e-1 that cancel to ~1e-17).
      check(r.qPinnedMax <= 1e-12 * r.qLive && r.qLive > 0 && r.legend.length === 3,
        `${tag}: μ = 0's curves pinned under μ = 0.3 (pinned max |q| = ${r.qPinnedMax}, live |q| up to ${r.qLive.toPrecision(3)}; ${r.legend.length} pinned legend entries)`);
      await page.click("#pin");
      const left = await page.evaluate(() => window.__canvasLog("profile").texts.filter((t) => t.text.includes("pinned")).length);
      check(left === 0, `${tag}: Unpin removes them`);
    });
    await section(`${tag} the cycle plays at one scale`, async () => {
      await open(page, "?scene=cattaneo_mindlin");
      await page.click("#cycle");
      await page.waitForFunction(() => window.contact2dPage.cycleStep === 21 && window.contact2dPage.run === "idle", { timeout: 60000 });
      const last = await frame(page);
      await scrubTo(page, 4);
      const f4 = await frame(page);
      await page.click("#step-fwd");
      const f5 = await frame(page);
      check(f4.k === 4 && f5.k === 5 && f5.caption.includes("step 5 of 21"), `${tag}: the cycle scrubs to 4 and steps to 5`);
      // The loop's axes: the whole cycle's Q range at every step.
      check(f4.historyTicks === last.historyTicks && f4.profileTicks === last.profileTicks && f4.beta === last.beta,
        `${tag}: the loop's and the profile's axes and β are the cycle's, at step 4 as at 21`);
      // The CSV: the whole loop (22 states: the press, the loading, 20 steps of the cycle),
      // whatever step is shown; its last Q is the table's Q at step 21.
      await scrubTo(page, 21);
      const q21 = await page.$eval('td[data-key="Q"]', (td) => Number(td.dataset.value));
      const csv = String((await downloads(page, ["#export-csv"]))["mindlin.csv"] || "");
      const rows = csv.split("\n");
      const at = rows.indexOf("step,delta_mm,Q_N_per_mm");
      const loop = rows.slice(at + 1).filter((r) => /^\d+,/.test(r)).map((r) => r.split(",").map(Number));
      check(at > 0 && loop.length === 22 && loop[21][0] === 21 && loop[21][2] === q21,
        `${tag}: the CSV holds the whole loop (${loop.length} rows; Q at step 21 = ${q21})`);
    });
    await page.close();
  }
  check(errors.length === 0, `no console or page error${errors.length ? ": " + errors.join("; ").slice(0, 300) : ""}`);
} finally {
  await browser.close();
  server.kill();
}
if (failures.length) {
  console.error(`${failures.length} presentation checks failed`);
  process.exit(1);
}
console.log("presentation test: ok");
