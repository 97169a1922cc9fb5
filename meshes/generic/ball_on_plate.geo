// ball_on_plate.geo -- Hertz's sphere on a flat as a body of revolution (kinematics =
// "axisymmetric", x = r >= 0, y = z): a ball of radius R pressed on a plate of radius W and
// depth H; the section r >= 0 of both, the axis r = 0 on the left.
//
//            C (0, R) ---(ball_top)--- P1 (R, R)
//            |                      _.-'
//          axis     ball       _.-'   ball_surface (circle of radius R about C)
//            |            _.-'
//            P0 (0, 0) --'                     the ball touches the plate at the origin
//            Q0 (0, 0) ---------(plate_top)--------------- Q3 (W, 0)
//            |                                                  |
//          axis                 plate                       plate_rim
//            |                                                  |
//            Q1 (0, -H) -------(plate_bottom)------------- Q2 (W, -H)
//
// R = 10 mm, W = H = 20 mm (over 18 contact radii at the page's largest force). P0 and Q0 are
// different points with different nodes (Geometry.AutoCoherence = 0): two separate meshes that
// touch geometrically. Grading: quadrangles (Frontal-Delaunay for quads + Blossom full-quad);
// h_contact = a / n_across within 1.4 a_max of the contact point (a = 0.866 mm, the Hertz radius
// at the page's default P = 5 kN; a_max = 1.09 mm at 10 kN), growing linearly to h_far at 8 mm.
// Small on purpose: the page solves it on every slider move.
//
// Run:  gmsh ball_on_plate.geo -2 -order 2 -format msh41 -o ball_on_plate.msh

Geometry.AutoCoherence = 0;
Mesh.SecondOrderIncomplete = 0;   // complete second order: Quad9, Line3

DefineConstant[
  R = 10, W = 20, H = 20,
  a = 0.866,        // Hertz contact radius at P = 5 kN, for the grading only
  a_max = 1.09,     // at P = 10 kN
  n_across = 8,     // elements across a near the contact
  h_far = 3,        // element size far from the contact
  alg = 8, rec = 3, smooth = 1
];
h_contact = a / n_across;

// ball (its lower half: the section 0 <= r <= R, 0 <= z <= R)
Point(1) = {0, 0, 0};       // P0, contact point
Point(2) = {R, R, 0};       // P1
Point(3) = {0, R, 0};       // C, centre
Circle(1) = {1, 3, 2};      // ball_surface, P0 -> P1
Line(2) = {2, 3};           // ball_top
Line(3) = {3, 1};           // axis (ball)
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

// plate
Point(11) = {0, 0, 0};      // Q0
Point(12) = {0, -H, 0};     // Q1
Point(13) = {W, -H, 0};     // Q2
Point(14) = {W, 0, 0};      // Q3
Line(11) = {12, 13};        // plate_bottom
Line(12) = {13, 14};        // plate_rim
Line(13) = {14, 11};        // plate_top
Line(14) = {11, 12};        // axis (plate)
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};

Field[1] = Distance;
Field[1].PointsList = {1, 11};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_contact;
Field[2].SizeMax = h_far;
Field[2].DistMin = 1.4 * a_max;
Field[2].DistMax = 8;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Mesh.Algorithm = alg;
Mesh.RecombinationAlgorithm = rec;
Mesh.Smoothing = smooth;
Mesh.RecombineAll = 1;

Physical Surface("ball") = {1};
Physical Surface("plate") = {2};
Physical Curve("ball_surface") = {1};
Physical Curve("ball_top") = {2};
Physical Curve("plate_top") = {13};
Physical Curve("plate_bottom") = {11};
Physical Curve("plate_rim") = {12};
Physical Curve("axis") = {3, 14};
