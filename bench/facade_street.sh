#!/usr/bin/env bash
# Finkenzeller's detail against the grammar (issue 22's acceptance): the Gründerzeit street of
# scenes/gruenderzeit-street.xml (split grammar, rules/gruenderzeit) and of
# scenes/gruenderzeit-street-detail.xml (the same fifteen footprints built from floor-plan
# modules, with masonry, casings, swept cornices and consoles), both framed at 1920 × 1080; the
# detail street twice, its masonry shaded procedurally (as the scene is, the default) and baked
# (<render masonry="baked">). For each it prints
#   * rendered: 15 buildings over the wall time of `veduta render --spp 16` (read, generate,
#     bake, BVH, trace), the median of 3 runs — the issue's "rendered at 1920 × 1080";
#   * scene: the wall time of `veduta info` (read, generate, bake, BVH), median of 7;
#   * generation alone: `veduta info` less the same scene without its buildings (reading the
#     materials, the sky, starting the texture system), medians of 7: what fifteen buildings cost,
#     with what a scene pays once for them (models, window assemblies, their materials' images);
#   * buildings per second: the street's footprints 24 times over, each copy 120 m east of the
#     last (360 buildings), against the street itself: 345 buildings over the difference of their
#     `veduta info` times, medians of 7, the rate at which more buildings are built (fewer copies
#     leave the difference within the runs' jitter);
#   * peak memory of the render;
# and the ratios detail / grammar. The issue asks for the speed and the memory within 2.
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

# Each footprint line of a scene repeated $2 times, the copies' x moved by 120 m each.
repeated() {
    awk -v n="$2" '
        /footprint="/ {
            match($0, /footprint="[^"]*"/)
            head = substr($0, 1, RSTART - 1); tail = substr($0, RSTART + RLENGTH)
            k = split(substr($0, RSTART + 11, RLENGTH - 12), v, " ")
            for (c = 0; c < n; ++c) {
                line = ""
                for (i = 1; i <= k; ++i) line = line (i > 1 ? " " : "") (i % 2 ? v[i] + 120 * c : v[i])
                print head "footprint=\"" line "\"" tail
            }
            next
        }
        { print }' "$1"
}

# The scene at 1920 × 1080 as scenes/.bench-NAME.xml, beside the originals so that their relative
# paths hold, with its render element changed by the sed expression $3; the same without its
# buildings, and with its footprints 24 times over.
framed() {
    local copy=scenes/.bench-$1.xml
    sed "s/resolution=\"960 540\"/resolution=\"1920 1080\"/; $3" "scenes/$2.xml" >"$copy"
    sed '/<buildings /,/<\/buildings>/d; /<modular_building /d' "$copy" >"scenes/.bench-$1-empty.xml"
    repeated "$copy" 24 >"scenes/.bench-$1-long.xml"
    copies+=("$copy" "scenes/.bench-$1-empty.xml" "scenes/.bench-$1-long.xml")
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
    local scene=scenes/.bench-$1.xml infos=() bare=() long=() renders=() rss=()
    seconds info "$scene" >/dev/null
    seconds render "$scene" --spp 1 -q -o "$work/warm.exr" >/dev/null
    for run in 1 2 3 4 5 6 7; do
        infos+=("$(seconds info "$scene")")
        bare+=("$(seconds info "scenes/.bench-$1-empty.xml")")
        long+=("$(seconds info "scenes/.bench-$1-long.xml")")
    done
    for run in 1 2 3; do
        renders+=("$(seconds render "$scene" --spp 16 -q -o "$work/r.exr")")
        rss+=("$(cat "$work/time")")
    done
    echo "$(median "${renders[@]}") $(median "${infos[@]}") $(median "${bare[@]}") $(median "${long[@]}")" \
        "$(median "${rss[@]}")"
}

framed grammar gruenderzeit-street ''
framed procedural gruenderzeit-street-detail ''
framed baked gruenderzeit-street-detail 's/<render /<render masonry="baked" /'
read -r gRender gInfo gBare gLong gRss <<<"$(measure grammar)"
report() {
    read -r dRender dInfo dBare dLong dRss <<<"$(measure "$2")"
    echo "$1:"
    awk -v gr="$gRender" -v gi="$gInfo" -v gb="$gBare" -v gl="$gLong" -v gm="$gRss" \
        -v dr="$dRender" -v di="$dInfo" -v db="$dBare" -v dl="$dLong" -v dm="$dRss" 'BEGIN {
        within = "(within 2: %s)"
        printf "  rendered (16 spp):   grammar %.1f s, detail %.1f s: %.2f / %.2f buildings/s, ratio %.2f " within "\n",
            gr, dr, 15 / gr, 15 / dr, dr / gr, dr / gr <= 2 ? "yes" : "no"
        printf "  scene (info):        grammar %.3f s, detail %.3f s: ratio %.2f\n", gi, di, di / gi
        gg = gi - gb; dg = di - db; if (gg < 0.001) gg = 0.001
        printf "  generation alone:    grammar %.3f s, detail %.3f s (info less %.3f / %.3f s without buildings): ratio %.1f\n",
            gi - gb, dg, gb, db, dg / gg
        gn = gl - gi; dn = dl - di; if (gn < 0.001) gn = 0.001
        printf "  buildings/s (long):  grammar %.0f, detail %.0f (345 more buildings in %.3f / %.3f s): ratio %.2f " within "\n",
            345 / gn, 345 / dn, gn, dn, dn / gn, dn / gn <= 2 ? "yes" : "no"
        printf "  peak RSS:            grammar %.0f MB, detail %.0f MB: ratio %.2f " within "\n",
            gm / 1024, dm / 1024, dm / gm, dm / gm <= 2 ? "yes" : "no"
    }'
}
report "detail, masonry shaded procedurally (the scene as it is)" procedural
report "detail, masonry baked" baked
