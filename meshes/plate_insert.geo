// plate_insert.geo -- structured 9-node-quad mesh of the plate with a deformable annular insert,
// upper half (x2 >= 0) by symmetry.  Problem: ../shared/paper/plate-with-insert.md (beside the
// project root), sections 1, 2 and 7.  meshes/README.md lists the physical groups and the files.
//
//   x2 = H 10-----(11)------9------(12)-----8---------(16)---------13
//          |`.              |              .'|                      |
//          |  `.  patch 3   |   patch 2  .'  |                      |
//     (13) |  (9)`. 90-135  |(8) 45-90 .'(7) |(10)    surface 5     | (15)
//     left |       `.   _.--4--._    .'      |    block [Xo, L2]    | right
//          | patch 4  5'   insert  '3 patch 1|                      |
//          | 135-180 /  30 .----. 28 \ 0-45  |                      |
//   x2 = 0 11--(5)--6,26  31  21  27   22,2-(6)-7--------(14)--------12
//         -L1       -R       -c          R   Xo                      L2
//
//   Point numbers as in the code, (n) = straight curve numbers; 22 is at R - 2c, 26 at -R.
//   The O-grid around the hole has 4 transfinite patches (hole arcs 0-45, 45-90, 90-135, 135-180 deg,
//   N/4 elements each, joined to the box [-L1, Xo] x [0, H] by straight radial lines graded
//   geometrically, finest at the hole).  The block [Xo, L2] x [0, H] is uniform.  The insert
//   (centre (-c, 0), radii R2..R1) is one transfinite half annulus, N elements in theta,
//   Nr_insert elements in rho, log-polar (square elements).
//
// Two separate bodies, only in contact: the hole edge (r = R about the origin) and the insert's
// outer edge (rho = R1 = R(1 - eps) about (-c, 0), c = eps R) are DIFFERENT curves with their
// own points and nodes, even for eps = 0 where they coincide geometrically.  No Coherence, no
// boolean operation, Geometry.AutoCoherence = 0: gmsh never merges them.  For eps > 0 they still
// touch at (-R, 0) (phi = theta = pi), where the insert rests against the hole.
//
// Run:  gmsh plate_insert.geo -2 -order 2 -format msh41 -setnumber N 64 -setnumber eps 0.05 -o out.msh

DefineConstant[ occ = 1 ];   // geometry kernel: 1 = OpenCASCADE (default), 0 = built-in
If (occ)
  // Exact circle parametrisation: contour nodes at angles k pi / (2N) to ~1e-15 rad.  (The
  // built-in kernel places transfinite nodes on arcs only within ~1e-9 rad of uniform.)  No
  // boolean operation is used, so OpenCASCADE never fuses the coincident edges either.
  SetFactory("OpenCASCADE");
EndIf
Geometry.AutoCoherence = 0;   // built-in kernel: never merge coincident points / curves

// ---------------------------------------------------------------- parameters (-setnumber NAME VALUE)
DefineConstant[
  eps = 0,            // clearance: insert outer radius R1 = R (1 - eps), centre (-eps R, 0)
  R = 1,              // hole radius
  R2 = 0.25,          // insert inner radius (clamped edge)
  H = 2.5,            // plate half width: top edge x2 = H
  L1 = 2.5,           // left edge x1 = -L1
  L2 = 5,             // right (pulled) edge x1 = L2
  Xo = 0,             // x1 of the O-grid box's right side, R < Xo < L2; <= 0: Xo = L1
  N = 32,             // elements along the half circle (hole edge and insert edge), multiple of 4
  Nr = 0,             // radial elements of the O-grid; <= 0: automatic (grading from the hole
                      // size to the box spacing along phi = 0, see below)
  hole_aspect = 1,    // radial size / arc spacing pi R / N of the element row at the hole edge
  radial_progression = 0,  // > 0: this one geometric ratio on all five O-grid radial lines
                           // (overrides hole_aspect); <= 0: one ratio per line from hole_aspect
  Nx_right = 0,       // elements along x1 in the block [Xo, L2]; <= 0: automatic (square)
  Nr_insert = 0,      // radial elements in the insert; <= 0: Round(ln(R1/R2) N / pi)
  insert_progression = 0   // ratio of successive radial sizes in the insert, growing outward;
                           // <= 0: (R1/R2)^(1/Nr_insert), log-polar: square elements
];

If (Xo <= 0)
  Xo = L1;
EndIf
c = eps * R;
R1 = R - c;

// ---------------------------------------------------------------- validation
// An invalid parameter stops gmsh with an error (exit status 1, no mesh written).
If (N < 4 || Modulo(N, 4) != 0)
  General.AbortOnError = 2;
  Error("plate_insert.geo: N = %g must be a positive multiple of 4", N);
EndIf
If (R <= 0 || eps < 0 || R2 <= 0 || R1 <= R2)
  General.AbortOnError = 2;
  Error("plate_insert.geo: need R > 0, eps >= 0, 0 < R2 < R1 = R (1 - eps) (R = %g, eps = %g, R2 = %g)", R, eps, R2);
EndIf
If (H <= R || L1 <= R || Xo <= R || L2 <= Xo)
  General.AbortOnError = 2;
  Error("plate_insert.geo: need H > R, L1 > R, R < Xo < L2 (H = %g, L1 = %g, Xo = %g, L2 = %g)", H, L1, Xo, L2);
EndIf
If (hole_aspect <= 0)
  General.AbortOnError = 2;
  Error("plate_insert.geo: hole_aspect = %g must be > 0", hole_aspect);
EndIf

// ---------------------------------------------------------------- derived mesh sizes
h0 = hole_aspect * Pi * R / N;     // radial size of the first element row at the hole edge
s_box = H / (N / 4);               // node spacing on the box sides x1 = -L1, x1 = Xo (N/4 elements)
ca = Cos(Pi / 4);
sa = Sin(Pi / 4);
// lengths of the five radial lines, hole edge -> box, at phi = 0, 45, 90, 135, 180 deg
D_0   = Xo - R;
D_45  = Sqrt((Xo - R * ca)^2 + (H - R * sa)^2);
D_90  = H - R;
D_135 = Sqrt((L1 - R * ca)^2 + (H - R * sa)^2);
D_180 = L1 - R;

If (Nr <= 0)
  // Geometric sizes along phi = 0 from h0 at the hole to s_box at the box:
  // h0 q^(n-1) = s_box and h0 (1 + q + ... + q^(n-1)) = D_0  =>  q = (D_0 - h0) / (D_0 - s_box).
  If (s_box > h0 && D_0 > s_box)
    Nr = Round(1 + Log(s_box / h0) / Log((D_0 - h0) / (D_0 - s_box)));
  Else
    Nr = Round(D_0 / h0);
  EndIf
  If (Nr < 1)
    Nr = 1;
  EndIf
EndIf
If (Nx_right <= 0)
  Nx_right = Round((L2 - Xo) / s_box);
  If (Nx_right < 1)
    Nx_right = 1;
  EndIf
EndIf
If (Nr_insert <= 0)
  Nr_insert = Round(Log(R1 / R2) * N / Pi);
  If (Nr_insert < 1)
    Nr_insert = 1;
  EndIf
EndIf
If (insert_progression <= 0)
  insert_progression = (R1 / R2)^(1 / Nr_insert);
EndIf

// Geometric ratio sp_q of a line of length sp_D cut into sp_n elements, the first of size sp_h:
// sp_h (1 + q + ... + q^(n-1)) = sp_D.  Bisection on q in (0.001, 100); the sum grows with q.
Macro SolveProgression
  sp_lo = 1e-3;
  sp_hi = 100;
  For sp_it In {1:200}
    sp_mid = 0.5 * (sp_lo + sp_hi);
    sp_sum = 0;
    sp_term = 1;
    For sp_k In {1:sp_n}
      sp_sum = sp_sum + sp_term;
      sp_term = sp_term * sp_mid;
    EndFor
    If (sp_h * sp_sum > sp_D)
      sp_hi = sp_mid;
    Else
      sp_lo = sp_mid;
    EndIf
  EndFor
  sp_q = 0.5 * (sp_lo + sp_hi);
Return

If (radial_progression > 0)
  q_0 = radial_progression;
  q_45 = radial_progression;
  q_90 = radial_progression;
  q_135 = radial_progression;
  q_180 = radial_progression;
Else
  // One statement per line: statements after a Call on the same line run before the macro.
  sp_h = h0;
  sp_n = Nr;
  sp_D = D_0;
  Call SolveProgression;
  q_0 = sp_q;
  sp_D = D_45;
  Call SolveProgression;
  q_45 = sp_q;
  sp_D = D_90;
  Call SolveProgression;
  q_90 = sp_q;
  sp_D = D_135;
  Call SolveProgression;
  q_135 = sp_q;
  sp_D = D_180;
  Call SolveProgression;
  q_180 = sp_q;
EndIf

Printf("plate_insert.geo: eps = %g, N = %g, Nr = %g, Nx_right = %g, Nr_insert = %g", eps, N, Nr, Nx_right, Nr_insert);
Printf("plate_insert.geo: O-grid progressions at phi = 0, 45, 90, 135, 180 deg: %.6f %.6f %.6f %.6f %.6f", q_0, q_45, q_90, q_135, q_180);
Printf("plate_insert.geo: insert progression %.6f", insert_progression);

// ---------------------------------------------------------------- plate: points
Point(1)  = {0, 0, 0};                // hole centre (no node in the saved mesh)
Point(2)  = {R, 0, 0};                // hole edge, phi = 0
Point(3)  = {R * ca, R * sa, 0};      // phi = 45 deg
Point(4)  = {0, R, 0};                // phi = 90 deg
Point(5)  = {-R * ca, R * sa, 0};     // phi = 135 deg
Point(6)  = {-R, 0, 0};               // phi = 180 deg
Point(7)  = {Xo, 0, 0};               // box
Point(8)  = {Xo, H, 0};
Point(9)  = {0, H, 0};
Point(10) = {-L1, H, 0};
Point(11) = {-L1, 0, 0};
Point(12) = {L2, 0, 0};               // block
Point(13) = {L2, H, 0};

// ---------------------------------------------------------------- plate: curves
// Straight edges on the outer boundary run in +x1 or +x2; entity tags increase in +x1 along
// the bottom and the top, so a group's elements in file order follow the edge.
// hole edge, counterclockwise from phi = 0 to phi = pi
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Line(5)  = {11, 6};   // x2 = 0, -L1 <= x1 <= -R   (radial line phi = 180 deg, towards the hole)
Line(6)  = {2, 7};    // x2 = 0, R <= x1 <= Xo     (radial line phi = 0)
Line(7)  = {3, 8};    // radial line phi = 45 deg, to the box corner (Xo, H)
Line(8)  = {4, 9};    // radial line phi = 90 deg, x1 = 0
Line(9)  = {5, 10};   // radial line phi = 135 deg, to the box corner (-L1, H)
Line(10) = {7, 8};    // x1 = Xo (interior, between O-grid and block)
Line(11) = {10, 9};   // x2 = H, -L1 <= x1 <= 0
Line(12) = {9, 8};    // x2 = H, 0 <= x1 <= Xo
Line(13) = {11, 10};  // x1 = -L1
Line(14) = {7, 12};   // x2 = 0, Xo <= x1 <= L2
Line(15) = {12, 13};  // x1 = L2
Line(16) = {8, 13};   // x2 = H, Xo <= x1 <= L2

// ---------------------------------------------------------------- plate: surfaces (counterclockwise)
Curve Loop(1) = {6, 10, -7, -1};     // patch phi in [0, 45] deg
Plane Surface(1) = {1};
Curve Loop(2) = {7, -12, -8, -2};    // patch phi in [45, 90] deg
Plane Surface(2) = {2};
Curve Loop(3) = {8, -11, -9, -3};    // patch phi in [90, 135] deg
Plane Surface(3) = {3};
Curve Loop(4) = {9, -13, 5, -4};     // patch phi in [135, 180] deg
Plane Surface(4) = {4};
Curve Loop(5) = {14, 15, -16, -10};  // block [Xo, L2] x [0, H]
Plane Surface(5) = {5};

// ---------------------------------------------------------------- insert: points
Point(21) = {-c, 0, 0};                    // insert centre (no node in the saved mesh)
Point(22) = {-c + R1, 0, 0};               // outer edge, theta = 0
Point(23) = {-c + R1 * ca, R1 * sa, 0};    // theta = 45 deg
Point(24) = {-c, R1, 0};                   // theta = 90 deg
Point(25) = {-c - R1 * ca, R1 * sa, 0};    // theta = 135 deg
Point(26) = {-c - R1, 0, 0};               // theta = 180 deg (= (-R, 0) for every eps)
Point(27) = {-c + R2, 0, 0};               // inner edge, theta = 0
Point(28) = {-c + R2 * ca, R2 * sa, 0};
Point(29) = {-c, R2, 0};
Point(30) = {-c - R2 * ca, R2 * sa, 0};
Point(31) = {-c - R2, 0, 0};               // inner edge, theta = 180 deg

// ---------------------------------------------------------------- insert: curves
// outer edge (contact), counterclockwise from theta = 0 to theta = pi
Circle(21) = {22, 21, 23};
Circle(22) = {23, 21, 24};
Circle(23) = {24, 21, 25};
Circle(24) = {25, 21, 26};
// inner edge (clamped), counterclockwise from theta = 0 to theta = pi
Circle(25) = {27, 21, 28};
Circle(26) = {28, 21, 29};
Circle(27) = {29, 21, 30};
Circle(28) = {30, 21, 31};
// symmetry lines, radially outward from rho = R2 to rho = R1
Line(29) = {27, 22};  // theta = 0   (+x1)
Line(30) = {31, 26};  // theta = pi  (-x1)

Curve Loop(6) = {29, 21, 22, 23, 24, -30, -28, -27, -26, -25};
Plane Surface(6) = {6};

// ---------------------------------------------------------------- structured mesh
Transfinite Curve {1, 2, 3, 4, 21, 22, 23, 24, 25, 26, 27, 28} = N / 4 + 1 Using Progression 1;
Transfinite Curve {6} = Nr + 1 Using Progression q_0;
Transfinite Curve {7} = Nr + 1 Using Progression q_45;
Transfinite Curve {8} = Nr + 1 Using Progression q_90;
Transfinite Curve {9} = Nr + 1 Using Progression q_135;
Transfinite Curve {5} = Nr + 1 Using Progression 1 / q_180;   // runs towards the hole
Transfinite Curve {10, 13, 15} = N / 4 + 1 Using Progression 1;
Transfinite Curve {11, 12} = N / 4 + 1 Using Progression 1;
Transfinite Curve {14, 16} = Nx_right + 1 Using Progression 1;
Transfinite Curve {29, 30} = Nr_insert + 1 Using Progression insert_progression;

Transfinite Surface {1} = {2, 7, 8, 3};
Transfinite Surface {2} = {3, 8, 9, 4};
Transfinite Surface {3} = {4, 9, 10, 5};
Transfinite Surface {4} = {5, 10, 11, 6};
Transfinite Surface {5} = {7, 12, 13, 8};
Transfinite Surface {6} = {27, 22, 26, 31};
Recombine Surface {1, 2, 3, 4, 5, 6};

Mesh.RecombineAll = 1;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;   // 9-node quads (Gmsh type 10), 3-node lines (type 8)
Mesh.SecondOrderLinear = 0;       // high-order nodes on the geometry (on the true circles)
Mesh.HighOrderOptimize = 0;
Mesh.MshFileVersion = 4.1;

// ---------------------------------------------------------------- physical groups
// Curves (dimension 1); boundary conditions of the spec, section 2.
Physical Curve("hole_edge", 1) = {1, 2, 3, 4};          // Gamma_p, r = R: contact, plate side
Physical Curve("insert_edge", 2) = {21, 22, 23, 24};    // Gamma_c, rho = R1: contact, insert side
Physical Curve("insert_inner", 3) = {25, 26, 27, 28};   // rho = R2: u1 = u2 = 0
Physical Curve("left", 4) = {13};                       // x1 = -L1: traction free
Physical Curve("top", 5) = {11, 12, 16};                // x2 = H: u2 = 0, s12 = 0
Physical Curve("bottom_plate", 6) = {5, 6, 14};         // x2 = 0, |x1| >= R: u2 = 0, s12 = 0
Physical Curve("right", 7) = {15};                      // x1 = L2: u1 = w, u2 = 0
Physical Curve("insert_symmetry", 8) = {29, 30};        // theta = 0, pi: u2 = 0, s12 = 0
// Surfaces (dimension 2)
Physical Surface("plate", 10) = {1, 2, 3, 4, 5};
Physical Surface("insert", 20) = {6};
