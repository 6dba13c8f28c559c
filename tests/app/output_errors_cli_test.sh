#!/bin/bash
# Output errors: a full disk or a read-only folder gives a clear message and a failing exit
# code, leaves no partial file under the output's name and keeps an older file there intact.
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

run render "${small[@]}" -o "$work/readonly/x.exr"
check "read-only folder: fails before rendering" rc_is 3
check "read-only folder: says so" err_has "$work/readonly/x.exr: its folder is not writable"
check "read-only folder: nothing written" nothing_but "$work/readonly"

summary output_errors_cli
