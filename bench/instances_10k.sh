#!/usr/bin/env bash
# Build time and peak memory of `veduta info` on the 10,000-instance scene, median of 5 runs.
# Usage: bench/instances_10k.sh [VEDUTA_BINARY]   (default build/release/src/veduta)
set -euo pipefail
cd "$(dirname "$0")/.."
veduta=${1:-build/release/src/veduta}
scene=scenes/bench/instances-10k.xml
builds=() rss=() walls=()
for run in 1 2 3 4 5; do
    out=$( { /usr/bin/time -f 'wall %e rss_kb %M' "$veduta" info "$scene"; } 2>&1 )
    builds+=("$(awk '/^bvh_build_seconds:/{print $2}' <<<"$out")")
    rss+=("$(awk '/^wall /{print $4}' <<<"$out")")
    walls+=("$(awk '/^wall /{print $2}' <<<"$out")")
done
median() { printf '%s\n' "$@" | sort -g | sed -n 3p; }
awk '/^(effective_triangles|bvh_bytes):/' <<<"$out"
echo "bvh_build_seconds median of 5: $(median "${builds[@]}")   (runs: ${builds[*]})"
echo "process wall seconds median of 5: $(median "${walls[@]}")"
echo "peak RSS MB median of 5: $(( $(median "${rss[@]}") / 1024 ))"
