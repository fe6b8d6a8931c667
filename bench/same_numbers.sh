#!/usr/bin/env bash
# Same numbers: shows that a NEW ffrf (e.g. after a refactor) gives the same numbers as an OLD one
# for `ffrf compare`, `ffrf rao` and `ffrf operability` on every shipped scene (cases/*.toml) that
# the command accepts. Each (command, scene) runs the same command line with OLD and with NEW, one
# program at a time, each with --out into its own directory and its stdout captured; then
# bench/same_numbers.py compares every number of the JSON and CSV files the two runs wrote (the
# same files, keys, columns and rows; relative tolerance RTOL, default 1e-12, absolute floor 1e-300)
# and the stdout to the last printed digit, with wall times, speed-ups in wall time, real-time
# factors, dates, version/commit, host names and paths masked. It prints a table
# command × scene → identical / the largest relative difference and where, and exits 1 when a run
# differs (2 on bad usage).
#
#   OLD=/path/to/old/ffrf [NEW=build/app/ffrf] [OUT=dir] [RTOL=1e-12] bash bench/same_numbers.sh
#
#   OLD   the reference program (required)
#   NEW   the program under test (default: build/app/ffrf of this repository)
#   OUT   where the runs, the table (table.md) and every difference (details.txt) go
#         (default: a new directory /tmp/same_numbers.XXXXXX; emptied of earlier runs: operability
#         would otherwise resume from its journal)
#   IRREGULAR_DURATION  simulated seconds of `compare` on an irregular-sea scene (default 60; the
#         scenes' records are hours long and the component sums cost ~1 ms per load)
#   OPERABILITY_ARGS    the sea-state grid of `operability` (default: 2 Hs × 2 Tp, 2 seeds of 300 s,
#         1 cell verified, 1 thread)
#
# Scenes per command (docs/user-guide.md, `ffrf CMD --help`): compare takes a crane ([hull]) or a
# hub ([hub]) scene; rao and operability a floating crane with a cargo ([hull] and [cargo]);
# cantilever.toml (a single beam) is for `ffrf modes` only. rao runs with --check-time-domain, so its
# regular-wave time-domain runs are compared too.
#
# Irregular seas. Since 6f395aa ffrf evaluates the incident sea from a record precomputed once per
# record (wave.kinematics = "precomputed", the default; docs/hydrodynamics.md §7.1) where earlier
# programs summed every component in every hull load. When NEW knows wave.kinematics and OLD does
# not, NEW runs each irregular-sea scene from a copy with wave.kinematics = "exact" (the same sums as
# OLD): row "exact sums". `operability` on a regular-wave scene builds its irregular cells from a
# scene that has no sea to set the key in: NEW can only use the recorded sea there, so those rows are
# "expected to differ (recorded sea)", reported with their differences but not counted as failures.
# NEW always runs in a scene tree under OUT (OUT/new-tree: cases/ holding the scenes, modified copies
# where needed, and links to the rest of the repository), so both programs read `cases/NAME.toml`
# and print the same paths.
#
# Runs one ffrf process at a time (a 2-core machine may be building); about 5 minutes in all.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
compare_py=$repo/bench/same_numbers.py

if [ -z "${OLD:-}" ]; then
  echo "same_numbers.sh: set OLD to the reference ffrf program, e.g." >&2
  echo "  OLD=/tmp/ffrf-8b41ec1/build/app/ffrf NEW=build/app/ffrf bash bench/same_numbers.sh" >&2
  exit 2
fi
NEW=${NEW:-$repo/build/app/ffrf}
abs() { case $1 in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }
old_ffrf=$(abs "$OLD")
new_ffrf=$(abs "$NEW")
for p in "$old_ffrf" "$new_ffrf"; do
  [ -x "$p" ] || { echo "same_numbers.sh: $p is not an executable program (OLD=$OLD NEW=$NEW)" >&2; exit 2; }
done
out=${OUT:-$(mktemp -d /tmp/same_numbers.XXXXXX)}
mkdir -p "$out"
out=$(cd "$out" && pwd)
rtol=${RTOL:-1e-12}
irregular_duration=${IRREGULAR_DURATION:-60}
read -r -a operability_args <<< "${OPERABILITY_ARGS:---hs 1:2:2 --tp 7:10:2 --seeds 2 --duration 300 --verify 1 --threads 1}"

started=$(date +%s)
rm -rf "$out/runs" "$out/new-tree" "$out/manifest.tsv"
mkdir -p "$out/runs"
manifest=$out/manifest.tsv
: > "$manifest"

# Does a program know the scene key wave.kinematics (its scene reference lists every key)? The
# reference is read whole first: `| grep -q` would stop reading at the match, and with pipefail the
# writer's SIGPIPE would turn a yes into a no.
knows_kinematics() {
  local reference
  reference=$("$1" scene-reference 2>/dev/null) || return 1
  [[ $reference == *'`kinematics`'* ]]
}
old_kin=no new_kin=no
knows_kinematics "$old_ffrf" && old_kin=yes
knows_kinematics "$new_ffrf" && new_kin=yes

# NEW's scene tree: cases/ with links to the shipped files (copies with wave.kinematics = "exact"
# made below), every other entry of the repository linked, so relative paths in scenes
# (../tests/hydro/data/barge.1) resolve as they do from the repository.
tree=$out/new-tree
mkdir -p "$tree/cases"
for entry in "$repo"/* "$repo"/.[!.]*; do
  [ -e "$entry" ] || continue
  name=$(basename "$entry")
  [ "$name" = cases ] || [ "$name" = .git ] || ln -s "$entry" "$tree/$name"
done
for entry in "$repo"/cases/*; do ln -s "$entry" "$tree/cases/$(basename "$entry")"; done

{
  echo "same_numbers.sh $(date -u '+%F %T') UTC, load average $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "OLD $old_ffrf: $("$old_ffrf" --version 2>&1 | head -2 | tr '\n' ' ')"
  echo "NEW $new_ffrf: $("$new_ffrf" --version 2>&1 | head -2 | tr '\n' ' ')"
  echo "wave.kinematics known: OLD $old_kin, NEW $new_kin; output in $out"
} | tee "$out/header.txt"

# run_pair COMMAND SCENE MODE ARGS...: the same command line with OLD (from the repository) and
# NEW (from its tree), each with its own --out; one line of the manifest.
run_pair() {
  local command=$1 scene=$2 mode=$3
  shift 3
  local dir=$out/runs/$command/$scene
  mkdir -p "$dir"
  local rc_old=0 rc_new=0 t0 t1 t2
  local line=("$command" "cases/$scene.toml" "$@")
  t0=$(date +%s%N)
  (cd "$repo" && "$old_ffrf" "${line[@]}" --out "$dir/old" </dev/null >"$dir/old.stdout" 2>"$dir/old.stderr") || rc_old=$?
  t1=$(date +%s%N)
  (cd "$tree" && "$new_ffrf" "${line[@]}" --out "$dir/new" </dev/null >"$dir/new.stdout" 2>"$dir/new.stderr") || rc_new=$?
  t2=$(date +%s%N)
  printf '%-12s %-28s exit OLD %s NEW %s   %6.1f s + %6.1f s   [%s]\n' "$command" "$scene" "$rc_old" "$rc_new" \
    "$(( (t1 - t0) / 1000000 ))e-3" "$(( (t2 - t1) / 1000000 ))e-3" "$mode"
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$command" "$scene" "$mode" "$dir/old" "$dir/new" \
    "$rc_old" "$rc_new" "ffrf ${line[*]} --out OLD_DIR" "ffrf ${line[*]} --out NEW_DIR" "$repo" "$tree" >>"$manifest"
}

for file in "$repo"/cases/*.toml; do
  scene=$(basename "$file" .toml)
  kind=" $(python3 "$compare_py" classify "$file") "
  irregular=no
  [[ $kind == *" irregular "* ]] && irregular=yes

  # What NEW reads: the shipped scene, or its exact-sums copy (see the header).
  sea_mode="as shipped"
  if [ $irregular = yes ] && [ $new_kin = yes ] && [ $old_kin = no ]; then
    rm "$tree/cases/$scene.toml"
    python3 "$compare_py" exact-copy "$file" "$tree/cases/$scene.toml"
    sea_mode='exact sums (NEW: wave.kinematics = "exact")'
  elif [ $irregular = yes ]; then
    sea_mode="as shipped (irregular: both programs' default)"
  fi

  if [[ $kind == *" crane "* || $kind == *" hub "* ]]; then
    if [ $irregular = yes ]; then
      run_pair compare "$scene" "$sea_mode" --duration "$irregular_duration"
    else
      run_pair compare "$scene" "$sea_mode"
    fi
  fi
  if [[ $kind == *" crane "* && $kind == *" cargo "* ]]; then
    run_pair rao "$scene" "$sea_mode" --check-time-domain
    op_mode=$sea_mode
    if [ $irregular = no ] && [ $new_kin = yes ] && [ $old_kin = no ]; then
      op_mode="recorded sea in NEW (a regular-wave scene: no key selects the sums)"
    fi
    run_pair operability "$scene" "$op_mode" "${operability_args[@]}"
  fi
done

echo
status=0
python3 "$compare_py" report "$manifest" "$out" --rtol "$rtol" || status=$?
echo "same_numbers.sh: $(( $(date +%s) - started )) s in all; runs, stdout and stderr in $out/runs"
exit $status
