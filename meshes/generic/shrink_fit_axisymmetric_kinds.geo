// shrink_fit_axisymmetric_kinds.geo -- a solid shaft (radius b = 10 mm) shrunk into a hub (inner radius
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
// This file: the same fit for every element type on two levels, for
// tests/verification/verify_axisymmetric_shrink_fit.rs (the bundled scene's mesh is
// shrink_fit_axisymmetric.geo, Q9 8 x 8). Element type by `kind`: 1 T3, 2 T6, 3 Q4, 4 Q8, 5 Q9;
// `level` 1 or 2: n x n cells per body, n = 4 * level (quadratic) or 8 * level (linear).
//
// Run:  gmsh shrink_fit_axisymmetric_kinds.geo -2 -format msh41 -setnumber kind 3 -setnumber level 1 \
//         -o shrink_fit_axisymmetric_Q4_L1.msh   (meshes/generic/generate.sh)

Geometry.AutoCoherence = 0;

DefineConstant[ kind = 5, level = 1 ];
quadratic = (kind == 2 || kind == 4 || kind == 5);
n = (quadratic ? 4 : 8) * level;
n_shaft = n; n_hub = n; n_z = n;
Mesh.ElementOrder = quadratic ? 2 : 1;
Mesh.SecondOrderIncomplete = (kind == 4) ? 1 : 0;

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
If (kind >= 3)
  Recombine Surface{1, 2};
EndIf

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
