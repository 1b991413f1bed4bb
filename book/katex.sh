#!/bin/sh
# Regenerates book/src/katex/: the KaTeX stylesheet and fonts that the book
# ships so that no page loads anything from the network.
# Source: the npm package katex@0.16.4 (the version whose stylesheet
# mdbook-katex 0.10 links to; the HTML it pre-renders expects it).
# mdBook copies src/katex/ to the output; theme/head.hbs links the stylesheet.
# Only the woff2 fonts are kept (every current browser reads them); the
# stylesheet's woff and ttf fallbacks are removed to match.
# Needs npm (the npm registry). Run from anywhere: sh book/katex.sh
set -eu
version=0.16.4
root=$(cd "$(dirname "$0")" && pwd)
out="$root/src/katex"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && npm pack --silent "katex@$version" >/dev/null && tar xzf "katex-$version.tgz")
rm -rf "$out"
mkdir -p "$out/fonts"
cp "$tmp/package/LICENSE" "$out/LICENSE"
cp "$tmp"/package/dist/fonts/*.woff2 "$out/fonts/"
sed -e 's/,url(fonts\/[A-Za-z0-9_-]*\.woff) format("woff")//g' \
    -e 's/,url(fonts\/[A-Za-z0-9_-]*\.ttf) format("truetype")//g' \
    "$tmp/package/dist/katex.min.css" > "$out/katex.min.css"
echo "katex $version: $(ls "$out/fonts" | wc -l) fonts in $out"
