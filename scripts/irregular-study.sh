#!/usr/bin/env bash
# The irregular-sea model study over long records and several seeds: `ffrf recommend` and `ffrf compare` on the
# irregular scenes at Tp = 5, 8 and 12 s with several seeds (docs/validation.md, "Irregular seas:
# does the recommended boom model change with Tp?"). Not part of the test suite.
#
# HOW LONG IT TAKES: about 25 minutes of CPU, 40 minutes of wall time with 2 jobs at once (measured
# 2026-11-26 at commit e3512c2 on the 2 shared, heavily loaded cores of the development machine;
# Release build; default WINDOW = 600 s of 20-minute records). CPU per study: recommend Tp = 5 s
# 270-275 s (600 components), Tp = 8 s 106-169 s (375), Tp = 12 s 77-95 s (250); the recommended
# model's own run 6-66 s; compare Tp = 8 s 133-152 s each; BEM barge recommend 21-62 s. The cost is
# about proportional to WINDOW; a 3-hour record costs ~6x more per simulated second than a 20-minute
# one (docs/validation.md), so 3-hour windows are not practical with this script. Since the hull
# pressure's phasor recurrence (after e3512c2) a run of the reference hull costs 1.6x (20-minute
# record) to 4.3x (3-hour record) less CPU than these figures.
#
# What it does: writes copies of cases/irregular_sea_crane.toml (and, for the BEM part,
# cases/irregular_bem_barge_crane.toml, its WAMIT paths made absolute) into OUT/scenes with
# wave.seed, wave.peak_period, the band [ωp/2, 3ωp] and simulation.duration (= RECORD: Δω = 2π/RECORD)
# changed; runs at most JOBS (2) ffrf processes at once under `nice -n 5`, each with
# `--duration WINDOW --out OUT/<study>`; each study's report (recommendation.json/.md or
# summary.json/report.md) records the models, integrators, tolerances, steps and wall times, and
# OUT/<study>.time its CPU time. Then it collects the verdicts into OUT/recommend.csv,
# OUT/compare.csv, OUT/statistics.csv and OUT/results.md.
#
# Usage: bash scripts/irregular-study.sh [OUT]            (after: cmake --build build --target ffrf)
#   environment: WINDOW (s, default 600), RECORD (s, default 1200), SEEDS ("1 2"), PERIODS ("5 8 12"),
#                PARTS ("recommend compare bem"), COMPARE_PERIODS ("8"), JOBS (2), FFRF (default build/app/ffrf)
#   An existing study directory is kept (rerunning resumes; delete it to redo that study);
#   `collect` alone as PARTS rebuilds the tables from what is there.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ffrf="${FFRF:-$root/build/app/ffrf}"
[[ -x "$ffrf" ]] || { echo "irregular-study: $ffrf missing: build first (cmake --build build --target ffrf)" >&2; exit 2; }
out="$(realpath -m "${1:-$root/results/irregular-study}")"
window="${WINDOW:-600}"
record="${RECORD:-1200}"
seeds="${SEEDS:-1 2}"
periods="${PERIODS:-5 8 12}"
parts="${PARTS:-recommend compare bem}"
jobs="${JOBS:-2}"
mkdir -p "$out/scenes"

# scene SOURCE NAME TP SEED: OUT/scenes/NAME.toml, SOURCE with the sea of Tp, the band [ωp/2, 3ωp],
# the seed and the record length changed (the BEM files' relative paths made absolute).
scene() {
  local source="$root/cases/$1" name="$2" tp="$3" seed="$4"
  local file="$out/scenes/$name.toml"
  read -r wmin wmax < <(awk -v tp="$tp" 'BEGIN { wp = 2 * 3.14159265358979 / tp; printf "%.6f %.6f\n", wp / 2, 3 * wp }')
  sed -e "s|^peak_period = .*|peak_period = $tp                 # s (Tp; irregular-study.sh)|" \
      -e "s|^seed = .*|seed = $seed                        # - (irregular-study.sh)|" \
      -e "s|^frequency_min = .*|frequency_min = $wmin          # rad/s (ωp/2; irregular-study.sh)|" \
      -e "s|^frequency_max = .*|frequency_max = $wmax          # rad/s (3 ωp; irregular-study.sh)|" \
      -e "s|^duration = .*|duration = $record              # s (the record: Δω = 2π/$record rad/s; irregular-study.sh)|" \
      -e "s|\"\.\./tests/hydro/data/|\"$root/tests/hydro/data/|" \
      "$source" > "$file"
  for key in peak_period seed frequency_min frequency_max duration; do
    grep -q "^$key = .*irregular-study.sh" "$file" || { echo "irregular-study: $key not set in $file" >&2; exit 1; }
  done
  echo "$file"
}

# study NAME COMMAND SCENE: runs `ffrf COMMAND SCENE --duration WINDOW --out OUT/NAME` (stdout and
# stderr in OUT/NAME.log, CPU and wall time in OUT/NAME.time) unless OUT/NAME exists; under `script`
# (compare draws its charts with gnuplot). After a recommend that chose a model, the recommended
# model's own run (the command recommend prints, `--out OUT/NAME-run`): its summary.json has the
# irregular-sea statistics (σ, most probable maxima) of the window.
study() {
  local name="$1" command="$2" file="$3" status=0
  if [[ -d "$out/$name" ]]; then echo "irregular-study: $name exists, kept" >&2
  elif ! mkdir "$out/$name.lock" 2> /dev/null; then
    echo "irregular-study: $name is running elsewhere ($out/$name.lock; remove it if not), skipped" >&2; return 0
  else
    echo "irregular-study: $(date -u +%H:%M:%S) start $name" >&2
    /usr/bin/time -f "cpu_s %U %S wall_s %e" -o "$out/$name.time" \
      script -q -e -c "nice -n 5 '$ffrf' $command '$file' --duration $window --out '$out/$name'" /dev/null \
      > "$out/$name.log" 2>&1 < /dev/null || status=$?
    echo "irregular-study: $(date -u +%H:%M:%S) end $name (exit $status; $(tail -1 "$out/$name.time"))" >&2
    rmdir "$out/$name.lock"
  fi
  if [[ "$command" == recommend && -f "$out/$name/recommendation.json" && ! -d "$out/$name-run" ]]; then
    local line
    line="$(jq -r '.run_command // empty' "$out/$name/recommendation.json")"
    [[ -n "$line" ]] || return 0
    /usr/bin/time -f "cpu_s %U %S wall_s %e" -o "$out/$name-run.time" \
      script -q -e -c "nice -n 5 '$ffrf' ${line#ffrf } --out '$out/$name-run'" /dev/null \
      > "$out/$name-run.log" 2>&1 < /dev/null || true
  fi
}

# collect: the verdicts of every study in OUT into recommend.csv, compare.csv, statistics.csv and
# results.md (the errors as each report gives them; CPU seconds from OUT/NAME.time).
collect() {
  python3 - "$out" <<'PY'
import csv, glob, json, os, re, sys
out = sys.argv[1]
def cpu(name):
    try:
        f = open(os.path.join(out, name + ".time")).read().split()
        i = f.index("cpu_s")
        return float(f[i + 1]) + float(f[i + 2]), float(f[f.index("wall_s") + 1])
    except (OSError, ValueError, IndexError):
        return float("nan"), float("nan")
def sea(name):
    m = re.match(r"(?:recommend|compare)-(bem-)?tp(\d+)-seed(\d+)$", name)
    return ("BEM barge" if m.group(1) else "reference hull", int(m.group(2)), int(m.group(3)))
def g(x, f="{:.3g}"):
    return "-" if x is None or x != x else f.format(x)

rec_rows, stat_rows, cmp_rows = [], [], []
for d in sorted(glob.glob(os.path.join(out, "recommend-*/recommendation.json"))):
    name = os.path.basename(os.path.dirname(d))
    r = json.load(open(d))
    hull, tp, seed = sea(name)
    cands = r["candidates"]
    ran = [c for c in cands if c["status"] in ("passed", "failed", "solver failure")]
    chosen = cands[r["chosen"]] if r["chosen"] is not None else None
    nxt = cands[r["next_cheaper"]] if r["next_cheaper"] is not None else None
    c_s, w_s = cpu(name)
    rec_rows.append({
        "scene": hull, "tp_s": tp, "seed": seed, "window_s": r["duration_s"],
        "error_window_start_s": r["reference"]["window_start_s"],
        "recommended": chosen["model"] if chosen else "none" + ("" if r["reference"]["converged"] else
                       " (reference not converged: change %s)" % g(r["reference"]["levels"][-1]["change"])),
        "integrator": chosen["integrator"] if chosen else "-",
        "rtol": r["reasoning"]["relative_tolerance"],
        "error": chosen["error"] if chosen else float("nan"),
        "worst_output": chosen["worst_output"] if chosen else "-",
        "next_cheaper": nxt["model"] + ", " + nxt["integrator"] if nxt else "-",
        "next_cheaper_error": nxt["error"] if nxt and nxt["error"] is not None else float("nan"),
        "candidates_run": "; ".join("%s %s %s %s" % (c["model"], c["integrator"],
                                                     g(c["error"]) if c["error"] is not None else c["status"],
                                                     c["worst_output"]) for c in ran),
        "runs": len(ran) + len(r["reference"]["levels"]),
        "reference": "%s rtol %g (change %s vs previous level)" % (r["reference"]["model"], r["reference"]["relative_tolerance"],
                                                               g(r["reference"]["levels"][-1]["change"])),
        "cpu_s": c_s, "wall_s": w_s})
    run = os.path.join(out, name + "-run", "summary.json")
    if os.path.exists(run):
        s = json.load(open(run))
        irr = s.get("irregular_sea", {})
        resp = irr.get("responses", {})
        def st(col, key):
            v = resp.get(col, {})
            return v.get("most_probable_maximum", {}).get("rayleigh", float("nan")) if key == "mpm" else v.get(key, float("nan"))
        det = {}
        for x in s.get("detections", []): det[x["kind"]] = det.get(x["kind"], 0) + 1
        rc, rw = cpu(name + "-run")
        stat_rows.append({
            "scene": hull, "tp_s": tp, "seed": seed, "model": s["model"], "window_from_s": irr.get("window_start_s"),
            "record_s": irr.get("record_length_s"),
            "realised_hs_m": irr.get("incident_wave", {}).get("significant_4_sigma", float("nan")),
            "crane_pitch_sigma_deg": st("crane_pitch_deg", "standard_deviation"),
            "cargo_heave_sigma_m": st("cargo_heave_m", "standard_deviation"),
            "cargo_heave_mpm_m": st("cargo_heave_m", "mpm"),
            "cargo_heave_max_m": st("cargo_heave_m", "observed_maximum"),
            "cargo_pitch_sigma_deg": st("cargo_pitch_deg", "standard_deviation"),
            "wire_tension_sigma_N": st("wire_tension_N", "standard_deviation"),
            "wire_tension_mpm_N": st("wire_tension_N", "mpm"),
            "wire_tension_max_N": st("wire_tension_N", "observed_maximum"),
            "static_tension_N": irr.get("wire_tension_daf", {}).get("static_tension_N", float("nan")),
            "slack_events": s["wire"]["slack_events"],
            "detections": "; ".join("%s ×%d" % kv for kv in det.items()) or "none",
            "steps": s["solver"]["steps"], "cpu_s": rc, "rtol": s["provenance"]["rtol"],
            "integrator": s["provenance"]["integrator"]})
for d in sorted(glob.glob(os.path.join(out, "compare-*/summary.json"))):
    name = os.path.basename(os.path.dirname(d))
    c = json.load(open(d))
    hull, tp, seed = sea(name)
    c_s, w_s = cpu(name)
    for m in c["models"]:
        e = m["errors_to_reference"]
        w = e["worst_output"]
        irr = m.get("irregular_sea_errors", {})
        cmp_rows.append({
            "scene": hull, "tp_s": tp, "seed": seed, "window_s": c["provenance"]["duration_s"], "model": m["model"],
            "worst_total": e["worst_normalized_rms"], "worst_output": w,
            "static_part": e[w]["static_error"], "dynamic_part": e[w]["dynamic_error"],
            "passed": m["verdict"]["passed"], "worst_statistic": irr.get("worst_statistic", float("nan")),
            "wire_tension_mpm_error": irr.get("responses", {}).get("wire_tension_N", {}).get("rayleigh_mpm_error", float("nan")),
            "cargo_heave_sigma_error": irr.get("responses", {}).get("cargo_heave_m", {}).get("sigma_error", float("nan")),
            "steps": m["solver"]["steps"], "rtol": c["provenance"]["rtol"], "integrator": c["provenance"]["integrator"],
            "reference": c["reference"]["model"], "compare_cpu_s": c_s})

def write_csv(name, rows):
    if not rows: return
    with open(os.path.join(out, name), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader(); w.writerows(rows)
write_csv("recommend.csv", rec_rows); write_csv("compare.csv", cmp_rows); write_csv("statistics.csv", stat_rows)
md = ["# Irregular-sea study (scripts/irregular-study.sh)", ""]
if rec_rows:
    md += ["## ffrf recommend (τ = 1 %)", "", "| scene | Tp [s] | seed | window [s] | recommended | error (worst output) | next cheaper: error | runs | CPU [s] |",
           "|---|--:|--:|--:|---|---|---|--:|--:|"]
    for r in rec_rows:
        md.append("| %s | %d | %d | %g | %s, %s %g | %s (%s) | %s: %s | %d | %.0f |" % (
            r["scene"], r["tp_s"], r["seed"], r["window_s"], r["recommended"], r["integrator"], r["rtol"], g(r["error"]),
            r["worst_output"], r["next_cheaper"], g(r["next_cheaper_error"]), r["runs"], r["cpu_s"]))
    md += ["", "Every candidate run (model, integrator, error, worst output):", ""]
    for r in rec_rows: md.append("* %s Tp %d seed %d: %s" % (r["scene"], r["tp_s"], r["seed"], r["candidates_run"]))
if cmp_rows:
    md += ["", "## ffrf compare", "", "| scene | Tp [s] | seed | model | worst total | worst output | static | dynamic | pass | worst statistic | tension MPM err | cargo heave σ err |",
           "|---|--:|--:|---|--:|---|--:|--:|---|--:|--:|--:|"]
    for r in cmp_rows:
        md.append("| %s | %d | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["scene"], r["tp_s"], r["seed"], r["model"], g(r["worst_total"]), r["worst_output"], g(r["static_part"]),
            g(r["dynamic_part"]), "pass" if r["passed"] else "FAIL", g(r["worst_statistic"]),
            g(r["wire_tension_mpm_error"]), g(r["cargo_heave_sigma_error"])))
if stat_rows:
    md += ["", "## Statistics of the recommended model's run (window after the ramp)", "",
           "| scene | Tp [s] | seed | model | Hs realised [m] | hull pitch σ [°] | cargo heave σ [m] | MPM [m] | max [m] | cargo pitch σ [°] | tension σ [MN] | tension MPM [MN] | max [MN] | static [MN] | detections |",
           "|---|--:|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|"]
    for r in stat_rows:
        md.append("| %s | %d | %d | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f | %.3f | %s |" % (
            r["scene"], r["tp_s"], r["seed"], r["model"], r["realised_hs_m"], r["crane_pitch_sigma_deg"], r["cargo_heave_sigma_m"],
            r["cargo_heave_mpm_m"], r["cargo_heave_max_m"], r["cargo_pitch_sigma_deg"], r["wire_tension_sigma_N"] / 1e6,
            r["wire_tension_mpm_N"] / 1e6, r["wire_tension_max_N"] / 1e6, r["static_tension_N"] / 1e6, r["detections"]))
open(os.path.join(out, "results.md"), "w").write("\n".join(md) + "\n")
PY
}

if [[ " $parts " == *" collect "* && "$parts" == collect ]]; then collect; exit 0; fi

queue=()
if [[ " $parts " == *" recommend "* ]]; then
  for tp in $periods; do for seed in $seeds; do
    queue+=("recommend-tp$tp-seed$seed recommend $(scene irregular_sea_crane.toml "hull-tp$tp-seed$seed" "$tp" "$seed")")
  done; done
fi
if [[ " $parts " == *" compare "* ]]; then
  for tp in ${COMPARE_PERIODS:-8}; do for seed in $seeds; do
    queue+=("compare-tp$tp-seed$seed compare $(scene irregular_sea_crane.toml "hull-tp$tp-seed$seed" "$tp" "$seed")")
  done; done
fi
if [[ " $parts " == *" bem "* ]]; then
  for seed in $seeds; do
    queue+=("recommend-bem-tp8-seed$seed recommend $(scene irregular_bem_barge_crane.toml "bem-tp8-seed$seed" 8 "$seed")")
  done
fi

# At most JOBS studies at once (each ffrf process is serial).
for entry in "${queue[@]}"; do
  while (( $(jobs -rp | wc -l) >= jobs )); do wait -n || true; done
  # shellcheck disable=SC2086
  study $entry &
done
wait

collect
echo "irregular-study: wrote $out/results.md, recommend.csv, compare.csv, statistics.csv" >&2
