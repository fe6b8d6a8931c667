#!/usr/bin/env bash
# Operability tables on this machine (docs/performance.md, "Operability"):
#  speedup  — the same small table (reference crane, irregular seas) by one process with one compute
#             thread and by `mpirun -np 2` (rank 0 schedules and computes on one thread, rank 1
#             computes), alternated REPEATS times; the tables (timing columns removed) must be equal.
#  cells    — cells per hour at 3-hour records: one cell, one seed, its record run with the model
#             recommend's reasoning picks and with the converged model (--verify 1: the same seed),
#             side by side in one run; cells/hour = 3600 / (seeds × wall per record).
#   bash bench/bench_operability.sh speedup|cells [BUILD_DIR]
#   (environment: REPEATS, COMPONENTS (cells: wave components per record, 0 = never repeating), HS, TP)
set -euo pipefail
mode=${1:?speedup or cells}
build=${2:-build}
ffrf="$build/app/ffrf"
scene=cases/paper_floating_crane.toml
[ -x "$ffrf" ] || { echo "bench_operability: $ffrf not built"; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
TIMEFORMAT='%3R %3U %3S'
echo "# $(date -u '+%F %T') UTC, $(git rev-parse --short HEAD), load average $(cut -d' ' -f1-3 /proc/loadavg)"

# operability.csv without its timing columns (*_s): the last two fields.
table() { sed 's/,[^,]*,[^,]*$//' "$1/operability.csv"; }

if [ "$mode" = speedup ]; then
  command -v mpirun > /dev/null || { echo "bench_operability: mpirun not installed"; exit 2; }
  grid=(--hs 1:2:2 --tp 7:9:2 --seeds 2 --duration 300 --components 60 --verify 0 --cargo-motion-limit 3)
  repeats=${REPEATS:-2}
  echo "grid: ${grid[*]}"
  printf '%-14s %8s %8s %8s\n' run wall_s cpu_s cores
  for r in $(seq 1 "$repeats"); do
    for launcher in one two; do
      out="$scratch/$launcher-$r"
      if [ $launcher = one ]; then
        { time "$ffrf" operability $scene "${grid[@]}" --threads 1 --out "$out" < /dev/null > "$out.log" 2>&1; } 2> "$out.time"
      else
        { time mpirun --oversubscribe -np 2 "$ffrf" operability $scene "${grid[@]}" --out "$out" < /dev/null > "$out.log" 2>&1; } 2> "$out.time"
      fi
      cmp -s <(table "$out") <(table "$scratch/one-1") || { echo "bench_operability: table of $launcher-$r differs" >&2; exit 1; }
      awk -v n="$launcher-$r" '{printf "%-14s %8.2f %8.2f %8.2f\n", n, $1, $2 + $3, ($2 + $3) / $1}' "$out.time"
      echo "$launcher $(cut -d' ' -f1 "$out.time")" >> "$scratch/walls"
    done
  done
  awk '!($1 in w) || $2 < w[$1] {w[$1] = $2} END {printf "fastest: 1 process %.2f s, mpirun -np 2 %.2f s: speed-up %.2fx\n", w["one"], w["two"], w["one"] / w["two"]}' "$scratch/walls"
elif [ "$mode" = cells ]; then
  components=${COMPONENTS:-200}
  out="$scratch/cells"
  args=(--hs "${HS:-2}" --tp "${TP:-8}" --seeds 1 --duration 10800 --components "$components" --verify 1 --threads 2)
  echo "cell: ${args[*]}"
  { time "$ffrf" operability $scene "${args[@]}" --out "$out" < /dev/null > "$out.log" 2>&1; } 2> "$out.time"
  cat "$out.log"
  # model, work, wall of each: columns of operability.csv by name.
  python3 - "$out/operability.csv" <<'EOF'
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
rec_wall, conv_wall = float(row["wall_s"]), float(row["converged_wall_s"])
rec_work, conv_work = float(row["work"]), float(row["converged_work"])
print(f"recommended: {row['model']}: wall {rec_wall:.1f} s per 3-hour record, {3600 / rec_wall:.1f} cells/hour (1 seed), work {rec_work:.4g}")
print(f"converged:   {row['converged_model']}: wall {conv_wall:.1f} s per record, {3600 / conv_wall:.1f} cells/hour, work {conv_work:.4g}")
print(f"ratio converged/recommended: wall {conv_wall / rec_wall:.2f}x, work {conv_work / rec_work:.2f}x")
EOF
else
  echo "bench_operability: mode $mode is not speedup or cells"; exit 2
fi
