#!/usr/bin/python3
"""GetFEM's side of the long-interface benchmark (issue 22, item 3; docs/benchmarks.md).

The one-step frictional press of benchmarks/long_interface.sh solved by GetFEM 5.4 (Debian's
python3-getfem; run with /usr/bin/python3): the same .msh file (meshes/generic/long_interface.geo,
MSH 4.1, read by GetFEM's own gmsh importer), the same model:

    lower block [0, 4] x [0, 1], upper block [1, 3] x [1, 2], E = 200000, nu = 0.3, plane strain
    lower_bottom (y = 0): u = 0;  upper_top (y = 2): u = (0, -0.001)
    contact upper_bottom (y = 1, x in [1, 3]) against lower_top, Coulomb mu (0.3 unless given)

Discretisation: Q9 (FEM_QK(2,2) on the 9-node quads, Gauss 3 x 3: degree 5), each block a mesh
and a displacement of its own (read_block); contact: GetFEM's integral contact brick between
non-matching meshes (add_integral_contact_between_nonmatching_meshes_brick), the contact stress
(normal and tangential) as a Q1 field on the upper block's bottom (a mortar-type multiplier, like
contact2d's segment_to_segment pairing), non-symmetric Alart-Curnier augmented Lagrangian with
r = E (GetFEM's advice), solved by GetFEM's semi-smooth Newton with MUMPS to a residual of 1e-9
of the total normal force.

Prints one JSON object: pairs (the upper block's bottom nodes, the nodes contact2d pairs), DOFs,
Newton iterations, whether it converged, the force through the interface (top_reaction: the
pressed top's reaction, K u summed over its vertical DOFs), the contact length (the extent along
x of the multiplier's nodes with a non-zero normal value) and wall times of the phases.

Usage: /usr/bin/python3 benchmarks/getfem_long_interface.py mesh.msh [mu]   (mu = 0.3 by default;
       the reference values of tests/behaviour/against_getfem.rs come from mu = 0, 0.1 and 0.3)

Measured: docs/benchmarks.md, "GetFEM side by side". Not used, and why: GetFEM's nodal contact
brick (add_nodal_contact_between_nonmatching_meshes_brick) on one mesh started from a singular
tangent (the blocks glued at the coincident nodes, read_block) and converged in 8 to 74
iterations or not at all for one input; on two meshes its Python interface cannot be called in
the frictional case (it reads one string more than documented, gf_model_set.cc, and then
exceeds its own argument count).
"""
import json
import sys
import time

import numpy as np
import getfem as gf

E, NU, PRESS = 200000.0, 0.3, 0.001
# Newton stops at this residual norm (force units; the total normal force is ~263, so 1e-9 of it).
RESIDUAL = 2.5e-7
# Alart-Curnier's augmentation parameter: E, as GetFEM's documentation advises.
R = E
Y_INTERFACE, Y_TOP = 1.0, 2.0
LAME = E * NU / ((1 + NU) * (1 - 2 * NU))  # plane strain Lame constants
SHEAR = E / (2 * (1 + NU))


def read_block(path, upper):
    """One block of the .msh file as a mesh of its own. GetFEM merges points with the same
    coordinates when it reads a mesh, so read whole the two blocks would share the nodes
    where their interface nodes coincide (x = 1, 2, 3 here: 18,963 points for the file's 18,966
    nodes at 193 pairs), gluing the blocks there; each block is read on its own instead (the
    cells of the other one deleted: the upper block's cells have their centroid above y = 1)."""
    mesh = gf.Mesh("import", "gmsh", path)
    cells = mesh.cvid()
    points, starts = mesh.pid_from_cvid(cells)
    y = mesh.pts()[1][points]
    counts = np.diff(starts)
    centroid = np.add.reduceat(y, starts[:-1]) / counts
    other = cells[(centroid > Y_INTERFACE) != upper]
    mesh.del_convex(other)
    mesh.optimize_structure()
    return mesh


def face_regions(mesh, upper):
    """Region numbers of the block's two boundary curves that the model needs, found by
    geometry (the importer renumbers physical tags that clash)."""
    wanted = {"upper_bottom": Y_INTERFACE, "upper_top": Y_TOP} if upper else \
        {"lower_bottom": 0.0, "lower_top": Y_INTERFACE}
    faces = mesh.outer_faces()
    groups = {name: [] for name in wanted}
    for cv, f in zip(faces[0], faces[1]):
        y = mesh.pts(mesh.pid_in_faces(np.array([[cv], [f]])))[1]
        for name, level in wanted.items():
            if np.allclose(y, level):
                groups[name].append((cv, f))
    numbers = {}
    for k, (name, items) in enumerate(groups.items()):
        region = 100 + k
        mesh.set_region(region, np.array(items, dtype=int).T)
        numbers[name] = region
    return numbers


class Block:
    """A block's mesh, displacement FEM, integration and regions, its elasticity and its
    prescribed boundary in the model."""

    def __init__(self, path, upper, model):
        self.name = "u_upper" if upper else "u_lower"
        self.mesh = read_block(path, upper)
        self.regions = face_regions(self.mesh, upper)
        self.fem = gf.MeshFem(self.mesh, 2)
        self.fem.set_fem(gf.Fem("FEM_QK(2,2)"))
        self.mim = gf.MeshIm(self.mesh, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,5)"))
        model.add_fem_variable(self.name, self.fem)
        model.add_isotropic_linearized_elasticity_brick(self.mim, self.name, "lambda", "mu")
        held, value = ("upper_top", "u_top") if upper else ("lower_bottom", "u_bottom")
        model.add_Dirichlet_condition_with_simplification(self.name, self.regions[held], value)

    def top_reaction(self, model):
        """The pressed top's reaction, K u summed over its y DOFs (K assembled alone)."""
        data = gf.MeshFem(self.mesh, 1)
        data.set_fem(gf.Fem("FEM_QK(2,0)"))
        ones = np.ones(data.nbdof())
        stiffness = gf.asm_linear_elasticity(self.mim, self.fem, data, LAME * ones, SHEAR * ones)
        internal = stiffness.mult(np.asarray(model.variable(self.name)))
        top = self.fem.basic_dof_on_region(self.regions["upper_top"])
        return float(-internal[top[1::2]].sum())


def main(path, friction):
    clock = time.perf_counter()
    times = {}
    md = gf.Model("real")
    md.add_initialized_data("lambda", [LAME])
    md.add_initialized_data("mu", [SHEAR])
    md.add_initialized_data("u_bottom", [0.0, 0.0])
    md.add_initialized_data("u_top", [0.0, -PRESS])
    upper, lower = Block(path, True, md), Block(path, False, md)
    slave = upper.regions["upper_bottom"]
    slave_dofs = upper.fem.basic_dof_on_region(slave)
    pairs = len(slave_dofs) // 2
    md.add_initialized_data("r", [R])
    md.add_initialized_data("friction", [friction])
    # The contact stress (normal and tangential), Q1 on the upper block's bottom.
    multiplier_fem = gf.MeshFem(upper.mesh, 2)
    multiplier_fem.set_fem(gf.Fem("FEM_QK(2,1)"))
    md.add_filtered_fem_variable("contact_stress", multiplier_fem, slave)
    md.add_integral_contact_between_nonmatching_meshes_brick(
        upper.mim, upper.name, lower.name, "contact_stress", "r", "friction", slave, lower.regions["lower_top"], 1)
    times["setup"] = time.perf_counter() - clock

    t = time.perf_counter()
    result = md.solve("noisy", "max_iter", 100, "max_res", RESIDUAL, "lsolver", "mumps")
    times["solve"] = time.perf_counter() - t
    iterations, converged = (result[0], bool(result[1])) if isinstance(result, tuple) else (result, None)

    # The force through the interface (the multipliers are a stress field, not nodal forces).
    reaction = upper.top_reaction(md)
    # (x, y) components per node of the multiplier's field; y is the normal one here.
    normal = np.asarray(md.variable("contact_stress"))[1::2]
    x = multiplier_fem.basic_dof_nodes(multiplier_fem.basic_dof_on_region(slave)[::2])[0]
    touching = np.abs(normal) > 1e-12 * max(np.abs(normal).max(), 1e-300)
    length = float(x[touching].max() - x[touching].min()) if touching.any() else 0.0
    times["whole"] = time.perf_counter() - clock
    print(json.dumps({
        "mesh": path, "pairs": pairs, "dofs": upper.fem.nbdof() + lower.fem.nbdof(),
        "iterations": int(iterations), "converged": converged,
        "top_reaction": abs(reaction), "contact_length": length,
        "time_s": times,
    }))


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 0.3)
