#!/usr/bin/env bash
# Measures the dev profile's trade: clean debug build time of the grader against
# the debug render time of two MIT 6.837 scenes at 200×200, for three variants:
#   plain  — every crate at opt-level 0 (cargo's default dev profile)
#   hot    — our own crates at opt-level 2 (the Cargo.toml of this repository)
#   all    — every crate, dependencies too, at opt-level 2
# Usage: scripts/measure-dev-profile.sh   (needs ../shared/data; takes ~10 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
data=../shared/data/mit6837
# The packages Cargo.toml names in its dev profile (not "*"): at their own levels in "hot".
named=$(sed -n 's/^\[profile\.dev\.package\.\([^]*"]*\)\]$/\1/p' Cargo.toml)
plain=(--config 'profile.dev.opt-level=0')
for p in $named; do plain+=(--config "profile.dev.package.\"$p\".opt-level=0"); done
all=(--config 'profile.dev.opt-level=2' --config 'profile.dev.package."*".opt-level=2')
for p in $named; do all+=(--config "profile.dev.package.\"$p\".opt-level=2"); done

run() {
  local name=$1; shift
  local target; target=$(mktemp -d)
  local start end
  start=$(date +%s.%N)
  CARGO_TARGET_DIR=$target cargo build -q -p grader "$@"
  end=$(date +%s.%N)
  local t1 t2
  t1=$( { /usr/bin/time -f %e "$target/debug/grader" render "$data/scene2_16_t_scale.txt" --size 200x200 -o "$target/a.png"; } 2>&1 | tail -1)
  t2=$( { /usr/bin/time -f %e "$target/debug/grader" render "$data/scene3_04_bunny_mesh_1k.txt" --size 200x200 -o "$target/b.png"; } 2>&1 | tail -1)
  printf '%-6s clean build %6.1f s   scene2_16 %6.2f s   bunny 1k %6.2f s\n' "$name" "$(echo "$end - $start" | bc)" "$t1" "$t2"
  rm -rf "$target"
}
run plain "${plain[@]}"
run hot
run all "${all[@]}"
