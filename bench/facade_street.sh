#!/usr/bin/env bash
# Finkenzeller's detail against the grammar (issue 22's acceptance): the Gründerzeit street of
# scenes/gruenderzeit-street.xml (split grammar, rules/gruenderzeit) and of
# scenes/gruenderzeit-street-detail.xml (the same fifteen footprints built from floor-plan
# modules, with masonry, casings, swept cornices and consoles), both framed at 1920 × 1080; the
# detail street twice, its masonry baked (as the scene is) and shaded procedurally
# (<render masonry="procedural">). For each it prints
#   * rendered: 15 buildings over the wall time of `veduta render --spp 16` (read, generate,
#     bake, BVH, trace), the median of 3 runs — the issue's "rendered at 1920 × 1080";
#   * scene: 15 over the wall time of `veduta info` (read, generate, bake, BVH), median of 5;
#   * generation alone: `veduta info` less the same scene without its buildings (reading the
#     materials, the sky, starting the texture system), medians of 5: what the buildings cost;
#   * peak memory of the render;
# and the ratios detail / grammar. The issue asks for the rendered speed and the memory within 2.
# One warm-up run each first converts the scenes' texture files into the cache, as a user's
# second render finds them; baked masonry is baked anew in every run (it reaches the renderer in
# memory).
#
#   bench/facade_street.sh [VEDUTA_BINARY]   (default build/release/src/veduta)
set -euo pipefail
cd "$(dirname "$0")/.."
veduta=${1:-build/release/src/veduta}
work=$(mktemp -d)
copies=()
trap 'rm -rf "$work" "${copies[@]}"' EXIT
export VEDUTA_CACHE_DIR=$work/cache

# The scenes at 1920 × 1080, beside the originals so that their relative paths hold, and the
# same without their buildings.
framed() {
    local copy=scenes/.bench-$1.xml
    sed 's/resolution="960 540"/resolution="1920 1080"/' "scenes/$1.xml" >"$copy"
    sed '/<buildings /,/<\/buildings>/d; /<modular_building /d' "$copy" >"scenes/.bench-$1-empty.xml"
    copies+=("$copy" "scenes/.bench-$1-empty.xml")
}

median() { printf '%s\n' "$@" | sort -g | sed -n "$((($# + 1) / 2))p"; }

# The wall time of one run of veduta with the arguments, to the millisecond (time's %e has only
# ten), its peak memory in $work/time; a failed run ends the benchmark.
seconds() {
    local start end
    start=$(date +%s%N)
    if ! /usr/bin/time -f '%M' -o "$work/time" "$veduta" "$@" >/dev/null 2>"$work/err"; then
        echo "facade_street.sh: veduta $* failed:" >&2
        tail -3 "$work/err" >&2
        kill -TERM $$
    fi
    end=$(date +%s%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f\n", (b - a) / 1e9 }'
}

measure() {
    local scene=scenes/.bench-$1.xml empty=scenes/.bench-$1-empty.xml infos=() bare=() renders=() rss=()
    seconds info "$scene" >/dev/null
    seconds render "$scene" --spp 1 -q -o "$work/warm.exr" >/dev/null
    for run in 1 2 3 4 5; do
        infos+=("$(seconds info "$scene")")
        bare+=("$(seconds info "$empty")")
    done
    for run in 1 2 3; do
        renders+=("$(seconds render "$scene" --spp 16 -q -o "$work/r.exr")")
        rss+=("$(cat "$work/time")")
    done
    echo "$(median "${renders[@]}") $(median "${infos[@]}") $(median "${bare[@]}") $(median "${rss[@]}")"
}

framed gruenderzeit-street
framed gruenderzeit-street-detail
# The detail street once more with its masonry shaded procedurally instead of baked.
sed 's/<render /<render masonry="procedural" /' scenes/.bench-gruenderzeit-street-detail.xml >scenes/.bench-procedural.xml
sed 's/<render /<render masonry="procedural" /' scenes/.bench-gruenderzeit-street-detail-empty.xml \
    >scenes/.bench-procedural-empty.xml
copies+=(scenes/.bench-procedural.xml scenes/.bench-procedural-empty.xml)
read -r gRender gInfo gBare gRss <<<"$(measure gruenderzeit-street)"
report() {
    read -r dRender dInfo dBare dRss <<<"$(measure "$2")"
    echo "$1:"
    awk -v gr="$gRender" -v gi="$gInfo" -v gb="$gBare" -v gm="$gRss" \
        -v dr="$dRender" -v di="$dInfo" -v db="$dBare" -v dm="$dRss" 'BEGIN {
        printf "  rendered (16 spp): grammar %.1f s, detail %.1f s: %.2f / %.2f buildings/s, ratio %.2f (within 2: %s)\n",
            gr, dr, 15 / gr, 15 / dr, dr / gr, dr / gr <= 2 ? "yes" : "no"
        printf "  scene (info):      grammar %.2f s, detail %.2f s: ratio %.2f\n", gi, di, di / gi
        gg = gi - gb; dg = di - db; if (gg < 0.005) gg = 0.005
        printf "  generation alone:  grammar %.3f s, detail %.3f s (info less %.2f / %.2f s without buildings): ratio %.0f\n",
            gi - gb, dg, gb, db, dg / gg
        printf "  peak RSS:          grammar %.0f MB, detail %.0f MB: ratio %.2f (within 2: %s)\n",
            gm / 1024, dm / 1024, dm / gm, dm / gm <= 2 ? "yes" : "no"
    }'
}
report "detail, masonry baked (the scene as it is)" gruenderzeit-street-detail
report "detail, masonry shaded procedurally" procedural
