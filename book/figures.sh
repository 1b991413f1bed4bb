#!/bin/sh
# Copies the reference images the book shows into book/src/figures/.
# Source: the lectures' snapshots, which `cargo run -p grader -- bless`
# regenerates from the reference solutions: lectures/NN-name/snapshots/
# SCENE.final.png (the complete tracer) becomes the figure NN-SCENE.png (NN =
# the lecture = the chapter; lecture 10's own SCENE.png is its final picture);
# SCENE.png (lecture NN's stage: what a student sees once lecture NN is done)
# becomes NN-SCENE.stage.png; other snapshots (SCENE.id) keep their name. Depth and
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
put() { # lecture-folder snapshot-file figure-file
    src="$root/lectures/$1/snapshots/$2"
    dst="$out/$3"
    listed="$listed $3"
    if ! $check; then
        mkdir -p "$out"
        cp "$src" "$dst"
    elif [ ! -f "$src" ]; then
        echo "figures: no snapshot lectures/$1/snapshots/$2 for book/src/figures/$3"
        problems=$((problems + 1))
    elif [ ! -f "$dst" ]; then
        echo "figures: missing book/src/figures/$3 (copy of lectures/$1/snapshots/$2)"
        problems=$((problems + 1))
    elif ! cmp -s "$src" "$dst"; then
        echo "figures: stale book/src/figures/$3 (differs from lectures/$1/snapshots/$2)"
        problems=$((problems + 1))
    fi
}
copy() { # lecture-folder snapshot...: SNAPSHOT.png as NN-SNAPSHOT.png
    lecture=$1; shift
    n=$(echo "$lecture" | cut -c1-2)
    for scene in "$@"; do put "$lecture" "$scene.png" "$n-$scene.png"; done
}
final() { # lecture-folder scene...: the complete tracer's SCENE.final.png as NN-SCENE.png
    lecture=$1; shift
    n=$(echo "$lecture" | cut -c1-2)
    for scene in "$@"; do put "$lecture" "$scene.final.png" "$n-$scene.png"; done
}
stage() { # lecture-folder scene...: the lecture's stage, SCENE.png, as NN-SCENE.stage.png
    lecture=$1; shift
    n=$(echo "$lecture" | cut -c1-2)
    for scene in "$@"; do put "$lecture" "$scene.png" "$n-$scene.stage.png"; done
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
final 01-transforms perspective orthographic rolled
stage 01-transforms perspective orthographic rolled
final 02-ray-casting spheres-on-plane overlapping-depths inside-sphere
copy 02-ray-casting spheres-on-plane.id
stage 02-ray-casting spheres-on-plane overlapping-depths inside-sphere orthographic
render 02-ray-casting spheres-on-plane depth
render 02-ray-casting spheres-on-plane normal
final 03-polygons-triangles boxes polygons triangles meshes
stage 03-polygons-triangles boxes polygons triangles meshes
final 04-quadrics-transforms cylinders-cones ellipsoid extreme-scale transformed-mesh
stage 04-quadrics-transforms cylinders-cones ellipsoid extreme-scale transformed-mesh
final 05-shading phong-exponents blinn-vs-phong coloured-lights attenuation spot
stage 05-shading phong-exponents blinn-vs-phong coloured-lights attenuation spot
final 06-shadows sphere-shadow coloured-shadows far-from-origin soft-shadows-1 soft-shadows-4 soft-shadows-16 soft-shadows-64
stage 06-shadows sphere-shadow coloured-shadows glass-shadow-filtered soft-shadows-16
final 07-reflection-refraction mirror-floor reflective-sphere glass-spheres tir-slab
stage 07-reflection-refraction mirror-floor reflective-sphere glass-spheres tir-slab
final 08-ray-tree whitted whitted-no-shadows facing-mirrors
stage 08-ray-tree whitted whitted-no-shadows facing-mirrors
final 09-acceleration many-spheres torus-65k
stage 09-acceleration many-spheres torus-65k
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
