#!/usr/bin/env bash
# The crane in the reference irregular sea (cases/irregular_sea_crane.toml: JONSWAP Hs 2 m, Tp 8 s,
# 3 375 components on the 3-hour grid, CVODE rtol 1e-6, one core) with the incident wave recorded once
# per record (wave.kinematics = "precomputed", the default) over the whole 3-hour record, and with
# the wave summed component by component (wave.kinematics = "exact") over its first EXACT_SECONDS,
# for rigid, modal k = 2 + static and nodal N = 32, side by side in one run (docs/performance.md,
# "Irregular seas"). Prints wall time, real-time factor (simulated seconds per wall second of the
# integration), steps, the record's size and build time and the loads taken by each path.
# With OLD_TREE (a source tree of an earlier commit with its Release build, e.g. made by
#   git archive 8b41ec1 | tar -x -C /tmp/ffrf-8b41ec1 && cmake -S /tmp/ffrf-8b41ec1 -B /tmp/ffrf-8b41ec1/build
#   -DCMAKE_BUILD_TYPE=Release && cmake --build /tmp/ffrf-8b41ec1/build --target ffrf)
# each model also runs that tree's program on that tree's scene over EXACT_SECONDS, in the same loop
# (row kinematics "before"): the earlier code itself, not only its algorithm.
#   bash bench/bench_irregular_sea.sh [BUILD_DIR]      (environment: EXACT_SECONDS, default 600; OLD_TREE)
set -euo pipefail
build=${1:-build}
old_tree=${OLD_TREE:-}
ffrf="$build/app/ffrf"
scene=cases/irregular_sea_crane.toml
exact_seconds=${EXACT_SECONDS:-600}
[ -x "$ffrf" ] || { echo "bench_irregular_sea: $ffrf not built"; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
awk '{ print } /^\[wave\]/ { print "kinematics = \"exact\"" }' "$scene" > "$scratch/exact.toml"
echo "# $(date -u '+%F %T') UTC, $(git rev-parse --short HEAD), load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-22s %-12s %9s %9s %10s %9s %9s %9s %9s\n' model kinematics duration_s wall_s real_time steps record_MB build_s exact_loads
for model in "rigid" "modal" "nodal -N 32"; do
  # shellcheck disable=SC2086
  paths="precomputed exact"
  [ -n "$old_tree" ] && paths="$paths before"
  for path in $paths; do
    program=$ffrf
    if [ $path = precomputed ]; then file=$scene duration=10800; else file=$scratch/exact.toml duration=$exact_seconds; fi
    if [ $path = before ]; then program=$old_tree/build/app/ffrf file=$old_tree/$scene; fi
    "$program" run "$file" --boom $model --duration $duration --json < /dev/null 2> /dev/null > "$scratch/run.json"
    python3 - "$scratch/run.json" "$model" $path $duration <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); s = d["solver"]; w = d.get("wave_kinematics", {}); r = w.get("record", {})
print(f"{sys.argv[2]:<22} {sys.argv[3]:<12} {float(sys.argv[4]):9.0f} {s['wall_time_s']:9.2f} {s['real_time_factor']:9.0f}x "
      f"{s['steps']:9d} {r.get('memory_MB', 0):9.1f} {r.get('build_time_s', 0):9.2f} {w.get('hull_loads_exact', 0):9d}")
PY
  done
done
