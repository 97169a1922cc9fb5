#!/usr/bin/env bash
# Regenerate the committed plate-with-insert meshes from plate_insert.geo and check every file.
#
#   pip install gmsh                     # gmsh 4.15.2 was used for the committed files
#   meshes/generate_plate_insert.sh      # writes meshes/plate_insert/plate_insert_eps{0,0.05}_N{16,32,64,128}.msh
#                                        # and, for the stress tests (contact2d stress),
#                                        # plate_insert_eps{1e-6,0.001,0.2}_N{16,32}.msh
#
# Options:  --no-check    only run gmsh
#           --check F EPS N [NAME=VALUE ...]
#                         only check one existing file (NAME=VALUE: geometry given to gmsh with
#                         -setnumber, e.g. R2=0.3 H=3; defaults as in plate_insert.geo)
# Environment: GMSH (default: gmsh), PYTHON (default: python3, must import gmsh).
#
# The check uses gmsh's Python API and fails (exit 1) unless every file has: only Quad9 (type 10)
# cells in `plate`/`insert` and only Line3 (type 8) on the curve groups; every node used by a cell;
# positive minimal Jacobian (minDetJac, minSJ, minSICN > 0); counterclockwise cells; all nodes of
# hole_edge / insert_edge / insert_inner on their circles (|r - R| < 1e-12) at the uniform angles
# k pi / (2N) to 1e-12; curve elements chained from angle 0 to pi in file order; the hole and insert
# edges sharing no node, and for eps = 0 paired node by node (2N + 1 coincident pairs).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
GMSH=${GMSH:-gmsh}
PYTHON=${PYTHON:-python3}

check() {
  "$PYTHON" - "$@" <<'PY'
import math
import sys

import gmsh

path, eps, N = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
geo = dict(R=1.0, R2=0.25, H=2.5, L1=2.5, L2=5.0)
for kv in sys.argv[4:]:
    k, v = kv.split("=")
    geo[k] = float(v)
R, R2, H, L1, L2 = (geo[k] for k in ("R", "R2", "H", "L1", "L2"))
c, R1 = eps * R, R - eps * R
TOL = 1e-12
problems = []

gmsh.initialize(["-nopopup"])
gmsh.option.setNumber("General.Terminal", 0)
gmsh.open(path)
tags, xyz, _ = gmsh.model.mesh.getNodes()
X = {int(t): (xyz[3 * i], xyz[3 * i + 1]) for i, t in enumerate(tags)}

groups = {}  # name -> (dim, tag, [(element tag, [node tags])] in file order)
for dim, ptag in gmsh.model.getPhysicalGroups():
    name = gmsh.model.getPhysicalName(dim, ptag)
    elems = []
    for ent in gmsh.model.getEntitiesForPhysicalGroup(dim, ptag):
        for ty, et, en in zip(*gmsh.model.mesh.getElements(dim, ent)):
            want, k = (10, 9) if dim == 2 else (8, 3)
            if ty != want:
                problems.append(f"{name}: element type {ty}, want {want}")
            elems += [(int(et[i]), [int(v) for v in en[k * i:k * i + k]]) for i in range(len(et))]
    groups[name] = (dim, ptag, elems)
expected = {"plate": 2, "insert": 2, "hole_edge": 1, "insert_edge": 1, "insert_inner": 1, "left": 1,
            "top": 1, "bottom_plate": 1, "right": 1, "insert_symmetry": 1}
for name, dim in expected.items():
    if groups.get(name, (None,))[0] != dim:
        problems.append(f"physical group {name} of dimension {dim} missing")
if problems:
    print(f"{path}: FAILED: {problems}")
    sys.exit(1)

quads = groups["plate"][2] + groups["insert"][2]
if {v for _, conn in quads for v in conn} != set(X):
    problems.append("some node is not used by any Quad9")
qual = {m: min(gmsh.model.mesh.getElementQualities([e for e, _ in quads], m))
        for m in ("minSICN", "minSJ", "minDetJac")}
problems += [f"{m} = {v}" for m, v in qual.items() if v <= 0]


def signed_area(conn):
    p = [X[v] for v in conn[:4]]
    return 0.5 * sum(p[i][0] * p[(i + 1) % 4][1] - p[(i + 1) % 4][0] * p[i][1] for i in range(4))


if any(signed_area(conn) <= 0 for _, conn in quads):
    problems.append("clockwise Quad9 corners")

angle_dev = 0.0


def check_circle(name, cx, rad):
    """Nodes on the circle, uniform angles, chain from 0 to pi in file order; returns node set."""
    global angle_dev
    dev = 0.0
    elems = groups[name][2]
    if len(elems) != N:
        problems.append(f"{name}: {len(elems)} Line3, want {N}")
    nodes = {v for _, conn in elems for v in conn}
    if max(abs(math.hypot(X[v][0] - cx, X[v][1]) - rad) for v in nodes) > TOL:
        problems.append(f"{name}: node off the circle of radius {rad}")
    angle = lambda v: math.atan2(X[v][1], X[v][0] - cx)
    for k, (_, (a, b, m)) in enumerate(elems):  # Line3: start, end, mid
        d = max(abs(angle(a) - k * math.pi / N), abs(angle(b) - (k + 1) * math.pi / N),
                abs(angle(m) - (k + 0.5) * math.pi / N))
        dev = max(dev, d)
    angle_dev = max(angle_dev, dev)
    if dev > TOL:
        problems.append(f"{name}: nodes not at angles k pi / (2N) (max deviation {dev:.1e})")
    if any(elems[k][1][1] != elems[k + 1][1][0] for k in range(len(elems) - 1)):
        problems.append(f"{name}: Line3 elements not chained in file order")
    return nodes


hole = check_circle("hole_edge", 0.0, R)
ins = check_circle("insert_edge", -c, R1)
check_circle("insert_inner", -c, R2)
if hole & ins:
    problems.append(f"hole_edge and insert_edge share {len(hole & ins)} nodes")
pairs = sum(1 for v in hole for w in ins if math.dist(X[v], X[w]) < TOL)
if eps == 0 and pairs != 2 * N + 1:
    problems.append(f"eps = 0: {pairs} coincident hole/insert node pairs, want {2 * N + 1}")

lines = {"left": lambda x, y: abs(x + L1) < TOL,
         "right": lambda x, y: abs(x - L2) < TOL,
         "top": lambda x, y: abs(y - H) < TOL,
         "bottom_plate": lambda x, y: abs(y) < TOL and abs(x) >= R - TOL,
         "insert_symmetry": lambda x, y: abs(y) < TOL and R2 - TOL <= abs(x + c) <= R1 + TOL}
for name, on_line in lines.items():
    if not all(on_line(*X[v]) for _, conn in groups[name][2] for v in conn):
        problems.append(f"{name}: node off its line")

# aspect ratio (radial / tangential corner-edge length) of the element rows at the two contact edges
def edge_aspect(body, edge_nodes):
    out = []
    for _, conn in groups[body][2]:
        on = [i for i in range(4) if conn[i] in edge_nodes]
        if len(on) == 2:
            i, j = on
            nb = (i + 3) % 4 if (i + 1) % 4 == j else (i + 1) % 4
            out.append(math.dist(X[conn[i]], X[conn[nb]]) / math.dist(X[conn[i]], X[conn[j]]))
    return min(out), max(out)


a_hole, a_ins = edge_aspect("plate", hole), edge_aspect("insert", ins)
gmsh.finalize()

n_plate = len({v for _, conn in groups["plate"][2] for v in conn})
n_ins = len({v for _, conn in groups["insert"][2] for v in conn})
print(f"{path.split('/')[-1]}: {len(X)} nodes (plate {n_plate}, insert {n_ins}), {2 * len(X)} DOFs, "
      f"{len(groups['plate'][2])}+{len(groups['insert'][2])} Quad9, "
      f"min quality SICN {qual['minSICN']:.3f} SJ {qual['minSJ']:.3f}, "
      f"aspect at hole {a_hole[0]:.2f}-{a_hole[1]:.2f} insert {a_ins[0]:.2f}-{a_ins[1]:.2f}, "
      f"max angle error {angle_dev:.0e}, coincident pairs {pairs}: "
      f"{'ok' if not problems else 'FAILED: ' + '; '.join(problems)}")
sys.exit(1 if problems else 0)
PY
}

if [[ ${1:-} == --check ]]; then
  shift
  check "$@"
  exit
fi

out="$here/plate_insert"
mkdir -p "$out"
"$GMSH" --version >/dev/null
status=0
generate() {  # eps N
  local f="$out/plate_insert_eps${1}_N${2}.msh"
  "$GMSH" "$here/plate_insert.geo" -2 -order 2 -format msh41 \
    -setnumber eps "$1" -setnumber N "$2" -v 2 -o "$f"
  if [[ ${CHECK:-1} == 1 ]]; then
    check "$f" "$1" "$2" || status=1
  fi
}
[[ ${1:-} == --no-check ]] && CHECK=0
for eps in 0 0.05; do
  for N in 16 32 64 128; do
    generate "$eps" "$N"
  done
done
# Clearances for the numerical stress tests (src/stress.rs): nearly coincident, small, large.
for eps in 1e-6 0.001 0.2; do
  for N in 16 32; do
    generate "$eps" "$N"
  done
done
exit $status
