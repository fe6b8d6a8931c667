#!/usr/bin/env bash
# README command 1: set up, build, and run the main job on the seed paper's scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
out=results/paper_floating_crane
./build/app/ffrf modes cases/paper_floating_crane.toml --modes 8 --out "$out/modes"
./build/app/ffrf compare cases/paper_floating_crane.toml --out "$out/compare"
echo "main job done: results in $out (report: $out/compare/report.md)"
