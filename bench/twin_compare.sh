#!/usr/bin/env bash
# Twin and compare on a square kilometre of LoD2 CityGML (issue 18's figure: ≤ 60 s together
# at 960×540, 64 spp, three views): `veduta twin` and `veduta compare` timed separately, three
# runs, medians. The tile is synthetic (bench_citygml_tile: 1,500 buildings, seed 1) unless
# TILE.gml names a real one.
# Usage: bench/twin_compare.sh [VEDUTA_BINARY] [TILE_BINARY] [TILE.gml]
#        (defaults build/release/src/veduta, build/release/bench/bench_citygml_tile)
set -euo pipefail
cd "$(dirname "$0")/.."
veduta=${1:-build/release/src/veduta}
maker=${2:-build/release/bench/bench_citygml_tile}
work=build/bench/twin-compare
mkdir -p "$work"
tile=${3:-}
if [ -z "$tile" ]; then
    tile=$work/tile.gml
    "$maker" "$tile" --buildings 1500 --seed 1
fi

# timed NAME COMMAND...: runs COMMAND, its output in $work/NAME.out and .err, the time's in
# .time; sets wall (seconds) and rss_kb (peak RSS).
timed() {
    local name=$1
    shift
    if ! /usr/bin/time -o "$work/$name.time" -f 'wall %e rss_kb %M' "$@" >"$work/$name.out" 2>"$work/$name.err"; then
        echo "FAILED: $* (its last messages follow)" >&2
        tail -n 20 "$work/$name.err" >&2
        exit 1
    fi
    wall=$(awk '/^wall /{print $2}' "$work/$name.time")
    rss_kb=$(awk '/^wall /{print $4}' "$work/$name.time")
}

twins=() compares=() totals=() rss=()
for run in 1 2 3; do
    timed twin "$veduta" twin "$tile" -o "$work/twin.xml"
    tw=$wall twin_rss=$rss_kb
    timed compare "$veduta" compare "$tile" "$work/twin.xml" -o "$work/report.html" \
        --res 960x540 --spp 64 --views 3 -q
    cw=$wall compare_rss=$rss_kb
    total=$(awk -v a="$tw" -v b="$cw" 'BEGIN{printf "%.2f", a + b}')
    peak=$(( twin_rss > compare_rss ? twin_rss : compare_rss ))
    twins+=("$tw") compares+=("$cw") totals+=("$total") rss+=("$peak")
    echo "run $run: twin $tw s, compare $cw s, total $total s, peak RSS $(( peak / 1024 )) MB" \
         "(twin $(( twin_rss / 1024 )) MB, compare $(( compare_rss / 1024 )) MB)"
done
cat "$work/twin.err" "$work/compare.out"  # the last run's summaries: how many twins, how they agree
median() { printf '%s\n' "$@" | sort -g | sed -n 2p; }
echo "tile: $tile ($(grep -c '<bldg:Building ' "$tile") buildings); report: $work/report.html"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "median of 3: twin $(median "${twins[@]}") s, compare $(median "${compares[@]}") s," \
     "total $(median "${totals[@]}") s, peak RSS $(( $(median "${rss[@]}") / 1024 )) MB"
if awk -v t="$(median "${totals[@]}")" 'BEGIN{exit !(t <= 60)}'; then
    echo "target 60 s: met"
else
    echo "target 60 s: not met"
fi
