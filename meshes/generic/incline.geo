// incline.geo -- an elastic block resting on a rigid incline (the friction threshold case).
//
// Built level, then the whole picture is turned by alpha = atan(0.1) counter-clockwise about the
// origin, so the incline rises to the right and gravity (-y) pulls the block down the slope:
//
//              B4 ------(block_top)------ B3
//              |          block           |           the block: L x H = 40 x 10 mm,
//         block_left                 block_right      nx x ny Quad9 cells (transfinite)
//              B1 ----(block_bottom)----- B2
//   G4 -----------------(ground_top)------------------ G3    the ground (a region that is no body:
//   |                     ground                        |    the rigid incline), ng cells along
//   G1 ------------------------------------------------ G2   its top
//
// B1 and G-top points are DIFFERENT points (Geometry.AutoCoherence = 0): the block only touches.
// Run: gmsh incline.geo -2 -order 2 -format msh41 -o incline.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  L = 40, H = 10,          // block
  nx = 20, ny = 5,         // block cells
  ng = 27,                 // ground cells along its top (not matching the block's)
  slope = 0.1              // tan(alpha)
];

Point(1) = {0, 0, 0};  Point(2) = {L, 0, 0};  Point(3) = {L, H, 0};  Point(4) = {0, H, 0};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};

Point(11) = {-20, -5, 0};  Point(12) = {L + 20, -5, 0};  Point(13) = {L + 20, 0, 0};  Point(14) = {-20, 0, 0};
Line(11) = {11, 12};  Line(12) = {12, 13};  Line(13) = {13, 14};  Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Transfinite Curve{11, 13} = ng + 1;
Transfinite Curve{12, 14} = 3;
Transfinite Surface{2};

Recombine Surface{1, 2};
Rotate {{0, 0, 1}, {0, 0, 0}, Atan(slope)} { Surface{1, 2}; }

Physical Surface("block") = {1};
Physical Surface("ground") = {2};
Physical Curve("block_bottom") = {1};
Physical Curve("block_right") = {2};
Physical Curve("block_top") = {3};
Physical Curve("block_left") = {4};
Physical Curve("ground_top") = {13};
