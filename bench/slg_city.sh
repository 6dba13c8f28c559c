#!/usr/bin/env bash
# Whole cities from <slg> alone (docs/slg.md): one district of about 10,000, 100,000 and 500,000
# buildings (a Berlin), each built and rendered as a 960 × 540 still from an aerial and a
# street-level camera under a memory budget (VEDUTA_MAX_MEMORY: 1G, 4G and 16G), printing the
# build's time, the whole command's time and peak RSS, and buildings, triangles and meshes per
# level of detail (`veduta info`); times and memory are the medians of RUNS runs (default 3).
# A render that runs out of its budget exits 3 and is reported.
# Usage: [RUNS=n] bench/slg_city.sh [VEDUTA_BINARY] [BUILDINGS...]   (default
#        build/release/src/veduta; 10000 100000 500000)
set -euo pipefail
cd "$(dirname "$0")/.."
veduta=$(realpath "${1:-build/release/src/veduta}")
shift || true
if (($# > 0)); then sizes=("$@"); else sizes=(10000 100000 500000); fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tables=$PWD/rules/slg/urban-geography.xml
runs=${RUNS:-3}
median() { printf '%s\n' "$@" | sort -g | sed -n "$((($# + 1) / 2))p"; }

# A district of side s metres holds about 2,130 buildings per km² (measured on 4 to 100 km²).
side_for() { awk -v n="$1" 'BEGIN { printf "%d", sqrt(n / 2130) * 1000 }'; }
budget_for() { if (($1 <= 10000)); then echo 1G; elif (($1 <= 100000)); then echo 4G; else echo 16G; fi; }

scene() {  # side camera-element
    cat <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<scene version="1">
  $2
  <sun azimuth="215" elevation="35" irradiance="3.2 3.05 2.8"/>
  <environment sky="preetham"/>
  <render spp="4" max_depth="3" seed="0"/>
  <material name="ground" diffuse="0.3 0.33 0.25"/>
  <plane size="$(($1 * 3)) $(($1 * 3))" translate="$(($1 / 2)) $(($1 / 2)) -0.05" material="ground"/>
  <slg level="district" outline="0 0 $1 0 $1 $1 0 $1" tables="$tables" seed="1" rooms_within="50"
       storeys_within="150"/>
</scene>
EOF
}

printf '%-8s %-7s %-6s %9s %9s %9s %8s  %s\n' buildings camera budget build_s render_s wall_s rss_MB \
    "levels of detail (buildings / triangles / meshes)"
for n in "${sizes[@]}"; do
    s=$(side_for "$n") budget=$(budget_for "$n")
    h=$((s / 2))
    aerial="<camera position=\"$((h - s / 3)) $((h - s / 3)) $((s / 6 + 300))\" look_at=\"$h $h 0\" up=\"0 0 1\" fov=\"50\" resolution=\"960 540\"/>"
    street="<camera position=\"-4 $h 1.7\" look_at=\"60 $((h + 25)) 8\" up=\"0 0 1\" fov=\"60\" resolution=\"960 540\"/>"
    for camera in aerial street; do
        file=$work/city-$n-$camera.xml
        scene "$s" "${!camera}" >"$file"
        info=$(VEDUTA_MAX_MEMORY=$budget "$veduta" info "$file" 2>&1) || {
            echo "$n $camera: veduta info failed: $info"
            continue
        }
        walls=() rsss=() infos=()
        for ((run = 0; run < runs; ++run)); do
            out=$( (/usr/bin/time -f 'wall %e rss_kb %M' env VEDUTA_MAX_MEMORY="$budget" "$veduta" render -q "$file" \
                -o "$work/city-$n-$camera.exr" --png "$work/city-$n-$camera.png") 2>&1) && status=0 || status=$?
            if ((status != 0)); then
                echo "$n $camera: render exited $status: $(tail -n 3 <<<"$out")"
                continue 2
            fi
            walls+=("$(awk '/^wall /{print $2}' <<<"$out")")
            rsss+=("$(awk '/^wall /{print int($4 / 1024)}' <<<"$out")")
            # The build's share: `veduta info` builds the same scene and its BVH without rendering.
            infos+=("$( (/usr/bin/time -f 'wall %e' env VEDUTA_MAX_MEMORY="$budget" "$veduta" info "$file" \
                >/dev/null) 2>&1 | awk '/^wall /{print $2}')")
        done
        wall=$(median "${walls[@]}") rss=$(median "${rsss[@]}") info_wall=$(median "${infos[@]}")
        render=$(awk -v a="$wall" -v b="$info_wall" 'BEGIN { printf "%.1f", a - b }')
        lods=$(awk -F': ' '/^lod /{sub(/^lod /, "", $1); gsub(/ buildings,| triangles,| meshes,| instances/, "", $2);
                              split($2, v, " "); printf "%s %s/%s/%s  ", $1, v[1], v[2], v[3]}' <<<"$info")
        printf '%-8s %-7s %-6s %9s %9s %9s %8s  %s\n' "$(awk '/^buildings:/{print $2}' <<<"$info")" "$camera" \
            "$budget" "$info_wall" "$render" "$wall" "$rss" "$lods"
        grep -i "warning" <<<"$info" | sed 's/^/    /' || true
        [[ -n "${SLG_CITY_KEEP:-}" ]] && cp "$work/city-$n-$camera.png" "$SLG_CITY_KEEP/" || true
    done
done
