// moving_roller.geo -- the moving roller of finite sliding: an elastic roller (the lower half
// disc of radius R) pressed onto a long block and driven along it, full model, plane strain
// (scenes/generic/moving_roller.toml).
//
//                 Tl (-R, R) ------------(roller_top)------------ Tr (R, R)
//                   \                       C (0, R)                /
//            roller_arc                      roller              roller_arc
//                      `-._                                   _.-'
//                          Pl --- P0 (0, 0) --- Pr           the bottom arc: n_margin cells
//                                                              of arc length h on each side
//   TL -------------- A ============(path)============= B -------------- TR      y = 0
//   |                 xl      the roller travels 0 -> D   xr                |  block_top = the
// block_sides                        block                          block_sides  three lines
//   |                                                                        |
//   BL -----------------------------(block_bottom)-------------------------- BR   y = -H
//   x = xl - W                                                          x = xr + W
//
// h = a / n_across is the cell length along the path (n_across = 8 * 2^(level - 1) cells across
// the Hertz half-width a = 3 mm the scene's press gives: a/R = 0.06); the path [xl, xr] =
// [-n_margin h, D + n_margin h] is a uniform line of 2 n_margin + n_travel cells, n_margin =
// ceil(1.25 n_across) (the contact of half-width a stays inside it), D = n_travel h the travel,
// n_travel = travel * n_across (travel = 0.5: the roller moves by a/2, 16 cells on level 3). The
// roller's bottom arc (Pl..Pr, through P0) has n_margin cells of arc length h on each side of P0,
// so that at the start its nodes face the block's (P0 on the block node at x = 0).
// P0 and the block's node at the origin are DIFFERENT nodes (Geometry.AutoCoherence = 0): the two
// bodies are separate meshes that touch geometrically.
//
// Grading: quadrangles (Frontal-Delaunay for quads + Blossom full-quad recombination) under a size
// field, one per body: h within 1.25 a of the path (block) or of the bottom arc (roller), growing
// linearly to h_far = h_far_1 / 2^(level - 1) at 60 mm, as meshes/generic/cylinder_on_block.geo
// (h_far_1 = 40: 10 mm on level 3, the far field no finer than cylinder_on_block_L1's).
// The block reaches W = 100 mm beyond the path on either side and is H = 100 mm deep (the
// cylinder_on_block block of the full model is 200 x 100 around the contact).
//
// Run:  gmsh moving_roller.geo -2 -order 2 -format msh41 -o moving_roller.msh   (level 3)

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  level = 3,        // 8 * 2^(level - 1) cells across a along the path
  R = 50,           // roller radius
  a = 3,            // Hertz half-width (grading and the path only)
  travel = 0.5,     // the travel D in units of a (a whole number of cells: travel * n_across)
  W = 100,          // the block beyond the path, on either side
  H = 100,          // depth of the block
  h_far_1 = 40,     // element size far from the contact at level 1 (halved per level)
  alg = 8, rec = 3, smooth = 1   // Frontal-Delaunay for quads, Blossom full-quad, 1 smoothing pass
];
n_across = 8 * 2^(level - 1);
h = a / n_across;
h_far = h_far_1 / 2^(level - 1);
n_margin = Ceil(1.25 * n_across);
n_travel = travel * n_across;
D = n_travel * h;
xl = -n_margin * h;
xr = D + n_margin * h;
theta = n_margin * h / R;         // the bottom arc's half angle: arc length n_margin h

// roller
Point(1) = {0, R, 0};                                   // C, centre
Point(2) = {-R, R, 0};                                  // Tl
Point(3) = {-R * Sin(theta), R - R * Cos(theta), 0};    // Pl
Point(4) = {0, 0, 0};                                   // P0, contact point
Point(5) = {R * Sin(theta), R - R * Cos(theta), 0};     // Pr
Point(6) = {R, R, 0};                                   // Tr
Circle(1) = {2, 1, 3};      // roller_arc, left side
Circle(2) = {3, 1, 4};      // roller_arc, bottom left
Circle(3) = {4, 1, 5};      // roller_arc, bottom right
Circle(4) = {5, 1, 6};      // roller_arc, right side
Line(5) = {6, 2};           // roller_top
Curve Loop(1) = {1, 2, 3, 4, 5};   // counter-clockwise
Plane Surface(1) = {1};
Transfinite Curve{2, 3} = n_margin + 1;

// block
Point(11) = {xl - W, -H, 0};   // BL
Point(12) = {xr + W, -H, 0};   // BR
Point(13) = {xr + W, 0, 0};    // TR
Point(14) = {xr, 0, 0};        // B
Point(15) = {xl, 0, 0};        // A
Point(16) = {xl - W, 0, 0};    // TL
Line(11) = {11, 12};        // block_bottom
Line(12) = {12, 13};        // block_sides (right)
Line(13) = {13, 14};        // block_top, right of the path
Line(14) = {14, 15};        // block_top, the path
Line(15) = {15, 16};        // block_top, left of the path
Line(16) = {16, 11};        // block_sides (left)
Curve Loop(2) = {11, 12, 13, 14, 15, 16};
Plane Surface(2) = {2};
Transfinite Curve{14} = 2 * n_margin + n_travel + 1;

// size fields: fine along the path (block) and the bottom arc (roller), coarse away
Field[1] = Distance;
Field[1].CurvesList = {14};
Field[1].Sampling = 20 * (2 * n_margin + n_travel);
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = h_far;
Field[2].DistMin = 1.25 * a;
Field[2].DistMax = 60;
Field[3] = Restrict;
Field[3].InField = 2;
Field[3].SurfacesList = {2};
Field[3].CurvesList = {11, 12, 13, 14, 15, 16};
Field[4] = Distance;
Field[4].CurvesList = {2, 3};
Field[4].Sampling = 40 * n_margin;
Field[5] = Threshold;
Field[5].InField = 4;
Field[5].SizeMin = h;
Field[5].SizeMax = h_far;
Field[5].DistMin = 1.25 * a;
Field[5].DistMax = 60;
Field[6] = Restrict;
Field[6].InField = 5;
Field[6].SurfacesList = {1};
Field[6].CurvesList = {1, 2, 3, 4, 5};
Field[7] = Min;
Field[7].FieldsList = {3, 6};
Background Field = 7;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Mesh.Algorithm = alg;
Mesh.RecombinationAlgorithm = rec;
Mesh.Smoothing = smooth;
Mesh.RecombineAll = 1;

Physical Surface("roller") = {1};
Physical Surface("block") = {2};
Physical Curve("roller_arc") = {1, 2, 3, 4};
Physical Curve("roller_top") = {5};
Physical Curve("block_top") = {13, 14, 15};
Physical Curve("block_bottom") = {11};
Physical Curve("block_sides") = {12, 16};
