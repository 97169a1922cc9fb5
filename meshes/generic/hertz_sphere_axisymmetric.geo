// hertz_sphere_axisymmetric.geo -- Hertz's sphere on a flat as bodies of revolution (x = r,
// y = z): the meridian section of a hemisphere of radius R (its flat equator on top, where the
// total force is applied) touching a cylindrical block of radius W and depth H at the origin.
//
//   C (0, R) ---(sphere_top)--- P1 (R, R)      sphere: r >= 0, r^2 + (z - R)^2 <= R^2, z <= R
//   |                       _.-'
// sphere_axis  sphere   _.-'  sphere_surface (quarter circle about C)
//   |              _.-'
//   P0 (0, 0) -'                                P0 and Q0 coincide; different nodes
//   Q0 (0, 0) ---------(block_top)--------- Q3 (W, 0)
//   |                                         |
// block_axis          block               block_side
//   |                                         |
//   Q1 (0, -H) -------(block_bottom)------- Q2 (W, -H)
//
// R = 10, W = H = 40 (about 40 a for the scene's a = 1.013). Grading: h = a / n_across within
// 1.25 a of the contact point, growing linearly to h_far at 15 (sphere and block alike).
// Element type by `kind`: 1 T3, 2 T6, 3 Q4, 4 Q8, 5 Q9 (order, recombination and incomplete
// second order set here; generate.sh passes no -order).
//
// Run:  gmsh hertz_sphere_axisymmetric.geo -2 -format msh41 -setnumber kind 5 -setnumber level 1 \
//         -o hertz_sphere_axisymmetric_Q9_L1.msh

Geometry.AutoCoherence = 0;

DefineConstant[
  kind = 5,         // 1 T3, 2 T6, 3 Q4, 4 Q8, 5 Q9
  level = 1,        // n_across = 6 * 2^(level - 1) cells across a (linear cells: twice as many)
  R = 10, W = 40, H = 40,
  a = 1.013,        // Hertz radius of the scene, for the grading only
  h_far = 4
];
quadratic = (kind == 2 || kind == 4 || kind == 5);
n_across = 6 * 2^(level - 1) * (quadratic ? 1 : 2);
h_contact = a / n_across;

Point(1) = {0, 0, 0};
Point(2) = {R, R, 0};
Point(3) = {0, R, 0};
Circle(1) = {1, 3, 2};      // sphere_surface, P0 -> P1
Line(2) = {2, 3};           // sphere_top
Line(3) = {3, 1};           // sphere_axis
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

Point(11) = {0, 0, 0};
Point(12) = {0, -H, 0};
Point(13) = {W, -H, 0};
Point(14) = {W, 0, 0};
Line(11) = {12, 13};        // block_bottom
Line(12) = {13, 14};        // block_side
Line(13) = {14, 11};        // block_top
Line(14) = {11, 12};        // block_axis
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};

Field[1] = Distance;
Field[1].PointsList = {1, 11};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_contact;
Field[2].SizeMax = h_far;
Field[2].DistMin = 1.25 * a;
Field[2].DistMax = 15;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Mesh.ElementOrder = quadratic ? 2 : 1;
Mesh.SecondOrderIncomplete = (kind == 4) ? 1 : 0;
If (kind >= 3)
  Mesh.Algorithm = 8;             // Frontal-Delaunay for quads
  Mesh.RecombinationAlgorithm = 3; // Blossom full-quad
  Mesh.RecombineAll = 1;
Else
  Mesh.Algorithm = 6;             // Frontal-Delaunay
  Mesh.RecombineAll = 0;
EndIf
Mesh.Smoothing = 1;

Physical Surface("sphere") = {1};
Physical Surface("block") = {2};
Physical Curve("sphere_surface") = {1};
Physical Curve("sphere_top") = {2};
Physical Curve("axis") = {3, 14};
Physical Curve("block_top") = {13};
Physical Curve("block_bottom") = {11};
Physical Curve("block_side") = {12};
