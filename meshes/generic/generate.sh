#!/usr/bin/env bash
# Regenerate the committed meshes of meshes/generic/ from their .geo sources and check each file.
#
#   pip install gmsh                 # gmsh 4.15.2 was used for the committed files
#   meshes/generic/generate.sh       # writes two_blocks.msh, cylinder_on_block_L{1,2,3}.msh,
#                                    # cylinder_on_block_big_L2.msh, pin_lug.msh,
#                                    # interference_fit.msh, shrink_fit_axisymmetric.msh, ball_on_plate.msh,
#                                    # cattaneo_mindlin_L{0,1,2,3}.msh,
#                                    # hills_nowell_L{1,2,3}.msh, incline.msh, pin_lug_L1.msh, pin_lug_L3.msh,
#                                    # long_interface_{96,190,380}.msh,
#                                    # pad_on_base_thin_{032,016}.msh,
#                                    # sliding_block_{matching,nonmatching}.msh,
#                                    # press_fit_L{1,2}.msh, moving_roller_L{1,3}.msh,
#                                    # hertz_sphere_axisymmetric_{T3,T6,Q4,Q8,Q9}_L{1,2}.msh,
#                                    # punch_axisymmetric_{T3,T6,Q4,Q8,Q9}_L{1,2}.msh
#   meshes/generic/generate.sh --no-check
#
# Environment: GMSH (default: gmsh), PYTHON (default: python3, must import gmsh for the check).
# The check (check_mesh.py) fails unless every body cell is a Quad9 and every curve cell a Line3,
# every physical group the scenes use exists, every cell is valid (minSJ, minDetJac > 0) and
# counter-clockwise, and the bodies share no node.  Nothing at test time needs gmsh.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
GMSH=${GMSH:-gmsh}
PYTHON=${PYTHON:-python3}
CHECK=1
[[ ${1:-} == --no-check ]] && CHECK=0
status=0

mesh() {  # geo out bodies curves [count ...] -- [gmsh -setnumber args ...]
  local geo=$1 out=$2 bodies=$3 curves=$4
  shift 4
  local counts=() args=()
  while [[ $# -gt 0 && $1 != -- ]]; do counts+=("$1"); shift; done
  [[ ${1:-} == -- ]] && shift
  args=("$@")
  "$GMSH" "$here/$geo" -2 -order 2 -format msh41 -v 1 "${args[@]}" -o "$here/$out"
  if [[ $CHECK == 1 ]]; then
    "$PYTHON" "$here/check_mesh.py" "$here/$out" "$bodies" "$curves" "${counts[@]}" || status=1
  fi
}

mesh two_blocks.geo two_blocks.msh lower,upper lower_bottom,lower_top,upper_bottom,upper_top
cob_curves=cylinder_arc,cylinder_top,block_top,block_bottom,axis,block_side
for level in 1 2 3; do
  mesh cylinder_on_block.geo "cylinder_on_block_L$level.msh" cylinder,block "$cob_curves" \
    cylinder_arc:6.21 block_top:6.21 -- -setnumber level "$level"
done
mesh cylinder_on_block.geo cylinder_on_block_big_L2.msh cylinder,block "$cob_curves" \
  cylinder_arc:6.21 block_top:6.21 -- -setnumber level 2 -setnumber scale 2
pin_curves=hole,pin_contact,pin_back,pin_arc,symmetry,lug_fixed,lug_end,lug_top
mesh pin_lug.geo pin_lug_L1.msh lug,pin "$pin_curves" -- -setnumber n_contact 20 -setnumber n_back 6 \
  -setnumber h_lug 8 -setnumber h_pin_centre 4
mesh pin_lug.geo pin_lug.msh lug,pin "$pin_curves"
mesh pin_lug.geo pin_lug_L3.msh lug,pin "$pin_curves" -- -setnumber n_contact 80 -setnumber n_back 20 \
  -setnumber h_lug 2 -setnumber h_pin_centre 1
mesh interference_fit.geo interference_fit.msh disk,ring disk_rim,ring_bore,ring_outer,sym_x,sym_y
mesh ball_on_plate.geo ball_on_plate.msh ball,plate ball_surface,ball_top,plate_top,plate_bottom,plate_rim,axis
mesh shrink_fit_axisymmetric.geo shrink_fit_axisymmetric.msh shaft,hub shaft_bottom,shaft_rim,shaft_top,axis,hub_bottom,hub_outer,hub_top,hub_bore
for level in 0 1 2 3; do
  mesh cattaneo_mindlin.geo "cattaneo_mindlin_L$level.msh" cylinder,block \
    cylinder_arc,cylinder_top,block_top,block_bottom,block_side -- -setnumber level "$level"
done
for level in 1 2 3; do
  mesh hills_nowell.geo "hills_nowell_L$level.msh" cylinder,block \
    cylinder_arc,cylinder_top,block_top,block_bottom,block_left,block_right -- -setnumber level "$level"
done
mesh incline.geo incline.msh block,ground block_bottom,block_left,block_right,block_top,ground_top
sb_curves=base_bottom,base_top,block_bottom,block_right,block_top,block_left
mesh sliding_block.geo sliding_block_matching.msh block,base "$sb_curves" -- -setnumber n_base 40
mesh sliding_block.geo sliding_block_nonmatching.msh block,base "$sb_curves" -- -setnumber n_base 29
pf_curves=plug_axis,plug_tip,plug_top,plug_back,wall_surface,wall_top
for level in 1 2; do
  mesh press_fit.geo "press_fit_L$level.msh" plug,wall "$pf_curves" -- -setnumber level "$level"
done
# press_fit.geo reflected about x = y as a body of revolution (x = r, y = z): its cells come out
# clockwise, which Model::add_body renumbers, so check_mesh.py (counter-clockwise) is not run.
for level in 1 2; do
  "$GMSH" "$here/press_fit_axisymmetric.geo" -2 -order 2 -format msh41 -v 1 -setnumber level "$level" \
    -o "$here/press_fit_axisymmetric_L$level.msh"
done
for level in 1 3; do
  mesh moving_roller.geo "moving_roller_L$level.msh" roller,block roller_arc,roller_top,block_top,block_bottom,block_sides \
    roller_arc:3 block_top:3 -- -setnumber level "$level"
done
for n in 96 190 380; do
  mesh long_interface.geo "long_interface_$n.msh" lower,upper lower_bottom,lower_top,upper_bottom,upper_top \
    -- -setnumber n_upper "$n"
done
for h in 032 016; do
  mesh pad_on_base.geo "pad_on_base_thin_$h.msh" base,pad base_bottom,base_top,pad_bottom,pad_top \
    -- -setnumber h "0.$h" -setnumber n_base_height 2 -setnumber n_pad_height 1
done
# Every element type (T3 T6 Q4 Q8 Q9): the .geo sets the order, the recombination and the
# incomplete second order from `kind`, so no -order here; check_mesh.py checks Quad9 files only,
# these are read by the tests (tests/verification/verify_axisymmetric_contact.rs and
# verify_axisymmetric_shrink_fit.rs).
kinds=(T3 T6 Q4 Q8 Q9)
for level in 1 2; do
  for k in 1 2 3 4 5; do
    for geo in hertz_sphere_axisymmetric punch_axisymmetric shrink_fit_axisymmetric_kinds; do
      "$GMSH" "$here/$geo.geo" -2 -format msh41 -v 1 -setnumber kind "$k" -setnumber level "$level" \
        -o "$here/${geo%_kinds}_${kinds[$((k - 1))]}_L$level.msh"
    done
  done
done
exit $status
