// press_fit.geo -- press-fit insertion (finite sliding): a plug of half-width a = 1 pushed along
// a slot whose wall (rigid) stands at y = a - delta, delta = 0.01, behind a rounded lead-in, for
// scenes/generic/press_fit.toml.  Half model about the plug's axis y = 0.  Structured Quad9.
//
//                          S (-1, 1.01)            wall_top                          (7, 1.24)
//                           \__ lead-in arc (R = 25.01, tangent to the wall at M)
//                              ''--..__ M (0, 0.99) ---------- wall_surface ------------ E (7, 0.99)
//   (-8.75, 1) ----------- plug_top ----------- (-0.75, 1)
//     |                    plug                   |          plug [-8.75, -0.75] x [0, 1]
//  plug_back                                   plug_tip      (the tip under the lead-in, whose
//     |                                           |           arc is 0.0012 above it there)
//   (-8.75, 0) ----------- plug_axis ---------- (-0.75, 0)   y = 0: the symmetry line
//
// The lead-in is the circular arc from S = (-ell, a + delta) to M = (0, a - delta), tangent to
// the flat wall at M: R = (ell^2 + 4 delta^2) / (4 delta) = 25.01 for ell = 1.  It closes the
// gap of the plug's top (y = a) from delta at S to -delta (the interference) at M gradually:
// y(x) = a - delta + R - sqrt(R^2 - x^2) ~ a - delta + x^2 / (2R).  wall_surface is the arc and
// the flat, one open curve from S to E (the slave of the contact).
//
// level 1: plug cells 0.25 x 0.25 (32 x 4), wall cells 0.125 on the arc (8) and 0.25 on the flat
// (28); level 2 halves every cell.  The bodies share no point, curve or node
// (Geometry.AutoCoherence = 0).
//
// Run:  gmsh press_fit.geo -2 -order 2 -format msh41 -setnumber level 1 -o press_fit_L1.msh
//       gmsh press_fit.geo -2 -order 2 -format msh41 -setnumber level 2 -o press_fit_L2.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  level = 1,      // mesh level: every cell count is multiplied by 2^(level - 1)
  a = 1,          // plug half-width
  delta = 0.01,   // interference per side (the wall stands at y = a - delta)
  ell = 1,        // lead-in length along x
  plug_back = -8.75, // the plug's back face (driven)
  plug_tip = -0.75, // the plug's tip, under the lead-in, 0.0012 below it (contact from the first step)
  wall_end = 7,   // the flat wall's end
  wall_t = 0.25   // the wall's thickness (a rigid obstacle: only its surface matters)
];

m = 2^(level - 1);
R = (ell^2 + 4 * delta^2) / (4 * delta);

// plug
Point(1) = {plug_back, 0, 0};
Point(2) = {plug_tip, 0, 0};
Point(3) = {plug_tip, a, 0};
Point(4) = {plug_back, a, 0};
Line(1) = {1, 2};   // plug_axis
Line(2) = {2, 3};   // plug_tip
Line(3) = {4, 3};   // plug_top, from the back to the tip
Line(4) = {1, 4};   // plug_back
Curve Loop(1) = {1, 2, -3, -4};
Plane Surface(1) = {1};

// wall: the lead-in arc S -> M, the flat M -> E, closed by its top
Point(11) = {-ell, a + delta, 0};          // S
Point(12) = {0, a - delta + R, 0};         // the arc's centre
Point(13) = {0, a - delta, 0};             // M
Point(14) = {wall_end, a - delta, 0};      // E
Point(15) = {wall_end, a - delta + wall_t, 0};
Point(16) = {0, a - delta + wall_t, 0};
Point(17) = {-ell, a - delta + wall_t, 0};
Circle(11) = {11, 12, 13};   // lead-in
Line(12) = {13, 14};         // flat wall
Line(13) = {14, 15};
Line(14) = {15, 16};
Line(15) = {16, 17};
Line(16) = {17, 11};
Line(17) = {13, 16};
Curve Loop(11) = {11, 17, 15, 16};
Plane Surface(11) = {11};
Curve Loop(12) = {12, 13, 14, -17};
Plane Surface(12) = {12};

Transfinite Curve{1, 3} = 32 * m + 1;
Transfinite Curve{2, 4} = 4 * m + 1;
Transfinite Curve{11, 15} = 8 * m + 1;
Transfinite Curve{12, 14} = 28 * m + 1;
Transfinite Curve{13, 16, 17} = 2;
Transfinite Surface{1, 11, 12};
Recombine Surface{1, 11, 12};

Physical Surface("plug") = {1};
Physical Surface("wall") = {11, 12};
Physical Curve("plug_axis") = {1};
Physical Curve("plug_tip") = {2};
Physical Curve("plug_top") = {3};
Physical Curve("plug_back") = {4};
Physical Curve("wall_surface") = {11, 12};
Physical Curve("wall_top") = {14, 15};
