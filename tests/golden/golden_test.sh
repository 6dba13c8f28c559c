#!/usr/bin/env bash
# Golden-image test of one example scene: renders it with the path tracer (low spp, the
# scene's seed) and with the preview, and compares both with the references in
# renders/golden/ through `veduta diff` (oiiotool's -fail 0.016 -failpercent 1 rule).
#
#   golden_test.sh VEDUTA SOURCE_DIR SCENE WORK_DIR
#
# With VEDUTA_GOLDEN_UPDATE=1 it writes the references instead of comparing. On a failure it
# writes WORK_DIR/<name>/report.html showing new, reference and difference side by side.
set -u
veduta=$1 source=$2 scene=$3 work=$4
relative=${scene#"$source"/scenes/}
name=$(echo "${relative%.xml}" | tr '/' '_')
golden=$source/renders/golden
out=$work/$name
mkdir -p "$out"
resolution=160x90
spp=16

# A scene on the data in ../shared (its MANIFEST.md) skips where that is not there, as every test
# that needs it does.
for needed in $(grep -o '\.\./\.\./shared/[^"]*' "$scene"); do
    if [ ! -e "$(dirname "$scene")/$needed" ]; then
        echo "golden: skipping $name: $needed is not there"
        exit 77
    fi
done

"$veduta" render "$scene" --res $resolution --spp $spp -q -o "$out/render.exr" || exit 2
"$veduta" preview "$scene" --res $resolution -q -o "$out/preview.png" || exit 2

if [ "${VEDUTA_GOLDEN_UPDATE:-0}" = 1 ]; then
    mkdir -p "$golden"
    cp "$out/render.exr" "$golden/$name-render.exr"
    cp "$out/preview.png" "$golden/$name-preview.png"
    echo "golden: updated the references of $name"
    exit 0
fi

failed=0
for kind in render.exr preview.png; do
    reference=$golden/$name-$kind
    if [ ! -e "$reference" ]; then
        echo "golden: no reference $reference; make it with VEDUTA_GOLDEN_UPDATE=1"
        failed=1
        continue
    fi
    "$veduta" diff "$out/$kind" "$reference" -o "$out/diff-${kind%.*}.png" >"$out/diff-${kind%.*}.txt"
    status=$?
    if [ $status -ne 0 ]; then
        echo "golden: $name $kind differs from $reference (veduta diff exit $status):"
        cat "$out/diff-${kind%.*}.txt"
        failed=1
    fi
done

# The colour channels of an EXR for oiiotool --ch: a render's Combined pass, or those of a plain image.
colour_channels() {
    if oiiotool --info -v "$1" 2>/dev/null | grep -q 'channel list: .*ViewLayer\.Combined\.R'; then
        echo R=ViewLayer.Combined.R,G=ViewLayer.Combined.G,B=ViewLayer.Combined.B
    else
        echo R,G,B
    fi
}

# EXR -> sRGB PNG for a browser.
view_png() {
    oiiotool "$1" --ch "$(colour_channels "$1")" --colorconvert linear sRGB -d uint8 -o "$2" 2>/dev/null
}

if [ $failed -ne 0 ]; then
    # A page for a person: browsers show PNG, so EXRs are converted for it.
    if command -v oiiotool >/dev/null; then
        view_png "$out/render.exr" "$out/render-view.png"
        [ -e "$golden/$name-render.exr" ] && view_png "$golden/$name-render.exr" "$out/reference-render-view.png"
    fi
    [ -e "$golden/$name-preview.png" ] && cp "$golden/$name-preview.png" "$out/reference-preview.png"
    cat >"$out/report.html" <<HTML
<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>golden: $name</title>
<style>body{font-family:sans-serif} img{image-rendering:pixelated;width:480px;border:1px solid #888}
td{vertical-align:top;padding:4px} pre{font-size:small}</style></head><body>
<h1>Golden test failed: $relative</h1>
<table>
<tr><th></th><th>new</th><th>reference</th><th>|new − reference| × 16</th></tr>
<tr><th>path tracer</th><td><img src="render-view.png"></td><td><img src="reference-render-view.png"></td>
<td><img src="diff-render.png"><pre>$(cat "$out/diff-render.txt" 2>/dev/null)</pre></td></tr>
<tr><th>preview</th><td><img src="preview.png"></td><td><img src="reference-preview.png"></td>
<td><img src="diff-preview.png"><pre>$(cat "$out/diff-preview.txt" 2>/dev/null)</pre></td></tr>
</table>
<p>Accept the new images with <code>VEDUTA_GOLDEN_UPDATE=1 ctest --preset test -L golden</code>.</p>
</body></html>
HTML
    echo "golden: report at $out/report.html"
    exit 1
fi
echo "golden: $name passed"
