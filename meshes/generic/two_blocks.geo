// two_blocks.geo -- two elastic blocks, the upper one resting on the lower one, for the
// "press, then slide" scene.  Structured Quad9 meshes, NON-matching along the interface:
// 16 elements along the lower block's top, 5 along the upper block's bottom.
//
//                8 -----(7)----- 7          y = 2    upper_top      (7)
//                |     upper     |                   upper block [1, 3] x [1, 2]
//               (8)             (6)
//                5 -----(5)----- 6          y = 1    upper_bottom   (5)
//   4 ---------------(3)------------------ 3     y = 1    lower_top      (3)
//   |                  lower                 |           lower block [0, 4] x [0, 1]
//  (4)                                      (2)
//   1 ---------------(1)------------------ 2     y = 0    lower_bottom   (1)
//  x=0                                      x=4
//
// The blocks touch along y = 1 but share no point, curve or node (Geometry.AutoCoherence = 0).
// Every curve runs so that the surface's curve loop is counter-clockwise: every cell is too.
//
// Run:  gmsh two_blocks.geo -2 -order 2 -format msh41 -o two_blocks.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  n_lower = 16,   // elements along x in the lower block
  n_upper = 5,    // elements along x in the upper block
  n_height = 6    // elements through the height of each block
];

Point(1) = {0, 0, 0};
Point(2) = {4, 0, 0};
Point(3) = {4, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {1, 1, 0};
Point(6) = {3, 1, 0};
Point(7) = {3, 2, 0};
Point(8) = {1, 2, 0};

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

Transfinite Curve{1, 3} = n_lower + 1;
Transfinite Curve{5, 7} = n_upper + 1;
Transfinite Curve{2, 4, 6, 8} = n_height + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_top") = {7};
