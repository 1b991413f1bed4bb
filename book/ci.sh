#!/usr/bin/env bash
# CI for the course book. Run from anywhere: bash book/ci.sh
# (.ci/run calls it after the Rust tests, with the workspace already built).
#
# 1. tools: installs mdBook and mdbook-katex at the pinned versions when they
#    are missing or of another version (cargo install --locked; ≈ 95 s + 45 s);
# 2. build: `mdbook build book`, failing on any WARN or ERROR line;
# 3. the handout's book: `grader handout`, then `mdbook build book` in it, as a
#    student builds it: no WARN or ERROR (nothing it includes is left out of the
#    handout), and its links resolve;
#    links: book/linkcheck.py on the built HTML (relative links, images and
#    #fragments resolve; no page loads anything from the network);
# 4. figures: book/figures.sh --check (every figure equals its snapshot);
# 5. browser: installs Debian's chromium when /usr/bin/chromium is missing, then
#    book/browsercheck.py opens chapters in headless Chromium (math rendered
#    with the shipped KaTeX stylesheet and fonts, every image loaded);
# 6. doctests: every ```rust block of the book, against the workspace crates.
set -euo pipefail
book=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$book")
cd "$root"

# The versions of the tools the book is built with (pinned: a new mdBook may
# reject book.toml or render differently; mdbook-katex 0.10 expects KaTeX 0.16.4,
# whose stylesheet and fonts ship in src/katex/).
MDBOOK_VERSION=0.5.4
MDBOOK_KATEX_VERSION=0.10.0
# mdbook-katex 0.10.0 (its --locked dependencies) is built against mdBook 0.5.3 and
# says so on every build under mdBook 0.5.4; harmless for this pair, and the only
# warning allowed below.
KNOWN_WARNING="mdbook-katex was built against mdbook v0.5.3, but we are being called from mdbook v$MDBOOK_VERSION"

step() { printf '\n=== book: %s (%s)\n' "$*" "$(date -u +%H:%M:%S)"; }
export PATH="${CARGO_HOME:-$HOME/.cargo}/bin:$PATH"

step "tools: mdbook $MDBOOK_VERSION, mdbook-katex $MDBOOK_KATEX_VERSION"
installed_version() { # tool -> its version number, or nothing when it is missing
    command -v "$1" >/dev/null 2>&1 || return 0
    "$1" --version 2>/dev/null | awk '{print $2}' | sed 's/^v//'
}
install_tool() { # crate version
    if [ "$(installed_version "$1")" = "$2" ]; then
        echo "$1 $2: installed"
    else
        echo "$1 $2: installing (found: $(installed_version "$1"))"
        cargo install --locked --quiet --version "$2" "$1"
    fi
}
install_tool mdbook "$MDBOOK_VERSION"
install_tool mdbook-katex "$MDBOOK_KATEX_VERSION"

step "build: mdbook build book"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
mdbook build book >"$log" 2>&1 || status=$?
# Colour codes out (some lines carry them), then every WARN/ERROR line but the known one.
sed -e 's/\x1b\[[0-9;]*m//g' "$log" >"$log.plain" && mv "$log.plain" "$log"
cat "$log"
problems=$(grep -E '(^|[[:space:]])(WARN|WARNING|ERROR)([[:space:]]|$)|\[(WARN|WARNING|ERROR)\]' "$log" \
    | grep -vF "$KNOWN_WARNING" || true)
if [ "$status" -ne 0 ] || [ -n "$problems" ]; then
    echo "book: mdbook build failed (exit $status) or warned:"
    printf '%s\n' "$problems"
    exit 1
fi

step "the handout's book: grader handout, then mdbook build book there, as a student does"
# Nothing it includes or links may be missing from the handout (the checks' tests, the
# instructors' scripts and documents are left out of it).
handout=$(mktemp -d)
trap 'rm -f "$log"; rm -rf "$handout"' EXIT
cargo run -q -p grader -- handout --force "$handout/raylab" >/dev/null
status=0
(cd "$handout/raylab" && mdbook build book) >"$log" 2>&1 || status=$?
sed -e 's/\x1b\[[0-9;]*m//g' "$log" >"$log.plain" && mv "$log.plain" "$log"
problems=$(grep -E '(^|[[:space:]])(WARN|WARNING|ERROR)([[:space:]]|$)|\[(WARN|WARNING|ERROR)\]' "$log" \
    | grep -vF "$KNOWN_WARNING" || true)
if [ "$status" -ne 0 ] || [ -n "$problems" ]; then
    cat "$log"
    echo "book: the handout's book failed to build (exit $status) or warned:"
    printf '%s\n' "$problems"
    exit 1
fi
python3 "$book/linkcheck.py" "$handout/raylab/book/book"
echo "the handout's book builds without a warning, and its links resolve"

step "links: python3 book/linkcheck.py"
python3 "$book/linkcheck.py" "$book/book"

step "figures: sh book/figures.sh --check"
sh "$book/figures.sh" --check

step "browser: headless Chromium"
if [ ! -x /usr/bin/chromium ]; then
    if ! command -v apt-get >/dev/null 2>&1; then
        echo "book: /usr/bin/chromium is missing and apt-get is unavailable: install Debian's chromium package"
        exit 1
    fi
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        command -v sudo >/dev/null 2>&1 || { echo "book: installing chromium needs root or sudo"; exit 1; }
        sudo="sudo"
    fi
    echo "installing chromium (apt-get)"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends chromium >/dev/null
fi
python3 "$book/browsercheck.py" --chromium /usr/bin/chromium --book "$book/book"

step "doctests: cargo test -p book-doctests --doc"
cargo test -p book-doctests --doc

step "book: all checks passed"
