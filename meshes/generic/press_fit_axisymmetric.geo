// press_fit_axisymmetric.geo -- the press fit of press_fit.geo as a body of revolution: a solid
// shaft of radius a = 1 pushed along its axis into a rigid bore of radius a - delta behind a
// rounded lead-in, for scenes/generic/press_fit_axisymmetric.toml.  The plane model's x (along
// the slot) becomes the axis z = y and its y (across) the radius r = x: the same geometry,
// reflected about the line x = y, so the half model's symmetry line y = 0 is the axis r = 0.
//
// Run:  gmsh press_fit_axisymmetric.geo -2 -order 2 -format msh41 -setnumber level 1 -o press_fit_axisymmetric_L1.msh
//       (level 2: press_fit_axisymmetric_L2.msh)

Include "press_fit.geo";

// (x, y) -> (y, x): the reflection about the plane x - y = 0.
Symmetry {1, -1, 0, 0} { Surface{1, 11, 12}; }
