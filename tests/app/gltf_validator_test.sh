#!/usr/bin/env bash
# The Khronos glTF validator on veduta's glTF: the default scene, the example landscape
# (25,800 instances, image maps, georeference) and the material showcase (glass, every kind of
# map), each as .gltf and .glb, must have no errors; warnings and infos are counted and shown.
# Needs node and the npm package gltf-validator: $VEDUTA_GLTF_VALIDATOR (the package's folder)
# or build/npm/node_modules/gltf-validator (npm install --prefix build/npm gltf-validator);
# exits 77 (skipped) without them.
# Usage: gltf_validator_test.sh VEDUTA_BINARY
set -u
veduta=$1
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
validator=${VEDUTA_GLTF_VALIDATOR:-$source_dir/build/npm/node_modules/gltf-validator}
if ! command -v node >/dev/null; then
    echo "gltf_validator: skipped: node is not installed (Debian: apt-get install nodejs)"
    exit 77
fi
if [ ! -f "$validator/package.json" ]; then
    echo "gltf_validator: skipped: no gltf-validator package at $validator" \
        "(npm install --prefix $source_dir/build/npm gltf-validator, or set VEDUTA_GLTF_VALIDATOR)"
    exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

validate() {  # validate NAME [SCENE]: exports the scene as NAME.gltf and NAME.glb, validates both
    local name=$1; shift
    mkdir "$work/$name"
    run export -q "$@" -o "$work/$name/$name.gltf"
    check "$name as .gltf" rc_is 0
    run export -q "$@" -o "$work/$name/$name.glb"
    check "$name as .glb" rc_is 0
    node "$(dirname "$0")/gltf_validate.js" "$validator" "$work/$name/$name.gltf" "$work/$name/$name.glb" \
        >"$work/$name/report" 2>&1
    local rc=$?
    grep -E ': [0-9]+ errors' "$work/$name/report" | sed "s|$work/$name/||"
    check "$name has no validation errors" test "$rc" = 0 || cat "$work/$name/report"
}

validate default
validate landscape "$source_dir/scenes/landscape.xml"
validate materials "$source_dir/scenes/materials.xml"
check "the landscape's maps are beside its .gltf" test -f "$work/landscape/plaster_diffuse.png"

summary gltf_validator
