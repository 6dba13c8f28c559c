#!/usr/bin/env bash
# veduta set-up on Debian 12: installs the Debian packages that are missing, builds, and then
#   ./setup.sh         renders the built-in default scene to renders/default.exr and .png
#   ./setup.sh test    builds with the tests and runs the whole suite through ctest, then the
#                      unit tests again under AddressSanitizer + UBSan (the sanitize preset),
#                      then every fuzz target for 20 s on its corpus and regression files
#   ./setup.sh stills  renders the publication stills of every example scene to renders/stills/
# Run it as root or as a user who may use sudo (only apt-get needs it).
set -euo pipefail
cd "$(dirname "$0")"

mode=${1:-render}
case "$mode" in
    render | test | stills) ;;
    *) echo "usage: $0 [render|test|stills]" >&2; exit 2 ;;
esac

packages=(
    cmake g++ make pkg-config ccache time clang-format clang libclang-rt-14-dev
    libembree-dev libopenimageio-dev openimageio-tools libopenexr-dev libopencolorio-dev opencolorio-tools
    libgeographiclib-dev libproj-dev proj-data libcgal-dev libgdal-dev libcitygml-dev libtbb-dev libpugixml-dev libcli11-dev
    libgtest-dev libbenchmark-dev libfmt-dev libassimp-dev libtinyobjloader-dev libtinygltf-dev libboost-dev libpng-dev zlib1g-dev libosmesa6-dev
    dpkg-dev slurm-wlm munge
)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing ${missing[*]}"
    as_root=()
    [ "$(id -u)" -eq 0 ] || as_root=(sudo)
    "${as_root[@]}" apt-get update -qq
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi

jobs=$(nproc)
# Compiler caches hit from any checkout folder: paths below it are hashed relative.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
if [ "$mode" = render ]; then
    cmake --preset release
    cmake --build --preset release -j "$jobs"
    build/release/src/veduta render -o renders/default.exr --png renders/default.png
    echo "setup: wrote renders/default.exr and renders/default.png"
elif [ "$mode" = stills ]; then
    cmake --preset release
    cmake --build --preset release -j "$jobs"
    find scenes -name '*.xml' | sort | while read -r scene; do
        name=$(echo "${scene#scenes/}" | sed 's/\.xml$//; s|/|_|g')
        # Scenes on the data in ../shared are left out where it is not there.
        missing=0
        for needed in $(grep -o '\.\./\.\./shared/[^"]*' "$scene"); do
            [ -e "$(dirname "$scene")/$needed" ] || missing=1
        done
        if [ $missing = 1 ]; then
            echo "setup: $scene needs ../shared, which is not there; left out"
            continue
        fi
        build/release/src/veduta render "$scene" --res 960x540 --spp 256 --max-depth 8 \
            -o "build/stills/$name.exr" --png "renders/stills/$name.png"
    done
else
    # The Khronos glTF validator for the gltf_validator test, where npm is installed (the test
    # skips without it).
    if command -v npm >/dev/null && [ ! -f build/npm/node_modules/gltf-validator/package.json ]; then
        npm install --silent --no-audit --no-fund --prefix build/npm gltf-validator@2.0.0-dev.3.10 ||
            echo "setup: gltf-validator could not be installed from npm; the gltf_validator test will skip"
    fi
    # The whole suite, then the unit tests once more under AddressSanitizer and UBSan.
    for preset in test sanitize; do
        start=$SECONDS
        cmake --preset "$preset"
        cmake --build --preset "$preset" -j "$jobs"
        built=$SECONDS
        ctest --preset "$preset" -j "$jobs"
        echo "setup: $preset preset built in $((built - start)) s, tested in $((SECONDS - built)) s"
    done
    start=$SECONDS
    cmake --preset fuzz
    cmake --build --preset fuzz -j "$jobs"
    built=$SECONDS
    fuzz/run_fuzzers.sh 20
    echo "setup: fuzz preset built in $((built - start)) s, fuzzed in $((SECONDS - built)) s"
fi
