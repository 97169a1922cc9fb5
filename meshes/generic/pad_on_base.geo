// pad_on_base.geo -- a thin pad pressed along a longer base (issue 22's second long-interface
// layout), for iteration counts against the number of pairs (docs/benchmarks.md). The pad's
// bottom is the master side: n_pad = Round(3 / h) cells of size h, 2 n_pad + 1 pairs; the base's
// top (slave, non-matching) has cells 1.2 times finer along its whole length; n_pad_height and
// n_base_height cells through each body, graded towards the interface y = 1 (consecutive cells
// differ by the factor `grading`, the finest at the interface).
//
//                 8 -------(7)-------- 7            y = 1.2   pad_top
//                 5 -------(5)-------- 6            y = 1     pad_bottom (master), pad [1, 4] x [1, 1.2]
//   4 -------------------(3)-------------------- 3  y = 1     base_top (slave)
//   |                    base                    |            base [0, 5] x [0, 1]
//   1 -------------------(1)-------------------- 2  y = 0     base_bottom
//
// Pairs against h: 0.032 -> 189, 0.016 -> 377, 0.008 -> 751, 0.004 -> 1,501, 0.002 -> 3,001.
// Run:  gmsh pad_on_base.geo -2 -order 2 -format msh41 -setnumber h 0.032 -o pad_on_base_032.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  h = 0.032,          // cell length along the pad's bottom (the characteristic length)
  n_pad_height = 4,   // elements through the pad's height
  n_base_height = 10, // elements through the base's height
  grading = 0.75      // size ratio of consecutive cells towards the interface
];
n_pad = Round(3 / h);
n_base = Round(1.2 * 5 / h);

Point(1) = {0, 0, 0};
Point(2) = {5, 0, 0};
Point(3) = {5, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {1, 1, 0};
Point(6) = {4, 1, 0};
Point(7) = {4, 1.2, 0};
Point(8) = {1, 1.2, 0};

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
Transfinite Curve{5, 7} = n_pad + 1;
// Progression r: each cell is r times the previous one along the curve's direction.
Transfinite Curve{2} = n_base_height + 1 Using Progression grading;     // y = 0 -> 1: fine at the top
Transfinite Curve{4} = n_base_height + 1 Using Progression 1 / grading; // y = 1 -> 0
Transfinite Curve{6} = n_pad_height + 1 Using Progression 1 / grading;  // y = 1 -> 1.2: fine at the bottom
Transfinite Curve{8} = n_pad_height + 1 Using Progression grading;      // y = 1.2 -> 1
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("base") = {1};
Physical Surface("pad") = {2};
Physical Curve("base_bottom") = {1};
Physical Curve("base_top") = {3};
Physical Curve("pad_bottom") = {5};
Physical Curve("pad_top") = {7};
