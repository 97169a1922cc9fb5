// The page's set-up in its URL: ?scene=<id>&<key>=<value>... for every control of the scene
// (and the common ones). Reading checks each value against its control (a slider's range and
// step, a menu's options); a value that fails, or a key the scene does not have, is reported and
// replaced by the control's default, so a bad link opens the page with a message, never blank.

/** The checked value of `control` for the raw URL text, or a reason it is refused. */
export function checkValue(control, raw) {
  if (control.kind === "range") {
    const v = Number(raw);
    if (raw.trim() === "" || !Number.isFinite(v)) return { reason: `"${raw}" is not a number` };
    if (v < control.min - 1e-12 || v > control.max + 1e-12) {
      return { reason: `${raw} is outside ${control.min} … ${control.max}` };
    }
    const k = (v - control.min) / control.step;
    if (Math.abs(k - Math.round(k)) > 1e-6) return { reason: `${raw} is not on the slider's steps of ${control.step}` };
    return { value: String(+(control.min + Math.round(k) * control.step).toFixed(10)) };
  }
  if (control.kind === "select") {
    const options = control.options.map(([value]) => value);
    if (!options.includes(raw)) return { reason: `"${raw}" is not one of ${options.join(", ")}` };
    return { value: raw };
  }
  if (control.kind === "checkbox") {
    if (raw !== "0" && raw !== "1") return { reason: `"${raw}" is not 0 or 1` };
    return { value: raw };
  }
  return { reason: "not settable from the URL" };
}

/** Reads `search` (location.search): the scene (default `fallback`), each control's value (its
 * default when absent or refused), and one note per refused or unknown parameter. */
export function readUrl(search, scenes, common, fallback) {
  const q = new URLSearchParams(search);
  const notes = [];
  let scene = fallback;
  if (q.has("scene")) {
    const s = q.get("scene");
    // Own keys only: "__proto__", "constructor" … are no scenes.
    if (Object.hasOwn(scenes, s)) scene = s;
    else notes.push(`scene=${s}: no such scene (${Object.keys(scenes).join(", ")}); showing ${fallback}`);
  }
  const controls = [...scenes[scene].controls, ...common];
  const values = {};
  for (const c of controls) {
    values[c.key] = String(c.value);
    if (!q.has(c.key)) continue;
    const checked = checkValue(c, q.get(c.key));
    if (checked.reason) notes.push(`${c.key}=${q.get(c.key)}: ${checked.reason}; using ${c.value}`);
    else values[c.key] = checked.value;
  }
  for (const key of q.keys()) {
    if (key !== "scene" && !controls.some((c) => c.key === key)) {
      notes.push(`${key}: not a parameter of this scene (${controls.map((c) => c.key).join(", ")}); ignored`);
    }
  }
  return { scene, values, notes };
}

/** The query string of a scene and its controls' values. */
export function urlOf(scene, values) {
  const q = new URLSearchParams({ scene });
  for (const [k, v] of Object.entries(values)) q.set(k, v);
  return `?${q}`;
}
