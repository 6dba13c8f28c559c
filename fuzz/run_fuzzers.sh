#!/usr/bin/env bash
# Runs veduta's libFuzzer targets (docs/fuzzing.md), built by the fuzz preset:
#   fuzz/run_fuzzers.sh SECONDS [TARGET …]
# First each target runs every file of fuzz/regressions/TARGET/ (inputs that once crashed or
# hung it), then it fuzzes for SECONDS from its seed corpus: the project's example files of
# its format, fuzz/corpus/TARGET/, and ../shared/data's files when present. What it learns
# stays in build/fuzz/corpus/TARGET/, so that a later run goes on from there; a crash, hang
# (over 10 s on one input), leak or excess memory leaves its input in
# build/fuzz/artifacts/TARGET/. Targets run side by side, one per core. Prints one line per
# target (executions, coverage, corpus) and exits 1 if any target failed.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ $# -lt 1 ] || ! [[ $1 =~ ^[0-9]+$ ]]; then
    echo "usage: $0 SECONDS [TARGET ...]" >&2
    exit 2
fi
seconds=$1
shift
all_targets=(scene material rules street_rules slg_tables slg_plans city_data osm citygml edbs xyz asc mesh_obj mesh_ply mesh_gltf checkpoint crs facade_languages cryptomatte_manifest farm_job)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")

bin=build/fuzz/fuzz
work=build/fuzz
shared=../shared/data

# The example files of each target's format, in the project and in ../shared/data.
seed_files() {
    case "$1" in
        scene) ls scenes/*.xml scenes/*/*.xml ;;
        material) ls materials/*.xml rules/*/materials.xml ;;
        rules) ls rules/*/*.xml | grep -v materials.xml | grep -v rules/slg/ ;;
        slg_tables) ls rules/slg/*.xml ;;
        city_data) ls cities/*.xml ;;
        osm) ls data/*/*.osm tests/data/osm/*.osm "$shared"/osm/*.osm ;;
        citygml) ls tests/data/citygml/*.gml "$shared"/citygml/*.gml "$shared"/citygml/*.xml ;;
        edbs) ls "$shared"/edbs/*.edbs ;;
        xyz) ls "$shared"/dgm/*.xyz ;;
        asc) ls data/*/*.asc "$shared"/dgm/*.asc ;;
        mesh_obj) ls tests/data/*.obj ;;
        mesh_ply) ls tests/data/*.ply ;;
        mesh_gltf | checkpoint | crs | slg_plans | facade_languages | cryptomatte_manifest | farm_job) ;;
    esac 2>/dev/null || true
}

# Fills the target's seed folder afresh. A file over 256 KiB is cut to its first 64 KiB at a
# line end: every example format is line-based, and a large seed only slows each execution.
prepare_seeds() {
    local target=$1 seeds=$work/seeds/$1
    rm -rf "$seeds"
    mkdir -p "$seeds" "$work/corpus/$target" "$work/artifacts/$target"
    [ -d "fuzz/corpus/$target" ] && cp fuzz/corpus/"$target"/* "$seeds"/
    local file n=0
    for file in $(seed_files "$target"); do
        n=$((n + 1))
        if [ "$(stat -c %s "$file")" -gt 262144 ]; then
            head -c 65536 "$file" | sed '$d' >"$seeds/$n-$(basename "$file")"
        else
            cp "$file" "$seeds/$n-$(basename "$file")"
        fi
    done
    if [ "$target" = checkpoint ]; then
        # The checkpoint target writes its own seed (a checkpoint of the render it reads for).
        VEDUTA_FUZZ_SEED_FOLDER=$seeds "$bin/checkpoint_fuzzer" -runs=0 "$seeds" >/dev/null 2>&1
    fi
}

run_target() {
    local target=$1 log=$work/logs/$1.log
    local fuzzer=$bin/${target}_fuzzer
    local options=(-timeout=10 -rss_limit_mb=2560 -print_final_stats=1
        "-artifact_prefix=$work/artifacts/$target/")
    mkdir -p "$work/logs"
    : >"$log"
    if [ ! -x "$fuzzer" ]; then
        echo "$target: $fuzzer is missing: cmake --preset fuzz && cmake --build --preset fuzz"
        return 1
    fi
    prepare_seeds "$target"
    local regressions=(fuzz/regressions/"$target"/*)
    if [ -e "${regressions[0]}" ] && ! "$fuzzer" "${options[@]}" "${regressions[@]}" >>"$log" 2>&1; then
        echo "$target: FAILED on a regression file (log: $log)"
        return 1
    fi
    if ! "$fuzzer" "${options[@]}" -max_total_time="$seconds" "$work/corpus/$target" "$work/seeds/$target" \
        >>"$log" 2>&1; then
        echo "$target: FAILED: $(grep -m1 -E 'ERROR|SUMMARY|Timeout|out-of-memory|deadly signal' "$log" || true)" \
            "(log: $log; input in $work/artifacts/$target/)"
        return 1
    fi
    local execs cov ft corpus
    execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$')
    cov=$(grep -o ' cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$')
    ft=$(grep -o ' ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$')
    corpus=$(find "$work/corpus/$target" -type f | wc -l)
    echo "$target: ok, ${execs:-0} executions in $seconds s, coverage ${cov:-0} edges (${ft:-0} features), corpus $corpus files"
}

# libFuzzer's own leak check stays on, but for the library leaks tests/lsan_suppressions.txt
# names; the rest as the sanitize preset has it.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/lsan_suppressions.txt:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export -f run_target prepare_seeds seed_files
export seconds bin work shared
status=0
printf '%s\n' "${targets[@]}" | xargs -P "$(nproc)" -I{} bash -c 'run_target {}' || status=1
exit $status
