#!/bin/sh
# Every figure and table of the book, made afresh by the reference: the
# lectures' scene snapshots and depth/normal renders (figures.sh, seconds) and
# the speed/accuracy tables and plots (tradeoffs.sh, a release run of about two
# minutes). Run from anywhere: sh book/regenerate.sh
set -eu
book=$(cd "$(dirname "$0")" && pwd)
sh "$book/figures.sh"
sh "$book/tradeoffs.sh"
