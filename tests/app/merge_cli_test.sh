#!/usr/bin/env bash
# `veduta merge`: the default scene rendered as four regions and merged is bit-identical to the
# whole render; rendered as two sample ranges and merged it is within 1 ulp of it (the reason is
# in docs/output.md, "Merging"); overlapping regions, a gap and a different scene exit 1.
# Pixel values are compared bit for bit.
# Usage: merge_cli_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"
command -v oiiotool >/dev/null || { echo "oiiotool missing (Debian: openimageio-tools)"; exit 1; }

render() { "$veduta" render --res 160x90 -q "$@" || echo "render $* failed"; }
render --spp 8 -o "$work/full.exr"
render --spp 8 --region 0 0 80 45 -o "$work/t1.exr"
render --spp 8 --region 80 0 160 45 -o "$work/t2.exr"
render --spp 8 --region 0 45 80 90 -o "$work/t3.exr"
render --spp 8 --region 80 45 160 90 -o "$work/t4.exr"
render --spp 4 -o "$work/r1.exr"
render --spp 4 --sample-offset 4 -o "$work/r2.exr"

# compare A B: per channel, how many values are bit-identical and the largest distance in ulps
# (steps between the floats' bit patterns), one line each: "CHANNEL IDENTICAL/COUNT MAX_ULPS".
# The pixels go through uncompressed float TIFFs, which hold the floats' bits as they are.
compare() {
    oiiotool --info -v "$1" | sed -n 's/^ *channel list: //p' >"$work/channels"
    oiiotool "$1" -d float --compression none -o "$work/a.tif"
    oiiotool "$2" -d float --compression none -o "$work/b.tif"
    python3 - "$work/channels" "$work/a.tif" "$work/b.tif" <<'PY'
import struct, sys
channels = [c.strip() for c in open(sys.argv[1]).read().split(",")]
def pixels(path):  # the strips of a little-endian TIFF, pixel-interleaved, as 32-bit integers
    data = open(path, "rb").read()
    assert data[:2] == b"II"
    ifd = struct.unpack_from("<I", data, 4)[0]
    tags = {}
    for k in range(struct.unpack_from("<H", data, ifd)[0]):
        tag, kind, count, value = struct.unpack_from("<HHII", data, ifd + 2 + 12 * k)
        form = "<" + ("H" if kind == 3 else "I") * count
        inline = count * (2 if kind == 3 else 4) <= 4
        tags[tag] = struct.unpack_from(form, data, ifd + 10 + 12 * k if inline else value)
    assert tags[277][0] == len(channels) and tags.get(284, (1,))[0] == 1 and tags.get(259, (1,))[0] == 1
    strips = b"".join(data[o:o + c] for o, c in zip(tags[273], tags[279]))
    return struct.unpack("<%di" % (len(strips) // 4), strips)
def ordered(i):  # float bits as an integer that orders like the value
    return i if i >= 0 else -(i & 0x7fffffff)
a, b = pixels(sys.argv[2]), pixels(sys.argv[3])
assert len(a) == len(b) > 0, (len(a), len(b))
for c, name in enumerate(channels):
    ulps = [abs(ordered(x) - ordered(y)) for x, y in zip(a[c::len(channels)], b[c::len(channels)])]
    print(name, f"{ulps.count(0)}/{len(ulps)}", max(ulps))
PY
}
# The largest ulp distance over the channels whose names match the pattern.
max_ulps() { awk -v p="$2" '$1 ~ p && $3 > m { m = $3 } END { print m + 0 }' "$1"; }

run merge "$work/tiles.exr" "$work/t3.exr" "$work/t1.exr" "$work/t4.exr" "$work/t2.exr"
check "four regions merge" rc_is 0
check "summary line" bash -c "grep -qF 'tiles.exr: 4 files, window 0 0 160 90 of 160x90, samples [0, 8)' '$work/err'"
compare "$work/full.exr" "$work/tiles.exr" >"$work/tiles.cmp"
echo "four regions vs the whole render:"; cat "$work/tiles.cmp"
check "regions: every pixel value bit-identical" test "$(max_ulps "$work/tiles.cmp" .)" = 0
check "regions: all channels compared" test "$(wc -l <"$work/tiles.cmp")" = 25

run merge -q "$work/ranges.exr" "$work/r2.exr" "$work/r1.exr"
check "two sample ranges merge" rc_is 0
check "quiet" test ! -s "$work/err"
compare "$work/full.exr" "$work/ranges.exr" >"$work/ranges.cmp"
echo "samples [0, 4) + [4, 8) vs [0, 8):"; cat "$work/ranges.cmp"
check "ranges: radiance within 1 ulp" test "$(max_ulps "$work/ranges.cmp" 'Combined')" -le 1
check "ranges: first-sample passes bit-identical" test "$(max_ulps "$work/ranges.cmp" 'Depth|Position|Index|SampleCount')" = 0
meta=$(oiiotool --info -v "$work/ranges.exr")
check "merged samples" grep -q 'veduta.samples: 8$' <<<"$meta"
check "merged offset" grep -q 'veduta.sampleOffset: 0$' <<<"$meta"

run merge "$work/bad.exr" "$work/full.exr" "$work/t1.exr"
check "overlapping regions exit 1" rc_is 1
check "overlap named" err_has "overlaps the data window 0 0 160 90 of $work/full.exr"
check "nothing written" test ! -e "$work/bad.exr"
run merge "$work/bad.exr" "$work/t1.exr" "$work/t2.exr" "$work/t3.exr"
check "a missing region exits 1" rc_is 1
check "missing pixels counted" err_has "the tiles leave 3600 of the 14400 pixels of their bounding box 0 0 160 90 uncovered"
run merge "$work/bad.exr" "$work/r1.exr" "$work/t1.exr"
check "tiles of different ranges exit 1" rc_is 1
cat >"$work/other.xml" <<'XML'
<scene>
  <camera position="0 -3 1" look_at="0 0 0.5" resolution="160 90"/>
  <box/>
</scene>
XML
"$veduta" render "$work/other.xml" --spp 4 --sample-offset 4 -q -o "$work/other.exr"
run merge "$work/bad.exr" "$work/r1.exr" "$work/other.exr"
check "a different scene exits 1" rc_is 1
check "different scene named" err_has "$work/other.exr: has a different veduta.sceneHash from $work/r1.exr"
run merge "$work/bad.exr" "$work/r1.exr" "$work/r1.exr"
check "the same range twice exits 1" rc_is 1
check "overlapping ranges named" err_has "its samples [0, 4) overlap the samples [0, 4)"
echo "not an image" >"$work/junk.exr"
run merge "$work/bad.exr" "$work/junk.exr"
check "an unreadable input exits 1" rc_is 1
run merge "$work/bad.exr" "$work/absent.exr"
check "an absent input exits 2" rc_is 2
run merge --help
check "help exits 0" rc_is 0
check "help text" out_has "Assemble tiles"

summary merge_cli
