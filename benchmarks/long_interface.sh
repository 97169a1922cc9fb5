#!/usr/bin/env bash
# Time against the number of contact pairs on long, fully closed interfaces (issue 13, item 3;
# results in docs/benchmarks.md, "Time against pair count").
#
# Generates meshes/generic/long_interface.geo at larger sizes than the committed ones (needs gmsh:
# `pip install gmsh`) into a scratch directory, then runs `contact2d run` on
# scenes/generic/long_interface.toml:
#   history  the scene's 40-step press-and-slide history (pairs up to HISTORY_MAX)
#   press    one frictional press step (the whole interface sticks), every size
# and prints one markdown row per run: pairs, DOFs, iterations, whole-run wall and CPU time, peak
# memory, and the JSON's per-phase times.
#
# Usage: benchmarks/long_interface.sh [n_upper ...]   (pairs = 2 n_upper + 1;
#        default 96 190 380 760 1520 2500; HISTORY_MAX=1600 by default;
#        LINEAR=auto|condensed|sparse sets solver.linear (default auto), or a list such as
#        LINEAR="condensed sparse" to run each; PRESS_MAX caps the pairs of the press runs;
#        CONTINUATION=auto|off sets solver.stick_continuation, or a list "auto off" to run each)
#        benchmarks/long_interface.sh pad [h ...]
#        the second layout (issue 22): scenes/generic/pad_on_base.toml, a pad pressed on a
#        longer base in one frictional step, on meshes/generic/pad_on_base.geo with cell length
#        h along the pad (pairs = 2 Round(3 / h) + 1; default 0.032 0.016 0.008 0.004 0.002,
#        189 to 3,001 pairs); LINEAR and CONTINUATION as above; FLOATING=1 runs
#        scenes/generic/pad_on_base_floating.toml instead (the pad's top free sideways: a body
#        held sideways by friction alone; the iterations are the inner solves' summed, the
#        Newton iterations on its rigid motion in brackets)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
layout=long_interface
if [ "${1:-}" = pad ]; then
  layout=pad_on_base
  shift
fi
sizes=("$@")
if [ ${#sizes[@]} -eq 0 ]; then
  if [ "$layout" = pad_on_base ]; then sizes=(0.032 0.016 0.008 0.004 0.002); else sizes=(96 190 380 760 1520 2500); fi
fi
history_max=${HISTORY_MAX:-1600}
press_max=${PRESS_MAX:-100000}
read -r -a linears <<< "${LINEAR:-auto}"
read -r -a continuations <<< "${CONTINUATION:-auto}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin contact2d
bin="$root/target/release/contact2d"
scene=$layout
[ "$layout" = pad_on_base ] && [ "${FLOATING:-0}" = 1 ] && scene=pad_on_base_floating
cp "$root/scenes/generic/$scene.toml" "$work/$layout.toml"

echo "| run | linear | continuation | pairs | DOFs | iterations | wall s | CPU s | peak RSS MiB | read | assemble | factor | condense | solve | post |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for n in "${sizes[@]}"; do
  mesh="$work/${layout}_$n.msh"
  runs=()
  if [ "$layout" = pad_on_base ]; then
    gmsh "$root/meshes/generic/pad_on_base.geo" -2 -order 2 -format msh41 -setnumber h "$n" -o "$mesh" > /dev/null
    runs=(press)
  else
    gmsh "$root/meshes/generic/long_interface.geo" -2 -order 2 -format msh41 -setnumber n_upper "$n" \
      -o "$mesh" > /dev/null
    [ $((2 * n + 1)) -le "$history_max" ] && runs=(history)
    [ $((2 * n + 1)) -le "$press_max" ] && runs+=(press)
  fi
  for run in "${runs[@]}"; do
   for linear in "${linears[@]}"; do
   for continuation in "${continuations[@]}"; do
    extra=(--set "solver.linear=\"$linear\"" --set "solver.stick_continuation=\"$continuation\"")
    [ "$run" = press ] && [ "$layout" = long_interface ] && extra+=(--set 'loading.schedule=[{press=1.0}]')
    /usr/bin/time -f "%e %U %S %M" -o "$work/time" \
      "$bin" run "$work/$layout.toml" --set "mesh=\"$mesh\"" "${extra[@]}" --json > "$work/out.json"
    python3 - "$run" "$work/out.json" "$work/time" "$linear" "$continuation" <<'EOF'
import json, sys
run, out, timing, linear, continuation = sys.argv[1:6]
d = json.load(open(out))
wall, user, system, rss = open(timing).read().split()[-4:]
t = d["time_s"]
phases = " | ".join(f"{t[k]:.3f}" for k in ("read", "assemble", "factor", "condense", "solve", "post"))
status = "" if d["status"] == "converged" else f" ({d['status']})"
outer = d["kkt"].get("floating_iterations", 0)
status += f" [{outer}]" if outer else ""
print(f"| {run} | {linear} | {continuation} | {d['pairs']} | {d['dofs']} | {d['iterations']}{status} | {float(wall):.2f} | "
      f"{float(user) + float(system):.2f} | {int(rss) // 1024} | {phases} |")
EOF
   done
   done
  done
  rm -f "$mesh"
done
