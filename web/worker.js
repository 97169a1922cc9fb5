// The solver's thread: the WebAssembly module loaded in a Web Worker, so that a long solve never
// blocks the page (drawing, sliders, the cancel button). One request at a time, in order:
//   {id, kind: "scene", scene, values, steps?}   a scene's solve for the controls' values
//   {id, kind: "cycle", values}                  the Mindlin–Deresiewicz cycle
//   {id, kind: "user", files}                    a user's scene (bytes)
// answered with {id, view, ms} or {id, error}. Cancelling is the page terminating this worker
// and starting a new one (a WebAssembly call cannot be interrupted from outside).
import init from "./pkg/contact2d_web.js";
import { PAPER_SCENES } from "./scenes_paper.js";
import { GENERIC_SCENES, solveUser } from "./scenes_generic.js";
import { solveCycle } from "./cycle.js";

const SCENES = { ...PAPER_SCENES, ...GENERIC_SCENES };
const ready = init();

self.onmessage = async ({ data }) => {
  try {
    await ready;
    const t0 = performance.now();
    let view;
    if (data.kind === "user") view = solveUser(data.files);
    else if (data.kind === "cycle") view = solveCycle(data.values);
    else view = SCENES[data.scene].solve(data.values, data.steps);
    self.postMessage({ id: data.id, view, ms: performance.now() - t0 });
  } catch (e) {
    self.postMessage({ id: data.id, error: String(e.message || e) });
  }
};
