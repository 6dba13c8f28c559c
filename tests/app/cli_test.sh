#!/usr/bin/env bash
# The veduta program as a script would call it: exit codes, messages, files written or not.
# Usage: cli_test.sh VEDUTA_BINARY TEST_DATA_DIR SOURCE_DIR
set -u
veduta=$1 data=$2 source=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

for sub in "" render info; do
    run $sub --help
    check "help $sub" rc_is 0
    check "help $sub text" out_has "Usage"
done
run --version
check "version" out_has "veduta 0."

run render --bogus-option
check "bad option exits 2" rc_is 2
run render --res 640by480
check "bad resolution exits 2" rc_is 2
run render -o picture.png
check "non-exr output exits 2" rc_is 2
run render --png picture.jpg
check "non-png display image exits 2" rc_is 2
# A device named as the scene: refused at once as no file, exit 1.
run info /dev/zero
check "a device as the scene exits 1" rc_is 1
check "a device as the scene is named" err_has "/dev/zero: is not a regular file"
# Numbers that are no numbers: NaN passes every comparison, so each option checks it.
for bad in "--noise-threshold nan" "--noise-threshold inf" "--time-limit nan" "--checkpoint-every -inf" \
    "--exposure nan --image x.png"; do
    run render $bad
    check "render $bad exits 2" rc_is 2
    check "render $bad names the value" err_has "is not a number from"
done

# The memory budget: past it, the command says so and writes nothing (exit 3); a budget that
# is no size is a bad command line (exit 2); a render within it runs.
VEDUTA_MAX_MEMORY=200M run render --res 8000x8000 --spp 1 -q -o "$work/huge.exr"
check "over the memory budget exits 3" rc_is 3
check "over the memory budget says so" err_has "memory ran out at veduta's budget of 0.2 GB (VEDUTA_MAX_MEMORY sets it"
check "over the memory budget writes nothing" test ! -e "$work/huge.exr"
VEDUTA_MAX_MEMORY=lots run info
check "a budget that is no size exits 2" rc_is 2
check "a budget that is no size is named" err_has "VEDUTA_MAX_MEMORY is 'lots', not a size"
VEDUTA_GDAL_TIME_LIMIT=soon run info
check "a GDAL time limit that is no number exits 2" rc_is 2
check "a GDAL time limit that is no number is named" err_has "VEDUTA_GDAL_TIME_LIMIT is 'soon', not a positive number"
VEDUTA_MAX_MEMORY=1.5G run render --res 64x48 --spp 1 -q -o "$work/small.exr"
check "a render within the budget runs" rc_is 0

# An output that cannot be written is reported before rendering: exit 3.
touch "$work/afile"
run render --res 8x8 --spp 1 -q -o "$work/afile/x.exr"
check "unwritable output exits 3" rc_is 3
check "unwritable output named" err_has "$work/afile/x.exr"

# The default scene renders to a valid EXR and PNG.
run render --res 40x24 --spp 2 -q -o "$work/d.exr" --png "$work/d.png"
check "default render" rc_is 0
check "exr written" test -s "$work/d.exr"
check "png written" test -s "$work/d.png"
# A multilayer EXR with Blender's pass names; aov_cli_test.sh checks every pass and attribute.
if command -v oiiotool >/dev/null; then
    oiiotool --info -v "$work/d.exr" >"$work/info"
    check "oiiotool reads the exr" grep -q '40 x  *24, 25 channel, float openexr' "$work/info"
    combined='ViewLayer.Combined.R, ViewLayer.Combined.G, ViewLayer.Combined.B, ViewLayer.Combined.A,'
    check "exr channels" grep -q "channel list: $combined" "$work/info"
fi
check "no temporary left" bash -c "! ls -a '$work' | grep -q tmp"

# 1 and 2 threads give bit-identical pixels.
run render --res 64x36 --spp 3 -q --threads 1 -o "$work/t1.exr"
check "1 thread" rc_is 0
run render --res 64x36 --spp 3 -q --threads 2 -o "$work/t2.exr"
check "2 threads" rc_is 0
if command -v idiff >/dev/null; then
    check "threads bit-identical" bash -c "idiff -fail 0 -failpercent 0 -warn 0 '$work/t1.exr' '$work/t2.exr' >/dev/null"
fi

# Bad scenes: exit 1, file:line: in the message, no output, an older output kept.
cat >"$work/unknown.xml" <<'XML'
<scene>
  <camera resolution="8 8"/>
  <teapot/>
</scene>
XML
cat >"$work/number.xml" <<'XML'
<scene>
  <render spp="many"/>
</scene>
XML
cat >"$work/mesh.xml" <<'XML'
<scene>
  <mesh file="missing.obj"/>
</scene>
XML
for bad in unknown:3 number:2 mesh:2; do
    name=${bad%%:*} line=${bad##*:}
    run render "$work/$name.xml" -q -o "$work/$name.exr" --png "$work/$name.png"
    check "$name exits 1" rc_is 1
    check "$name message" err_has "$work/$name.xml:$line:"
    check "$name no exr" test ! -e "$work/$name.exr"
    check "$name no png" test ! -e "$work/$name.png"
done
echo "keep me" >"$work/old.exr"
run render "$work/unknown.xml" -q -o "$work/old.exr"
check "old output kept" grep -q "keep me" "$work/old.exr"

# info prints the statistics scripts read.
run info "$source/scenes/default.xml"
check "info exits 0" rc_is 0
for key in meshes: prototypes: instances: effective_triangles: bvh_build_seconds: bvh_bytes:; do
    check "info $key" out_has "$key"
done

# The 10k-instance benchmark scene: 10,000 instances of a 10,000-triangle prototype.
run info "$source/scenes/bench/instances-10k.xml"
check "10k instances" out_has "instances: 10000"
check "10k effective triangles" out_has "effective_triangles: 100000002"

# A CityGML file: its building counted by info; given to atkis info, pointed to <citygml>.
cat >"$work/citygml.xml" <<XML
<scene version="1"><georeference crs="EPSG:25832" origin="500005 5400004"/>
<citygml file="$source/fuzz/corpus/citygml/lod1-box.gml"/></scene>
XML
run info "$work/citygml.xml"
check "info on CityGML exits 0" rc_is 0
check "info counts the CityGML building" out_line "buildings: 1"
run atkis info "$source/fuzz/corpus/citygml/lod1-box.gml"
check "CityGML as ATKIS exits 1" rc_is 1
check "CityGML as ATKIS points to <citygml>" err_has "is CityGML (3D city models), not an ATKIS file: a scene reads it with <citygml"

# A scene with a mesh file renders.
cat >"$work/meshes.xml" <<XML
<scene>
  <camera position="2 -3 2" look_at="0 0 0" resolution="16 16"/>
  <render spp="1"/>
  <mesh file="$data/tetra.obj"/>
  <mesh file="$data/quad.ply" translate="0 0 -0.1" scale="4"/>
</scene>
XML
run render "$work/meshes.xml" -q -o "$work/meshes.exr"
check "mesh scene renders" rc_is 0

summary cli
