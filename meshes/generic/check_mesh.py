"""Checks one generated mesh of meshes/generic/ (called by generate.sh; needs gmsh's Python API).

Usage: python3 check_mesh.py FILE.msh BODY1,BODY2 CURVE1,CURVE2,... [COUNT_CURVE:XMAX ...]

Fails (exit 1) unless: every cell of the 2D groups is a Quad9 (Gmsh type 10) and every cell of
the 1D groups a Line3 (type 8); every group named on the command line exists; the minimal scaled
Jacobian (minSJ) and minDetJac of every Quad9 are positive and every cell is counter-clockwise
(positive signed area of its corner polygon); the bodies share no node.
Prints nodes, cells per body and per curve group, the worst quality, and for each COUNT_CURVE:XMAX the number of
Line3 of that curve group lying in 0 <= x <= XMAX (the elements across the contact zone).
"""
import sys

import gmsh

path, bodies, curves = sys.argv[1], sys.argv[2].split(","), sys.argv[3].split(",")
counts = [c.split(":") for c in sys.argv[4:]]
problems = []
gmsh.initialize(["-nopopup"])
gmsh.option.setNumber("General.Terminal", 0)
gmsh.open(path)
tags, xyz, _ = gmsh.model.mesh.getNodes()
X = {int(t): (xyz[3 * i], xyz[3 * i + 1]) for i, t in enumerate(tags)}

groups = {}
for dim, ptag in gmsh.model.getPhysicalGroups():
    name = gmsh.model.getPhysicalName(dim, ptag)
    elems = []
    for ent in gmsh.model.getEntitiesForPhysicalGroup(dim, ptag):
        for ty, et, en in zip(*gmsh.model.mesh.getElements(dim, ent)):
            want, k = (10, 9) if dim == 2 else (8, 3)
            if ty != want:
                problems.append(f"{name}: element type {ty}, want {want}")
                continue
            elems += [(int(et[i]), [int(v) for v in en[k * i:k * i + k]]) for i in range(len(et))]
    groups[name] = (dim, elems)
for name in bodies + curves:
    want = 2 if name in bodies else 1
    if groups.get(name, (None,))[0] != want:
        problems.append(f"physical group {name} of dimension {want} missing")
if problems:
    print(f"{path}: FAILED: {problems}")
    sys.exit(1)

quads = [e for b in bodies for e in groups[b][1]]
qual = {m: min(gmsh.model.mesh.getElementQualities([e for e, _ in quads], m)) for m in ("minSJ", "minDetJac")}
problems += [f"{m} = {v}" for m, v in qual.items() if v <= 0]


def signed_area(conn):
    p = [X[v] for v in conn[:4]]
    return 0.5 * sum(p[i][0] * p[(i + 1) % 4][1] - p[(i + 1) % 4][0] * p[i][1] for i in range(4))


if any(signed_area(c) <= 0 for _, c in quads):
    problems.append("clockwise cells")
node_sets = [{v for _, c in groups[b][1] for v in c} for b in bodies]
for i in range(len(bodies)):
    for j in range(i + 1, len(bodies)):
        if node_sets[i] & node_sets[j]:
            problems.append(f"{bodies[i]} and {bodies[j]} share {len(node_sets[i] & node_sets[j])} nodes")
across = []
for name, xmax in counts:
    xmax = float(xmax)
    n = sum(1 for _, c in groups[name][1] if all(-1e-9 <= X[v][0] <= xmax + 1e-9 for v in c[:2]))
    sizes = [abs(X[c[1]][0] - X[c[0]][0]) for _, c in groups[name][1] if X[c[0]][0] <= xmax and X[c[1]][0] <= xmax]
    across.append(f"{name} {n} in x <= {xmax:g} (dx {min(sizes):.3g}-{max(sizes):.3g})")
gmsh.finalize()
cells = ", ".join(f"{b} {len(groups[b][1])}" for b in bodies)
lines = ", ".join(f"{c} {len(groups[c][1])}" for c in curves)
print(f"{path.split('/')[-1]}: {len(X)} nodes, {2 * len(X)} DOFs, Quad9: {cells}; "
      f"Line3: {lines}; min SJ {qual['minSJ']:.3f}; {'; '.join(across)}: {'ok' if not problems else 'FAILED: ' + '; '.join(problems)}")
sys.exit(1 if problems else 0)
