#!/bin/bash
# Output errors: a full disk or a read-only folder gives a clear message and a failing exit
# code, leaves no partial file under the output's name and keeps an older file there intact.
# Every command that writes files is tried: render (EXR, PNG, display image, checkpoint),
# preview, facade, building, cubemap, merge, export and diff.
# Needs a private mount namespace with tmpfs (root or user namespaces); skips (exit 77) without.
# Usage: output_errors_cli_test.sh VEDUTA
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/test_lib.sh"

if [ -z "$VEDUTA_IN_NAMESPACE" ]; then
    if ! unshare -m --map-root-user true 2>/dev/null && ! unshare -m true 2>/dev/null; then
        echo "output_errors_cli: skipped, no mount namespace here"
        exit 77
    fi
    flags=(-m)
    unshare -m true 2>/dev/null || flags=(-m --map-root-user)
    VEDUTA_IN_NAMESPACE=1 exec unshare "${flags[@]}" bash "$0" "$@"
fi
mkdir "$work/full" "$work/readonly"
if ! mount -t tmpfs -o size=96k tmpfs "$work/full" 2>/dev/null || ! mount -t tmpfs -o ro tmpfs "$work/readonly"; then
    echo "output_errors_cli: skipped, cannot mount tmpfs here"
    exit 77
fi
trap 'umount "$work/full" "$work/readonly"; rm -rf "$work"' EXIT

nothing_but() {  # nothing_but FOLDER FILE...: the folder holds exactly these files
    local folder=$1; shift
    [ "$(ls -A "$folder" | sort | tr '\n' ' ')" = "$( (($#)) && printf '%s\n' "$@" | sort | tr '\n' ' ')" ] ||
        { echo "$folder holds: $(ls -A "$folder")"; false; }
}

small=(--res 160x90 --spp 2 -q)
echo "an older image" >"$work/full/x.exr"
run render "${small[@]}" -o "$work/full/x.exr"
check "full disk: exit code 3" rc_is 3
check "full disk: the message names the file and the cause" err_has "$work/full/x.exr: No space left on device"
check "full disk: the older file is intact" grep -q "an older image" "$work/full/x.exr"
check "full disk: no temporary is left" nothing_but "$work/full" x.exr

run render "${small[@]}" -o "$work/full/y.exr" --image "$work/full/y.png"
check "full disk, display image: fails" rc_is 3
check "full disk, display image: nothing left" nothing_but "$work/full" x.exr

run preview --res 2000x2000 -q -o "$work/full/z.png"
check "full disk, preview PNG: fails" rc_is 3
check "full disk, preview PNG: nothing left" nothing_but "$work/full" x.exr

# Six faces that do not all fit: none of them is left.
if command -v oiiotool >/dev/null; then
    oiiotool --pattern noise:type=white 256x128 3 -d float -o "$work/noise.exr"
    run cubemap "$work/noise.exr" -o "$work/full/c_{face}.exr" --size 64
    check "full disk, cube faces: fails" rc_is 3
    check "full disk, cube faces: no face is left" nothing_but "$work/full" x.exr
fi

# EXR and PNG are one set: the PNG that does not fit takes the new EXR with it, and the
# older pair stays as it was.
echo "an older png" >"$work/full/x.png"
run render --res 160x90 --spp 2 -q -o "$work/full/x.exr" --png "$work/full/x.png"
check "full disk, EXR + PNG: fails" rc_is 3
check "full disk, EXR + PNG: the older EXR is intact" grep -q "an older image" "$work/full/x.exr"
check "full disk, EXR + PNG: the older PNG is intact" grep -q "an older png" "$work/full/x.png"
check "full disk, EXR + PNG: nothing else" nothing_but "$work/full" x.exr x.png
rm "$work/full/x.png"

# A checkpoint that does not fit: the render stops with the error, the older checkpoint stays.
echo "an older checkpoint" >"$work/full/c.checkpoint"
run render --res 400x300 --spp 4 -q -o "$work/elsewhere.exr" --checkpoint "$work/full/c.checkpoint" \
    --checkpoint-every 0.001
check "full disk, checkpoint: fails" rc_is 3
check "full disk, checkpoint: the older checkpoint is intact" grep -q "an older checkpoint" "$work/full/c.checkpoint"
check "full disk, checkpoint: nothing else" nothing_but "$work/full" x.exr c.checkpoint
rm "$work/full/c.checkpoint"

# The other commands on a disk that holds one page more than their older output: whatever
# they write does not fit (a facade's PNG compresses too well for the 96 kB disk).
mkdir "$work/tiny"
mount -t tmpfs -o size=8k tmpfs "$work/tiny" || { echo "output_errors_cli: cannot mount a second tmpfs"; exit 1; }
trap 'umount "$work/full" "$work/readonly" "$work/tiny"; rm -rf "$work"' EXIT
rules=$(dirname "$0")/../../rules/gruenderzeit/FacadeStructure.xml
footprint=(--footprint 0 0 16 0 16 14 0 14)
fails_keeping() {  # fails_keeping NAME EXIT FILE -- COMMAND...: FILE, older, is all that is left
    local name=$1 code=$2 file=$3
    shift 4
    rm -f "$work/tiny"/*
    echo "older" >"$work/tiny/$file"
    run "$@"
    check "tiny disk, $name: exit code $code" rc_is "$code"
    check "tiny disk, $name: the older file is intact" grep -qx "older" "$work/tiny/$file"
    check "tiny disk, $name: nothing else is left" nothing_but "$work/tiny" "$file"
}
fails_keeping facade 3 f.png -- facade "$rules" --res 800x800 -o "$work/tiny/f.png"
fails_keeping building 3 b.png -- building "$rules" "${footprint[@]}" --res 800x800 -q -o "$work/tiny/b.png"
fails_keeping "preview EXR" 3 p.exr -- preview --res 400x300 -q -o "$work/tiny/p.exr"
# An OBJ and its MTL are one set; so are a glTF and its .bin.
fails_keeping "OBJ export" 3 b.obj -- export --rules "$rules" "${footprint[@]}" -o "$work/tiny/b.obj"
fails_keeping "glTF export" 3 b.gltf -- export --rules "$rules" "${footprint[@]}" -o "$work/tiny/b.gltf"
"$veduta" render --res 400x300 --spp 1 -q --region 0 0 400 150 -o "$work/top.exr"
"$veduta" render --res 400x300 --spp 1 -q --region 0 150 400 300 -o "$work/bottom.exr"
fails_keeping merge 3 m.exr -- merge "$work/tiny/m.exr" "$work/top.exr" "$work/bottom.exr"
"$veduta" render --res 400x300 --spp 1 -q -o "$work/a.exr"
"$veduta" render --res 400x300 --spp 1 -q --seed 9 -o "$work/b.exr"
fails_keeping "diff image" 2 d.png -- diff "$work/a.exr" "$work/b.exr" -o "$work/tiny/d.png"

run render "${small[@]}" -o "$work/readonly/x.exr"
check "read-only folder: fails before rendering" rc_is 3
check "read-only folder: says so" err_has "$work/readonly/x.exr: its folder is not writable"
check "read-only folder: nothing written" nothing_but "$work/readonly"

summary output_errors_cli
