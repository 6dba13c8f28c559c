#!/usr/bin/env bash
# Display images from `veduta render --image`: PNG, JPEG and TIFF through the built-in config and
# through one given by path, the view in the metadata, unknown names (exit 1, listing the valid
# ones, nothing rendered), options without --image (exit 2), an unwritable folder (exit 3). A write
# failing part-way is tested in tests/images/display_images_test.cpp.
# Usage: display_cli_test.sh VEDUTA_BINARY TEST_DATA_DIR
set -u
veduta=$1 data=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"
command -v oiiotool >/dev/null || { echo "oiiotool missing (Debian: openimageio-tools)"; exit 1; }

cat >"$work/scene.xml" <<'XML'
<scene>
  <camera position="0 -3 1" look_at="0 0 0.5" resolution="16 12"/>
  <render spp="1"/>
  <box/>
</scene>
XML
render() { run render "$work/scene.xml" -q -o "$work/out.exr" "$@"; }
info() { oiiotool --info -v "$1" 2>&1; }

for name in a.png b.jpg c.tif d.JPEG; do
    render --image "$work/$name" --view "ACES 1.0 - SDR Video"
    check "$name written" rc_is 0
    check "$name readable" bash -c "iinfo '$work/$name' | grep -q '16 x   12'"
    check "$name records the view" bash -c "oiiotool --info -v '$work/$name' | grep -q \"view 'ACES 1.0 - SDR Video'\""
done
check "png keeps alpha" bash -c "iinfo '$work/a.png' | grep -q '4 channel'"
check "tiff is 16 bits" bash -c "iinfo '$work/c.tif' | grep -q 'uint16'"
check "png names the view" bash -c "oiiotool --info -v '$work/a.png' | grep -q 'ocioview: \"ACES 1.0 - SDR Video\"'"

render --image "$work/standard.png" --png "$work/plain.png"
check "default view" rc_is 0
check "default view is Standard" bash -c "oiiotool --info -v '$work/standard.png' | grep -q \"view 'Standard'\""
check "Standard equals the plain sRGB PNG" bash -c "idiff -q '$work/standard.png' '$work/plain.png' >/dev/null"
render --image "$work/bright.png" --exposure 1.5 --look "Blue Light Fix" --view "ACES 1.0 - SDR Video" --display sRGB
check "exposure and look" rc_is 0
check "exposure recorded" bash -c "oiiotool --info -v '$work/bright.png' | grep -q 'exposure +1.5 stops'"
check "look recorded" bash -c "oiiotool --info -v '$work/bright.png' | grep -q \"look 'Blue Light Fix'\""

render --image "$work/other.png" --ocio-config "$data/gamma22.ocio"
check "config by path" rc_is 0
check "config by path: its default view" bash -c "oiiotool --info -v '$work/other.png' | grep -q \"display 'Rec709', view 'Gamma2.2'\""
OCIO="$data/gamma22.ocio" render --image "$work/env.png" --view Raw
check "\$OCIO chooses the config" rc_is 0
blender=/usr/share/blender/datafiles/colormanagement/config.ocio
if [ -e "$blender" ]; then
    render --image "$work/blender.png" --ocio-config "$blender" --display sRGB --view Filmic
    check "Blender's config, Filmic" rc_is 0
else
    echo "skipped: $blender is absent (Debian: blender-data)"
fi

rm -f "$work/out.exr"
render --image "$work/bad.png" --view Filmc
check "unknown view exits 1" rc_is 1
check "unknown view lists the views" err_has "unknown view 'Filmc' for display 'sRGB'; views: Standard, ACES 1.0 - SDR Video, Raw"
render --image "$work/bad.png" --view Filmic
check "veduta's former Filmic exits 1" rc_is 1
check "veduta's former Filmic names its new name" err_has "once called 'Filmic', is now the view 'ACES 1.0 - SDR Video'"
check "unknown view: nothing rendered" test ! -e "$work/out.exr"
render --image "$work/bad.png" --display sRBG
check "unknown display exits 1" rc_is 1
check "unknown display lists the displays" err_has "unknown display 'sRBG'; displays: sRGB"
render --image "$work/bad.png" --look Punchy
check "unknown look exits 1" rc_is 1
check "unknown look lists the looks" err_has "looks: Gamut Compression, Blue Light Fix"
render --image "$work/bad.png" --ocio-config "$data/gamma22.ocio" --view Filmic
check "unknown view of a config by path exits 1" rc_is 1
check "names the config" err_has "$data/gamma22.ocio: unknown view 'Filmic' for display 'Rec709'; views: Gamma2.2, Raw"
echo "not a config" >"$work/broken.ocio"
render --image "$work/bad.png" --ocio-config "$work/broken.ocio"
check "broken config exits 1" rc_is 1
check "broken config named" err_has "$work/broken.ocio"
check "nothing written for bad names" test ! -e "$work/bad.png"

render --view Filmic
check "--view without --image exits 2" rc_is 2
render --image "$work/x.exr"
check "--image not png/jpg/tif exits 2" rc_is 2
render --image "$work/x.png" --ocio-config "$work/missing.ocio"
check "missing config file exits 2" rc_is 2

echo "not a folder" >"$work/file"
render --image "$work/file/out.png"
check "unwritable folder exits 3" rc_is 3
check "unwritable folder named" err_has "$work/file/out.png"

summary display_cli
