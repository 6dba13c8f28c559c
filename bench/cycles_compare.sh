#!/usr/bin/env bash
# veduta against Blender Cycles, side by side, on the same scenes (issue 19, deliverable 4).
# Every scene is exported with `veduta export` (OBJ, Z up), rebuilt in Blender 3.4 by
# bench/cycles/cycles_build.py with every setting mirrored (bench/cycles/*.py say how, and
# docs/cycles-compare.md lists every convention and what is approximated), and rendered by both.
#
# Figures, per scene:
#   (a) equal spp: veduta's time / Cycles' time at --spp (medians of --runs interleaved runs:
#       veduta, Cycles, veduta, Cycles, …). veduta's time is its summary line's (the render loop,
#       without reading the scene and building the BVH), Cycles' is its render_time (the path
#       tracing, without Blender's start-up, the .blend loading and Cycles' scene
#       synchronisation and BVH build), read from the EXR header. Also both relMSEs there.
#   (b) equal time: veduta is given the time Cycles took (as samples at veduta's rate in (a)), and both images are
#       compared with a long Cycles reference (--ref-spp, another seed, cached under
#       OUT/reference): relMSE = mean over pixels and channels of (x − ref)² / (ref² + 0.01).
#   (c) veduta at --hi-spp against the reference: relMSE, the mean ratio and the worst relative
#       difference of the means of 4×4 regions (a bias shows here, noise averages out).
# Checks (--no-checks skips them): a white plane under a zenith sun (radiance E/π in both) and
# each scene at depth 1 (direct light only: veduta --max-depth 1, Cycles max_bounces 0).
#
# Usage: bench/cycles_compare.sh [--scene blocks,street|FILE.xml] [--spp 64] [--ref-spp 4096]
#          [--hi-spp 1024] [--res WxH] [--runs 3] [--threads 2] [--quick] [--no-checks]
#          [--veduta build/release/src/veduta] [--out /tmp/cycles-compare] [--cycles-filter-scale 1]
# --cycles-filter-scale K: Cycles' filter_width = K × veduta's. veduta's filter_width now follows
# Cycles' convention (Blackman–Harris w spans ±w pixels): K = 1. For a veduta built before that
# change (its Blackman–Harris w spanned ±w/2), K = 0.5 makes the two filters the same.
# --quick: 96×54, 16 spp, a 256-spp reference, 64 spp for (c), one run: checks that the whole
# chain works, in a minute or two; its figures mean little.
# Needs Blender (Debian 12: 3.4.1), python3-numpy and python3-openimageio; installs what is
# missing with apt-get (as root, or through sudo). Not part of the test suite.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
here=$root/bench/cycles

scenes=blocks,street spp=64 ref_spp=4096 hi_spp=1024 res= runs=3 threads=2 quick=0 checks=1
veduta=$root/build/release/src/veduta out=/tmp/cycles-compare filter_scale=1
set_spp=0 set_ref=0 set_hi=0 set_runs=0
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit "${1:-2}"; }
while (($#)); do
    case $1 in
        --scene|--scenes) scenes=$2; shift ;;
        --spp) spp=$2 set_spp=1; shift ;;
        --ref-spp) ref_spp=$2 set_ref=1; shift ;;
        --hi-spp) hi_spp=$2 set_hi=1; shift ;;
        --res) res=$2; shift ;;
        --runs) runs=$2 set_runs=1; shift ;;
        --threads) threads=$2; shift ;;
        --quick) quick=1 ;;
        --no-checks) checks=0 ;;
        --veduta) veduta=$2; shift ;;
        --out) out=$2; shift ;;
        --cycles-filter-scale) filter_scale=$2; shift ;;
        -h|--help) usage 0 ;;
        *) echo "cycles_compare.sh: unknown option $1" >&2; usage ;;
    esac
    shift
done
if ((quick)); then
    res=${res:-96x54}
    ((set_spp)) || spp=16
    ((set_ref)) || ref_spp=256
    ((set_hi)) || hi_spp=64
    ((set_runs)) || runs=1
fi
[[ -z $res || $res =~ ^[0-9]+x[0-9]+$ ]] || { echo "cycles_compare.sh: --res wants WxH, not $res" >&2; exit 2; }
veduta=$(readlink -f "$veduta")
[ -x "$veduta" ] || { echo "cycles_compare.sh: no veduta binary at $veduta (--veduta PATH)" >&2; exit 2; }

# --- what it needs: Debian's blender, and numpy and OpenImageIO for the system python ---------
py=/usr/bin/python3
need=()
command -v blender >/dev/null || need+=(blender)
$py -c 'import numpy' 2>/dev/null || need+=(python3-numpy)
$py -c 'import OpenImageIO' 2>/dev/null || need+=(python3-openimageio)
if ((${#need[@]})); then
    sudo=; [ "$(id -u)" = 0 ] || sudo=sudo
    echo "installing ${need[*]} …"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get install -y --no-install-recommends "${need[@]}" >/dev/null ||
        { $sudo apt-get update >/dev/null && $sudo apt-get install -y --no-install-recommends "${need[@]}" >/dev/null; }
fi
blender_version=$(blender --version 2>/dev/null | head -n 1)

mkdir -p "$out/reference"
summary=$out/summary.txt
: >"$summary"
say() { echo "$*" | tee -a "$summary"; }
fail() { echo "FAILED: $1 (its last messages follow)" >&2; tail -n 25 "$2" >&2; exit 1; }
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END{print (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2)}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN{ if (b > 0) printf "%.3f", a / b; else print "inf" }'; }
img() { $py "$here/compare_images.py" "$@"; }

# veduta_render LOG OUT.exr ARGS…: sets v_seconds and v_spp from veduta's summary line.
veduta_render() {
    local log=$1 exr=$2
    shift 2
    "$veduta" render "$dir/scene.xml" -o "$exr" --threads "$threads" --res "$res_now" "$@" 2>"$log" ||
        fail "veduta render $*" "$log"
    local line
    line=$(grep ' spp, .* s, ' "$log" | tail -n 1)
    v_spp=$(sed 's/.*, \([0-9.e+]*\) spp, .*/\1/' <<<"$line")
    v_seconds=$(sed 's/.* spp, \([0-9.]*\) s, .*/\1/' <<<"$line")
}

# cycles_render LOG OUT.exr SPP DEPTH SEED [TIME_LIMIT]: sets c_seconds (Cycles' render_time),
# c_total (with synchronisation) and c_wall (bpy.ops.render.render).
cycles_render() {
    local log=$1 exr=$2
    blender -b "$dir/scene.blend" -t "$threads" --python "$here/cycles_render.py" -- --spp "$3" \
        --max-depth "$4" --seed "$5" --res "$res_now" --threads "$threads" --filter "$filter" \
        --filter-width "$cycles_filter_width" --time-limit "${6:-0}" --out "$exr" >"$log" 2>&1 ||
        fail "blender render ($3 spp)" "$log"
    grep -q '^CYCLES_RENDER ' "$log" || fail "blender render ($3 spp): no CYCLES_RENDER line" "$log"
    c_wall=$(awk '/^CYCLES_RENDER /{print $3}' "$log")
    read -r _ c_seconds _ c_total _ _ < <(img cycles-time "$exr")
}

json() { $py -c "import json,sys; d=json.load(open('$dir/scene.json')); print($1)"; }

# --- the units check: E/π from a white plane under a zenith sun ------------------------------
prepare() {  # prepare NAME SCENE.xml: dir, the veduta scene, the OBJ, the sky and the .blend
    dir=$out/$1
    mkdir -p "$dir"
    $py "$here/prepare_scene.py" "$2" "$dir" >"$dir/prepare.log" 2>&1 || fail "prepare_scene.py $2" "$dir/prepare.log"
    "$veduta" export "$dir/scene.xml" -o "$dir/scene.obj" 2>"$dir/export.log" || fail "veduta export" "$dir/export.log"
    local sky=()
    if [ "$(json "d['environment']['kind']")" = map ]; then
        # The environment as veduta renders it (the baked Preetham sky, or a cubemap with its
        # rotation and intensity), as a Blender-convention lat-long map.
        "$veduta" cubemap "$dir/scene.xml" -o "$dir/sky.exr" --to latlong --size 128 >"$dir/cubemap.log" 2>&1 ||
            fail "veduta cubemap" "$dir/cubemap.log"
        sky=(--sky "$dir/sky.exr")
    fi
    blender -b --factory-startup --python "$here/cycles_build.py" -- --json "$dir/scene.json" \
        --obj "$dir/scene.obj" "${sky[@]}" --blend "$dir/scene.blend" >"$dir/build.log" 2>&1 ||
        fail "blender build" "$dir/build.log"
    grep -q '^CYCLES_BUILD objects' "$dir/build.log" || fail "blender build: no CYCLES_BUILD line" "$dir/build.log"
    depth=$(json "d['render']['max_depth']")
    seed=$(json "d['render']['seed']")
    filter=$(json "d['render']['filter']")
    filter_width=$(json "d['render']['filter_width']")
    # Box: both span ±w/2 pixels whatever the build; only Blackman–Harris changed convention.
    cycles_filter_width=$(awk -v w="$filter_width" -v k="$filter_scale" -v f="$filter" \
        'BEGIN{printf "%.6g", f == "box" ? w : w * k}')
    res_now=${res:-$(json "'%dx%d' % tuple(d['camera']['resolution'])")}
}

say "veduta: $veduta"
say "cycles: $blender_version, CPU, $threads threads; machine: $(nproc) cores," \
    "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
if ((checks)); then
    res_keep=$res
    res=16x16
    prepare sun-plane "$here/sun_plane.xml"
    veduta_render "$dir/veduta.log" "$dir/veduta.exr" --spp 16 --max-depth 1
    cycles_render "$dir/cycles.log" "$dir/cycles.exr" 16 1 0
    read -r vr _ _ < <(img mean "$dir/veduta.exr")
    read -r cr _ _ < <(img mean "$dir/cycles.exr")
    say "check, white plane under a 3 W/m² zenith sun, direct light: radiance veduta $vr, Cycles $cr," \
        "E/π $(awk 'BEGIN{printf "%.6g", 3 / atan2(0, -1)}')"
    res=$res_keep
fi

IFS=, read -r -a names <<<"$scenes"
for name in "${names[@]}"; do
    case $name in
        blocks) file=$root/scenes/bench/blocks.xml ;;
        street) file=$root/scenes/gruenderzeit-street.xml ;;
        *.xml) file=$(readlink -f "$name"); name=$(basename "$name" .xml) ;;
        *) echo "cycles_compare.sh: unknown scene $name (blocks, street or a file.xml)" >&2; exit 2 ;;
    esac
    prepare "$name" "$file"
    say ""
    say "== $name: $(sed 's/^prepared [^:]*: [0-9]*x[0-9]*, //' "$dir/prepare.log")"
    say "   $res_now, max_depth $depth, seed $seed, filter $filter $filter_width (Cycles $cycles_filter_width);" \
        "$(sed -n 's/^CYCLES_BUILD objects \([0-9]*\) triangles \([0-9]*\).*materials \([0-9]*\)/\2 triangles, \3 materials in Blender/p' "$dir/build.log")"
    grep '^CYCLES_BUILD materials from' "$dir/build.log" | sed 's/^CYCLES_BUILD/  /' | tee -a "$summary" || true

    # (a) equal spp, interleaved runs.
    vt=() ct=() ctot=()
    for ((run = 1; run <= runs; run++)); do
        veduta_render "$dir/veduta-$spp.log" "$dir/veduta-$spp.exr" --spp "$spp"
        vt+=("$v_seconds")
        cycles_render "$dir/cycles-$spp.log" "$dir/cycles-$spp.exr" "$spp" "$depth" "$seed"
        ct+=("$c_seconds") ctot+=("$c_total")
        say "   run $run: veduta $v_seconds s, Cycles $c_seconds s (with synchronisation $c_total s, whole" \
            "render call $c_wall s)"
    done
    vmed=$(median "${vt[@]}") cmed=$(median "${ct[@]}")

    # The reference: Cycles, many samples, another seed; cached by everything that makes it.
    key=$( (echo "$cycles_filter_width"; cat "$dir/scene.json" "$dir/scene.obj" "$here/cycles_build.py" "$here/cycles_render.py" \
        $( [ -f "$dir/sky.exr" ] && echo "$dir/sky.exr")) | md5sum | cut -c1-12)
    ref=$out/reference/$name-$res_now-$ref_spp-$key.exr
    if [ -f "$ref" ]; then
        say "   reference: $ref (cached)"
    else
        cycles_render "$dir/cycles-ref.log" "$dir/ref-tmp.exr" "$ref_spp" "$depth" 1000003
        mv "$dir/ref-tmp.exr" "$ref"
        say "   reference: Cycles $ref_spp spp, seed 1000003, $c_seconds s: $ref"
    fi

    v_rel=$(img relmse "$dir/veduta-$spp.exr" "$ref")
    c_rel=$(img relmse "$dir/cycles-$spp.exr" "$ref")
    say "(a) equal spp ($spp): veduta $vmed s, Cycles $cmed s (medians of $runs): veduta/Cycles time $(ratio "$vmed" "$cmed")"
    say "    relMSE at $spp spp: veduta $v_rel, Cycles $c_rel: relMSE veduta/Cycles $(ratio "$v_rel" "$c_rel")"

    # (b) equal time: veduta gets Cycles' median time, as samples at its own measured rate
    # (spp × Cycles' time / veduta's time): --time-limit would stop at the last whole pass
    # within the limit, which at small sizes leaves much of the time unused.
    eq_spp=$(awk -v s="$spp" -v c="$cmed" -v v="$vmed" 'BEGIN{ n = v > 0 ? int(s * c / v + 0.5) : s; print n < 1 ? 1 : n }')
    veduta_render "$dir/veduta-equal-time.log" "$dir/veduta-equal-time.exr" --spp "$eq_spp"
    e_rel=$(img relmse "$dir/veduta-equal-time.exr" "$ref")
    say "(b) equal time ($cmed s): veduta $v_spp spp in $v_seconds s, relMSE $e_rel; Cycles $spp spp," \
        "relMSE $c_rel: relMSE veduta/Cycles $(ratio "$e_rel" "$c_rel")"

    # (c) veduta with many samples against the reference: bias shows in the region means.
    veduta_render "$dir/veduta-$hi_spp.log" "$dir/veduta-$hi_spp.exr" --spp "$hi_spp"
    h_rel=$(img relmse "$dir/veduta-$hi_spp.exr" "$ref")
    read -r _ mr _ wr _ at < <(img regions "$dir/veduta-$hi_spp.exr" "$ref" 4)
    say "(c) veduta $hi_spp spp ($v_seconds s) against Cycles $ref_spp spp: relMSE $h_rel, mean veduta/Cycles $mr," \
        "worst of 4x4 region means $(awk -v w="$wr" 'BEGIN{printf "%.2f", 100 * w}') % (region $at)"

    if ((checks)); then
        veduta_render "$dir/veduta-d1.log" "$dir/veduta-d1.exr" --spp "$spp" --max-depth 1
        cycles_render "$dir/cycles-d1.log" "$dir/cycles-d1.exr" "$spp" 1 "$seed"
        read -r _ mr _ wr _ at < <(img regions "$dir/veduta-d1.exr" "$dir/cycles-d1.exr" 4)
        say "    check, depth 1 (direct light), $spp spp each: mean veduta/Cycles $mr, worst of 4x4 region means" \
            "$(awk -v w="$wr" 'BEGIN{printf "%.2f", 100 * w}') % (region $at)," \
            "relMSE between them $(img relmse "$dir/veduta-d1.exr" "$dir/cycles-d1.exr")"
    fi
done
say ""
say "images and logs: $out/<scene>/; this summary: $summary"
