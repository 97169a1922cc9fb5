// sliding_block.geo -- the sliding patch test: an elastic block on a long rigid flat base, for
// scenes/generic/sliding_patch*.toml (finite sliding).  Structured Quad9 meshes.
//
//                     8 --(7)-- 7             y = 0.5   block_top
//                     |  block  |                       block [0, 1] x [0, 0.5]
//                    (8)       (6)                      block_left (8), block_right (6)
//                     5 --(5)-- 6             y = 0     block_bottom (5)
//   4 ----------------------(3)-------------------- 3   y = 0     base_top (3)
//   |                      base (rigid)              |            base [-0.5, 3.5] x [-0.25, 0]
//   1 ----------------------(1)-------------------- 2   y = -0.25 base_bottom (1)
//  x=-0.5                                           x=3.5
//
// n_block elements along the block's bottom (cell 1/n_block), n_base along the base's top
// (cell 4/n_base): n_block = 10, n_base = 40 give matching cells (every block node lands on a
// base node after each whole cell of travel); n_base = 29 gives non-matching ones.
// The bodies share no point, curve or node (Geometry.AutoCoherence = 0).
//
// Run:  gmsh sliding_block.geo -2 -order 2 -format msh41 -setnumber n_base 40 -o sliding_block_matching.msh
//       gmsh sliding_block.geo -2 -order 2 -format msh41 -setnumber n_base 29 -o sliding_block_nonmatching.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  n_block = 10,   // elements along the block's bottom
  n_base = 40,    // elements along the base's top
  n_height = 4    // elements through the block's height
];

Point(1) = {-0.5, -0.25, 0};
Point(2) = {3.5, -0.25, 0};
Point(3) = {3.5, 0, 0};
Point(4) = {-0.5, 0, 0};
Point(5) = {0, 0, 0};
Point(6) = {1, 0, 0};
Point(7) = {1, 0.5, 0};
Point(8) = {0, 0.5, 0};

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

Transfinite Curve{1, 3} = n_base + 1;
Transfinite Curve{2, 4} = 2;
Transfinite Curve{5, 7} = n_block + 1;
Transfinite Curve{6, 8} = n_height + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("base") = {1};
Physical Surface("block") = {2};
Physical Curve("base_bottom") = {1};
Physical Curve("base_top") = {3};
Physical Curve("block_bottom") = {5};
Physical Curve("block_right") = {6};
Physical Curve("block_top") = {7};
Physical Curve("block_left") = {8};
