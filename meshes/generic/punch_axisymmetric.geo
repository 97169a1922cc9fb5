// punch_axisymmetric.geo -- Boussinesq's rigid flat punch as a body of revolution (x = r, y = z):
// the meridian section of a flat-ended cylindrical punch of radius a (a region that is no body:
// the scene makes its face a rigid obstacle) on an elastic cylinder of radius and depth L (the
// half-space).
//
//   (0, a) ---------- (a, a)           punch: 0 <= r <= a, 0 <= z <= a (rigid, not meshed as a body)
//   |      punch       |
//   (0, 0) -punch_face- (a, 0)         punch_face: z = 0, 0 <= r <= a
//   (0, 0) ------------------block_top---------------- (L, 0)
//   |                                                    |
//  axis                    block                     block_side
//   |                                                    |
//   (0, -L) -----------------block_bottom-------------- (L, -L)
//
// a = 1, L = 50 (scale = 2: L = 100, the domain check). Grading: h = a / n_face within 0.1 a of the
// face's points (r <= a, z = 0), growing linearly to h_far = 8 / 2^(level - 1) (linear cells: half) at 30; h_face / 4 within 0.02 a of the
// edge (a, 0), growing to h_far at 0.5 a (the singular edge). block_top has a node at r = a.
// Element type by `kind`: 1 T3, 2 T6, 3 Q4, 4 Q8, 5 Q9.
//
// Run:  gmsh punch_axisymmetric.geo -2 -format msh41 -setnumber kind 5 -setnumber level 1 \
//         -o punch_axisymmetric_Q9_L1.msh

Geometry.AutoCoherence = 0;

DefineConstant[
  kind = 5,         // 1 T3, 2 T6, 3 Q4, 4 Q8, 5 Q9
  level = 1,        // n_face = 8 * 2^(level - 1) cells across a (linear cells: twice as many)
  a = 1, L0 = 50, scale = 1,
  h_far_1 = 8       // the far size of quadratic cells at level 1 (halved per level, linear cells half)
];
L = L0 * scale;
quadratic = (kind == 2 || kind == 4 || kind == 5);
n_face = 8 * 2^(level - 1) * (quadratic ? 1 : 2);
h_face = a / n_face;
h_far = h_far_1 / (2^(level - 1) * (quadratic ? 1 : 2));

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {a, a, 0};
Point(4) = {0, a, 0};
Line(1) = {1, 2};           // punch_face
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(11) = {0, 0, 0};
Point(12) = {0, -L, 0};
Point(13) = {L, -L, 0};
Point(14) = {L, 0, 0};
Point(15) = {a, 0, 0};      // under the punch's edge: a node of block_top there
Line(11) = {12, 13};        // block_bottom
Line(12) = {13, 14};        // block_side
Line(13) = {14, 15};        // block_top, outside the punch
Line(15) = {15, 11};        // block_top, under the punch
Line(14) = {11, 12};        // axis
Curve Loop(2) = {11, 12, 13, 15, 14};
Plane Surface(2) = {2};

Field[1] = Distance;
Field[1].CurvesList = {1};
Field[1].Sampling = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_face;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0.1 * a;
Field[2].DistMax = 30;
Field[3] = Distance;
Field[3].PointsList = {2, 15};
Field[4] = Threshold;
Field[4].InField = 3;
Field[4].SizeMin = h_face / 4;
Field[4].SizeMax = h_far;
Field[4].DistMin = 0.02 * a;
Field[4].DistMax = 0.5 * a;
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Mesh.ElementOrder = quadratic ? 2 : 1;
Mesh.SecondOrderIncomplete = (kind == 4) ? 1 : 0;
If (kind >= 3)
  Mesh.Algorithm = 8;
  Mesh.RecombinationAlgorithm = 3;
  Mesh.RecombineAll = 1;
Else
  Mesh.Algorithm = 6;
  Mesh.RecombineAll = 0;
EndIf
Mesh.Smoothing = 1;

Physical Surface("punch") = {1};
Physical Surface("block") = {2};
Physical Curve("punch_face") = {1};
Physical Curve("block_top") = {15, 13};
Physical Curve("block_bottom") = {11};
Physical Curve("block_side") = {12};
Physical Curve("axis") = {14};
