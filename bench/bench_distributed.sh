#!/usr/bin/env bash
# Speed-up of the distributed engine on this machine: the toy farm (tests/distributed/toy_farm.cpp,
# a CPU-bound Monte-Carlo estimate of pi per task, tasks of 1 to 5 cost units mixed) run by one
# process with one compute thread, by `mpirun -np 2` (rank 0 schedules on its main thread and
# computes on one worker thread, rank 1 computes), and, for comparison, by one process with two
# compute threads. The three are interleaved and repeated; the speed-ups are given from the
# medians and from the fastest runs (the least disturbed on a shared machine); the wall time
# includes MPI start-up. The tables must be byte-identical (the run stops otherwise). The CPU
# time per wall second says how many cores a run actually got: on a machine shared with other
# jobs it is below 2 and the speed-up with it.
#   bash bench/bench_distributed.sh [BUILD_DIR]      (environment: TASKS, SAMPLES, REPEATS)
set -euo pipefail
build=${1:-build}
toy="$build/tests/distributed/toy_farm"
[ -x "$toy" ] || { echo "bench_distributed: $toy not built (cmake --build $build --target toy_farm)"; exit 2; }
command -v mpirun > /dev/null || { echo "bench_distributed: mpirun not installed (openmpi-bin)"; exit 2; }
tasks=${TASKS:-64}
samples=${SAMPLES:-6000000}
repeats=${REPEATS:-5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
load_before=$(cut -d' ' -f1 /proc/loadavg)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Runs one configuration into a fresh directory; prints "wall_s cpu_s farm_s": wall time, user +
# system time of the program and its children (mpirun reaps its ranks), and the time run_farm
# itself took (the program's "wall_s": without process and MPI start-up and shut-down).
TIMEFORMAT='%3R %3U %3S'
run() {
  local name=$1 repeat=$2
  shift 2
  local out="$scratch/$name-$repeat"
  { time "$@" --out "$out" --tasks "$tasks" --samples "$samples" < /dev/null > "$out.log" 2>&1; } 2> "$out.time" ||
    { cat "$out.log" >&2; exit 1; }
  cmp -s "$out/table.csv" "$scratch/one_process-0/table.csv" || { echo "bench_distributed: $name table differs" >&2; exit 1; }
  local farm
  farm=$(sed -n 's/.* wall_s \([0-9.]*\)$/\1/p' "$out.log")
  awk -v farm="$farm" '{printf "%.3f %.3f %.3f\n", $1, $2 + $3, farm}' "$out.time"
}

median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
minimum() { printf '%s\n' "$@" | sort -g | head -n 1; }

declare -a one two threads one_cpu two_cpu threads_cpu one_farm two_farm threads_farm
for ((r = 0; r < repeats; ++r)); do
  read -r wall cpu farm < <(run one_process "$r" "$toy" --threads 1)
  one+=("$wall"); one_cpu+=("$cpu"); one_farm+=("$farm")
  read -r wall cpu farm < <(run two_processes "$r" mpirun -np 2 "$toy" --threads 1)
  two+=("$wall"); two_cpu+=("$cpu"); two_farm+=("$farm")
  read -r wall cpu farm < <(run two_threads "$r" "$toy" --threads 2)
  threads+=("$wall"); threads_cpu+=("$cpu"); threads_farm+=("$farm")
done
report() {  # label, the number of runs, then the walls, the CPU times and the farm times
  local label=$1 n=$2
  shift 2
  local walls=("${@:1:n}") cpus=("${@:n+1:n}") farms=("${@:2*n+1:n}")
  printf '  %-34s %7.2f s %7.2f s %7.2f s  %5.2f cores busy   (wall: %s)\n' "$label" "$(median "${walls[@]}")" \
    "$(minimum "${walls[@]}")" "$(median "${farms[@]}")" \
    "$(awk -v c="$(median "${cpus[@]}")" -v w="$(median "${walls[@]}")" 'BEGIN {print c / w}')" "${walls[*]}"
}
t1=$(median "${one[@]}")
t2=$(median "${two[@]}")
tt=$(median "${threads[@]}")
echo "toy farm: $tasks tasks, $samples to $((5 * samples)) samples each, $(nproc) cores, $repeats runs each," \
  "load average before: $load_before"
printf '  %-34s %9s %9s %9s\n' "" "wall" "fastest" "in farm"
report "1 process, 1 compute thread" "$repeats" "${one[@]}" "${one_cpu[@]}" "${one_farm[@]}"
report "mpirun -np 2 (1 thread on rank 0)" "$repeats" "${two[@]}" "${two_cpu[@]}" "${two_farm[@]}"
report "1 process, 2 compute threads" "$repeats" "${threads[@]}" "${threads_cpu[@]}" "${threads_farm[@]}"
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }
echo "speed-up 2 processes / 1 process: $(ratio "$t1" "$t2") (median wall), $(ratio "$(minimum "${one[@]}")" \
  "$(minimum "${two[@]}")") (fastest wall), $(ratio "$(median "${one_farm[@]}")" "$(median "${two_farm[@]}")") (median in farm)"
echo "speed-up 2 threads / 1 thread:    $(ratio "$t1" "$tt") (median wall), $(ratio "$(minimum "${one[@]}")" \
  "$(minimum "${threads[@]}")") (fastest wall), $(ratio "$(median "${one_farm[@]}")" "$(median "${threads_farm[@]}")") (median in farm)"
echo "tables byte-identical across all runs; \"cores busy\" = CPU time / wall time (2 when nothing else runs)"
