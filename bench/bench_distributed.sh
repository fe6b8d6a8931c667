#!/usr/bin/env bash
# Speed-up of the distributed engine on this machine: the toy farm (tests/distributed/toy_farm.cpp,
# a CPU-bound Monte-Carlo estimate of pi per task, tasks of 1 to 5 cost units mixed) run by one
# process with one compute thread, by `mpirun -np 2` (rank 0 schedules on its main thread and
# computes on one worker thread, rank 1 computes), and, for comparison, by one process with two
# compute threads. The three are interleaved, repeated, and compared by their medians; the wall
# time includes MPI start-up. The tables must be byte-identical (the run stops otherwise).
#   bash bench/bench_distributed.sh [BUILD_DIR]      (environment: TASKS, SAMPLES, REPEATS)
set -euo pipefail
build=${1:-build}
toy="$build/tests/distributed/toy_farm"
[ -x "$toy" ] || { echo "bench_distributed: $toy not built (cmake --build $build --target toy_farm)"; exit 2; }
command -v mpirun > /dev/null || { echo "bench_distributed: mpirun not installed (openmpi-bin)"; exit 2; }
tasks=${TASKS:-64}
samples=${SAMPLES:-6000000}
repeats=${REPEATS:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Runs one configuration into a fresh directory; prints its wall time in seconds.
run() {
  local name=$1 repeat=$2
  shift 2
  local out="$scratch/$name-$repeat"
  local start end
  start=$(date +%s.%N)
  "$@" --out "$out" --tasks "$tasks" --samples "$samples" < /dev/null > "$out.log" 2>&1 || { cat "$out.log" >&2; exit 1; }
  end=$(date +%s.%N)
  cmp -s "$out/table.csv" "$scratch/one_process-0/table.csv" || { echo "bench_distributed: $name table differs" >&2; exit 1; }
  awk -v a="$start" -v b="$end" 'BEGIN {printf "%.3f\n", b - a}'
}

median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

declare -a one two threads
for ((r = 0; r < repeats; ++r)); do
  one+=("$(run one_process "$r" "$toy" --threads 1)")
  two+=("$(run two_processes "$r" mpirun -np 2 "$toy" --threads 1)")
  threads+=("$(run two_threads "$r" "$toy" --threads 2)")
done
t1=$(median "${one[@]}")
t2=$(median "${two[@]}")
tt=$(median "${threads[@]}")
echo "toy farm: $tasks tasks, $samples to $((5 * samples)) samples each, $(nproc) cores, median of $repeats runs"
printf '  %-34s %8.2f s   (runs: %s)\n' "1 process, 1 compute thread" "$t1" "${one[*]}"
printf '  %-34s %8.2f s   (runs: %s)\n' "mpirun -np 2 (1 thread on rank 0)" "$t2" "${two[*]}"
printf '  %-34s %8.2f s   (runs: %s)\n' "1 process, 2 compute threads" "$tt" "${threads[*]}"
printf 'speed-up 2 processes / 1 process: %.2f   (2 threads / 1 thread: %.2f)\n' \
  "$(awk -v a="$t1" -v b="$t2" 'BEGIN {print a / b}')" "$(awk -v a="$t1" -v b="$tt" 'BEGIN {print a / b}')"
echo "tables byte-identical across all runs"
