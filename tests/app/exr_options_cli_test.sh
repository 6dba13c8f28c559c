#!/usr/bin/env bash
# `veduta render`'s EXR options as other programs see them through OpenImageIO: --passes, --half,
# --compression, --rgba, the chromaticities and camera matrices, Cryptomatte's layers and header,
# and `veduta merge` of parts written with them.
# Usage: exr_options_cli_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

for tool in oiiotool idiff; do
    if ! command -v $tool >/dev/null; then
        echo "exr_options_cli: $tool (OpenImageIO's tools) not found; skipping"
        exit 77
    fi
done

describe() { oiiotool --info -v "$1" >"$work/info" 2>&1; }
channel_list() { grep -E '^ *channel list:' "$work/info"; }
# has_channel NAME [TYPE]: oiiotool shows types only when the channels' types differ.
has_channel() {
    local pattern="$1( \\([a-z]+\\))?"
    [ $# -gt 1 ] && pattern="$1 \\($2\\)"
    channel_list | grep -qE "(: |, )$pattern(,|\$)" || { echo "no $* in:"; channel_list; false; }
}
lacks_channel() { ! channel_list | grep -qE "(: |, )$1 \("; }
has_attribute() { grep -qE "^ *$1: $2" "$work/info" || { echo "no attribute $1: $2 in:"; cat "$work/info"; false; }; }
channel_count_is() { grep -q "40 x  *24, $1 channel" "$work/info" || { head -2 "$work/info"; false; }; }
small=(--res 40x24 --spp 8 -q)

run render --help
check "help exits 0" rc_is 0
for option in --passes --half --compression --rgba --cryptomatte-depth; do
    check "help names $option" out_has "$option"
done

# --passes: only the passes asked for; --png still comes from the film.
run render "${small[@]}" --passes Combined,Depth -o "$work/two.exr" --png "$work/two.png"
check "two passes" rc_is 0
describe "$work/two.exr"
check "two passes: 5 channels" channel_count_is 5
check "two passes: Combined" has_channel ViewLayer.Combined.A
check "two passes: Depth" has_channel ViewLayer.Depth.Z
check "two passes: no Normal" lacks_channel ViewLayer.Normal.X
run render "${small[@]}" --passes Depth -o "$work/depth.exr" --png "$work/depth.png"
check "png without the Combined pass in the EXR" rc_is 0
check "png written" test -s "$work/depth.png"
check "png the same as with Combined" idiff -q -fail 0 "$work/two.png" "$work/depth.png"

run render "${small[@]}" --passes Combined,Bogus -o "$work/bogus.exr"
check "unknown pass exits 2" rc_is 2
check "unknown pass names the valid ones" err_has "unknown pass 'Bogus'; passes: all, Combined, CombinedEven"
check "unknown pass writes nothing" test ! -e "$work/bogus.exr"

# --half: colour passes half, data passes float; --rgba: top-level R G B A that oiiotool --ch finds.
run render "${small[@]}" --half --rgba -o "$work/half.exr"
check "half and rgba" rc_is 0
describe "$work/half.exr"
check "half: 29 channels" channel_count_is 29
for channel in R A ViewLayer.Combined.R ViewLayer.CombinedOdd.B ViewLayer.Normal.X ViewLayer.DiffCol.G; do
    check "half: $channel half" has_channel "$channel" half
done
for channel in ViewLayer.Depth.Z ViewLayer.Position.X ViewLayer.IndexOB.X ViewLayer.IndexMA.X ViewLayer.SampleCount.X; do
    check "half: $channel float" has_channel "$channel" float
done
check "chromaticities Rec.709 D65" has_attribute chromaticities '0.64, 0.33, 0.3, 0.6, 0.15, 0.06, 0.3127, 0.329$'
check "worldToNDC" has_attribute worldToNDC '[-0-9.e]+(, [-0-9.e]+){15}$'
check "veduta.scene" has_attribute veduta.scene '"\(built-in default scene\)"'
oiiotool "$work/half.exr" --ch R,G,B,A -o "$work/rgba.exr" 2>"$work/err"
check "oiiotool --ch R,G,B,A" test -s "$work/rgba.exr"
oiiotool "$work/half.exr" --ch ViewLayer.Combined.R,ViewLayer.Combined.G,ViewLayer.Combined.B,ViewLayer.Combined.A \
    --chnames R,G,B,A -o "$work/combined.exr" 2>"$work/err"
check "top-level RGBA is the Combined pass" idiff -q -fail 0 "$work/rgba.exr" "$work/combined.exr"

# --compression: OpenEXR's codecs by name; those that change 32-bit floats only without data passes.
run render "${small[@]}" --compression piz -o "$work/piz.exr"
check "piz" rc_is 0
describe "$work/piz.exr"
check "piz in the header" has_attribute compression '"piz"'
for codec in pxr24 dwaa dwab; do
    run render "${small[@]}" --compression $codec -o "$work/$codec.exr"
    check "$codec with data passes exits 2" rc_is 2
    check "$codec names the data passes" err_has "would change the data passes Depth, Position, IndexOB"
    check "$codec writes nothing" test ! -e "$work/$codec.exr"
done
run render "${small[@]}" --compression dwab --half --passes Combined,Normal,DiffCol -o "$work/dwab.exr"
check "dwab with colour passes" rc_is 0
describe "$work/dwab.exr"
check "dwab in the header" has_attribute compression '"dwab"'
run render "${small[@]}" --compression lzma -o "$work/lzma.exr"
check "unknown codec exits 2" rc_is 2

# Cryptomatte: Blender's layer names, the specification's header entries, ids in the manifest.
run render "${small[@]}" --passes Combined,SampleCount,CryptoObject,CryptoMaterial -o "$work/crypto.exr"
check "cryptomatte" rc_is 0
describe "$work/crypto.exr"
check "cryptomatte: 5 + 2 x 12 channels" channel_count_is 29
for kind in Object Material; do
    for layer in 00 01 02; do
        for c in R G B A; do check "Crypto$kind$layer.$c" has_channel "ViewLayer.Crypto$kind$layer.$c"; done
    done
    check "Crypto$kind: 6 ranks only" lacks_channel "ViewLayer.Crypto${kind}03.R"
    key=$(grep -E "^ *cryptomatte/[0-9a-f]{7}/name: \"ViewLayer.Crypto$kind\"" "$work/info" | sed -E 's|^ *cryptomatte/([0-9a-f]{7})/.*|\1|')
    check "Crypto$kind: named in the header" test -n "$key"
    check "Crypto$kind: hash" has_attribute "cryptomatte/$key/hash" '"MurmurHash3_32"'
    check "Crypto$kind: conversion" has_attribute "cryptomatte/$key/conversion" '"uint32_to_float32"'
done
check "object manifest" grep -qE '^ *cryptomatte/[0-9a-f]{7}/manifest: "\{"object_[0-9]+":"[0-9a-f]{8}"' "$work/info"
check "material manifest" grep -qE '^ *cryptomatte/[0-9a-f]{7}/manifest: .*"plaster_white":"3ce13570"' "$work/info"
run render "${small[@]}" --passes CryptoObject --cryptomatte-depth 2 -o "$work/depth2.exr"
check "cryptomatte depth 2" rc_is 0
describe "$work/depth2.exr"
check "depth 2: one layer" channel_count_is 4

# Merging: ranges and regions written with --half, --rgba, a codec and Cryptomatte.
opts=(--res 40x24 -q --half --rgba --compression piz --passes all)
"$veduta" render "${opts[@]}" --spp 8 -o "$work/whole.exr"
"$veduta" render "${opts[@]}" --spp 4 -o "$work/first.exr"
"$veduta" render "${opts[@]}" --spp 4 --sample-offset 4 -o "$work/second.exr"
run merge -q "$work/ranges.exr" "$work/second.exr" "$work/first.exr"
check "merge of half ranges" rc_is 0
describe "$work/ranges.exr"
check "merged: half kept" has_channel ViewLayer.Combined.R half
check "merged: float kept" has_channel ViewLayer.CryptoObject00.R float
check "merged: codec kept" has_attribute compression '"piz"'
crypto=$(oiiotool --info -v "$work/whole.exr" | grep -oE 'ViewLayer\.Crypto[A-Za-z]+0[0-9]\.[RGBA]' | sort -u | paste -sd,)
oiiotool "$work/whole.exr" --ch "$crypto" -o "$work/whole_crypto.exr"
oiiotool "$work/ranges.exr" --ch "$crypto" -o "$work/ranges_crypto.exr"
check "merged ranges: Cryptomatte as the single render" idiff -q -fail 0 "$work/whole_crypto.exr" "$work/ranges_crypto.exr"
"$veduta" render "${opts[@]}" --spp 8 --region 0 0 40 10 -o "$work/top.exr"
"$veduta" render "${opts[@]}" --spp 8 --region 0 10 40 24 -o "$work/bottom.exr"
run merge -q "$work/regions.exr" "$work/top.exr" "$work/bottom.exr"
check "merge of half regions" rc_is 0
check "merged regions: the whole render" idiff -q -fail 0 "$work/whole.exr" "$work/regions.exr"
"$veduta" render --res 40x24 -q --rgba --compression piz --passes all --spp 4 --sample-offset 4 -o "$work/float.exr"
run merge -q "$work/mixed.exr" "$work/first.exr" "$work/float.exr"
check "half and float parts exit 1" rc_is 1
check "half and float parts named" err_has "as half"
check "half and float parts: nothing written" test ! -e "$work/mixed.exr"

summary exr_options_cli
