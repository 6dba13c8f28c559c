#!/usr/bin/env bash
# `veduta export`: the default scene as GLB, OBJ (with its .mtl, an object per mesh) and PLY, the
# summary line; a georeferenced scene with an image map as glTF (the map copied beside it, the
# .prj and .geo.json sidecars); and the exit codes of a bad extension (2), a bad scene (1),
# neither leaving a file behind, and an output that cannot be written (3).
# Usage: export_cli_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
out=$work/files  # what export writes, apart from run's out, err and rc
mkdir "$out"

run export --help
check "help exits 0" rc_is 0
check "help text" out_has "glTF (Y up, instanced"
check "help names ply" out_has "FILE.gltf|.glb|.obj|.ply"

run export -o "$out/default.glb"
check "default scene as GLB" rc_is 0
check "glb written" test -s "$out/default.glb"
check "glb magic" test "$(head -c 4 "$out/default.glb")" = glTF
check "glb summary" err_has "default.glb: 10 meshes, 49 instances, 4766 triangles, 0 textures, 1 files, "
check "no georeference said" err_has "no georeference: the file is in local metres only"
check "one file written" test "$(ls -A "$out")" = default.glb

run export -q -o "$out/default.obj"
check "default scene as OBJ" rc_is 0
check "quiet" test ! -s "$work/err"
check "obj written" grep -q '^f ' "$out/default.obj"
check "an object per mesh and copy" test "$(grep -c '^o ' "$out/default.obj")" = 57
check "obj names its mtl" grep -qx 'mtllib default.mtl' "$out/default.obj"
check "mtl written" grep -q '^newmtl ' "$out/default.mtl"
check "no temporaries left" test "$(ls -A "$out" | tr '\n' ' ')" = "default.glb default.mtl default.obj "

run export -q -o "$out/default.ply"
check "default scene as PLY" rc_is 0
check "ply header" test "$(head -c 36 "$out/default.ply" | tr '\n' ' ')" = "ply format binary_little_endian 1.0 "
check "ply faces" grep -aqx 'element face 4766' "$out/default.ply"

map=$source_dir/materials/textures/brick_diffuse.png
cat >"$work/geo.xml" <<XML
<scene>
  <georeference crs="EPSG:25832" origin="531200 5326800"/>
  <material name="brick" diffuse_map="$map"/>
  <box size="4 4 3" material="brick"/>
</scene>
XML
mkdir "$out/geo"
run export "$work/geo.xml" -o "$out/geo/wall.gltf"
check "georeferenced scene as glTF" rc_is 0
check "its files" test "$(ls -A "$out/geo" | tr '\n' ' ')" = "brick_diffuse.png wall.bin wall.geo.json wall.gltf wall.prj "
check "map copied as it is" cmp -s "$map" "$out/geo/brick_diffuse.png"
check "map referenced" grep -q '"uri":"brick_diffuse.png"' "$out/geo/wall.gltf"
check "crs in the asset's extras" grep -q '"crs": "EPSG:25832"' "$out/geo/wall.gltf"
check "prj is ESRI WKT" grep -q '^PROJCS\["ETRS_1989_UTM_Zone_32N"' "$out/geo/wall.prj"
check "geo.json origin" grep -q '"origin": \[531200, 5326800, 0\]' "$out/geo/wall.geo.json"
check "textures counted" err_has "1 textures, 5 files"

run export -o "$out/default.fbx"
check "unknown extension exits 2" rc_is 2
check "unknown extension named" err_has "'$out/default.fbx' is not an .obj, .gltf, .glb or .ply file"
check "nothing written for it" test ! -e "$out/default.fbx"

printf '<scene>\n  <box sise="1 1 1"/>\n</scene>\n' >"$work/bad.xml"
run export "$work/bad.xml" -o "$out/bad.gltf"
check "bad scene exits 1" rc_is 1
check "bad scene place" err_has "$work/bad.xml:2:8: unknown attribute 'sise' on <box>"
check "nothing written for it either" test ! -e "$out/bad.gltf" -a ! -e "$out/bad.bin"

touch "$work/afile"
run export -o "$work/afile/x.glb"
check "unwritable output exits 3" rc_is 3
check "unwritable output named" err_has "$work/afile"

mkdir "$out/in_the_way.obj"
run export -o "$out/in_the_way.obj"
check "a folder in the way exits 3" rc_is 3
check "the folder is named" err_has "in_the_way.obj: cannot write it: something other than a file is there"
check "and left alone, no .mtl written" test -d "$out/in_the_way.obj" -a ! -e "$out/in_the_way.mtl"

summary export_cli
