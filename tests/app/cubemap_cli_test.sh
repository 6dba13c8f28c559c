#!/usr/bin/env bash
# Cubemaps as users give them: `veduta cubemap` conversions, and scenes whose cubemap faces are
# missing, unreadable, of different sizes or not square (exit 1 with file:line:, no output).
# Usage: cubemap_cli_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"
command -v oiiotool >/dev/null || { echo "oiiotool missing (Debian: openimageio-tools)"; exit 1; }

face() {  # face NAME SIZE: a constant-colour float EXR, WxH
    oiiotool --pattern constant:color=0.4,0.5,0.7 "$2" 3 -d float -o "$work/$1"
}
for f in east west north south up down; do face "sky_$f.exr" 8x8; done

run cubemap --help
check "help" rc_is 0
check "help names the layouts" out_has "vertical-cross"

run cubemap "$work/sky_{face}.exr" -o "$work/cross.exr"
check "faces to cross" rc_is 0
check "vertical cross is 3x4 faces" bash -c "iinfo '$work/cross.exr' | grep -q '24 x   32'"
run cubemap "$work/cross.exr" -o "$work/h.exr" --to horizontal-cross
check "horizontal cross is 4x3 faces" bash -c "iinfo '$work/h.exr' | grep -q '32 x   24'"
run cubemap "$work/h.exr" -o "$work/ll.exr" --to latlong
check "lat-long is 4N x 2N" bash -c "iinfo '$work/ll.exr' | grep -q '32 x   16'"
run cubemap "$work/ll.exr" -o "$work/back_{axis}.exr" --size 4
check "lat-long to faces" rc_is 0
check "faces named by axis" test -s "$work/back_+z.exr"
check "faces resized" bash -c "iinfo '$work/back_-y.exr' | grep -q '4 x    4'"
run cubemap "$work/cross.exr" -o "$work/x.exr" --to faces
check "faces need {face} in the name: exit 2" rc_is 2
run cubemap "$work/nothing.exr" -o "$work/y.exr"
check "missing input exits 1" rc_is 1
check "missing input named" err_has "nothing.exr"

scene() {  # scene NAME PATTERN: a scene lit by the cubemap PATTERN
    cat >"$work/$1.xml" <<XML
<scene>
  <camera position="0 -3 1" look_at="0 0 0.5" resolution="8 8"/>
  <render spp="1"/>
  <environment cubemap="$2"/>
  <box/>
</scene>
XML
}
scene good "sky_{face}.exr"
run render "$work/good.xml" -q -o "$work/good.exr"
check "faces render" rc_is 0
run cubemap "$work/good.xml" -o "$work/from_scene.exr"
check "a scene's environment converts" rc_is 0

mkdir "$work/missing" "$work/sizes" "$work/oblong" "$work/garbage"
for f in east west north south up; do cp "$work/sky_$f.exr" "$work/missing/sky_$f.exr"; done
for f in east west north south up down; do
    cp "$work/sky_$f.exr" "$work/sizes/sky_$f.exr"
    cp "$work/sky_$f.exr" "$work/oblong/sky_$f.exr"
    cp "$work/sky_$f.exr" "$work/garbage/sky_$f.exr"
done
face "sizes/sky_north.exr" 16x16
face "oblong/sky_up.exr" 8x4
echo "not an image" >"$work/garbage/sky_west.exr"
for bad in missing:sky_down.exr sizes:north oblong:up garbage:sky_west.exr; do
    name=${bad%%:*} what=${bad##*:}
    scene "$name" "$name/sky_{face}.exr"
    run render "$work/$name.xml" -q -o "$work/$name.exr"
    check "$name face exits 1" rc_is 1
    check "$name face: file:line:" err_has "$work/$name.xml:4:"
    check "$name face named" err_has "$what"
    check "$name face: no output" test ! -e "$work/$name.exr"
done

# An unknown material field.
cat >"$work/material.xml" <<'XML'
<scene>
  <material name="brick" diffuse="0.5"
            bumpiness="2"/>
</scene>
XML
run render "$work/material.xml" -q -o "$work/material.exr"
check "unknown material field exits 1" rc_is 1
check "unknown material field: file:line:col" err_has "$work/material.xml:3:13: unknown attribute 'bumpiness' on <material>"

summary cubemap_cli
