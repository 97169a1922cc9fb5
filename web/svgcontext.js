// A 2D context that writes SVG: the subset of CanvasRenderingContext2D that chart.js draws with
// (paths of lines, quadratic curves, full-circle arcs and rectangles; stroke, fill, clip; text;
// save / restore; translate, rotate, setTransform; line dashes), each call turned into SVG
// elements in the canvas's device pixels. Running a chart's own drawing code on it gives the
// figure export (figure.js) the chart as vectors: a line is a <polyline>, a filled shape or a
// dotted series a <path>, text is <text>, with the chart's exact layout.
//
// svgCanvas(canvas) is a stand-in for a canvas (same id and sizes) whose getContext("2d")
// returns the recording context; svg() of that context is the drawing's markup.

const f = (v) => +v.toFixed(2);
const esc = (t) => String(t).replaceAll("&", "&amp;").replaceAll("<", "&lt;").replaceAll(">", "&gt;").replaceAll('"', "&quot;");
let clipIds = 0;

class SvgContext {
  constructor(canvas) {
    this.canvas = canvas;
    this.out = [];
    this.path = [];
    this.measurer = document.createElement("canvas").getContext("2d");
    this.s = { fillStyle: "#000", strokeStyle: "#000", lineWidth: 1, font: "10px sans-serif", dash: [], m: [1, 0, 0, 1, 0, 0],
      clip: null, textBaseline: "alphabetic" };
    this.stack = [];
    this.series = null;
  }

  // The state the canvas API exposes as properties.
  get fillStyle() { return this.s.fillStyle; } set fillStyle(v) { this.s.fillStyle = v; }
  get strokeStyle() { return this.s.strokeStyle; } set strokeStyle(v) { this.s.strokeStyle = v; }
  get lineWidth() { return this.s.lineWidth; } set lineWidth(v) { this.s.lineWidth = v; }
  get font() { return this.s.font; } set font(v) { this.s.font = v; }
  get textBaseline() { return this.s.textBaseline; } set textBaseline(v) { this.s.textBaseline = v; }

  save() { this.stack.push({ ...this.s, dash: [...this.s.dash], m: [...this.s.m] }); }
  restore() { if (this.stack.length) this.s = this.stack.pop(); }
  setTransform(a, b, c, d, e, g) { this.s.m = [a, b, c, d, e, g]; }
  getTransform() { const [a, b, c, d, e, g] = this.s.m; return { a, b, c, d, e, f: g }; }
  transform(a, b, c, d, e, g) {
    const [A, B, C, D, E, F] = this.s.m;
    this.s.m = [A * a + C * b, B * a + D * b, A * c + C * d, B * c + D * d, A * e + C * g + E, B * e + D * g + F];
  }
  translate(x, y) { this.transform(1, 0, 0, 1, x, y); }
  rotate(t) { this.transform(Math.cos(t), Math.sin(t), -Math.sin(t), Math.cos(t), 0, 0); }
  scale(x, y) { this.transform(x, 0, 0, y, 0, 0); }
  setLineDash(d) { this.s.dash = [...d]; }
  getLineDash() { return [...this.s.dash]; }
  measureText(t) { this.measurer.font = this.s.font; return this.measurer.measureText(t); }

  /** A point in device pixels. */
  at(x, y) { const [a, b, c, d, e, g] = this.s.m; return [f(a * x + c * y + e), f(b * x + d * y + g)]; }
  /** A length in device pixels (the transform's scale). */
  len(v) { return v * Math.hypot(this.s.m[0], this.s.m[1]); }

  beginPath() { this.path = []; }
  moveTo(x, y) { this.path.push(["M", ...this.at(x, y)]); }
  lineTo(x, y) { this.path.push(["L", ...this.at(x, y)]); }
  quadraticCurveTo(cx, cy, x, y) { this.path.push(["Q", ...this.at(cx, cy), ...this.at(x, y)]); }
  closePath() { this.path.push(["Z"]); }
  rect(x, y, w, h) {
    this.moveTo(x, y); this.lineTo(x + w, y); this.lineTo(x + w, y + h); this.lineTo(x, y + h); this.closePath();
  }
  /** Full circles only (the charts' points): two half-circle arcs. */
  arc(x, y, r) {
    const [cx, cy] = this.at(x, y), R = f(this.len(r));
    this.path.push(["M", f(cx + R), cy], ["A", R, R, 0, 1, 0, f(cx - R), cy], ["A", R, R, 0, 1, 0, f(cx + R), cy]);
  }
  d() { return this.path.map(([op, ...v]) => `${op}${v.join(" ")}`).join(""); }

  /** Starts the group of a chart's series (chart.js calls it, when present, before each). */
  svgSeries(label) {
    if (this.series !== null) this.out.push("</g>");
    this.series = label;
    if (label !== null) this.out.push(`<g class="series" data-series="${esc(label)}">`);
  }

  attrs() { return this.s.clip ? ` clip-path="url(#${this.s.clip})"` : ""; }
  dash() { return this.s.dash.length ? ` stroke-dasharray="${this.s.dash.map((v) => f(this.len(v))).join(" ")}"` : ""; }
  stroke() {
    if (!this.path.length) return;
    const width = ` stroke="${this.s.strokeStyle}" stroke-width="${f(this.len(this.s.lineWidth))}" fill="none"${this.dash()}${this.attrs()}`;
    const lines = this.path.every(([op], i) => (i === 0 ? op === "M" : op === "L"));
    this.out.push(lines
      ? `<polyline points="${this.path.map(([, x, y]) => `${x},${y}`).join(" ")}"${width}/>`
      : `<path d="${this.d()}"${width}/>`);
  }
  fill() { if (this.path.length) this.out.push(`<path d="${this.d()}" fill="${this.s.fillStyle}"${this.attrs()}/>`); }
  clip() {
    const id = `clip${++clipIds}`;
    this.out.push(`<clipPath id="${id}"><path d="${this.d()}"/></clipPath>`);
    this.s.clip = id;
  }
  strokeRect(x, y, w, h) { this.beginPath(); this.rect(x, y, w, h); this.stroke(); this.beginPath(); }
  fillRect(x, y, w, h) { this.beginPath(); this.rect(x, y, w, h); this.fill(); this.beginPath(); }
  clearRect() {}
  fillText(text, x, y) {
    const px = Number((/([\d.]+)px/.exec(this.s.font) || [0, 10])[1]);
    const bold = /bold/.test(this.s.font) ? ' font-weight="bold"' : "";
    const [a, b, c, d, e, g] = this.s.m;
    this.out.push(`<text transform="matrix(${[a, b, c, d, e, g].map(f).join(" ")})" x="${f(x)}" y="${f(y)}" ` +
      `font-family="sans-serif" font-size="${px}"${bold} fill="${this.s.fillStyle}"${this.attrs()}>${esc(text)}</text>`);
  }

  /** The drawing's SVG markup. */
  svg() { if (this.series !== null) this.svgSeries(null); return this.out.join("\n"); }
}

/** A stand-in for `canvas` (its id and sizes) whose 2D context records SVG. */
export function svgCanvas(canvas) {
  const ctx = { current: null };
  return {
    id: canvas.id, width: canvas.width, height: canvas.height, clientWidth: canvas.clientWidth,
    clientHeight: canvas.clientHeight,
    getContext() { ctx.current = ctx.current || new SvgContext(this); return ctx.current; },
    svg() { return ctx.current ? ctx.current.svg() : ""; },
  };
}
