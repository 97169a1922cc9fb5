// What the browser tests share: a static server for web/ (python3 -m http.server, the documented
// way), headless Chromium through puppeteer-core, pass/fail bookkeeping, and an instrument loaded
// into every page before the page's own code that records, independently of the page, what is
// drawn on each canvas: every text (its font size in CSS px and its box in device pixels) and
// the extent of every path point, reset whenever the canvas is cleared.
import { spawn } from "node:child_process";
import { fileURLToPath } from "node:url";
import { dirname, join } from "node:path";
import puppeteer from "puppeteer-core";

export const here = dirname(fileURLToPath(import.meta.url));
export const web = join(here, "..");
export const out = join(web, "out");

export const failures = [];
export const check = (ok, what) => {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures.push(what);
};

/** Serves web/ (or PAGE_DIR: another copy of the page, e.g. the one before issue 24, to see
 * the defect tests fail on it). */
export async function serve() {
  const root = process.env.PAGE_DIR || web;
  const port = 8000 + Math.floor(Math.random() * 1000);
  const server = spawn("python3", ["-m", "http.server", String(port), "--bind", "127.0.0.1", "--directory", root], {
    stdio: "ignore",
  });
  const base = `http://127.0.0.1:${port}`;
  for (let i = 0; i < 50; i++) {
    try { if ((await fetch(`${base}/index.html`)).ok) break; } catch { /* not up yet */ }
    await new Promise((r) => setTimeout(r, 100));
  }
  return { base, server };
}

export function launch() {
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"],
  });
}

// Runs in the page before its scripts: wraps the 2D context's drawing calls.
function instrument() {
  const P = CanvasRenderingContext2D.prototype;
  const logs = new Map();
  const log = (ctx) => {
    if (!logs.has(ctx.canvas)) logs.set(ctx.canvas, { texts: [], x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity });
    return logs.get(ctx.canvas);
  };
  const clear = P.clearRect;
  P.clearRect = function (x, y, w, h) {
    const t = this.getTransform();
    if (x <= 0 && y <= 0 && w * t.a >= this.canvas.width && h * t.d >= this.canvas.height) logs.delete(this.canvas);
    return clear.call(this, x, y, w, h);
  };
  const fill = P.fillText;
  P.fillText = function (text, x, y, ...rest) {
    const t = this.getTransform();
    const m = this.measureText(text);
    const px = Number((/([\d.]+)px/.exec(this.font) || [0, 0])[1]);
    const cssPerDevice = this.canvas.clientWidth / this.canvas.width;
    // The box in device pixels (axis-aligned for unrotated text; rotated text by its corners).
    const corners = [[x, y - m.actualBoundingBoxAscent], [x + m.width, y + m.actualBoundingBoxDescent]]
      .map(([u, v]) => [t.a * u + t.c * v + t.e, t.b * u + t.d * v + t.f]);
    const scale = Math.hypot(t.a, t.b);
    log(this).texts.push({
      text: String(text), css_px: px * scale * cssPerDevice,
      box: [Math.min(corners[0][0], corners[1][0]), Math.min(corners[0][1], corners[1][1]),
        Math.max(corners[0][0], corners[1][0]), Math.max(corners[0][1], corners[1][1])],
    });
    return fill.call(this, text, x, y, ...rest);
  };
  for (const name of ["moveTo", "lineTo", "quadraticCurveTo", "arc"]) {
    const original = P[name];
    P[name] = function (...args) {
      if (this.canvas.id === "mesh") {
        const t = this.getTransform(), l = log(this);
        const points = name === "quadraticCurveTo" ? [[args[2], args[3]]] : [[args[0], args[1]]];
        for (const [u, v] of points) {
          const X = t.a * u + t.c * v + t.e, Y = t.b * u + t.d * v + t.f;
          l.x0 = Math.min(l.x0, X); l.x1 = Math.max(l.x1, X); l.y0 = Math.min(l.y0, Y); l.y1 = Math.max(l.y1, Y);
        }
      }
      return original.apply(this, args);
    };
  }
  window.__canvasLog = (id) => {
    const c = document.getElementById(id);
    const l = logs.get(c);
    return l ? { ...l, width: c.width, height: c.height, clientWidth: c.clientWidth } : null;
  };
}

export async function newPage(browser, errors, viewport = { width: 1366, height: 768 }) {
  const page = await browser.newPage();
  await page.setViewport(viewport);
  await page.evaluateOnNewDocument(instrument);
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("pageerror", (e) => errors.push(String(e)));
  return page;
}

/** Waits until the page has made `n` more updates than `before`. */
export const updated = (page, before, timeout = 60000) =>
  page.waitForFunction((k) => window.contact2dPage.updates > k, { timeout }, before);

export const updates = (page) => page.evaluate(() => window.contact2dPage.updates);

/** Two boxes [x0, y0, x1, y1] overlap (by more than a pixel). */
export const overlap = (a, b) => a[0] < b[2] - 1 && b[0] < a[2] - 1 && a[1] < b[3] - 1 && b[1] < a[3] - 1;
