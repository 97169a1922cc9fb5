// The teaching page's defects of issue 24, one check each, in headless Chromium: each failed on
// the page before the issue (named in the check's comment) and must pass now.
//
//   state      history + tab switch, history clicked twice, a control moved during a history,
//              the published column after a history, b at μ = 0, full sliding, c/a ≤ 1
//   cycle      the Mindlin–Deresiewicz cycle against Masing's rule, reverse slip from the edges
//   readable   canvases at devicePixelRatio, chart text ≥ 14 CSS px at 1366×768 (≥ 20 in
//              projector mode), no two chart labels overlapping, the figure beside the controls
//              at 1024×768, 1366×768 and 1366 at 125 % (1093×615), first on a phone, the deformed
//              mesh inside its canvas at β = 3
//   shareable  every control in the URL and back, bad parameters reported and replaced by the
//              defaults, reset, PNG and CSV export, file:// explained
//   scenes     a user's own scene (files chosen on the page): Coulomb's μP; a bad file's message
//
// What is drawn is recorded by harness.mjs's instrument (the canvas calls themselves), not by
// the page. Usage: node web/tests/browser_page.mjs [reference.json]
import { readFileSync, mkdirSync, existsSync, readdirSync, rmSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import { check, failures, launch, newPage, out, overlap, serve, updated, updates, web } from "./harness.mjs";

mkdirSync(out, { recursive: true });
const reference = JSON.parse(readFileSync(process.argv[2] || join(out, "reference.json"), "utf8"));
const nativeFlagship = (params) => reference.flagship.find((c) => Object.entries(params).every(([k, v]) => c.params[k] === v)
  && Object.keys(c.params).length === Object.keys(params).length).view;
const close = (a, b, tol = 1e-12) => Math.abs(a - b) <= tol * Math.max(Math.abs(a), Math.abs(b));
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

const { base, server } = await serve();
const browser = await launch();
const errors = [];
const open = async (page, query = "") => {
  await page.goto(`${base}/index.html${query}`, { waitUntil: "load" });
  await page.waitForFunction(() => window.contact2dPage && window.contact2dPage.updates >= 1
    && window.contact2dPage.run !== "solving" && window.contact2dPage.run !== "scheduled", { timeout: 20000 });
};
const cell = (page, key) => page.$eval(`td[data-key="${key}"]`, (td) => ({ value: td.dataset.value, text: td.textContent }));
const pageState = (page) => page.evaluate(() => ({
  run: window.contact2dPage.run, shows: window.contact2dPage.shows, history: window.contact2dPage.history,
  scene: window.contact2dPage.view && (window.contact2dPage.view.scene || (window.contact2dPage.view.closed_form ? "closed" : "flagship")),
}));
const historyStep = (page, k) => page.waitForFunction((n) => (window.contact2dPage.history || []).length >= n,
  { timeout: 30000 }, k);

try {
  const page = await newPage(browser, errors);
  let s, before;
  // A section that throws (a selector or state the page lacks) is one failed check, and the
  // next section still runs: on the page before issue 24 every section fails on its own.
  const section = async (name, body) => {
    try { await body(); } catch (e) { check(false, `${name}: ${String(e.message || e).split("\n")[0]}`); }
  };

  // --- state -----------------------------------------------------------------------------
  await section("history + tab switch", async () => {
    // Before: the history kept running after a tab switch and drew the plate into the Hertz tab.
    await open(page, "?eps=0.05&mu=0.3&load=0.3838");
    await page.click("#history");
    await historyStep(page, 2);
    await page.click('[data-scene="hertz"]');
    const afterSwitch = (await pageState(page)).history.length;
    await sleep(1500);
    s = await pageState(page);
    check(s.shows.scene === "hertz" && s.run === "idle" && s.history.length === afterSwitch
      && (await page.$('td[data-key="a"]')) !== null && (await page.$('td[data-key="l"]')) === null,
    `a tab switch stops the history: Hertz shown, history stayed at ${afterSwitch} points, run ${s.run}`);
  });
  await section("history clicked twice", async () => {
    // Before: a second click started a second run and the two interleaved (l(w), b(w) zig-zag).
    await open(page, "?eps=0.05&mu=0.3&load=0.3838");
    await page.click("#history");
    await historyStep(page, 1);
    check((await page.$eval("#history", (b) => b.textContent)).startsWith("Stop"), "the history button reads \"Stop\" while running");
    await page.click("#history");
    await sleep(800);
    s = await pageState(page);
    const stopped = s.history.length;
    check(s.run === "idle" && stopped < 10, `the second click stops the run (${stopped} points, run ${s.run})`);
    await page.click("#history");
    await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.history.length === 10,
      { timeout: 60000 });
    s = await pageState(page);
    const ws = s.history.map((p) => p.w);
    check(ws.every((w, i) => i === 0 || w > ws[i - 1]), `a complete history has 10 points in increasing w (${ws.join(", ")})`);

    // Before: after a run the "published" column vanished and the table silently showed the
    // 10-step solution.
    const published = await page.$eval("#published-head", (th) => th.textContent);
    const caption = await page.$eval("#table-caption", (p) => p.textContent);
    const label = await page.$eval("#published-label", (p) => p.textContent);
    check(published === "published" && caption.includes("step 10 of 10") && label.includes("load steps"),
      `after a history the table says so ("${caption.slice(0, 60)}…") and keeps the published column with the load-step caveat`);
  });
  await section("history clicked while a solve runs", async () => {
    // Before: a click on History while a solve of the controls ran (a preset chosen a frame
    // earlier, on a busy machine) was dropped: no history, and CI's wait for "step 10/10" timed
    // out. Now the history starts when that solve has been drawn. The click is made in the
    // page at a moment the page reports a solve in flight (and, second, one scheduled for the
    // next frame with another queued behind a running one), so both orders are exercised
    // every run, not by chance.
    for (const when of ["solving", "scheduled"]) {
      await open(page, "?eps=0.05&mu=0.3&load=0.3838");
      const at = await page.evaluate(async (w) => {
        const fire = (id, v) => { const e = document.getElementById(id); e.value = v; e.dispatchEvent(new Event("input")); };
        fire("load", "0.3");
        if (w === "solving") {
          // The scheduled solve starts in the next frame; the worker's answer is a later task.
          await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
        } else {
          await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
          fire("load", "0.3838"); // queued behind the running solve
        }
        const run = window.contact2dPage.run;
        document.getElementById("history").click();
        return run;
      }, when);
      await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.shows.kind === "history"
        && window.contact2dPage.shows.step === 10, { timeout: 60000 });
      s = await pageState(page);
      const timing = await page.$eval("#timing", (p) => p.textContent);
      const last = when === "solving" ? 0.3 : 0.3838; // the controls' load when History was clicked
      check(at === "solving" && s.history.length === 10 && s.history[9].w === last && timing.includes("step 10/10"),
        `History clicked while a solve ${when === "solving" ? "runs" : "runs and another is queued"} (page: ${at}): ` +
        `the history runs to w = ${s.history[9] && s.history[9].w} (${s.history.length} points, "${timing.slice(0, 24)}…")`);
    }
  });
  await section("control moved during a history", async () => {
    // Before: moving a control during a run left the table showing the run's answer (ε = 0.05's
    // l = 0.154 under a slider at ε = 0).
    await page.click("#history");
    await historyStep(page, 2);
    await page.select("#eps", "0");
    await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.shows.kind === "solve",
      { timeout: 30000 });
    await sleep(1000); // a history still running would draw its next step within 120 ms
    const eps0 = nativeFlagship({ friction: 0.3, stiffness_ratio: 1, eps: 0, refinement: 16, load: 0.3838, variant: "hole_master" });
    const l = Number((await cell(page, "l")).value);
    s = await pageState(page);
    check(s.run === "idle" && s.shows.kind === "solve" && close(l, eps0.summary.paper.l),
      `a control moved during a history: the table shows ε = 0's l = ${l.toFixed(4)} (native ${eps0.summary.paper.l.toFixed(4)})`);
  });
  await section("b at μ = 0", async () => {
    // Before: at μ = 0 the table showed b = l although nothing sticks.
    before = await updates(page);
    await page.click('[data-preset="nogap_mu0"]');
    await updated(page, before);
    check((await cell(page, "b")).text === "—", "at μ = 0 the stick end b is shown as \"—\"");
    // Before: Table 2 U(1) showed b = 0.1544 beside the paper's 0.1309 without a word.
    before = await updates(page);
    await page.click('[data-preset="gap_v1_mu03"]');
    await updated(page, before);
    const note = await page.$eval("#published-label", (p) => p.textContent);
    check(note.includes("b depends on the load steps"), `Table 2 U(1): "${note.slice(-75)}"`);
  });
  await section("full sliding, c/a", async () => {
    // Before: full sliding (Q = μP) was not announced; c/a read above 1 at zero shear.
    await open(page, "?scene=cattaneo_mindlin&shear=0.9");
    const banner = await page.$eval("#banner", (b) => (b.hidden ? "" : b.textContent));
    check(banner.includes("Full sliding"), `Cattaneo–Mindlin past Q = μP: "${banner.slice(0, 50)}…"`);
    for (const press of ["0.5", "1", "1.5"]) {
      await open(page, `?scene=cattaneo_mindlin&shear=0&press=${press}`);
      const ca = Number((await cell(page, "c_over_a")).value);
      check(ca <= 1, `c/a = ${ca} ≤ 1 at zero shear, press ${press}`);
    }
  });
  // Before: no cycle. The Mindlin–Deresiewicz cycle (+A → −A → +A) against Masing's rule
  // (Mindlin and Deresiewicz 1953; Johnson §7.3): Q(−A) = −Q(+A) to 1e-3 of Q* (exact for the
  // continuum; L0 measured 2.1e-4), the loop closes at +A to 1e-6 (measured 1e-13); after the
  // reversal, slip in the new direction appears at both edges first, outside the stick zone.
  await section("Mindlin–Deresiewicz cycle", async () => {
    await open(page, "?scene=cattaneo_mindlin&amp=0.3");
    await page.click("#cycle");
    await page.waitForFunction(() => window.contact2dPage.cycleStep === 21 && window.contact2dPage.run === "idle",
      { timeout: 60000 });
    const cyc = await page.evaluate(() => window.contact2dPage.cycle.summary.steps.map((st) => ({
      Q: st.reactions.cylinder_top[0], profile: st.contacts.roller.profile })));
    const Q = cyc.map((c) => c.Q);
    check(Math.abs(Q[11] + Q[1]) <= 1e-3 * Math.abs(Q[1]) && Math.abs(Q[21] - Q[1]) <= 1e-6 * Math.abs(Q[1]),
      `the loop is symmetric and closes: Q(+A) = ${Q[1].toFixed(3)}, Q(−A) = ${Q[11].toFixed(3)}, Q(+A) again = ${Q[21].toFixed(3)}`);
    const p2 = cyc[2].profile, loading = cyc[1].profile.state.find((st) => st.startsWith("slip"));
    const xsOf = (cond) => p2.x.filter((_, i) => cond(p2.state[i])).map(Math.abs);
    const rev = p2.x.filter((_, i) => p2.state[i].startsWith("slip") && p2.state[i] !== loading);
    const stick = xsOf((st) => st === "stick");
    check(rev.some((x) => x < 0) && rev.some((x) => x > 0) && stick.length > 0
      && Math.min(...rev.map(Math.abs)) > Math.max(...stick),
    `after the reversal reverse slip at both edges (${rev.length} pairs) outside the stick zone (${stick.length} pairs)`);
    const loopText = (await page.evaluate(() => window.__canvasLog("history-plot"))).texts.map((t) => t.text);
    check(loopText.includes("Q(δ), computed"), "the Q–δ loop is drawn");
    await page.screenshot({ path: join(out, "cycle.png"), fullPage: true });
  });

  // Before: no explanation. Every tab's panel names Coulomb's law and defines its symbols; every
  // scene's panel has a sketch.
  await section("explanation panels", async () => {
    await open(page);
    for (const scene of await page.$$eval("#scenes button", (bs) => bs.map((b) => b.dataset.scene))) {
      await page.click(`[data-scene="${scene}"]`);
      const panel = await page.$eval("#explain-body", (d) => ({ text: d.textContent, svg: d.querySelectorAll("svg").length }));
      check(panel.text.includes("|q| ≤ μ p") && panel.text.includes("Symbols") && (scene === "user" || panel.svg === 1),
        `${scene}: the panel has Coulomb's law, the symbols${scene === "user" ? "" : " and a sketch"}`);
    }
  });

  await section("readability and layout", async () => {
    // --- readable ------------------------------------------------------------------------------
    const texts = async (id) => (await page.evaluate((i) => window.__canvasLog(i), id)) || { texts: [] };
    const readable = async (what, minPx) => {
      for (const id of ["profile", "history-plot"]) {
        const log = await texts(id);
        if (!log.texts.length) continue;
        const smallest = Math.min(...log.texts.map((t) => t.css_px));
        check(smallest >= minPx, `${what}: ${id} text ≥ ${minPx} CSS px (smallest ${smallest.toFixed(1)})`);
        const clash = [];
        log.texts.forEach((a, i) => log.texts.slice(i + 1).forEach((b) => { if (overlap(a.box, b.box)) clash.push(`${a.text}/${b.text}`); }));
        check(clash.length === 0, `${what}: no two ${id} labels overlap${clash.length ? ": " + clash.join(", ") : ""}`);
      }
    };
    for (const dpr of [1, 2]) {
      await page.setViewport({ width: 1366, height: 768, deviceScaleFactor: dpr });
      await open(page, "?eps=0.05&mu=0.3&load=0.3838");
      await page.click("#history");
      await page.waitForFunction(() => window.contact2dPage.run === "idle" && window.contact2dPage.history.length === 10,
        { timeout: 60000 });
      const c = await page.$eval("#profile", (e) => ({ w: e.width, cw: e.clientWidth }));
      check(c.w === Math.round(c.cw * dpr), `devicePixelRatio ${dpr}: the chart's backing store is ${c.w} px for ${c.cw} CSS px`);
      await readable(`1366×768 at ratio ${dpr}`, 14);
    }
    await page.setViewport({ width: 1366, height: 768, deviceScaleFactor: 1 });
    const smallDom = await page.evaluate(() => [...document.querySelectorAll("body *")].filter((e) => {
      const own = [...e.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim());
      return own && e.offsetParent !== null && parseFloat(getComputedStyle(e).fontSize) < 14;
    }).map((e) => `${e.tagName}#${e.id}: ${getComputedStyle(e).fontSize}`));
    check(smallDom.length === 0, `every visible text on the page ≥ 14 CSS px${smallDom.length ? ": " + smallDom.slice(0, 5).join(", ") : ""}`);
    for (const scene of ["hertz", "cattaneo_mindlin", "pin_lug"]) {
      await open(page, `?scene=${scene}`);
      await readable(`1366×768 ${scene}`, 14);
    }
    await open(page, "?eps=0.05&mu=0.3&load=0.3838&projector=1");
    await readable("projector mode", 20);
    const box = (sel) => page.$eval(sel, (e) => { const r = e.getBoundingClientRect(); return { l: r.left, r: r.right, t: r.top, b: r.bottom }; });
    let [mesh, controls] = [await box("#mesh"), await box("#controls")];
    check(mesh.r <= controls.l + 1, "projector mode: the figures come first (left of the controls)");
    await page.screenshot({ path: join(out, "projector_1366x768.png") });
    for (const [w, h] of [[1024, 768], [1366, 768], [1093, 615]]) {
      await page.setViewport({ width: w, height: h });
      await open(page);
      [mesh, controls] = [await box("#mesh"), await box("#controls")];
      check(mesh.l >= controls.r - 1 && mesh.t < h / 2, `${w}×${h}: the mesh beside the controls (left ${mesh.l} ≥ ${controls.r}), top at ${mesh.t}`);
      if (w === 1024) await page.screenshot({ path: join(out, "projector_1024x768.png") });
    }
    await page.setViewport({ width: 390, height: 844, deviceScaleFactor: 3, isMobile: true, hasTouch: true });
    await open(page);
    [mesh, controls] = [await box("#mesh"), await box("#controls")];
    check(mesh.b <= controls.t && mesh.t < 844 / 2, `phone 390×844: the mesh first (top ${mesh.t.toFixed(0)}, controls from ${controls.t.toFixed(0)})`);
    await page.screenshot({ path: join(out, "phone_390x844.png") });
    await page.setViewport({ width: 1366, height: 768, deviceScaleFactor: 1 });
    for (const q of ["?mag=3&eps=0.2&mu=0.3&load=1", "?mag=3&eps=0&mu=0&load=1&ratio=0.25", "?scene=pin_lug&mag=3"]) {
      await open(page, q);
      const log = await page.evaluate(() => window.__canvasLog("mesh"));
      check(log.x0 >= 0 && log.y0 >= 0 && log.x1 <= log.width && log.y1 <= log.height,
        `β = 3 (${q}): the deformed mesh lies inside its canvas (x ${log.x0.toFixed(0)}…${log.x1.toFixed(0)} of ${log.width}, ` +
        `y ${log.y0.toFixed(0)}…${log.y1.toFixed(0)} of ${log.height})`);
    }

    // --- shareable -----------------------------------------------------------------------------
  });
  await section("URL, reset, export", async () => {
    // Before: controls never reached the URL; ?scene=foo, ?N=64, ?mu=abc broke the page or were
    // silently changed.
    await open(page);
    await page.focus("#mu");
    before = await updates(page);
    await page.keyboard.press("ArrowRight");
    await updated(page, before);
    await page.select("#eps", "0.05");
    await page.waitForFunction(() => location.search.includes("eps=0.05"));
    const search = await page.evaluate(() => location.search);
    check(/mu=0.05/.test(search) && /eps=0.05/.test(search) && /load=1/.test(search) && /N=16/.test(search),
      `the URL holds the controls (${search})`);
    await open(page, search);
    check((await page.$eval("#mu", (e) => e.value)) === "0.05" && (await page.$eval("#eps", (e) => e.value)) === "0.05",
      "opening that URL restores μ and ε");
    for (const [q, key] of [["?scene=foo", "scene=foo"], ["?N=64", "N=64"], ["?mu=abc", "mu=abc"], ["?mu=0.33", "mu=0.33"],
      ["?scene=hertz&force=1e9", "force=1e9"], ["?bogus=1", "bogus"]]) {
      await open(page, q);
      const notes = await page.$eval("#url-notes", (p) => (p.hidden ? "" : p.textContent));
      const solved = await page.evaluate(() => !window.contact2dPage.error && window.contact2dPage.updates >= 1);
      check(notes.includes(key) && solved, `${q}: reported ("${notes.slice(0, 70)}…") and the page solved with defaults`);
    }
    await open(page, "?N=64");
    check((await page.$eval("#refinement", (e) => e.value)) === "16", "?N=64 is replaced by the default N = 16");
    await open(page, "?mu=0.4&eps=0.05&load=0.5");
    before = await updates(page);
    await page.click("#reset");
    await updated(page, before);
    check((await page.$eval("#mu", (e) => e.value)) === "0" && !(await page.evaluate(() => location.search)).includes("mu=0.4"),
      "reset returns the scene's controls to their defaults (and the URL with them)");
    const downloads = join(out, "downloads");
    rmSync(downloads, { recursive: true, force: true });
    mkdirSync(downloads, { recursive: true });
    const cdp = await page.createCDPSession();
    await cdp.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: downloads });
    await page.click("#export-csv");
    await page.click("#export-png");
    // Up to 15 s: the one-figure PNG is composed and encoded first (seconds on a loaded machine).
    for (let i = 0; i < 150 && readdirSync(downloads).filter((f) => !f.endsWith(".crdownload")).length < 2; i++) await sleep(100);
    const files = readdirSync(downloads);
    const csv = files.find((f) => f.endsWith(".csv"));
    const lCell = (await cell(page, "l")).value;
    check(csv && readFileSync(join(downloads, csv), "utf8").includes(`"contact end l","${lCell}"`)
      && files.some((f) => f.endsWith("_figure.png")),
    `export: ${files.join(", ")} (the CSV holds the table's exact l)`);
  });
  await section("file://", async () => {
    // Before: from file:// the page said "loading the solver…" forever.
    const local = await newPage(browser, []);
    await local.goto(pathToFileURL(join(process.env.PAGE_DIR || web, "index.html")).href, { waitUntil: "load" });
    const warning = await local.$eval("#file-warning", (p) => (p.hidden ? "" : p.textContent));
    check(warning.includes("python3 -m http.server"), "opened from file:// the page says how to serve it");
    await local.close();

    // --- a user's own scene ----------------------------------------------------------------------
  });
  await section("a user's scene", async () => {
    // Before: no way to solve a scene of one's own. The two blocks' scene and mesh chosen as files:
    // once the whole joint slips, Coulomb gives Στ = μ Σλ = 0.3 × 1000 (the press).
    await open(page, "?scene=user");
    const input = await page.$("#user-input");
    before = await updates(page);
    await input.uploadFile(join(web, "../scenes/generic/two_blocks_press_slide.toml"), join(web, "../meshes/generic/two_blocks.msh"));
    await updated(page, before);
    const tangential = Math.abs(Number((await cell(page, "tangential_force")).value));
    const normal = Number((await cell(page, "normal_force")).value);
    check(close(normal, 1000, 1e-8) && close(tangential, 300, 1e-8),
      `a user's scene: Σλ = ${normal}, Στ = ${tangential} = μ P (to 1e-8: a floating block, see wasm_matches_native.mjs)`);
    const bad = join(out, "bad_scene.toml");
    writeFileSync(bad, "name = \"bad\"\nmesh = \"x.msh\"\nplane = \"sideways\"\n");
    before = await updates(page);
    await input.uploadFile(bad, join(web, "../meshes/generic/two_blocks.msh"));
    await updated(page, before);
    const message = await page.$eval("#error", (p) => (p.hidden ? "" : p.textContent));
    check(message.includes("bad_scene.toml") && message.includes("sideways"), `a bad scene's message names file and value: "${message.slice(0, 90)}…"`);
    if (existsSync(bad)) rmSync(bad);
    // The CLI's limit on a scene file (1 MiB) and its message.
    const big = join(out, "big_scene.toml");
    writeFileSync(big, "#".repeat((1 << 20) + 1));
    before = await updates(page);
    await input.uploadFile(big, join(web, "../meshes/generic/two_blocks.msh"));
    await updated(page, before);
    const tooBig = await page.$eval("#error", (p) => (p.hidden ? "" : p.textContent));
    check(tooBig.includes("big_scene.toml") && tooBig.includes("1048577 bytes exceed the limit of 1048576 bytes"),
      `a scene over the CLI's 1 MiB: "${tooBig.slice(0, 100)}"`);
    rmSync(big);
  });
  check(errors.length === 0, `no console or page error${errors.length ? ": " + errors.join("; ") : ""}`);
} finally {
  await browser.close();
  server.kill();
}
if (failures.length) {
  console.error(`${failures.length} page checks failed`);
  process.exit(1);
}
console.log("page test: ok");
