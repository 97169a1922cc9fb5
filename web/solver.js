// The solver's thread (worker.js) as the page's thread sees it: requests answered in order, each
// a promise; while one runs longer than 0.3 s the page shows the elapsed time and a Cancel
// button (#busy). Cancel = terminate the worker (a WebAssembly call cannot be interrupted) and
// start a new one; every request waiting is rejected with Cancelled.

const $ = (id) => document.getElementById(id);

/** A request that was cancelled (not a failure of the solve). */
export class Cancelled extends Error {}

/** The solver over `page` (the page's test state: solvesStarted, solveWindows): {start(),
 * solve(request) → {view, ms}, cancel()}. */
export function makeSolver(page) {
  const solver = { worker: null, pending: new Map(), next: 0 };

  function start() {
    solver.worker = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
    solver.worker.onmessage = ({ data }) => {
      const p = solver.pending.get(data.id);
      if (!p) return;
      p.arrived = performance.now();
      solver.pending.delete(data.id);
      if (data.error) p.reject(new Error(data.error)); else p.resolve(data);
    };
    solver.worker.onerror = (e) => {
      for (const p of solver.pending.values()) p.reject(new Error(`the solver's thread failed: ${e.message || e}`));
      solver.pending.clear();
    };
  }

  /** Sends one request to the worker; resolves to {view, ms}. */
  function solve(request) {
    page.solvesStarted += 1;
    const id = ++solver.next, t0 = performance.now();
    const busy = setInterval(() => {
      const s = (performance.now() - t0) / 1000;
      if (s < 0.3) return;
      $("busy").hidden = false;
      $("busy-time").textContent = `solving… ${s.toFixed(1)} s`;
    }, 100);
    const entry = {};
    return new Promise((resolve, reject) => {
      Object.assign(entry, { resolve, reject });
      solver.pending.set(id, entry);
      solver.worker.postMessage({ ...request, id });
    }).finally(() => {
      clearInterval(busy);
      if (!solver.pending.size) $("busy").hidden = true;
      // The solve's window ends when the worker's answer reaches this thread (its handling and
      // drawing follow, and are timed apart).
      page.solveWindows.push([t0, entry.arrived ?? performance.now()]);
    });
  }

  /** Terminates the worker and starts a new one; the requests waiting are rejected. */
  function cancel() {
    solver.worker.terminate();
    const waiting = [...solver.pending.values()];
    solver.pending.clear();
    start();
    for (const p of waiting) p.reject(new Cancelled("cancelled"));
  }

  return { start, solve, cancel };
}
