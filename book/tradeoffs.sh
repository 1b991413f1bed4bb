#!/bin/sh
# Measures the speed/accuracy trade (`grader tradeoffs`, release build, f32 and
# f64 in one run, ~2 minutes on the 2-core machines) and copies its Markdown
# tables and SVG plots into book/src/tradeoffs/, which the appendix
# "Speed against accuracy" includes. Run from anywhere: sh book/tradeoffs.sh
#
# Not part of book/figures.sh --check: the times differ from run to run (the
# tables state the machine's noise), so a fresh run never equals the copy byte
# for byte; the accuracy columns are those of the fixed seeds.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cargo run --release -q -p grader -- tradeoffs
mkdir -p book/src/tradeoffs
cp target/grader/tradeoffs/*.svg book/src/tradeoffs/
# The tables link their plots beside them; the appendix that includes them sits one folder up.
sed -e '/^# Speed against accuracy$/d' -e 's|](\([a-z]*\.svg\))|](tradeoffs/\1)|g' target/grader/tradeoffs/tradeoffs.md > book/src/tradeoffs/tradeoffs.md
echo "tradeoffs: copied into book/src/tradeoffs/ ($(date -u +%Y-%m-%d))"
