#!/bin/sh
# Copies the reference images the book shows into book/src/figures/.
# Source: the lectures' snapshots, lectures/NN-name/snapshots/SCENE.png, which
# `cargo run -p grader -- bless` regenerates from the reference solutions.
# A figure is named NN-SCENE.png (NN = the lecture = the chapter). Depth and
# normal figures (NN-SCENE.depth.png, .normal.png) are rendered by the
# reference with `grader render --aov` (it builds the workspace if needed).
# Run from anywhere: sh book/figures.sh
#
# sh book/figures.sh --check   changes nothing; fails (exit 1) naming every
#   figure that differs from its snapshot (stale: run sh book/figures.sh),
#   whose snapshot is missing, or that is in src/figures/ but not listed here.
#   Byte-equal is the right test: a figure is a copy of its snapshot, or a
#   render that the same code repeats pixel for pixel.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/book/src/figures"
check=false
case "${1:-}" in
    --check) check=true ;;
    "") ;;
    *) echo "usage: sh book/figures.sh [--check]" >&2; exit 2 ;;
esac
problems=0
listed=""
copy() { # lecture-folder scene...
    lecture=$1; shift
    n=$(echo "$lecture" | cut -c1-2)
    for scene in "$@"; do
        src="$root/lectures/$lecture/snapshots/$scene.png"
        dst="$out/$n-$scene.png"
        listed="$listed $n-$scene.png"
        if ! $check; then
            mkdir -p "$out"
            cp "$src" "$dst"
        elif [ ! -f "$src" ]; then
            echo "figures: no snapshot lectures/$lecture/snapshots/$scene.png for book/src/figures/$n-$scene.png"
            problems=$((problems + 1))
        elif [ ! -f "$dst" ]; then
            echo "figures: missing book/src/figures/$n-$scene.png (copy of lectures/$lecture/snapshots/$scene.png)"
            problems=$((problems + 1))
        elif ! cmp -s "$src" "$dst"; then
            echo "figures: stale book/src/figures/$n-$scene.png (differs from lectures/$lecture/snapshots/$scene.png)"
            problems=$((problems + 1))
        fi
    done
}
# render lecture-folder scene aov: the scene's depth or normal image as a
# viewable PNG (`grader render --aov depth|normal -o X.png`), rendered afresh
# by the reference (in --check too: compared with the committed figure).
render() {
    lecture=$1; scene=$2; aov=$3
    n=$(echo "$lecture" | cut -c1-2)
    dst="$out/$n-$scene.$aov.png"
    listed="$listed $n-$scene.$aov.png"
    tmp=$(mktemp --suffix=.png)
    (cd "$root" && cargo run -q -p grader -- render "lectures/$lecture/scenes/$scene.toml" --aov "$aov" -o "$tmp") >/dev/null
    if ! $check; then
        mkdir -p "$out"
        cp "$tmp" "$dst"
    elif [ ! -f "$dst" ]; then
        echo "figures: missing book/src/figures/$n-$scene.$aov.png (grader render --aov $aov)"
        problems=$((problems + 1))
    elif ! cmp -s "$tmp" "$dst"; then
        echo "figures: stale book/src/figures/$n-$scene.$aov.png (differs from a fresh grader render --aov $aov)"
        problems=$((problems + 1))
    fi
    rm -f "$tmp"
}
copy 01-transforms perspective orthographic rolled
copy 02-ray-casting spheres-on-plane spheres-on-plane.id overlapping-depths inside-sphere
render 02-ray-casting spheres-on-plane depth
render 02-ray-casting spheres-on-plane normal
copy 03-polygons-triangles boxes polygons triangles meshes
copy 04-quadrics-transforms cylinders-cones ellipsoid extreme-scale transformed-mesh
copy 05-shading phong-exponents blinn-vs-phong coloured-lights attenuation spot
copy 06-shadows sphere-shadow coloured-shadows far-from-origin soft-shadows-1 soft-shadows-4 soft-shadows-16 soft-shadows-64
copy 07-reflection-refraction mirror-floor reflective-sphere glass-spheres tir-slab
copy 08-ray-tree whitted whitted-no-shadows facing-mirrors
copy 09-acceleration many-spheres torus-65k
copy 10-textures-sampling checkerboard solid-checker checker-aliasing-1spp checker-aliasing-16spp
if ! $check; then
    echo "figures: $(ls "$out" | wc -l) files in $out"
    exit 0
fi
# Figures that no line above makes (left behind by a renamed scene).
for file in "$out"/*; do
    [ -e "$file" ] || continue
    name=$(basename "$file")
    case " $listed " in
        *" $name "*) ;;
        *) echo "figures: book/src/figures/$name is not made by book/figures.sh"; problems=$((problems + 1)) ;;
    esac
done
if [ "$problems" -gt 0 ]; then
    echo "figures: $problems problem(s); regenerate with: sh book/figures.sh"
    exit 1
fi
echo "figures: all $(echo $listed | wc -w) figures match their snapshots"
