#!/usr/bin/env bash
# contact2d against GetFEM on the one-step frictional press of benchmarks/long_interface.sh
# (issue 22, item 3; results in docs/benchmarks.md, "GetFEM side by side").
#
# For each size: generates meshes/generic/long_interface.geo (needs gmsh: `pip install gmsh`),
# then runs contact2d and GetFEM (benchmarks/getfem_long_interface.py with Debian's
# python3-getfem: `apt-get install python3-getfem`) one after the other on the same .msh file,
# and prints one markdown row: pairs, DOFs, each code's iterations, wall and CPU time (user +
# system of the whole process) and peak memory, the CPU ratio, and the force through the
# interface and the contact length of both with their relative gap.
#
# Usage: benchmarks/getfem_side_by_side.sh [n_upper ...]   (pairs = 2 n_upper + 1;
#        default 96 190 380 760 1520 2500, 193 to 5,001 pairs)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sizes=("$@")
[ ${#sizes[@]} -eq 0 ] && sizes=(96 190 380 760 1520 2500)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin contact2d
bin="$root/target/release/contact2d"

echo "| pairs | DOFs | contact2d: iterations, wall s, CPU s, MiB | GetFEM: iterations, wall s, CPU s, MiB | CPU ratio | force contact2d / GetFEM (gap) | contact length contact2d / GetFEM |"
echo "|---|---|---|---|---|---|---|"
for n in "${sizes[@]}"; do
  mesh="$work/long_interface_$n.msh"
  gmsh "$root/meshes/generic/long_interface.geo" -2 -order 2 -format msh41 -setnumber n_upper "$n" \
    -o "$mesh" > /dev/null
  /usr/bin/time -f "%e %U %S %M" -o "$work/time_c" "$bin" run "$root/scenes/generic/long_interface.toml" \
    --set "mesh=\"$mesh\"" --set 'loading.schedule=[{press=1.0}]' --json > "$work/contact2d.json"
  /usr/bin/time -f "%e %U %S %M" -o "$work/time_g" /usr/bin/python3 "$root/benchmarks/getfem_long_interface.py" \
    "$mesh" > "$work/getfem.out" 2> "$work/getfem.err" || true
  python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
def timing(name):
    wall, user, system, rss = open(f"{work}/time_{name}").read().split()[-4:]
    return float(wall), float(user) + float(system), int(rss) // 1024
c = json.load(open(f"{work}/contact2d.json"))
joint = c["contacts"]["joint"]
cw, cc, cm = timing("c")
gw, gc, gm = timing("g")
lines = [l for l in open(f"{work}/getfem.out").read().splitlines() if l.startswith("{")]
status = "" if c["status"] == "converged" else f" ({c['status']})"
row = f"| {c['pairs']:,} | {c['dofs']:,} | {c['iterations']}{status}, {cw:.2f}, {cc:.2f}, {cm} | "
if lines:
    g = json.loads(lines[-1])
    ok = "" if g["converged"] else " (not converged)"
    gap = abs(joint["normal_force"] - g["top_reaction"]) / g["top_reaction"]
    row += (f"{g['iterations']}{ok}, {gw:.2f}, {gc:.2f}, {gm} | {gc / cc:.1f}× | "
            f"{joint['normal_force']:.4f} / {g['top_reaction']:.4f} ({gap:.1e}) | "
            f"{joint['contact_length']:.4f} / {g['contact_length']:.4f} |")
else:
    row += f"failed, {gw:.2f}, {gc:.2f}, {gm} | — | {joint['normal_force']:.4f} / — | — |"
print(row, flush=True)
PY
  rm -f "$mesh"
done
