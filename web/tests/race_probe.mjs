// Not part of test.sh: repeats browser.mjs's history-after-preset sequence N times (PAGE_DIR to
// try another copy of the page) and reports whether each History click ran to step 10.
import { launch, newPage, serve } from "./harness.mjs";
const N = Number(process.argv[2] || 5);
const { base, server } = await serve();
const browser = await launch();
let ok = 0, ok2 = 0;
try {
  for (let i = 0; i < N; i++) {
    const page = await newPage(browser, []);
    await page.goto(`${base}/index.html?mu=0.3`, { waitUntil: "load" });
    await page.waitForFunction(() => window.contact2dPage && window.contact2dPage.updates >= 1
      && window.contact2dPage.run === "idle", { timeout: 60000 });
    await page.select("#refinement", "16");
    await page.click('[data-preset="gap_v1_mu03"]');
    const at = await page.evaluate(() => window.contact2dPage.run);
    await page.click("#history");
    let done = true;
    try {
      await page.waitForFunction(() => document.querySelector("#timing").textContent.includes("step 10/10"), { timeout: 30000 });
    } catch { done = false; }
    ok += done;
    console.log(`run ${i + 1}: page ${at} when History was clicked -> ${done ? "history ran to step 10/10" : "NO history (timed out)"}`);
    // The same click made in the page while its solve is in flight (browser_page.mjs's section).
    await page.evaluate(async () => {
      const e = document.getElementById("load"); e.value = "0.3"; e.dispatchEvent(new Event("input"));
      await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      window.__at = window.contact2dPage.run;
      document.getElementById("history").click();
    });
    let done2 = true;
    try {
      await page.waitForFunction(() => window.contact2dPage.shows.kind === "history" && window.contact2dPage.shows.step === 10
        && window.contact2dPage.run === "idle", { timeout: 30000 });
    } catch { done2 = false; }
    ok2 += done2;
    console.log(`       in-page click while ${await page.evaluate(() => window.__at)} -> ${done2 ? "history ran to step 10" : "NO history"}`);
    await page.close();
  }
} finally { await browser.close(); server.kill(); }
console.log(`${ok}/${N} histories after a preset, ${ok2}/${N} clicked during a solve`);
