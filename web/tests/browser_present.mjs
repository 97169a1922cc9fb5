// Issue 42's presentation items in headless Chromium, at 1366×768, 1024×768 and 390×844:
//
//   player (item 3)  a finished loading history and the Mindlin–Deresiewicz cycle play, pause,
//                    step and scrub; every step is drawn at one scale: β and the charts' axes are
//                    the same at every step, so the drawn deformation grows with the load
//
// What is drawn is recorded by harness.mjs's instrument (the canvas calls), not by the page.
// Usage: node web/tests/browser_present.mjs
import { mkdirSync } from "node:fs";
import { join } from "node:path";
import { check, failures, launch, newPage, out, serve } from "./harness.mjs";

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
