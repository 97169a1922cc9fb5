// Presentation export: the figures on screen as ONE figure, in PNG and SVG. The layout is
// computed once (figureParts) and drawn twice: on a canvas (PNG) and as SVG elements (the
// title, the key numbers and the mesh's colour key as SVG text and shapes; each chart drawn
// again by chart.js on an SVG-writing context (svgcontext.js): its series as <polyline>s and
// <path>s, its axes, ticks and legend as lines and <text>; the mesh embedded as the image it is
// on the page). Sizes are the canvases' device pixels, so the figure is as sharp as the screen
// it came from.
import { COLOURS, chart, lastCharts } from "./chart.js";
import { svgCanvas } from "./svgcontext.js";

// The mesh's colour key: the pairs' states as drawMesh colours them (chart.js COLOURS).
const KEY = [["stick", "stick"], ["slip+", "slip +x"], ["slip-", "slip −x"], ["contact", "contact (μ = 0)"], ["free", "free"]];

/** Lays out {title, caption, numbers: [text], canvases: [HTMLCanvasElement]} top to bottom:
 * the title, the caption (wrapped), the key numbers, each canvas (the mesh followed by its
 * colour key). Returns {width, height, items}: text {x, y, text, size, bold}, image {x, y, w,
 * h, canvas, vector (a chart's SVG markup, else null)}, dot {x, y, r, colour}. */
export function figureParts({ title, caption, numbers, canvases }) {
  const dpr = canvases.length ? canvases[0].width / Math.max(1, canvases[0].clientWidth) : 1;
  const width = Math.max(600 * dpr, ...canvases.map((c) => c.width));
  const pad = 12 * dpr, f = 16 * dpr;
  const ctx = document.createElement("canvas").getContext("2d");
  const items = [];
  let y = pad;
  const text = (t, size, bold = false, x = pad) => {
    ctx.font = `${bold ? "bold " : ""}${size}px sans-serif`;
    // Wrapped at the figure's width, word by word.
    let line = "";
    for (const word of String(t).split(" ")) {
      const next = line ? `${line} ${word}` : word;
      if (line && ctx.measureText(next).width > width - 2 * pad) {
        y += 1.3 * size; items.push({ type: "text", x, y, text: line, size, bold }); line = word;
      } else line = next;
    }
    if (line) { y += 1.3 * size; items.push({ type: "text", x, y, text: line, size, bold }); }
  };
  text(title, 1.4 * f, true);
  text(caption, f);
  if (numbers.length) text(numbers.join("   "), 1.2 * f, true);
  y += pad;
  for (const c of canvases) {
    // A chart: its last spec drawn again as SVG (vectors); the mesh: the canvas's image.
    let vector = null;
    if (lastCharts[c.id]) {
      const stand = svgCanvas(c);
      chart(stand, lastCharts[c.id]);
      vector = stand.svg();
    }
    items.push({ type: "image", x: 0, y, w: c.width, h: c.height, canvas: c, vector });
    y += c.height;
    if (c.id === "mesh") {
      ctx.font = `${f}px sans-serif`;
      let x = pad;
      y += 1.3 * f;
      for (const [state, name] of KEY) {
        items.push({ type: "dot", x: x + 0.4 * f, y: y - 0.35 * f, r: 0.35 * f, colour: COLOURS[state] });
        items.push({ type: "text", x: x + f, y, text: name, size: f, bold: false });
        x += f + ctx.measureText(name).width + 1.2 * f;
      }
      y += 0.5 * f;
    }
    y += pad;
  }
  return { width: Math.ceil(width), height: Math.ceil(y), items };
}

/** The figure drawn on a new canvas (white background): call toBlob on it for the PNG. */
export function figurePng(fig) {
  const canvas = document.createElement("canvas");
  canvas.width = fig.width;
  canvas.height = fig.height;
  const ctx = canvas.getContext("2d");
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, fig.width, fig.height);
  for (const it of fig.items) {
    if (it.type === "image") ctx.drawImage(it.canvas, it.x, it.y, it.w, it.h);
    else if (it.type === "dot") {
      ctx.fillStyle = it.colour; ctx.beginPath(); ctx.arc(it.x, it.y, it.r, 0, 2 * Math.PI); ctx.fill();
    } else {
      ctx.fillStyle = "#000"; ctx.font = `${it.bold ? "bold " : ""}${it.size}px sans-serif`; ctx.fillText(it.text, it.x, it.y);
    }
  }
  return canvas;
}

const esc = (t) => String(t).replaceAll("&", "&amp;").replaceAll("<", "&lt;").replaceAll(">", "&gt;").replaceAll('"', "&quot;");

/** The figure as an SVG document (text). */
export function figureSvg(fig) {
  const body = fig.items.map((it) => {
    if (it.type === "image" && it.vector !== null) return `<g transform="translate(${it.x} ${it.y})">\n${it.vector}\n</g>`;
    if (it.type === "image") {
      return `<image x="${it.x}" y="${it.y}" width="${it.w}" height="${it.h}" href="${it.canvas.toDataURL("image/png")}"/>`;
    }
    if (it.type === "dot") return `<circle cx="${it.x}" cy="${it.y}" r="${it.r}" fill="${it.colour}"/>`;
    return `<text x="${it.x}" y="${it.y}" font-family="sans-serif" font-size="${it.size}"` +
      `${it.bold ? ' font-weight="bold"' : ""}>${esc(it.text)}</text>`;
  });
  return `<svg xmlns="http://www.w3.org/2000/svg" width="${fig.width}" height="${fig.height}" ` +
    `viewBox="0 0 ${fig.width} ${fig.height}">\n<rect width="100%" height="100%" fill="#fff"/>\n${body.join("\n")}\n</svg>\n`;
}
