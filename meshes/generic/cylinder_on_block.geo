// cylinder_on_block.geo -- the NAFEMS Hertz benchmark (a long roller pressed on a block, plane
// strain), half model x >= 0 with the symmetry line x = 0.
//
//            C (0, R) ---(cylinder_top)--- P1 (R, R)
//            |                         _.-'
//          axis   cylinder        _.-'   cylinder_arc (circle of radius R about C)
//            |               _.-'
//            P0 (0, 0) --'                     the roller touches the block at the origin
//            Q0 (0, 0) ---------(block_top)--------------- Q3 (W, 0)
//            |                                                  |
//          axis                 block                       block_side
//            |                                                  |
//            Q1 (0, -H) -------(block_bottom)------------- Q2 (W, -H)
//
// R = 50 mm, W = H = 100 mm (the block of the full model is 200 mm wide and 100 mm deep) unless
// set on the command line; `scale = 2` doubles W and H (the half-space check).
// P0 and Q0 are DIFFERENT points with different nodes (Geometry.AutoCoherence = 0): the two
// bodies are separate meshes that touch geometrically.
//
// Grading: quadrangles everywhere (Frontal-Delaunay for quads + Blossom full-quad recombination); the size
// field is h_contact = a / (8 * 2^(level - 1)) within 1.25 a of the contact point (a = 6.21 mm,
// the Hertz half-width of the benchmark, see README.md), growing linearly to h_far at 60 mm.
//
// Run:  gmsh cylinder_on_block.geo -2 -order 2 -format msh41 -setnumber level 2 -o cylinder_on_block_L2.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  level = 1,        // refinement level: 8 * 2^(level - 1) elements across a near the contact
  R = 50,           // roller radius
  W = 100,          // half-width of the block (before scale)
  H = 100,          // depth of the block (before scale)
  scale = 1,        // block size factor (2: the "big" variant)
  a = 6.21,         // Hertz contact half-width, for the grading only
  h_far_1 = 10,     // element size far from the contact at level 1 (halved per level)
  alg = 8, rec = 3, smooth = 1   // Frontal-Delaunay for quads, Blossom full-quad, 1 smoothing pass
];
Wb = W * scale;
Hb = H * scale;
n_across = 8 * 2^(level - 1);
h_contact = a / n_across;
h_far = h_far_1 / 2^(level - 1);

// roller
Point(1) = {0, 0, 0};       // P0, contact point
Point(2) = {R, R, 0};       // P1
Point(3) = {0, R, 0};       // C, centre
Circle(1) = {1, 3, 2};      // cylinder_arc, P0 -> P1
Line(2) = {2, 3};           // cylinder_top
Line(3) = {3, 1};           // axis (roller)
Curve Loop(1) = {1, 2, 3};  // counter-clockwise
Plane Surface(1) = {1};

// block
Point(11) = {0, 0, 0};      // Q0, contact point of the block
Point(12) = {0, -Hb, 0};    // Q1
Point(13) = {Wb, -Hb, 0};   // Q2
Point(14) = {Wb, 0, 0};     // Q3
Line(11) = {12, 13};        // block_bottom
Line(12) = {13, 14};        // block_side
Line(13) = {14, 11};        // block_top
Line(14) = {11, 12};        // axis (block)
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};

// size field: fine around the contact point, coarse away
Field[1] = Distance;
Field[1].PointsList = {1, 11};
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

Mesh.Algorithm = alg;               // 8: Frontal-Delaunay for quads
Mesh.RecombinationAlgorithm = rec;  // 3: Blossom full-quad (min scaled Jacobian 0.40; plain Blossom left one 0.00003)
Mesh.Smoothing = smooth;
Mesh.RecombineAll = 1;

Physical Surface("cylinder") = {1};
Physical Surface("block") = {2};
Physical Curve("cylinder_arc") = {1};
Physical Curve("cylinder_top") = {2};
Physical Curve("block_top") = {13};
Physical Curve("block_bottom") = {11};
Physical Curve("block_side") = {12};
Physical Curve("axis") = {3, 14};
