// pin_lug.geo -- a pin in the hole of a lug, with radial clearance; half model, symmetric about
// y = 0 (y >= 0).  The pin is pushed into the hole by a force on its back (pin_back).
//
//   y = 25  6 -----------------------(lug_top)------------------------------- 5
//           |                                                                  |
//           |                          _.--- 9 ---._   hole (r = 10)          |
//       lug_fixed         lug       .'   19 (120 deg)  `.                   lug_end
//           |                      /   .' pin (r = 9.9)  `.                    |
//           |                      |  /  pin_back   pin_contact \              |
//   y = 0   1 ---(symmetry)------- 2 20 --(sym)-- 21 --(sym)-- 18 3 ---(symmetry)--- 4
//          x=-40                 -10 -9.9          0          9.9 10                x=25
//
// Lug: [-40, 25] x [0, 25] minus the half disc r < 10 about the origin.  Pin: the half disc
// r <= 9.9 about the origin (radial clearance 0.1).  hole: the lug's arc (two curves, split at
// 120 deg); pin_contact: the pin's arc for 0 <= theta <= 120 deg; pin_back: 120..180 deg;
// pin_arc: both (the whole pin arc, 0..180 deg);
// symmetry: the y = 0 lines of BOTH bodies.  The bodies share no point (AutoCoherence = 0).
// Both arcs: n_contact elements over 0..120 deg, n_back over 120..180 deg (uniform in theta).
// Quadrangles everywhere (Frontal-Delaunay for quads + Blossom full-quad), sizes from the points.
//
// Run:  gmsh pin_lug.geo -2 -order 2 -format msh41 -o pin_lug.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  R_hole = 10,       // hole radius
  R_pin = 9.9,       // pin radius
  n_contact = 40,    // elements on each arc for 0 <= theta <= 120 deg (3 deg each)
  n_back = 10,       // elements on each arc for 120 <= theta <= 180 deg (6 deg each)
  h_lug = 4,         // element size at the lug's outer corners
  h_pin_centre = 2   // element size at the pin's centre
];
h_arc = R_hole * Pi * 2 / 3 / n_contact;
c120 = Cos(2 * Pi / 3);
s120 = Sin(2 * Pi / 3);

// lug
Point(1) = {-40, 0, 0, h_lug};
Point(2) = {-R_hole, 0, 0, h_arc};
Point(3) = {R_hole, 0, 0, h_arc};
Point(4) = {25, 0, 0, h_lug};
Point(5) = {25, 25, 0, h_lug};
Point(6) = {-40, 25, 0, h_lug};
Point(7) = {0, 0, 0};                          // hole centre (construction only)
Point(9) = {R_hole * c120, R_hole * s120, 0, h_arc};
Line(1) = {1, 2};                              // symmetry (lug, left of the hole)
Circle(2) = {2, 7, 9};                         // hole, 180 -> 120 deg
Circle(3) = {9, 7, 3};                         // hole, 120 -> 0 deg
Line(4) = {3, 4};                              // symmetry (lug, right of the hole)
Line(5) = {4, 5};                              // lug_end
Line(6) = {5, 6};                              // lug_top
Line(7) = {6, 1};                              // lug_fixed
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};         // counter-clockwise (the region is on the left)
Plane Surface(1) = {1};

// pin
Point(17) = {0, 0, 0};                         // pin centre (construction only)
Point(18) = {R_pin, 0, 0, h_arc};
Point(19) = {R_pin * c120, R_pin * s120, 0, h_arc};
Point(20) = {-R_pin, 0, 0, h_arc};
Point(21) = {0, 0, 0, h_pin_centre};           // on the pin's diameter
Circle(11) = {18, 17, 19};                     // pin_contact, 0 -> 120 deg
Circle(12) = {19, 17, 20};                     // pin_back, 120 -> 180 deg
Line(13) = {20, 21};                           // symmetry (pin)
Line(14) = {21, 18};                           // symmetry (pin)
Curve Loop(2) = {11, 12, 13, 14};              // counter-clockwise
Plane Surface(2) = {2};

Transfinite Curve{3, 11} = n_contact + 1;
Transfinite Curve{2, 12} = n_back + 1;

Mesh.Algorithm = 8;               // Frontal-Delaunay for quads
Mesh.RecombinationAlgorithm = 3;  // Blossom full-quad
Mesh.RecombineAll = 1;

Physical Surface("lug") = {1};
Physical Surface("pin") = {2};
Physical Curve("hole") = {2, 3};
Physical Curve("pin_contact") = {11};
Physical Curve("pin_back") = {12};
Physical Curve("pin_arc") = {11, 12};                 // the whole pin arc (a rigid pin as the slave)
Physical Curve("symmetry") = {1, 4, 13, 14};
Physical Curve("lug_fixed") = {7};
Physical Curve("lug_end") = {5};
Physical Curve("lug_top") = {6};
