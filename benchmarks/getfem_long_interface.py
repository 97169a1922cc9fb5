#!/usr/bin/python3
"""GetFEM's side of the long-interface benchmark (issue 22, item 3; docs/benchmarks.md).

The one-step frictional press of benchmarks/long_interface.sh solved by GetFEM 5.4 (Debian's
python3-getfem; run with /usr/bin/python3): the same .msh file (meshes/generic/long_interface.geo,
MSH 4.1, read by GetFEM's own gmsh importer), the same model:

    lower block [0, 4] x [0, 1], upper block [1, 3] x [1, 2], E = 200000, nu = 0.3, plane strain
    lower_bottom (y = 0): u = 0;  upper_top (y = 2): u = (0, -0.001)
    contact upper_bottom (y = 1, x in [1, 3]) against lower_top, Coulomb mu = 0.3

Discretisation: Q9 (FEM_QK(2,2) on the 9-node quads, Gauss 3 x 3); contact: GetFEM's nodal
contact brick between non-matching meshes (add_nodal_contact_between_nonmatching_meshes_brick),
the upper block's bottom nodes as its slave nodes (contact2d pairs the same nodes: 2 n_upper + 1
pairs), non-symmetric Alart-Curnier augmented Lagrangian (augmented_version 1), solved by
GetFEM's semi-smooth Newton with MUMPS, to a residual of 1e-9 of the total normal force.

Prints one JSON object: pairs, DOFs, Newton iterations, whether it converged, the force
through the interface (top_reaction: the pressed top's reaction), the sum of the normal
multipliers (normal_force, see below), the contact length (the extent along x of the slave nodes
with a non-zero normal multiplier) and wall times of the phases.

Usage: /usr/bin/python3 benchmarks/getfem_long_interface.py mesh.msh

Measured (docs/benchmarks.md, "GetFEM side by side"). Two things GetFEM needs here: the
upper block lifted by 1e-9 (lift_upper_block: with an exactly zero gap the brick leaves slave
nodes unpaired and its Newton fails from 381 pairs on), and the argument order below (its
interface reads one string more than documented). The sum of the normal multipliers is printed
but is not the transmitted force (it is off by orders of magnitude once the block is lifted);
the force compared is the top's reaction, K u summed over its vertical DOFs.
"""
import json
import sys
import time

import numpy as np
import getfem as gf

E, NU, MU, PRESS = 200000.0, 0.3, 0.3, 0.001
# Newton stops at this residual norm (force units; the total normal force is ~263, so 1e-9 of it).
RESIDUAL = 2.5e-7
# Alart-Curnier's augmentation parameter: E / 10 (with r = E GetFEM's Newton stalls at a
# residual of 1e-3 on a singular tangent at 193 pairs; E / 10 converges in 6 iterations).
R = E / 10
# The upper block's lift (lift_upper_block).
LIFT = 1e-9
Y_INTERFACE, Y_TOP = 1.0, 2.0


def face_regions(mesh):
    """Region numbers of the four boundary curves, found by geometry (the importer renumbers
    physical tags that clash): the upper block's cells have their centroid above y = 1."""
    faces = mesh.outer_faces()
    cvs, fs = faces[0], faces[1]
    groups = {"lower_bottom": [], "lower_top": [], "upper_bottom": [], "upper_top": []}
    for cv, f in zip(cvs, fs):
        pts = mesh.pts(mesh.pid_in_faces(np.array([[cv], [f]])))
        y = pts[1]
        upper = mesh.pts(mesh.pid_in_cvids(cv))[1].mean() > Y_INTERFACE
        if np.allclose(y, 0.0):
            groups["lower_bottom"].append((cv, f))
        elif np.allclose(y, Y_INTERFACE):
            groups["upper_bottom" if upper else "lower_top"].append((cv, f))
        elif np.allclose(y, Y_TOP) and upper:
            groups["upper_top"].append((cv, f))
    numbers = {}
    for k, (name, items) in enumerate(groups.items()):
        region = 100 + k
        mesh.set_region(region, np.array(items, dtype=int).T)
        numbers[name] = region
    return numbers


def lift_upper_block(mesh, regions):
    """Moves the upper block up by LIFT. With the blocks exactly touching, GetFEM's nodal brick
    leaves some slave nodes unpaired (its search for the master face fails on round-off when
    the gap is exactly zero): its multipliers there stay zero and from 381 pairs on its Newton
    stops at the first iteration on a singular tangent. A gap of 1e-9 (1e-6 of the press)
    changes the transmitted force by ~1e-6 relative."""
    pts = mesh.pts()
    moved = set(np.flatnonzero(pts[1] > Y_INTERFACE + 1e-12))
    moved.update(int(p) for p in mesh.pid_in_regions(regions["upper_bottom"]))
    lift = np.zeros_like(pts)
    lift[1, sorted(moved)] = LIFT
    mesh.set_pts(pts + lift)


def main(path):
    clock = time.perf_counter()
    times = {}
    mesh = gf.Mesh("import", "gmsh", path)
    regions = face_regions(mesh)
    lift_upper_block(mesh, regions)
    times["read"] = time.perf_counter() - clock

    t = time.perf_counter()
    fem = gf.MeshFem(mesh, 2)
    fem.set_fem(gf.Fem("FEM_QK(2,2)"))
    mim = gf.MeshIm(mesh, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,5)"))
    md = gf.Model("real")
    md.add_fem_variable("u", fem)
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))  # plane strain Lame constants
    shear = E / (2 * (1 + NU))
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [shear])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    md.add_initialized_data("u_bottom", [0.0, 0.0])
    md.add_initialized_data("u_top", [0.0, -PRESS])
    md.add_Dirichlet_condition_with_simplification("u", regions["lower_bottom"], "u_bottom")
    md.add_Dirichlet_condition_with_simplification("u", regions["upper_top"], "u_top")
    slave_dofs = fem.basic_dof_on_region(regions["upper_bottom"])
    pairs = len(slave_dofs) // 2
    md.add_initialized_data("r", [R])
    md.add_initialized_data("friction", [MU])
    # The brick adds the multipliers lambda_n, lambda_t itself. GetFEM's interface
    # (interface/src/gf_model_set.cc) reads one string more than its documented signature in
    # the frictional case: it takes the argument after multname_t as the sign that friction is
    # on and discards it, then reads dataname_r and dataname_fr. So a placeholder goes there.
    md.add_nodal_contact_between_nonmatching_meshes_brick(
        mim, "u", "lambda_n", "lambda_t", "discarded", "r", "friction",
        regions["upper_bottom"], regions["lower_top"], 1, 0, 1)
    times["setup"] = time.perf_counter() - t

    t = time.perf_counter()
    result = md.solve("noisy", "max_iter", 100, "max_res", RESIDUAL, "lsolver", "mumps")
    times["solve"] = time.perf_counter() - t
    iterations, converged = (result[0], bool(result[1])) if isinstance(result, tuple) else (result, None)

    # The reaction of the pressed top, K u summed over its y DOFs (K assembled alone): the
    # force through the interface, independent of how the brick scales its multipliers.
    mf_data = gf.MeshFem(mesh, 1)
    mf_data.set_fem(gf.Fem("FEM_QK(2,0)"))
    ones = np.ones(mf_data.nbdof())
    stiffness = gf.asm_linear_elasticity(mim, fem, mf_data, lam * ones, shear * ones)
    internal = stiffness.mult(np.asarray(md.variable("u")))
    top = fem.basic_dof_on_region(regions["upper_top"])
    reaction = float(-internal[top[1::2]].sum())
    normal = np.asarray(md.variable("lambda_n"))
    # The slave nodes in the order of their x DOFs (the multipliers follow the slave DOFs).
    x = fem.basic_dof_nodes(slave_dofs[::2])[0]
    touching = np.abs(normal) > 1e-12 * max(np.abs(normal).max(), 1e-300)
    length = float(x[touching].max() - x[touching].min()) if touching.any() else 0.0
    times["whole"] = time.perf_counter() - clock
    print(json.dumps({
        "mesh": path, "pairs": pairs, "dofs": fem.nbdof(),
        "iterations": int(iterations), "converged": converged,
        "normal_force": float(abs(normal.sum())), "top_reaction": abs(reaction), "contact_length": length,
        "time_s": times,
    }))


if __name__ == "__main__":
    main(sys.argv[1])
