// The presentation export: "Figure (PNG)", "Figure (SVG)" (figure.js: one figure of what is
// shown) and "Numbers (CSV)" (the table, the profile chart's series and the whole run made: the
// loading history's (w, l, b) or the cycle's loop), each saved as a download.
import { chartCsv } from "./chart.js";
import { figureParts, figurePng, figureSvg } from "./figure.js";

const $ = (id) => document.getElementById(id);

/** Wires the export buttons to the page: ctx = {state, page, scenes} (app.js's state, its test
 * state and SCENES). */
export function installExport({ state, page, scenes }) {
  function download(name, blob) {
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = name;
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
  }

  /** The CSV: what is shown, the table, the profile chart's series, and the whole run when one
   * was made: the loading history's (w, l, b) or the cycle's (step, δ, Q) loop. */
  function exportCsv() {
    const rows = [...$("summary").tBodies[0].rows].map((r) => [r.cells[0].textContent, r.cells[1].dataset.value,
      r.cells[2].textContent]);
    const quote = (s) => `"${String(s).replaceAll('"', '""')}"`;
    const run = [];
    if (state.scene === "flagship" && state.history.length) {
      run.push(`${quote("loading history")}`, "w,l,b", ...state.history.map((h) => `${h.w},${h.l},${h.b}`), "");
    }
    if (state.scene === "cattaneo_mindlin" && page.cycle && state.player && state.player.kind === "cycle") {
      const v = page.cycle;
      run.push(`${quote("Mindlin–Deresiewicz cycle (the whole loop)")}`, "step,delta_mm,Q_N_per_mm",
        ...v.summary.steps.map((st, k) => `${k},${v.cycle_shear[k] * 0.01},${st.reactions.cylinder_top[0]}`), "");
    }
    const text = [`${quote("shows")},${quote($("table-caption").textContent)}`, `${quote("url")},${quote(location.href)}`, "",
      "quantity,live,published", ...rows.map((r) => r.map(quote).join(",")), "", chartCsv("profile"), ...run].join("\n");
    download(`contact2d_${state.scene}.csv`, new Blob([text], { type: "text/csv" }));
  }

  /** The figures shown, as one figure: title, key numbers, the mesh with its colour key, the
   * profile and (when shown) the history or loop chart, each with its legend. */
  function shownFigure() {
    const canvases = ["mesh", "profile", "history-plot"].map($).filter((c) => !c.closest("[hidden]") && c.width > 0);
    const numbers = [...$("summary").tBodies[0].rows].slice(0, 4).map((r) => `${r.cells[0].textContent} = ${r.cells[1].textContent}`);
    return figureParts({ title: `contact2d — ${scenes[state.scene].title}`, caption: $("table-caption").textContent,
      numbers, canvases });
  }

  function exportPng() {
    figurePng(shownFigure()).toBlob((png) => download(`contact2d_${state.scene}_figure.png`, png));
  }

  function exportSvg() {
    download(`contact2d_${state.scene}_figure.svg`, new Blob([figureSvg(shownFigure())], { type: "image/svg+xml" }));
  }

  $("export-png").addEventListener("click", exportPng);
  $("export-csv").addEventListener("click", exportCsv);
  $("export-svg").addEventListener("click", exportSvg);
}
