#!/usr/bin/env bash
# Wall time of `veduta export` on the example landscape, median of 3 runs per format, against
# `veduta info` on the same scene (which reads and builds it, as export does first): glTF as
# .glb and .gltf, and, with --all, OBJ and PLY, which write every one of the 25,800 instances
# out as a copy (83 million triangles: some 10 GB of OBJ text).
# Usage: bench/export_landscape.sh [--all] [VEDUTA_BINARY] [SCENE]
#        (default build/release/src/veduta, scenes/landscape.xml)
set -euo pipefail
cd "$(dirname "$0")/.."
formats=(glb gltf)
if [ "${1:-}" = --all ]; then
    formats+=(obj ply)
    shift
fi
veduta=${1:-build/release/src/veduta}
scene=${2:-scenes/landscape.xml}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# The wall seconds of one run of the command, its output dropped.
wall() { /usr/bin/time -f %e "$@" 2>&1 >/dev/null | tail -1; }
median3() { printf '%s\n' "$@" | sort -g | sed -n 2p; }

runs=()
for run in 1 2 3; do runs+=("$(wall "$veduta" info "$scene")"); done
info=$(median3 "${runs[@]}")
echo "info: $info s (runs: ${runs[*]})"
for format in "${formats[@]}"; do
    runs=()
    for run in 1 2 3; do
        runs+=("$(wall "$veduta" export -q "$scene" -o "$out/scene.$format")")
        size=$(du -sh "$out" | cut -f1)
        rm -rf "${out:?}"/*
    done
    m=$(median3 "${runs[@]}")
    echo "export .$format: $m s, $(awk -v a="$m" -v b="$info" 'BEGIN { printf "%.2f", a / b }') × info, $size written (runs: ${runs[*]})"
done
