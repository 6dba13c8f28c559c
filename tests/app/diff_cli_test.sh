#!/usr/bin/env bash
# `veduta diff` as a script would call it: idiff's exit codes (0 pass, 1 fail, 2 error), the
# key: value figures, messages and the diff image. Test images are made with oiiotool.
# Usage: diff_cli_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

fail_early() { echo "$1"; echo "diff_cli: 0 passed, 1 failed"; exit 1; }
command -v oiiotool >/dev/null || fail_early "oiiotool is missing (Debian package openimageio-tools)"

# One oiiotool run (each start costs about a second): a 64x64 reference; a copy with one pixel
# off by 0.5 (0.02 % of the pixels); one with a 9x9 block off by 0.1 (1.98 %); a narrower image;
# a constant per-sample variance of 0.04; an 8-bit PNG.
oiiotool -d float --pattern constant:color=0.2,0.4,0.6 64x64 3 -o "$work/ref.exr" \
    --dup --fill:color=0.7,0.4,0.6 1x1+10+12 -o "$work/one.exr" --pop \
    --dup --fill:color=0.3,0.4,0.6 9x9+20+20 -o "$work/block.exr" --pop \
    --pattern constant:color=0.2,0.4,0.6 32x64 3 -o "$work/narrow.exr" \
    --pattern constant:color=0.04,0.04,0.04 64x64 3 -o "$work/var.exr" \
    --pattern checker:color1=0.1,0.1,0.1:color2=0.9,0.9,0.9 64x64 3 -d uint8 -o "$work/checker.png" ||
    fail_early "oiiotool could not make the test images"

run diff --help
check "help exits 0" rc_is 0
check "help text" grep -qF "Usage" "$work/out"
check "help names the exit codes" grep -qF "Exit codes" "$work/out"

run diff "$work/ref.exr" "$work/ref.exr"
check "identical exits 0" rc_is 0
for line in "pixels: 4096" "failed_pixels: 0" "mean_error: 0" "max_error: 0" "rmse: 0" "relmse: 0" "psnr_db: inf" \
    "verdict: pass"; do
    check "identical: $line" out_line "$line"
done

run diff "$work/checker.png" "$work/checker.png"
check "identical PNGs exit 0" rc_is 0

run diff "$work/one.exr" "$work/ref.exr"
check "one pixel off exits 0" rc_is 0
check "one pixel off counted" out_line "failed_pixels: 1"
check "one pixel off: max error" out_line "max_error: 0.5"
check "one pixel off: where" out_line "max_error_at: 10,12"
check "one pixel off: verdict" out_line "verdict: pass"

run diff "$work/block.exr" "$work/ref.exr"
check "2% off exits 1" rc_is 1
check "2% off counted" out_line "failed_pixels: 81"
check "2% off: verdict" out_line "verdict: fail"
run diff "$work/block.exr" "$work/ref.exr" --failpercent 2
check "2% off within --failpercent 2" rc_is 0
run diff "$work/block.exr" "$work/ref.exr" --fail 0.2
check "2% off within --fail 0.2" rc_is 0
run diff "$work/block.exr" "$work/ref.exr" --fail nan
check "--fail nan is a bad command line" rc_is 2
run diff "$work/block.exr" "$work/ref.exr" --warn 0.05 --failpercent 5
check "warning still passes" rc_is 0
check "warning counted" out_line "warned_pixels: 81"
check "warning on stderr" err_has "veduta: warning:"

run diff "$work/block.exr" "$work/ref.exr" --metric relmse --max-relmse 0.01
check "relmse within threshold" rc_is 0
check "relmse metric named" out_line "metric: relmse"
run diff "$work/block.exr" "$work/ref.exr" --metric relmse --max-relmse 0.0001
check "relmse over threshold" rc_is 1

# Z-test: with a per-sample variance of 0.04, the block's 0.1 is 2 σ of a 16-sample mean, which
# the Šidák-corrected test lets through, and 32 σ of a 4096-sample mean, which it does not.
run diff "$work/block.exr" "$work/ref.exr" --metric ztest --reference-variance "$work/var.exr" --spp 16
check "ztest passes noise-sized differences" rc_is 0
check "ztest fraction printed" grep -qF "ztest_pass_fraction: 1" "$work/out"
run diff "$work/block.exr" "$work/ref.exr" --metric ztest --reference-variance "$work/var.exr" --spp 4096
check "ztest fails a 32 σ difference" rc_is 1

# Errors: exit 2.
run diff "$work/ref.exr" "$work/narrow.exr"
check "size mismatch exits 2" rc_is 2
check "size mismatch message" err_has "veduta: error: sizes differ: A is 64x64, B is 32x64"
run diff "$work/ref.exr" "$work/missing.exr"
check "missing file exits 2" rc_is 2
echo "not an image" >"$work/bad.exr"
run diff "$work/ref.exr" "$work/bad.exr"
check "unreadable file exits 2" rc_is 2
check "unreadable file named" err_has "$work/bad.exr"
run diff "$work/ref.exr" "$work/ref.exr" --bogus
check "bad option exits 2" rc_is 2
run diff "$work/ref.exr" "$work/ref.exr" --metric nonsense
check "bad metric exits 2" rc_is 2
run diff "$work/ref.exr" "$work/ref.exr" --metric relmse
check "relmse without threshold exits 2" rc_is 2
run diff "$work/ref.exr" "$work/ref.exr" --metric ztest
check "ztest without variance exits 2" rc_is 2
run diff "$work/ref.exr" "$work/ref.exr" -o "$work/diff.jpg"
check "non-png diff image exits 2" rc_is 2

# The diff image: 8-bit RGB PNG, |A - B| x 16, no temporary left beside it.
run diff "$work/one.exr" "$work/ref.exr" -o "$work/diffs/diff.png"
check "diff image run exits 0" rc_is 0
check "diff image written" test -s "$work/diffs/diff.png"
oiiotool --info -v --dumpdata "$work/diffs/diff.png" >"$work/pixels" 2>&1
check "diff image is 8-bit RGB PNG" grep -qF "64 x   64, 3 channel, uint8 png" "$work/pixels"
check "diff image: the changed pixel is red" grep -qF "Pixel (10, 12): 255 0 0" "$work/pixels"
check "diff image: elsewhere black" grep -qF "Pixel (11, 12): 0 0 0" "$work/pixels"
check "no temporary left" bash -c "! ls -a '$work/diffs' | grep -q tmp"
run diff "$work/block.exr" "$work/ref.exr" -o "$work/diffs/diff2.png"
check "diff image written when the images differ" test -s "$work/diffs/diff2.png"

summary diff_cli
