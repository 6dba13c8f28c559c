#!/usr/bin/env bash
# Whether Blender picks veduta's Cryptomatte as veduta meant it: renders a scene with the Crypto
# passes, lets Blender's Cryptomatte node key one material and one object by name (through the
# manifest), and compares the mean of Blender's matte with the mean coverage veduta stored for
# that name (bench_cryptomatte_coverage). Exits 77 without Blender.
# Usage: bench/blender_cryptomatte.sh [BUILD_DIR] [MATERIAL] [OBJECT]
#        (default build/release, the default scene's roof_tiles and object_17)
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v blender >/dev/null; then
    echo "blender_cryptomatte: skipped: blender is not installed (Debian: apt-get install blender)"
    exit 77
fi
build=${1:-build/release} material=${2:-roof_tiles} object=${3:-object_17}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/src/veduta" render --spp 16 --res 320x180 --passes all -q -o "$work/crypto.exr"

compare() {  # compare LAYER KIND NAME
    blender -b --factory-startup --python-exit-code 1 -P bench/blender_cryptomatte.py -- \
        "$work/crypto.exr" "ViewLayer.$1" "$3" 320 180 "$work/matte.exr" >"$work/blender.log" 2>&1 ||
        { tail -20 "$work/blender.log"; exit 1; }
    local blender veduta
    blender=$(oiiotool "$work/matte.exr" --ch R --printstats | awk '/Stats Avg/ { print $3 }')
    veduta=$("$build/bench/bench_cryptomatte_coverage" "$work/crypto.exr" "$2" "$3")
    echo "$1 '$3': mean matte in Blender $blender, mean coverage veduta stored $veduta"
}
compare CryptoMaterial material "$material"
compare CryptoObject object "$object"
