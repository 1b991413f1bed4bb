#!/usr/bin/env bash
# Primary-ray throughput: lecture 09's BVH (`grader bench-rays`) against Embree 4
# (`benches/embree_compare.py`), one thread each, on the Stanford bunny and on a
# generated 80k-triangle torus; prints both figures and the ratio ours/Embree.
#
#   benches/bench_rays.sh                  # REPEAT=5 runs each, median
#   CARGO_TARGET_DIR=/tmp/bench benches/bench_rays.sh
#
# The bunny is ../shared/data/meshes/stanford-bunny.obj (69,451 triangles; not
# shipped with the project): when it is absent that half says SKIPPED.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
REPEAT="${REPEAT:-5}"
DATA="${RAYLAB_SHARED_DATA:-$ROOT/../shared/data}"
BUNNY="$DATA/meshes/stanford-bunny.obj"

cd "$ROOT"
cargo build --release -p grader --quiet
GRADER="$TARGET/release/grader"

# Mrays/s from a line "... Mrays/s: F hits: N ...".
rate() { sed -n 's/.*Mrays\/s: \([0-9.]*\).*/\1/p' <<<"$1" | head -n 1; }
ratio() { python3 -c "print('%.2f' % ($1 / $2))"; }

compare() {
    local name="$1"
    shift
    echo "== $name"
    local out ours cpu embree robust fast
    out="$("$GRADER" bench-rays "$@" --threads 1 --repeat "$REPEAT" 2>&1)"
    ours="$(grep '^Mrays/s' <<<"$out")"
    # By CPU time, as Embree's side is timed (time.process_time); wall time if unknown.
    cpu="$(rate "$(grep '^cpu Mrays/s' <<<"$out")")"
    cpu="${cpu:-$(rate "$ours")}"
    embree="$(python3 "$ROOT/benches/embree_compare.py" "$@" --repeat "$REPEAT")"
    echo "raylab bvh   : $ours (wall time); by CPU time: $cpu"
    echo "$embree"
    robust="$(rate "$(grep robust <<<"$embree")")"
    fast="$(rate "$(grep fast <<<"$embree")")"
    echo "ratio ours/embree by CPU time: $(ratio "$cpu" "$robust") (robust), $(ratio "$cpu" "$fast") (fast)"
}

if [[ -f "$BUNNY" ]]; then
    compare "Stanford bunny, 1000x1000 (expected hits: 353424)" "$BUNNY" --size 1000x1000 \
        --eye -0.0168,0.110,0.30 --at -0.0168,0.110,-0.0015 --up 0,1,0 --fovy 40
else
    echo "!!!!!!!! SKIPPED the Stanford bunny: $BUNNY is not here (set RAYLAB_SHARED_DATA) !!!!!!!!"
fi

compare "generated torus, about 80k triangles, 1000x1000" --generated 80000 --size 1000x1000 \
    --eye 0,-2.6,2.6 --at 0,0,0 --up 0,0,1 --fovy 40
