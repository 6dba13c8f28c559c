#!/usr/bin/env bash
# `veduta export`: the default scene as GLB and OBJ (with its .mtl), the summary line, and the
# exit codes of a bad extension (2), a bad scene (1), neither leaving a file behind, and an
# output that cannot be written (3).
# Usage: export_cli_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"
out=$work/files  # what export writes, apart from run's out, err and rc
mkdir "$out"

run export --help
check "help exits 0" rc_is 0
check "help text" out_has "glTF (Y up, instanced)"

run export -o "$out/default.glb"
check "default scene as GLB" rc_is 0
check "glb written" test -s "$out/default.glb"
check "glb magic" test "$(head -c 4 "$out/default.glb")" = glTF
check "glb summary" err_has "default.glb: "
check "glb counted as one file" err_has ", 1 files, "
check "one file written" test "$(ls -A "$out")" = default.glb

run export -q -o "$out/default.obj"
check "default scene as OBJ" rc_is 0
check "quiet" test ! -s "$work/err"
check "obj written" grep -q '^f ' "$out/default.obj"
check "obj names its mtl" grep -qx 'mtllib default.mtl' "$out/default.obj"
check "mtl written" grep -q '^newmtl ' "$out/default.mtl"
check "no temporaries left" test "$(ls -A "$out" | tr '\n' ' ')" = "default.glb default.mtl default.obj "

run export -o "$out/default.fbx"
check "unknown extension exits 2" rc_is 2
check "unknown extension named" err_has "'$out/default.fbx' is not an .obj, .gltf or .glb file"
check "nothing written for it" test ! -e "$out/default.fbx"

printf '<scene>\n  <box sise="1 1 1"/>\n</scene>\n' >"$work/bad.xml"
run export "$work/bad.xml" -o "$out/bad.gltf"
check "bad scene exits 1" rc_is 1
check "bad scene place" err_has "$work/bad.xml:2:8: unknown attribute 'sise' on <box>"
check "nothing written for it either" test "$(ls -A "$out" | wc -l)" = 3

touch "$work/afile"
run export -o "$work/afile/x.glb"
check "unwritable output exits 3" rc_is 3
check "unwritable output named" err_has "$work/afile"

summary export_cli
