// long_interface.geo -- two blocks pressed together along their whole overlap, for timing
// contact solves against the number of pairs (docs/benchmarks.md, "Long contact interfaces").
// The two_blocks.geo layout with the cells refined along the interface: n_upper cells along
// the upper block's bottom (2 n_upper + 1 master nodes = pairs), n_lower = 2.4 n_upper along the
// lower block's top (non-matching), n_height cells through each block, graded towards y = 1
// (consecutive cells differ by the factor `grading`, the finest at the interface).
//
//                8 -----(7)----- 7          y = 2    upper_top
//                |     upper     |                   upper block [1, 3] x [1, 2]
//                5 -----(5)----- 6          y = 1    upper_bottom (master)
//   4 ---------------(3)------------------ 3     y = 1    lower_top (slave)
//   |                  lower                 |           lower block [0, 4] x [0, 1]
//   1 ---------------(1)------------------ 2     y = 0    lower_bottom
//
// Run:  gmsh long_interface.geo -2 -order 2 -format msh41 -setnumber n_upper 96 -o long_interface_96.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  n_upper = 96,   // elements along the upper block's bottom (pairs = 2 n_upper + 1)
  n_height = 14,  // elements through the height of each block
  grading = 0.75  // size ratio of consecutive cells towards the interface
];
n_lower = Round(2.4 * n_upper);

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
// Progression r: each cell is r times the previous one along the curve's direction.
Transfinite Curve{2} = n_height + 1 Using Progression grading;       // y = 0 -> 1: fine at the top
Transfinite Curve{4} = n_height + 1 Using Progression 1 / grading;   // y = 1 -> 0
Transfinite Curve{6} = n_height + 1 Using Progression 1 / grading;   // y = 1 -> 2: fine at the bottom
Transfinite Curve{8} = n_height + 1 Using Progression grading;       // y = 2 -> 1
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_top") = {7};
