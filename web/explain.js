// The explanation panel: per scene, a sketch of the set-up, Coulomb's law, every symbol on the
// page, the materials and dimensions, and the caveats a lecturer should know. Plain HTML strings.

const COULOMB = `<h3>Coulomb's law at each pair</h3>
<p>p ≥ 0 is the contact pressure (positive in compression, and so plotted), q the shear (tangential traction), μ the friction coefficient.
Where the bodies touch, <b>|q| ≤ μ p</b>:</p>
<ul>
<li><span class="key stick">stick</span>: |q| &lt; μ p, no relative sliding;</li>
<li><span class="key slip">slip +x</span> <span class="key slipm">slip −x</span>: |q| = μ p, the surfaces slide,
q opposes the sliding. The sign is the global direction in which the surface carrying the dots (the pair's
master side) slides over the other body: red towards +x, orange towards −x (+y / −y where the surface is
steeper than 45°). Pushing a block towards +x shows “slip +x”.</li>
<li><span class="key free">free</span> (separation): a gap is open, p = q = 0;</li>
<li><span class="key contact">contact</span>: touching without friction (μ = 0): q = 0, nothing can stick.</li>
</ul>`;

// A small SVG sketch: shapes given as SVG elements inside a 320×150 box.
const sketch = (body, caption) => `<figure class="sketch"><svg viewBox="0 0 320 150" role="img"
  aria-label="${caption}" xmlns="http://www.w3.org/2000/svg">${body}</svg><figcaption>${caption}</figcaption></figure>`;
const arrow = (x1, y1, x2, y2) => `<line x1="${x1}" y1="${y1}" x2="${x2}" y2="${y2}" stroke="#d62728"
  stroke-width="3" marker-end="url(#head)"/>`;
const HEAD = `<defs><marker id="head" markerWidth="8" markerHeight="8" refX="6" refY="4" orient="auto">
  <path d="M0,0 L8,4 L0,8 z" fill="#d62728"/></marker></defs>`;
const GROUND = (x, y, w) => `<line x1="${x}" y1="${y}" x2="${x + w}" y2="${y}" stroke="#000" stroke-width="2"/>` +
  Array.from({ length: Math.floor(w / 12) }, (_, i) =>
    `<line x1="${x + 12 * i}" y1="${y}" x2="${x + 12 * i - 8}" y2="${y + 8}" stroke="#000"/>`).join("");

const GENERIC_SYMBOLS = `<h3>Symbols</h3><dl>
  <dt>p, q</dt><dd>the contact pressure and shear (tangential traction) along the interface's master curve, MPa</dd>
  <dt>s</dt><dd>arc length along the master curve, mm</dd>
  <dt>Σλ, Στ</dt><dd>the interface's total normal and tangential force, N per mm of thickness</dd>
  <dt>contact length, stick length</dt><dd>the length of the master curve in contact, and of it the length that sticks</dd>
  <dt>β</dt><dd>the drawing's displacement magnification (the drawing only)</dd></dl>`;

export const EXPLAIN = {
  flagship: `${sketch(`${HEAD}<rect x="20" y="20" width="270" height="110" fill="#eee" stroke="#555"/>
    <circle cx="110" cy="130" r="45" fill="#fff" stroke="#555"/><circle cx="110" cy="130" r="43" fill="#e7d8b8" stroke="#8a6d3b"/>
    <circle cx="110" cy="130" r="11" fill="#fff" stroke="#8a6d3b"/>${arrow(290, 75, 315, 75)}
    <text x="292" y="65" font-size="16">w</text><text x="30" y="40" font-size="15">plate E1</text>
    <text x="92" y="115" font-size="15">insert E2</text>`, "Upper half of a plate pulled by w at its right edge, an insert in its hole")}
  <h3>The set-up</h3>
  <p>A plate (width 2H, hole radius R) holds an elastic insert (outer radius R1 = R − ε R, clamped on its
  inner circle R2 = 0.25 R). The plate's right edge is pulled by the displacement w; the plate bears on the
  insert on the side away from the pull. Upper half modelled (symmetry). Non-dimensional units of the paper:
  R = 1, H = L1 = 2.5, L2 = 5, E1 = 1, ν1 = ν2 = 0.3, plane stress (Solodovnikov 1998).</p>
  ${COULOMB}
  <h3>Symbols</h3>
  <dl><dt>η = 1 − φ/π</dt><dd>position along the hole edge: η = 0 where the plate bears on the insert, η = 1 on the far side</dd>
  <dt>l</dt><dd>contact end: the contact arc is 0 ≤ η ≤ l</dd>
  <dt>b</dt><dd>stick end: pairs stick for η ≤ b and slip between b and l; shown as “—” at μ = 0 (nothing sticks)</dd>
  <dt>P</dt><dd>the pulling force on the right edge, per unit thickness</dd>
  <dt>Φ_E1, Φ_E2, Φ_f</dt><dd>strain energies of plate and insert, and the energy dissipated by friction</dd>
  <dt>σ*, H, K</dt><dd>σ* the largest hoop stress σφφ on the hole edge; K = H σ*/P the stress concentration factor</dd>
  <dt>ε, c, ω</dt><dd>the insert's clearance in the geometry (ε R) and in displacement units c = ω ε, ω = 20 (Table 2)</dd>
  <dt>β</dt><dd>the drawing's displacement magnification (the drawing only)</dd></dl>
  <h3>Caveats</h3>
  <ul><li><b>b depends on the load steps.</b> With clearance and friction the stick zone depends on the path:
  the page solves 3 equal steps (the paper's Table 2), the loading history k steps; at Table 2 U(1) this
  gives b ≈ 0.154 on N = 16 beside the paper's 0.1309 (its finer mesh and its own steps).</li>
  <li>The page's meshes (N = 16, 32) are coarser than the paper's: expect the N = 16/32 differences of
  docs/verification.md.</li>
  <li>Without clearance the solution is linear in w: l and b do not change with w.</li></ul>`,

  hertz: `${sketch(`${HEAD}<circle cx="160" cy="55" r="45" fill="#e7d8b8" stroke="#8a6d3b"/>
    <rect x="40" y="100" width="240" height="40" fill="#eee" stroke="#555"/>${arrow(160, 2, 160, 20)}
    <text x="168" y="16" font-size="16">F</text><text x="150" y="60" font-size="15">R</text>`,
    "A steel roller pressed on an aluminium block")}
  <h3>The set-up</h3>
  <p>NAFEMS benchmark (Code_Aster SSNP154): a roller of radius R = 50 mm, steel E = 210 GPa, ν = 0.3, pressed
  by a force F per mm of thickness onto an aluminium block, E = 70 GPa, ν = 0.3; plane strain, frictionless
  (μ = 0), half model. Mesh L1 (the coarsest; L2 takes over a second per solve in a browser).</p>
  ${COULOMB}
  <h3>Symbols</h3>
  <dl><dt>E*</dt><dd>[(1 − ν1²)/E1 + (1 − ν2²)/E2]⁻¹, the contact modulus</dd>
  <dt>a</dt><dd>the contact half-width: Hertz a = √(4 F R/(π E*)); FE: the computed contact length</dd>
  <dt>p0</dt><dd>the peak pressure 2F/(π a); p(x) = p0 √(1 − x²/a²)</dd></dl>
  <h3>Caveats</h3><ul><li>L1 resolves a to about one element; the finer meshes are verified in docs/verification.md.</li></ul>`,

  cattaneo_mindlin: `${sketch(`${HEAD}<circle cx="160" cy="55" r="45" fill="#e7d8b8" stroke="#8a6d3b"/>
    <rect x="40" y="100" width="240" height="40" fill="#eee" stroke="#555"/>${arrow(160, 2, 160, 20)}
    ${arrow(205, 20, 240, 20)}<text x="168" y="16" font-size="16">P</text><text x="244" y="24" font-size="16">Q</text>`,
    "A roller pressed (P) then pushed sideways (Q)")}
  <h3>The set-up</h3>
  <p>A steel roller R = 50 mm on a steel block (E = 210 GPa, ν = 0.3, plane strain, μ = 0.3, full model),
  mesh L0 (4 cells across a). Two steps: the roller's top is pressed down (P ≈ 450 N/mm at press 1), then moved
  sideways with the press held; P and Q are the measured reactions of the top.</p>
  ${COULOMB}
  <h3>Symbols</h3>
  <dl><dt>P, Q</dt><dd>normal and tangential force per mm of thickness</dd>
  <dt>a, p0</dt><dd>Hertz's half-width and peak pressure at the measured P</dd>
  <dt>c</dt><dd>the stick half-width: closed form c/a = √(1 − Q/(μP)); FE: stick length / contact length (≤ 1)</dd>
  <dt>q(x)</dt><dd>μ p0 [√(1 − x²/a²) − (c/a) √(1 − x²/c²)] (Cattaneo 1938, Mindlin 1949)</dd></dl>
  <h3>The Mindlin–Deresiewicz cycle</h3><p>The button moves the top to +A, back to −A and up to +A again
  (ten steps each way, the press held). After each reversal the shear must change by 2μp before a pair slips
  the other way, so reverse slip (orange) grows in from both edges while the middle sticks, and Q(δ) traces a
  hysteresis loop: by Masing's rule its unloading branch is the loading curve doubled and reflected, so
  Q(−A) = −Q(+A) and the loop closes at +A. Its area (shaded) is the energy friction dissipates per cycle.
  Below A = 0.615 (partial slip throughout) the loop is thin, 1–3 % of its box; the default A = 0.75 reaches
  full sliding at the ends of the stroke (gross slip) and the loop opens wide. The first loading 0 → +A is one
  load step (drawn grey).</p>
  <h3>Caveats</h3><ul><li>When Q reaches μP no pair sticks: the page says “full sliding”; moving further only adds slip.</li>
  <li>L0 places the stick ends to about one cell (a/4): c/a runs 0.03–0.09 below the closed form.</li></ul>`,

  pin_lug: `${sketch(`${HEAD}<rect x="60" y="20" width="240" height="120" fill="#eee" stroke="#555"/>
    <circle cx="130" cy="80" r="42" fill="#fff" stroke="#555"/><circle cx="130" cy="80" r="38" fill="#e7d8b8" stroke="#8a6d3b"/>
    ${arrow(60, 80, 100, 80)}<text x="66" y="72" font-size="16">F</text>`, "A pin pushed through the hole of a lug")}
  <h3>The set-up</h3><p>A steel pin (E = 210 GPa, ν = 0.3, radius 9.9 mm) in the 10 mm hole of an aluminium lug
  (E = 70 GPa, ν = 0.33): radial clearance 0.1 mm, plane stress, half model, 4 load steps
  (scenes/generic/pin_lug.toml on the coarser mesh pin_lug_L1.msh). The pin is held only by the contact: it
  crosses the clearance, then bears on the hole.</p>${COULOMB}
  ${GENERIC_SYMBOLS}<dl><dt>F</dt><dd>force on the half model's pin, N per mm of thickness</dd></dl>
  <h3>Caveats</h3><ul><li>The stick zone depends on the 4 load steps (friction is path-dependent).</li></ul>`,

  interference_fit: `${sketch(`<circle cx="160" cy="150" r="130" fill="#eee" stroke="#555"/>
    <circle cx="160" cy="150" r="66" fill="#e7d8b8" stroke="#8a6d3b"/><text x="150" y="120" font-size="15">disk a</text>
    <text x="210" y="60" font-size="15">ring b</text>`, "A disk shrunk into a ring (quarter model)")}
  <h3>The set-up</h3><p>A solid disk a = 500 mm shrunk into a ring b = 1000 mm of the same steel (E = 200 GPa,
  ν = 0.3), radial interference δ (a negative gap), plane stress, quarter model. Lamé's closed form:
  p = E δ (b² − a²)/(2 a b²) (100 MPa at δ = 0.6667 mm).</p>${COULOMB}
  ${GENERIC_SYMBOLS}<dl><dt>δ</dt><dd>radial interference, mm (the contact's gap is −δ)</dd>
  <dt>a, b</dt><dd>the disk's radius and the ring's outer radius</dd></dl>
  <h3>Caveats</h3><ul><li>Friction hardly matters here: the fit is axisymmetric, there is almost no sliding.</li></ul>`,

  incline_push: `${sketch(`${HEAD}<polygon points="20,140 300,140 300,112" fill="#ddd" stroke="#000"/>
    <polygon points="120,124 200,116 203,96 123,104" fill="#e7d8b8" stroke="#8a6d3b"/>${arrow(80, 110, 118, 110)}
    <text x="84" y="102" font-size="16">F</text>`, "An elastic block on a rigid incline, pushed up the slope")}
  <h3>The set-up</h3><p>A rubber-like block (40 × 10 mm, E = 10 MPa, ν = 0.3, plane strain) under its weight G
  rests on a rigid incline tan α = 0.1 and is pushed horizontally by F. Two load steps: the weight, then the
  push. Statics with Coulomb: the block slides up when F/G ≥ (tan α + μ)/(1 − μ tan α) (0.4124 at μ = 0.3).</p>
  ${COULOMB}${GENERIC_SYMBOLS}<dl><dt>F/G</dt><dd>the push over the block's weight</dd>
  <dt>α</dt><dd>the incline's angle, tan α = 0.1</dd></dl><h3>Caveats</h3><ul><li>Past the threshold no equilibrium exists: the solve cannot converge — that is
  the physics, and the page says so.</li><li>The scene file climbs in 9 steps; the page's 2 steps give the
  same answer while the push grows monotonically, up to the path-dependence of partial slip.</li></ul>`,

  two_blocks_press_slide: `${sketch(`${HEAD}<rect x="40" y="90" width="240" height="50" fill="#eee" stroke="#555"/>
    <rect x="100" y="40" width="120" height="50" fill="#e7d8b8" stroke="#8a6d3b"/>${arrow(160, 5, 160, 36)}
    ${arrow(222, 45, 262, 45)}`, "A block pressed on another, then slid")}
  <h3>The set-up</h3><p>Two steel blocks (E = 200 GPa, ν = 0.3, plane strain): the upper one is pressed with
  P = 1000 N/mm, then its top is moved sideways while the force is held. Once the whole interface slips the
  tangential force is μ P (300 N/mm at μ = 0.3).</p>${COULOMB}${GENERIC_SYMBOLS}<dl>
  <dt>P</dt><dd>the press, 1000 N per mm of thickness</dd><dt>slide</dt><dd>the top's sideways displacement, in units of 0.01 mm</dd></dl>
  <h3>Caveats</h3><ul><li>The upper block is held in x2 only by the contact (a floating body).</li></ul>`,

  ball_on_plate: `${sketch(`${HEAD}<circle cx="160" cy="55" r="45" fill="#e7d8b8" stroke="#8a6d3b"/>
    <rect x="40" y="100" width="240" height="40" fill="#eee" stroke="#555"/>${arrow(160, 0, 160, 12)}
    <line x1="160" y1="5" x2="160" y2="140" stroke="#000" stroke-dasharray="4 3"/>`,
    "A ball pressed on a plate: a body of revolution about the dashed axis")}
  <h3>The set-up</h3><p>A steel ball (R = 10 mm, E1 = 210 GPa) pressed by a total force P on an aluminium
  plate (20 mm radius, 20 mm deep, E2 = 70 GPa), ν = 0.3 both, its bottom held. Solved as a body of revolution
  (<code>kinematics = "axisymmetric"</code>: x is the radius r, y the axis z; the drawing is the section r ≥ 0,
  the axis on the left): each element stands for the ring it sweeps, P is the total force over the
  circumference, and the pressure is per unit area. Hertz's sphere: E* = [(1 − ν1²)/E1 + (1 − ν2²)/E2]⁻¹,
  a = (3PR/(4E*))^(1/3), p0 = 3P/(2πa²), p(r) = p0 √(1 − r²/a²): the contact radius grows as P^(1/3), not as
  the roller's half-width √F of the plane Hertz tab.</p>${COULOMB}<h3>Symbols</h3><dl><dt>Σλ</dt><dd>the contact's
  total normal force, N (over the whole circumference: it equals P)</dd><dt>r</dt><dd>distance from the
  axis, mm</dd><dt>a</dt><dd>contact radius; the computed one is r = R sin(s/R) of the contact's arc s on the
  ball</dd><dt>p0</dt><dd>the peak pressure, on the axis</dd></dl>
  <h3>Caveats</h3><ul><li>The mesh is small (8 elements across a at P = 5 kN) so that the page solves it at
  once; the contact edge is placed to about a node's spacing (0.05 mm).</li><li>Hertz is frictionless; with
  μ &gt; 0 the dissimilar materials make the surfaces slip against each other and the pressure changes a
  little (about 2 % at μ = 0.2, P = 10 kN).</li><li>The ball is held only by the contact (its one rigid motion,
  along the axis).</li></ul>`,

  user: `<h3>Your own scene</h3><p>Choose or drop a generic scene file (.toml, as <code>contact2d run</code>
  reads it, see docs/user-guide.md) together with its Gmsh mesh (.msh). It is solved here, in this browser: nothing
  leaves the machine. The scene's <code>mesh</code> key is replaced by the file you give. The CLI's limits hold:
  a scene of at most 1 MiB of UTF-8, a mesh of at most 1 GiB (a browser will run out of memory long before), and
  errors carry the CLI's messages. A large mesh takes as long as it takes: the page stays busy until it is solved.</p>
  ${COULOMB}${GENERIC_SYMBOLS}`,
};
