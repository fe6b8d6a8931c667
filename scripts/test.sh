#!/usr/bin/env bash
# README command 2: set up, build, and run the whole test suite (ctest over GoogleTest; the
# `slow` label runs too).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
ctest --output-on-failure -j"$(nproc)" --timeout 900
