// shrink_fit_axisymmetric.geo -- a solid shaft (radius b = 10 mm) shrunk into a hub (inner radius
// b, outer radius c = 20 mm), both of length L = 10 mm: the meridian section of a body of
// revolution (x = r, y = z). The shaft's rim and the hub's bore coincide geometrically (two
// curves, separate nodes); the interference is the scene's given gap (negative). Quad9 cells,
// structured.
//
//   z
//   |  shaft_top  hub_top
//   +-------+---------+ L      shaft: 0 <= r <= b     hub: b <= r <= c
//   |       |         |        axis: r = 0 (the shaft's left side)
//   | shaft |   hub   |        shaft_rim and hub_bore: r = b
//   |       |         |        hub_outer: r = c
//   +-------+---------+--> r
//   0  shaft_bottom  hub_bottom
//
// Run:  gmsh shrink_fit_axisymmetric.geo -2 -order 2 -format msh41 -o shrink_fit_axisymmetric.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;

DefineConstant[ n_shaft = 8, n_hub = 8, n_z = 8 ];

b = 10; c = 20; L = 10;

Point(1) = {0, 0, 0};
Point(2) = {b, 0, 0};
Point(3) = {b, L, 0};
Point(4) = {0, L, 0};
Point(5) = {b, 0, 0};
Point(6) = {c, 0, 0};
Point(7) = {c, L, 0};
Point(8) = {b, L, 0};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};

Transfinite Curve{1, 3} = n_shaft + 1;
Transfinite Curve{5, 7} = n_hub + 1;
Transfinite Curve{2, 4, 6, 8} = n_z + 1;
Transfinite Surface{1};
Transfinite Surface{2};
Recombine Surface{1, 2};

Physical Surface("shaft") = {1};
Physical Surface("hub") = {2};
Physical Curve("shaft_bottom") = {1};
Physical Curve("shaft_rim") = {2};
Physical Curve("shaft_top") = {3};
Physical Curve("axis") = {4};
Physical Curve("hub_bottom") = {5};
Physical Curve("hub_outer") = {6};
Physical Curve("hub_top") = {7};
Physical Curve("hub_bore") = {8};
