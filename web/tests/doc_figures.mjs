// The screenshots of docs/teaching.md (docs/figures/teaching_*.png), at projector and phone
// sizes: node web/tests/doc_figures.mjs (after web/build.sh; the page must pass web/test.sh).
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
try {
  for (const [name, viewport, query, cycleStep] of shots) {
    const page = await newPage(browser, [], viewport);
    await page.goto(`${base}/index.html${query}`, { waitUntil: "load" });
    await page.waitForFunction(() => window.contact2dPage && window.contact2dPage.updates >= 1
      && window.contact2dPage.run === "idle", { timeout: 60000 });
    if (cycleStep) {
      await page.click("#cycle");
      await page.waitForFunction((k) => window.contact2dPage.cycleStep === k, { timeout: 60000 }, cycleStep);
      await page.click("#cycle"); // stop there
      await page.$eval("#profile", (c) => c.scrollIntoView({ block: "start" }));
    }
    await page.screenshot({ path: join(figures, name) });
    console.log(`docs/figures/${name}`);
    await page.close();
  }
} finally {
  await browser.close();
  server.kill();
}
