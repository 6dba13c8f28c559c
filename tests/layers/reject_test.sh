#!/usr/bin/env bash
# check_layers.sh must refuse a tree with a wrong include and one whose link list differs from
# the documented graph; the real tree must pass (the ctest `layers`).
set -euo pipefail
root=${1:?usage: reject_test.sh ROOT}
check=$(dirname "$0")/check_layers.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

copy() { rm -rf "$work/tree"; mkdir -p "$work/tree"; cp -r "$root/src" "$root/docs" "$work/tree/"; }
expect_refusal() {  # what, expected message
    if out=$(bash "$check" "$work/tree" 2>&1); then echo "FAIL: $1 was accepted"; exit 1; fi
    grep -qF "$2" <<<"$out" || { echo "FAIL: $1: no '$2' in:"; echo "$out"; exit 1; }
    echo "ok: $1 refused"
}

copy
sed -i '1i #include "render/bvh.h"' "$work/tree/src/geo/atkis.h"
expect_refusal "geo including render" "src/geo/atkis.h:1: geo may not include render/"

copy
sed -i '1i #include "city/footprint.h"' "$work/tree/src/scene/mesh.cpp"
expect_refusal "scene including city" "src/scene/mesh.cpp:1: scene may not include city/"

copy
sed -i 's/^\(  USES core scene film\)$/\1 io/' "$work/tree/src/CMakeLists.txt"
expect_refusal "render linking io" "layer render links [ core film io scene ]"

copy
mkdir "$work/tree/src/extra" && echo '#include "core/error.h"' > "$work/tree/src/extra/x.h"
expect_refusal "an undocumented folder" "src/extra: a folder that the layer table"

copy
bash "$check" "$work/tree" >/dev/null && echo "ok: the unchanged tree passes"
