// hills_nowell.geo -- the roller on a block of cattaneo_mindlin.geo (same geometry, same size
// field, same nodes level by level) with the block's two end faces in separate groups, so that a
// bulk stress can be imposed by displacing them apart (scenes/generic/hills_nowell.toml):
//
//        T1 (-R, R) ------------(cylinder_top)------------ T2 (R, R)
//            `-._          cylinder (lower half disk)          _.-'
//                `-._  cylinder_arc (radius R about (0, R)) _.-'
//                     `-------------- P0 (0, 0) ----------'
//   Q1 (-W, 0) -------------------(block_top)---------------------- Q2 (W, 0)
//   |                                block                             |
//   block_left                                                block_right
//   Q4 (-W, -H) ------------------(block_bottom)------------------- Q3 (W, -H)
//
// R = 50, W = 100, H = 100 (mm); graded for a = 0.5 mm exactly as cattaneo_mindlin.geo (its header
// says why a << R). Only the physical groups differ: block_side is split into block_left (x = -W)
// and block_right (x = W).
//
// Run:  gmsh hills_nowell.geo -2 -order 2 -format msh41 -setnumber level 2 -o hills_nowell_L2.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  level = 1, R = 50, W = 100, H = 100,
  a = 0.5,           // Hertz half-width, for the grading only
  h_far_1 = 10,      // element size far from the contact at level 1 (halved per level)
  alg = 8, rec = 3, smooth = 1
];
n_across = 8 * 2^(level - 1);
h_contact = a / n_across;
h_far = h_far_1 / 2^(level - 1);

// roller
Point(1) = {0, 0, 0};        // P0
Point(2) = {R, R, 0};        // T2
Point(3) = {0, R, 0};        // centre
Point(4) = {-R, R, 0};       // T1
Circle(1) = {4, 3, 1};       // T1 -> P0
Circle(2) = {1, 3, 2};       // P0 -> T2
Line(3) = {2, 4};            // cylinder_top, T2 -> T1
Curve Loop(1) = {1, 2, 3};   // counter-clockwise
Plane Surface(1) = {1};

// block
Point(11) = {-W, 0, 0};      // Q1
Point(12) = {-W, -H, 0};     // Q4
Point(13) = {W, -H, 0};      // Q3
Point(14) = {W, 0, 0};       // Q2
Point(15) = {0, 0, 0};       // the block's contact point
Line(11) = {12, 13};         // block_bottom
Line(12) = {13, 14};         // block_side (right)
Line(13) = {14, 15};         // block_top (right half)
Line(14) = {15, 11};         // block_top (left half)
Line(15) = {11, 12};         // block_side (left)
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};

Field[1] = Distance;
Field[1].PointsList = {1, 15};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_contact;
Field[2].SizeMax = h_far;
Field[2].DistMin = 1.25 * a;
Field[2].DistMax = 60;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Mesh.Algorithm = alg;
Mesh.RecombinationAlgorithm = rec;
Mesh.Smoothing = smooth;
Mesh.RecombineAll = 1;

Physical Surface("cylinder") = {1};
Physical Surface("block") = {2};
Physical Curve("cylinder_arc") = {1, 2};
Physical Curve("cylinder_top") = {3};
Physical Curve("block_top") = {13, 14};
Physical Curve("block_bottom") = {11};
Physical Curve("block_left") = {15};
Physical Curve("block_right") = {12};
