#!/usr/bin/env bash
# Side-by-side speed of the coupled-crane benchmark before and after a change, measured in one run:
# builds this tree's bench_crane.cpp against the libraries of OLD_COMMIT in a second source tree
# (exported with `git archive`, never committed), then runs the old and the new program alternately
# REPEATS times (so both see the same machine load) and prints one table with the best wall time of
# each, the speed-ups, the cost exponent in N and the real-time-factor targets (crane_bench_table.hpp).
#   bench/before_after.sh OLD_COMMIT [OLD_TREE (default /tmp/ffrf-bench-OLD_COMMIT)] [REPEATS (default 3)]
# The new program is ./build/bench/bench_crane (build it first, Release). Check `uptime` first: other
# jobs on the machine inflate wall times.
set -euo pipefail
old_commit=${1:?usage: bench/before_after.sh OLD_COMMIT [OLD_TREE] [REPEATS]}
here=$(git rev-parse --show-toplevel)
old_tree=${2:-/tmp/ffrf-bench-$old_commit}
repeats=${3:-3}
new_bench=$here/build/bench/bench_crane
[ -x "$new_bench" ] || { echo "before_after.sh: build $new_bench first" >&2; exit 1; }

if [ ! -f "$old_tree/CMakeLists.txt" ]; then
  mkdir -p "$old_tree"
  git -C "$here" archive "$old_commit" | tar -x -C "$old_tree"
fi
cp "$here/bench/bench_crane.cpp" "$here/bench/crane_bench_table.hpp" "$old_tree/bench/"
cmake -S "$old_tree" -B "$old_tree/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null </dev/null
cmake --build "$old_tree/build" -j2 --target bench_crane >/dev/null </dev/null
old_bench=$old_tree/build/bench/bench_crane

results=$(mktemp -d)
before=() after=()
for i in $(seq 1 "$repeats"); do
  echo "run $i/$repeats: before ($old_commit), load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
  "$old_bench" --csv="$results/before_$i.csv" "${@:4}" </dev/null >"$results/before_$i.log" 2>&1
  echo "run $i/$repeats: after, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
  "$new_bench" --csv="$results/after_$i.csv" "${@:4}" </dev/null >"$results/after_$i.log" 2>&1
  before+=("$results/before_$i.csv")
  after+=("$results/after_$i.csv")
done
"$new_bench" --before="$(IFS=,; echo "${before[*]}")" --after="$(IFS=,; echo "${after[*]}")" </dev/null
echo "(logs and CSV files: $results)"
