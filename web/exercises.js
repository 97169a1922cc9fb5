// The classroom exercises of docs/teaching.md as predict-then-reveal steps: the page sets the
// exercise's start, the student commits to a prediction of how one number of the table moves
// under one change, and only then can reveal: the page makes the change, solves, and compares
// the number before and after (the solver decides, not a stored answer), then explains.
// installExercises wires the panel of index.html (#exercises) to the page through three hooks.

/** Each exercise: its tab (`scene`, the flagship when absent) and start values, the change made
 * on reveal, the table's key read before and after, the question and the explanation; an
 * exercise whose answer is not a number's trend gives its own `choices` and `classify(before,
 * after)` (the cells' values). */
export const EXERCISES = [
  {
    id: "friction", title: "1. Friction grows the stick zone",
    start: { mu: "0.1", ratio: "1", eps: "0", load: "1", variant: "hole_master", N: "16" }, change: { mu: "0.3" },
    key: "b", name: "the stick end b",
    question: "At μ = 0.1 a small stick zone (blue) sits at η = 0. Raise μ to 0.3: the stick end b …",
    explain: "More friction lets the shear q stay below μp over more of the interface, so more of it sticks " +
      "(the paper's b = 0.1485 at μ = 0.3).",
  },
  {
    id: "stiffness", title: "2. A stiffer insert shrinks the stick zone",
    start: { mu: "0.3", ratio: "1", eps: "0", load: "1", variant: "hole_master", N: "16" }, change: { ratio: "16" },
    key: "b", name: "the stick end b",
    question: "At μ = 0.3, make the insert 16 times stiffer than the plate (E2/E1 = 16): the stick end b …",
    explain: "An insert that hardly deforms cannot follow the plate's tangential displacement at the interface: " +
      "the bodies must slide over more of it, so the stick zone shrinks (b ≈ 0.03 on N = 16).",
  },
  {
    id: "clearance", title: "3. Clearance shortens the contact arc",
    start: { mu: "0.3", ratio: "1", eps: "0", load: "0.3838", variant: "hole_master", N: "16" }, change: { eps: "0.05" },
    key: "l", name: "the contact end l",
    question: "At μ = 0.3 and w = 0.3838, open a clearance ε = 0.05 (the paper's U(1)): the contact end l …",
    explain: "With a gap the plate must first close it and then touches the insert over a much shorter arc " +
      "(l from about 0.47 to about 0.15), which raises the stress concentration K.",
  },
  {
    id: "linear", title: "4. Without a gap, the load does not move the contact end",
    start: { mu: "0", ratio: "1", eps: "0", load: "0.5", variant: "hole_master", N: "16" }, change: { load: "1" },
    key: "l", name: "the contact end l",
    question: "No gap, no friction, w = 0.5. Double the load to w = 1: the contact end l …",
    explain: "Without a gap the problem is linear in w (spec §5.2): every displacement doubles, and so does " +
      "the pressure, but where it falls to zero does not move.",
  },
  {
    id: "partial_slip", scene: "cattaneo_mindlin", title: "5. Partial slip grows in from the edges",
    start: { press: "1", shear: "0.15", level: "L0" }, change: { shear: "0.45" },
    key: "c_over_a", name: "the stick half-width c/a",
    question: "The roller is pressed, then its top moved sideways a little: the middle sticks, the edges slip. " +
      "Move the top three times as far (shear 0.15 → 0.45, Q closer to μP): the stick half-width c/a …",
    explain: "Slip starts where the pressure, and so the friction limit μp, falls to zero: at the edges. As Q " +
      "approaches μP the slip zones grow inward and the stick zone shrinks, as Cattaneo and Mindlin's " +
      "c/a = √(1 − Q/(μP)) says (the table's closed-form row); at Q = μP nothing sticks.",
  },
  {
    id: "incline", scene: "incline_push", title: "6. A threshold from statics: the incline",
    start: { mu: "0.3", push: "0.35" }, change: { mu: "0.2" },
    key: "status", name: "the block",
    choices: [["holds", "still holds"], ["slides", "slides up the slope"]],
    // The solver's status decides: a converged run is an equilibrium (the block holds); any other
    // (not held: friction cannot hold it) is none.
    classify: (before, after) => (String(after).startsWith("converged") ? "holds" : "slides"),
    question: "On the incline (tan α = 0.1) at μ = 0.3 a horizontal push F/G = 0.35 leaves the block at rest. " +
      "Lower the friction to μ = 0.2 with the same push: the block …",
    explain: "Statics with Coulomb: pushed up the slope once F cos α − G sin α > μ (G cos α + F sin α), i.e. " +
      "F/G > (tan α + μ)/(1 − μ tan α): 0.412 at μ = 0.3 but 0.306 at μ = 0.2, below the push of 0.35. " +
      "Past it no equilibrium exists, and the solver says so.",
  },
];

export const CHOICES = [["grows", "grows"], ["stays", "stays the same"], ["shrinks", "shrinks"]];

/** How a number moved: "grows" / "shrinks" when it changed by more than 1e-6 relative (well
 * above the solver's round-off, well below the smallest change of the exercises, ~10 %), else
 * "stays". */
export function outcome(before, after) {
  const tol = 1e-6 * Math.max(Math.abs(before), Math.abs(after), 1e-12);
  return after > before + tol ? "grows" : after < before - tol ? "shrinks" : "stays";
}

const $ = (id) => document.getElementById(id);

/** Wires the exercises panel: `page` is the page's test state (page.exercise: {id, committed,
 * revealed}); hooks {open(ex): show the exercise's start, change(values): apply the change and
 * schedule its solve, solved(): resolves when the set-up on screen is solved}. */
export function installExercises(page, hooks) {
  let current = null;
  const open = (id) => {
    current = EXERCISES.find((e) => e.id === id);
    $("ex-question").textContent = current.question;
    $("ex-choices").replaceChildren(...(current.choices || CHOICES).map(([value, text]) => {
      const label = document.createElement("label");
      const input = Object.assign(document.createElement("input"), { type: "radio", name: "ex-choice", value });
      label.append(input, ` ${text}`);
      return label;
    }));
    $("ex-commit").disabled = false;
    $("ex-reveal").disabled = true;
    $("ex-answer").textContent = "";
    delete $("ex-answer").dataset.right;
    page.exercise = { id, committed: null, revealed: null };
    hooks.open(current);
  };
  const commit = () => {
    const chosen = document.querySelector('input[name="ex-choice"]:checked');
    if (!chosen) { $("ex-answer").textContent = "Choose a prediction first."; return; }
    document.querySelectorAll('input[name="ex-choice"]').forEach((i) => { i.disabled = true; });
    $("ex-commit").disabled = true;
    $("ex-reveal").disabled = false;
    $("ex-answer").textContent = "Prediction committed: now reveal.";
    page.exercise.committed = chosen.value;
  };
  const reveal = async () => {
    const ex = current;
    if (!ex || !page.exercise.committed) return;
    $("ex-reveal").disabled = true;
    await hooks.solved();
    const cell = () => document.querySelector(`td[data-key="${ex.key}"]`)?.dataset.value;
    const read = ex.classify ? cell : () => Number(cell());
    const before = read();
    hooks.change(ex.change);
    await hooks.solved();
    const after = read();
    const moved = (ex.classify || outcome)(before, after);
    const right = moved === page.exercise.committed;
    const said = Object.fromEntries(ex.choices || CHOICES)[moved];
    const shown = (v) => (typeof v === "number" ? v.toPrecision(4) : v);
    $("ex-answer").textContent = ex.classify
      ? `${right ? "Right" : "Not quite"}: ${ex.name} ${said} (the solver: ${after}). ${ex.explain}`
      : `${right ? "Right" : "Not quite"}: ${ex.name} went from ${shown(before)} to ${shown(after)}: it ${said}. ${ex.explain}`;
    $("ex-answer").dataset.right = right ? "1" : "0";
    page.exercise.revealed = { before, after, moved, right };
  };
  for (const ex of EXERCISES) $("ex-pick").add(new Option(ex.title, ex.id));
  $("ex-pick").addEventListener("change", () => open($("ex-pick").value));
  $("exercises").addEventListener("toggle", () => {
    $("exercises-toggle").textContent = $("exercises").open ? "Close the exercises" : "Exercises";
    if ($("exercises").open && !current) open($("ex-pick").value);
  });
  $("exercises-toggle").addEventListener("click", () => { $("exercises").open = !$("exercises").open; });
  $("ex-commit").addEventListener("click", commit);
  $("ex-reveal").addEventListener("click", reveal);
}
