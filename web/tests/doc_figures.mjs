// The screenshots of docs/teaching.md (docs/figures/teaching_*.png), at projector and phone
// sizes: node web/tests/doc_figures.mjs (after web/build.sh; the page must pass web/test.sh).
import { mkdirSync } from "node:fs";
import { join } from "node:path";
import { launch, newPage, serve, web } from "./harness.mjs";

const figures = join(web, "../docs/figures");
const { base, server } = await serve();
const browser = await launch();
const shots = [
  ["teaching_projector_1366x768.png", { width: 1366, height: 768 }, "?mu=0.3&projector=1"],
  ["teaching_1024x768.png", { width: 1024, height: 768 }, "?scene=cattaneo_mindlin&shear=0.3"],
  ["teaching_phone_390x844.png", { width: 390, height: 844, deviceScaleFactor: 2, isMobile: true, hasTouch: true }, "?mu=0.3"],
  ["teaching_pin_lug_1366x768.png", { width: 1366, height: 768 }, "?scene=pin_lug&mu=0.2"],
  ["teaching_cycle_1366x768.png", { width: 1366, height: 768 }, "?scene=cattaneo_mindlin&amp=0.45&projector=1", 14],
];
// The ten-minute plan of docs/teaching.md in projector mode at 1366×768, one shot per row,
// written at 0.6 × scale (small PNGs in docs/figures/teaching/).
const plan = { width: 1366, height: 768, deviceScaleFactor: 0.6 };
shots.push(
  ["teaching/plan_0_two_blocks.png", plan, "?scene=two_blocks_press_slide&mu=0.3&slide=1&projector=1"],
  ["teaching/plan_1_cattaneo_mindlin.png", plan, "?scene=cattaneo_mindlin&shear=0.45&projector=1"],
  ["teaching/plan_3_cycle.png", plan, "?scene=cattaneo_mindlin&projector=1", 14],
  ["teaching/plan_5_plate_mu03.png", plan, "?mu=0.3&projector=1"],
  ["teaching/plan_7_table2_u1.png", plan, "?mu=0.3&eps=0.05&load=0.3838&projector=1"],
  // The loading history played back with the player, stopped at step 5 of 10 (one scale).
  ["teaching/plan_7_history_player.png", plan, "?mu=0.3&eps=0.05&load=0.3838&projector=1", async (page) => {
    await page.click("#history");
    await page.waitForFunction(() => window.contact2dPage.player && window.contact2dPage.run === "idle", { timeout: 300000 });
    await page.evaluate(() => { const s = document.getElementById("scrub"); s.value = "5"; s.dispatchEvent(new Event("input")); });
  }],
  // An exercise revealed (predict, then reveal), opened with the "Exercises" button.
  ["teaching/plan_ex_exercise.png", plan, "?projector=1", async (page) => {
    await page.click("#exercises-toggle");
    await page.waitForFunction(() => window.contact2dPage.exercise && window.contact2dPage.run === "idle", { timeout: 60000 });
    await page.click('input[name="ex-choice"][value="grows"]');
    await page.click("#ex-commit");
    await page.click("#ex-reveal");
    await page.waitForFunction(() => window.contact2dPage.exercise.revealed, { timeout: 60000 });
  }],
  ["teaching/plan_8_incline_past.png", plan, "?scene=incline_push&mu=0.3&push=0.45&projector=1"],
  ["teaching/plan_9_pin_lug.png", plan, "?scene=pin_lug&mu=0.2&projector=1"],
);
mkdirSync(join(figures, "teaching"), { recursive: true });
try {
  for (const [name, viewport, query, cycleStep] of shots) {
    const page = await newPage(browser, [], viewport);
    await page.goto(`${base}/index.html${query}`, { waitUntil: "load" });
    await page.waitForFunction(() => window.contact2dPage && window.contact2dPage.updates >= 1
      && window.contact2dPage.run === "idle", { timeout: 60000 });
    if (typeof cycleStep === "function") await cycleStep(page);
    else if (cycleStep) {
      await page.click("#cycle");
      await page.waitForFunction((k) => window.contact2dPage.cycleStep === k, { timeout: 60000 }, cycleStep);
      await page.click("#cycle"); // stop there
      if (viewport.deviceScaleFactor !== 0.6) await page.$eval("#profile", (c) => c.scrollIntoView({ block: "start" }));
    }
    await page.screenshot({ path: join(figures, name) });
    console.log(`docs/figures/${name}`);
    await page.close();
  }
} finally {
  await browser.close();
  server.kill();
}
