#!/usr/bin/env bash
# Records the regression baselines of the shipped scenes, cases/baselines/*.json, which ffrf's own
# ctest checks (`baseline_*` tests, added with cmake/FfrfBaseline.cmake in tests/app/CMakeLists.txt).
# Run from anywhere after building; the program defaults to build/app/ffrf of this checkout:
#   bash scripts/record_baselines.sh [path/to/ffrf]
# Re-record only when a change is meant to move the results, and say why in the commit
# (docs/baselines.md, "When to re-record").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ffrf=$(realpath "${1:-$root/build/app/ffrf}")
cd "$root"
record() { "$ffrf" baseline record "$@" </dev/null; }
record cases/paper_floating_crane.toml --duration 40 --out cases/baselines/paper_floating_crane.json
record cases/paper_floating_crane.toml --boom modal --modes 2 --static-modes --stiffening static --duration 40 \
  --out cases/baselines/paper_floating_crane_modal.json
record cases/dropped_load.toml --outputs tip_transverse_m,wire_tension_N,cargo_heave_m \
  --out cases/baselines/dropped_load.json
record cases/spin_up_beam.toml --out cases/baselines/spin_up_beam.json
