#!/usr/bin/env bash
# Finkenzeller's detail against the grammar (issue 22's acceptance): the Gründerzeit street of
# scenes/gruenderzeit-street.xml (split grammar, rules/gruenderzeit) and of
# scenes/gruenderzeit-street-detail.xml (the same fifteen footprints built from floor-plan
# modules, with baked masonry, casings, swept cornices and consoles), both framed at
# 1920 × 1080. For each it prints the median of 5 runs of
#   * buildings per second: 15 over the wall time of `veduta info` (read, generate, bake, BVH);
#   * peak memory of `veduta render --spp 1` at 1920 × 1080 (geometry, textures, film);
# and the ratios detail / grammar. The issue asks for both ratios within 2. One warm-up run
# each first converts the scenes' texture files into the cache, as a user's second render finds
# them; the masonry is baked anew in every run (it reaches the renderer in memory).
#
#   bench/facade_street.sh [VEDUTA_BINARY]   (default build/release/src/veduta)
set -euo pipefail
cd "$(dirname "$0")/.."
veduta=${1:-build/release/src/veduta}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VEDUTA_CACHE_DIR=$work/cache

# The scenes at 1920 × 1080, beside the originals so that their relative paths hold.
framed() {
    local copy=scenes/.bench-$1.xml
    sed 's/resolution="960 540"/resolution="1920 1080"/' "scenes/$1.xml" >"$copy"
    echo "$copy"
}

median() { printf '%s\n' "$@" | sort -g | sed -n 3p; }

measure() {
    local scene=$1 walls=() rss=()
    "$veduta" info "$scene" >/dev/null 2>&1
    "$veduta" render "$scene" --spp 1 -q -o "$work/warm.exr" >/dev/null 2>&1
    for run in 1 2 3 4 5; do
        /usr/bin/time -f '%e' -o "$work/time" "$veduta" info "$scene" >/dev/null 2>&1
        walls+=("$(cat "$work/time")")
        /usr/bin/time -f '%M' -o "$work/time" "$veduta" render "$scene" --spp 1 -q -o "$work/r.exr" >/dev/null 2>&1
        rss+=("$(cat "$work/time")")
    done
    echo "$(median "${walls[@]}") $(median "${rss[@]}")"
}

grammar=$(framed gruenderzeit-street)
detail=$(framed gruenderzeit-street-detail)
trap 'rm -rf "$work" "$grammar" "$detail"' EXIT
read -r gWall gRss <<<"$(measure "$grammar")"
read -r dWall dRss <<<"$(measure "$detail")"
awk -v gw="$gWall" -v gr="$gRss" -v dw="$dWall" -v dr="$dRss" 'BEGIN {
    printf "grammar: %.1f buildings/s (info %.2f s), peak RSS %.0f MB\n", 15 / gw, gw, gr / 1024
    printf "detail:  %.1f buildings/s (info %.2f s), peak RSS %.0f MB\n", 15 / dw, dw, dr / 1024
    printf "speed ratio grammar/detail: %.2f (within 2: %s)\n", dw / gw, dw / gw <= 2 ? "yes" : "no"
    printf "memory ratio detail/grammar: %.2f (within 2: %s)\n", dr / gr, dr / gr <= 2 ? "yes" : "no"
}'
