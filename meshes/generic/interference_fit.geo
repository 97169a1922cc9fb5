// interference_fit.geo -- a solid disk (radius a = 500 mm) shrunk into a ring (inner radius a,
// outer radius b = 1000 mm): a quarter model (x >= 0, y >= 0) with symmetry lines on both axes.
// The disk's rim and the ring's bore coincide geometrically; the interference is the scene's
// given gap (negative). Quad9 cells, structured in the ring, a quadrilateral O-grid in the disk.
//
//   y
//   |\__ ring_outer (r = b)
//   |   \__
//   | ring \            ring: a <= r <= b          disk: r <= a
//   |___    \           disk_rim and ring_bore: r = a (two curves, separate nodes)
//   |disk\   |          sym_x: the x = 0 lines of both bodies (u1 = 0)
//   |_____|__|___ x     sym_y: the y = 0 lines of both bodies (u2 = 0)
//
// Run:  gmsh interference_fit.geo -2 -order 2 -format msh41 -o interference_fit.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;

DefineConstant[ n_arc = 16, n_ring = 12, n_core = 6 ];

a = 500; b = 1000; c = 0.45 * a;   // c: half side of the disk's inner square

// Disk: an inner square [0, c]^2 and the ring between the square and the rim (O-grid).
Point(1) = {0, 0, 0};
Point(2) = {c, 0, 0};
Point(3) = {c, c, 0};
Point(4) = {0, c, 0};
Point(5) = {a, 0, 0};
Point(6) = {0, a, 0};
Point(7) = {a * Cos(Pi/4), a * Sin(Pi/4), 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {2, 5};
Circle(6) = {5, 1, 7};
Line(7) = {3, 7};
Circle(8) = {7, 1, 6};
Line(9) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, -7, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {7, 8, 9, -3};
Plane Surface(3) = {3};
Transfinite Curve{1, 3, 6, 8} = n_arc / 2 + 1;
Transfinite Curve{2, 4} = n_arc / 2 + 1;
Transfinite Curve{5, 7, 9} = n_core + 1;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};

// Ring: a <= r <= b, its own points on r = a.
Point(11) = {0, 0, 0};
Point(12) = {a, 0, 0};
Point(13) = {b, 0, 0};
Point(14) = {0, b, 0};
Point(15) = {0, a, 0};
Line(11) = {12, 13};
Circle(12) = {13, 11, 14};
Line(13) = {14, 15};
Circle(14) = {15, 11, 12};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Transfinite Curve{12, 14} = n_arc + 1;
Transfinite Curve{11, 13} = n_ring + 1;
Transfinite Surface{11};
Recombine Surface{11};

Physical Surface("disk") = {1, 2, 3};
Physical Surface("ring") = {11};
Physical Curve("disk_rim") = {6, 8};
Physical Curve("ring_bore") = {14};
Physical Curve("ring_outer") = {12};
Physical Curve("sym_x") = {4, 9, 13};
Physical Curve("sym_y") = {1, 5, 11};
