#!/bin/sh
# Copies the reference images the book shows into book/src/figures/.
# Source: the lectures' snapshots, lectures/NN-name/snapshots/SCENE.png, which
# `cargo run -p grader -- bless` regenerates from the reference solutions.
# A figure is named NN-SCENE.png (NN = the lecture = the chapter).
# Run from anywhere: sh book/figures.sh
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/book/src/figures"
mkdir -p "$out"
copy() { # lecture-folder scene...
    lecture=$1; shift
    n=$(echo "$lecture" | cut -c1-2)
    for scene in "$@"; do
        cp "$root/lectures/$lecture/snapshots/$scene.png" "$out/$n-$scene.png"
    done
}
copy 01-transforms perspective orthographic rolled
copy 02-ray-casting spheres-on-plane spheres-on-plane.id overlapping-depths inside-sphere
copy 03-polygons-triangles boxes polygons triangles meshes
copy 04-quadrics-transforms cylinders-cones ellipsoid extreme-scale transformed-mesh
copy 05-shading phong-exponents blinn-vs-phong coloured-lights attenuation spot
copy 06-shadows sphere-shadow coloured-shadows far-from-origin soft-shadows-1 soft-shadows-4 soft-shadows-16 soft-shadows-64
copy 07-reflection-refraction mirror-floor reflective-sphere glass-spheres tir-slab
copy 08-ray-tree whitted whitted-no-shadows facing-mirrors
copy 09-acceleration many-spheres torus-65k
echo "figures: $(ls "$out" | wc -l) files in $out"
