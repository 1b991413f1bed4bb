#!/bin/sh
# Copies the reference images the book shows into book/src/figures/.
# Source: the lectures' snapshots, which `cargo run -p grader -- bless`
# regenerates from the reference solutions: lectures/NN-name/snapshots/
# SCENE.png (lecture NN's stage: what a student sees once lecture NN is done)
# becomes NN-SCENE.stage.png (NN = the lecture = the chapter); lecture 10's own
# SCENE.png, its final picture, becomes NN-SCENE.png; other snapshots (SCENE.id)
# keep their name. The complete tracer's picture of an earlier lecture's scene
# (NN-SCENE.png) is rendered by the reference at the scene's size with `grader
# render --stage 10` (the graded SCENE.final.png is drawn at half the width and
# height), and the depth and normal figures (NN-SCENE.depth.png, .normal.png)
# with `grader render --aov` (it builds the workspace if needed).
# Run from anywhere: sh book/figures.sh
#
# sh book/figures.sh --check   changes nothing; fails (exit 1) naming every
#   figure that differs from its snapshot (stale: run sh book/figures.sh),
#   whose snapshot is missing, or that is in src/figures/ but shown by no chapter.
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
# render lecture-folder scene figure-file grader-render-flags…: the scene
# drawn by `grader render FLAGS -o X.png` (the complete tracer's picture with
# `--stage 10`, the depth or normal image as a viewable PNG with `--aov`),
# rendered afresh by the reference (in --check too: compared with the
# committed figure).
render() {
    lecture=$1; scene=$2; figure=$3; shift 3
    dst="$out/$figure"
    listed="$listed $figure"
    tmp=$(mktemp --suffix=.png)
    # cargo's and the grader's build lines only where the render fails.
    if ! (cd "$root" && cargo run -q -p grader -- render "lectures/$lecture/scenes/$scene.toml" "$@" -o "$tmp") \
        >/dev/null 2>"$tmp.err"; then
        cat "$tmp.err" >&2
        exit 1
    fi
    rm -f "$tmp.err"
    if ! $check; then
        mkdir -p "$out"
        cp "$tmp" "$dst"
    elif [ ! -f "$dst" ]; then
        echo "figures: missing book/src/figures/$figure (grader render $*)"
        problems=$((problems + 1))
    elif ! cmp -s "$tmp" "$dst"; then
        echo "figures: stale book/src/figures/$figure (differs from a fresh grader render $*)"
        problems=$((problems + 1))
    fi
    rm -f "$tmp"
}
# The figures are those the chapters show: every figures/NN-NAME.png named in
# book/src/*.md, made from lecture NN's snapshots by the rules above.
lecture_folder() { # NN: the name of the folder lectures/NN-*
    for dir in "$root"/lectures/"$1"-*/; do basename "$dir"; return; done
}
shown=$(grep -oh 'figures/[0-9][0-9]-[A-Za-z0-9._-]*\.png' "$root"/book/src/*.md | sed 's#^figures/##' | sort -u)
for figure in $shown; do
    lecture=$(lecture_folder "$(echo "$figure" | cut -c1-2)")
    name=${figure#??-}
    name=${name%.png}
    case "$name" in
        *.stage) put "$lecture" "${name%.stage}.png" "$figure" ;;
        *.depth | *.normal) render "$lecture" "${name%.*}" "$figure" --aov "${name##*.}" ;;
        *)
            # The complete tracer's picture at the scene's size where its graded final picture
            # is (lectures 01–09), else the snapshot itself (lecture 10's own scenes, geometry
            # images such as SCENE.id).
            if [ -f "$root/lectures/$lecture/snapshots/$name.final.png" ]; then
                render "$lecture" "$name" "$figure" --stage 10
            else
                put "$lecture" "$name.png" "$figure"
            fi
            ;;
    esac
done
# The ray tree chapter 8 prints: the grader's own test snapshot (ray_tree_cli), from its line 5
# (after insta's header), so that the book shows what `grader render --tree` prints and the
# handout, which has no checks' tests, still has it.
tree_src="$root/grader/checks/tests/snapshots/ray_tree_cli__glass_sphere_pixel_100_75.snap"
tree="08-glass-sphere-tree.txt"
listed="$listed $tree"
if ! $check; then
    mkdir -p "$out"
    tail -n +5 "$tree_src" >"$out/$tree"
elif ! tail -n +5 "$tree_src" | cmp -s - "$out/$tree"; then
    echo "figures: stale or missing book/src/figures/$tree (lines 5– of $tree_src)"
    problems=$((problems + 1))
fi
if ! $check; then
    echo "figures: $(ls "$out" | wc -l) files in $out"
    exit 0
fi
# Figures that no chapter shows (left behind by a renamed scene).
for file in "$out"/*; do
    [ -e "$file" ] || continue
    name=$(basename "$file")
    case " $listed " in
        *" $name "*) ;;
        *) echo "figures: book/src/figures/$name is shown by no chapter"; problems=$((problems + 1)) ;;
    esac
done
if [ "$problems" -gt 0 ]; then
    echo "figures: $problems problem(s); regenerate with: sh book/figures.sh"
    exit 1
fi
echo "figures: all $(echo $listed | wc -w) figures match their snapshots and renders"
