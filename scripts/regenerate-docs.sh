#!/usr/bin/env bash
# Regenerates the examples in README.md and docs/user-guide.md from real runs of ./build/app/ffrf:
# every block between
#   <!-- BEGIN generated: ID (scripts/regenerate-docs.sh) -->
#   <!-- END generated: ID -->
# is replaced by the output of the command below with that ID (a code block with the command line,
# or, for the README's main-job verdict, the verdict section of the main job's compare report).
# The README's verdict numbers are checked against a fresh run of the main job's compare by the
# test ReadmeNumbers (tests/app/test_readme_numbers.cpp). With --figures, the charts the docs show
# are copied from these runs into docs/figures/ as well.
#
# Usage: bash scripts/regenerate-docs.sh [--figures]      (after a build: cmake --build build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ffrf="$root/build/app/ffrf"
[[ -x "$ffrf" ]] || { echo "regenerate-docs: $ffrf missing: build first (cmake --build build)" >&2; exit 2; }
figures=false
[[ "${1:-}" == "--figures" ]] && figures=true

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
ln -s "$root/cases" "$work/cases"
cd "$work"

# replace FILE ID CONTENT_FILE: the block ID of FILE becomes the content of CONTENT_FILE.
replace() {
  local file="$1" id="$2" content="$3"
  grep -q "<!-- BEGIN generated: $id " "$file" || { echo "regenerate-docs: no block '$id' in $file" >&2; exit 1; }
  awk -v id="$id" -v content="$content" '
    index($0, "<!-- BEGIN generated: " id " ") == 1 { print; while ((getline line < content) > 0) print line; skip = 1; next }
    index($0, "<!-- END generated: " id " ") == 1 { skip = 0 }
    !skip { print }' "$file" > "$file.new"
  mv "$file.new" "$file"
}

# example FILE ID "ARGS" [FILTER]: runs `ffrf ARGS` here (stdout and stderr), filters it, and
# writes it as a code block headed by "$ ffrf ARGS".
example() {
  local file="$1" id="$2" args="$3" filter="${4:-cat}"
  echo "regenerate-docs: ffrf $args" >&2
  {
    echo '```'
    echo "\$ ffrf $args"
    eval "\"$ffrf\" $args" 2>&1 < /dev/null | eval "$filter" || true
    echo '```'
  } > "$work/block.md"
  replace "$root/$file" "$id" "$work/block.md"
}

readme=README.md
guide=docs/user-guide.md

# --- README: the main job's verdict and the modes example ---
echo "regenerate-docs: ffrf compare cases/paper_floating_crane.toml (the main job's compare)" >&2
"$ffrf" compare cases/paper_floating_crane.toml --out main-compare > /dev/null < /dev/null
sed -n '/<!-- verdict:begin -->/,/<!-- verdict:end -->/p' main-compare/report.md | sed '1d;$d' > verdict.md
replace "$root/$readme" main-job-verdict "$work/verdict.md"
example "$readme" readme-modes "modes cases/paper_floating_crane.toml --modes 6"

# --- user guide ---
cat > bad_scene.toml <<'EOF'
[boom]
length = "120 kg"
youngs_modulus = 2.1e11
area = 0
second_moment = 8.333e-6
density = 7850
elemnts = 8
EOF
example "$guide" check-bad "check bad_scene.toml"
example "$guide" check-ok "check cases/paper_floating_crane.toml"
example "$guide" modes-cantilever "modes cases/cantilever.toml --elements 64"
example "$guide" modes-supported "modes cases/pinned_luffing_crane.toml"
example "$guide" modes-a-frame "modes cases/a_frame_crane.toml" "sed -n '/^supported boom/,\$p'"
example "$guide" modes-spin "modes cases/spin_up_beam.toml --spin 5 --modes 4"
example "$guide" modes-campbell "modes cases/spin_up_beam.toml --spin-range 0:20:5" \
  "awk 'NR == 1 { print \"...\" } /^spin \\[rad\\/s\\]/ { table = 1 } table && NF'"
example "$guide" modes-axial "modes cases/cantilever.toml --axial-force -20000 --modes 3" \
  "awk '/^axial/ { print \"...\"; print; next } /^mode / { print \"...\"; table = 1 } table && NF'"
example "$guide" run-example "run cases/paper_floating_crane.toml --integrator ida --out run-out"
example "$guide" statics-example "statics cases/large_crane.toml"
example "$guide" run-divergence "run cases/spin_up_beam.toml --stiffening none" "grep 'solver failure'"
sed 's/^mass = 1.3e6 /mass = 14.0e6/' cases/paper_floating_crane.toml > heavy_cargo.toml
example "$guide" run-newton "run heavy_cargo.toml --out out" "grep -v 'warning:\|note:'"
example "$guide" compare-example "compare cases/paper_floating_crane.toml --out cmp"
example "$guide" sweep-example "sweep cases/paper_floating_crane.toml --quick --out sw"
example "$guide" recommend-example "recommend cases/paper_floating_crane.toml --tolerance 1%"
example "$guide" bem-run "run cases/bem_barge_crane.toml --radiation state-space --duration 30" "grep -v 'note:' | sed -n '1,4p'"
example "$guide" bem-compare "compare cases/bem_barge_crane.toml --duration 30" "awk '/^radiation models/ { p = 1 } p'"
example "$guide" capytaine-run "run cases/capytaine_barge_crane.toml --duration 10" "grep -v 'note:' | sed -n '1,6p'"
example "$guide" rao-example "rao cases/paper_floating_crane.toml --check-time-domain --out rao" \
  "awk 'NR <= 11 { print; next } NR == 12 { print \"...\" } /^time-domain check/'"

if $figures; then
  cp cmp/cargo_heave.png "$root/docs/figures/compare_cargo_heave.png"
  echo "regenerate-docs: copied cmp/cargo_heave.png to docs/figures/compare_cargo_heave.png" >&2
fi
echo "regenerate-docs: done (review with git diff)" >&2
