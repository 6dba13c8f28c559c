#!/usr/bin/env bash
# Issue 23's acceptance: "A landscape from a 34 × 20 km DGM at 10 m renders at 1920 × 1080
# within 8 GB." bench_dgm_geotiff writes bench_terrain's generated DGM (3401 × 2001 nodes,
# generated_dgm.h) as a float32 GeoTIFF; a scene takes it as its <landscape> at full resolution,
# seen from a low aerial camera 300 m above the terrain, 500 m in from the west edge, looking
# east along the 34 km under a Preetham sky and an afternoon sun, so the whole DGM recedes to
# its far edge. `veduta render` renders it at 4 spp (SPP=N to change) 3 times back to back under
# /usr/bin/time; the script prints
#   * the DGM's triangles, Embree's build time and memory, and the wall time and peak resident
#     memory of `veduta info` (read, mesh, BVH, no film): what the scene costs before a ray is
#     traced;
#   * each render's wall time (the whole command: read, mesh, BVH, trace, write) with the trace
#     time of veduta's summary, and its peak resident memory (ru_maxrss);
#   * the median wall time, the largest peak, and PASS or FAIL against 8 GB (8·10⁹ bytes);
# and, if it passes, the same scene once more at 3840 × 2160. The PNGs are kept (the EXRs and
# the 27 MB GeoTIFF, in a folder under /tmp, are not). The machine's load average is printed
# before and after: timings on a shared machine depend on it.
#
#   bench/big_landscape.sh [VEDUTA_BINARY [PNG_FOLDER]]
#       defaults build/release/src/veduta and renders; bench_dgm_geotiff is taken from the
#       same build folder: the folder of VEDUTA_BINARY, then ../bench/bench_dgm_geotiff
set -euo pipefail
cd "$(dirname "$0")/.."
veduta=${1:-build/release/src/veduta}
pngs=${2:-renders}
writer=$(dirname "$veduta")/../bench/bench_dgm_geotiff
spp=${SPP:-4}
limit=8000000000
for program in "$veduta" "$writer"; do
    [[ -x $program ]] || { echo "big_landscape.sh: $program is not built" >&2; exit 2; }
done
work=$(mktemp -d "${TMPDIR:-/tmp}/big_landscape.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$pngs"

# The camera: 500 m east of the DGM's west edge (400000), on its middle row, 300 m above the
# terrain there, pitched 8° down (the far edge, 0.5° below level, sits a third below the top of a
# 40° frame).
east=400500 north=5610000
dgm=$("$writer" "$work/dgm.tif" "$east" "$north")
ground=$(awk '/^height:/ { print $4 }' <<<"$dgm")
eye=$(awk -v g="$ground" 'BEGIN { printf "%.1f", g + 300 }')
target=$(awk -v e="$eye" 'BEGIN { printf "%.1f", e - 140.5 }')  # 1000 m ahead, tan 8° · 1000 m lower
cat >"$work/big_landscape.xml" <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<!-- bench/big_landscape.sh: a 34 × 20 km DGM at 10 m (3401 × 2001 nodes) at full resolution. -->
<scene version="1">
  <georeference crs="EPSG:25832" origin="417000 5610000"/>
  <camera crs="EPSG:25832" position="$east $north $eye" look_at="$((east + 1000)) $north $target" up="0 0 1"
          fov="40" resolution="1920 1080"/>
  <sun azimuth="210" elevation="20"/>
  <environment sky="preetham"/>
  <render spp="$spp"/>
  <landscape>
    <dgm file="dgm.tif"/>
  </landscape>
</scene>
EOF

median() { printf '%s\n' "$@" | sort -g | sed -n "$((($# + 1) / 2))p"; }
gb() { awk -v k="$1" 'BEGIN { printf "%.2f", k * 1024 / 1e9 }'; }

# One render at the resolution $1 into the PNG $2; sets wall (seconds, to the millisecond: time's
# %e has only ten), kib (peak resident memory) and trace (the trace time of veduta's summary). A
# failed run ends the benchmark.
render() {
    local start end
    start=$(date +%s%N)
    if ! /usr/bin/time -f '%M' -o "$work/time" "$veduta" render "$work/big_landscape.xml" --res "$1" \
        -o "$work/big_landscape.exr" --png "$2" 2>"$work/err"; then
        echo "big_landscape.sh: veduta render --res $1 failed:" >&2
        tail -3 "$work/err" >&2
        exit 1
    fi
    end=$(date +%s%N)
    wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", (b - a) / 1e9 }')
    kib=$(cat "$work/time")
    trace=$(sed -n 's/.*spp, \([0-9.]*\) s,.*/\1/p' "$work/err")
}

echo "load average before: $(uptime | sed 's/.*load average: //')"
echo "camera: $east $north $eye m (terrain $ground m), looking east 8° down; $spp spp"
start=$(date +%s%N)
info=$("$veduta" info "$work/big_landscape.xml")
end=$(date +%s%N)
awk '/^(stored_triangles|bvh_build_seconds|bvh_bytes|bvh_peak_bytes|peak_rss_bytes):/' <<<"$info"
echo "veduta info (read, mesh, BVH) wall: $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", (b - a) / 1e9 }') s"
walls=() rss=()
for run in 1 2 3; do
    render 1920x1080 "$pngs/big_landscape_1920x1080.png"
    echo "1920 × 1080 run $run: wall $wall s (trace $trace s), peak RSS $(gb "$kib") GB"
    walls+=("$wall") rss+=("$kib")
done
peak=$(printf '%s\n' "${rss[@]}" | sort -g | tail -1)
verdict=$(awk -v k="$peak" -v l="$limit" 'BEGIN { print k * 1024 <= l ? "PASS" : "FAIL" }')
echo "1920 × 1080: wall median of 3 $(median "${walls[@]}") s, peak RSS $(gb "$peak") GB (largest of 3)" \
    "— $verdict (<= 8 GB)"
if [[ $verdict == PASS ]]; then
    render 3840x2160 "$pngs/big_landscape_3840x2160.png"
    echo "3840 × 2160 once: wall $wall s (trace $trace s), peak RSS $(gb "$kib") GB"
fi
echo "images: $pngs/big_landscape_*.png"
echo "load average after: $(uptime | sed 's/.*load average: //')"
