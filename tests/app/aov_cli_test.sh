#!/usr/bin/env bash
# What `veduta render` writes, as other programs see it through `oiiotool --info -v`: Blender's
# pass names in a multilayer EXR, the render's metadata (with the georeference when the scene has
# one), and a --region as the data window inside the full display window.
# Usage: aov_cli_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

if ! command -v oiiotool >/dev/null; then
    echo "aov_cli: oiiotool not found"
    exit 1
fi

# oiiotool's description of FILE into $work/info.
describe() { oiiotool --info -v "$1" >"$work/info" 2>&1; }
has_channel() { grep -E '^ *channel list:' "$work/info" | grep -qE "(: |, )$1(,|\$)"; }
# An attribute line "NAME: VALUE" whose value starts as given.
has_attribute() { grep -qE "^ *$1: $2" "$work/info" || { echo "no attribute $1: $2 in:"; cat "$work/info"; false; }; }

channels=(ViewLayer.Combined.{R,G,B,A} ViewLayer.CombinedEven.{R,G,B} ViewLayer.CombinedOdd.{R,G,B}
          ViewLayer.Depth.Z ViewLayer.Normal.{X,Y,Z} ViewLayer.DiffCol.{R,G,B} ViewLayer.Position.{X,Y,Z}
          ViewLayer.IndexOB.X ViewLayer.IndexMA.X ViewLayer.IndexBuilding.X ViewLayer.IndexInstance.X
          ViewLayer.SampleCount.X)

run render --res 40x24 --spp 4 -q -o "$work/d.exr"
check "default render" rc_is 0
describe "$work/d.exr"
check "oiiotool reads the render" grep -q '40 x  *24, 25 channel, float openexr' "$work/info"
for channel in "${channels[@]}"; do
    check "channel $channel" has_channel "$channel"
done
check "attribute Software" has_attribute Software '"veduta '
check "attribute RenderTime" has_attribute RenderTime '"[0-9]{2}:[0-9]{2}\.[0-9]{2}"'
check "attribute veduta.samples" has_attribute veduta.samples '4$'
check "attribute veduta.sampleOffset" has_attribute veduta.sampleOffset '0$'
check "attribute veduta.seed" has_attribute veduta.seed '-?[0-9]+$'
check "attribute veduta.sceneHash" has_attribute veduta.sceneHash '"[0-9a-f]+"'
check "attribute veduta.renderSeconds" has_attribute veduta.renderSeconds '[0-9.e-]+$'
check "attribute veduta.camera" has_attribute veduta.camera '"position '
check "attribute veduta.crs" has_attribute veduta.crs '"local \(no georeference\)"'
check "attribute worldToCamera" has_attribute worldToCamera '[-0-9.e]+(, [-0-9.e]+){15}$'
check "no origin without a georeference" bash -c "! grep -q 'veduta.origin' '$work/info'"

# A scene with a georeference names its CRS and origin.
cat >"$work/geo.xml" <<'XML'
<scene>
  <georeference crs="EPSG:25833" origin="317000 5690000.5"/>
  <camera position="2 -3 2" look_at="0 0 0" resolution="16 12"/>
  <render spp="2"/>
  <sphere radius="1"/>
</scene>
XML
run render "$work/geo.xml" -q -o "$work/geo.exr"
check "georeferenced render" rc_is 0
describe "$work/geo.exr"
check "attribute veduta.crs EPSG" has_attribute veduta.crs '"EPSG:25833"'
check "attribute veduta.origin" has_attribute veduta.origin '"317000.000 5690000.500"'
check "georeferenced samples" has_attribute veduta.samples '2$'

# --region: the data window is the region, inside the full display window.
run render --res 40x24 --spp 2 -q --region 8 4 20 10 -o "$work/region.exr"
check "region render" rc_is 0
describe "$work/region.exr"
check "region data size" grep -q '12 x  *6, 25 channel, float openexr' "$work/info"
check "region data origin" grep -qE 'pixel data origin: x=8, y=4' "$work/info"
check "region full size" grep -qE 'full/display size: 40 x 24' "$work/info"
check "region full origin" grep -qE 'full/display origin: 0, 0' "$work/info"

# A region outside the image is an input error, and nothing is written.
for region in "30 4 50 10" "8 4 8 10" "-1 0 4 4"; do
    run render --res 40x24 --spp 1 -q --region $region -o "$work/outside.exr"
    check "region $region exits 1" rc_is 1
    check "region $region message" err_has "is not a window inside the 40x24 image"
    check "region $region no exr" test ! -e "$work/outside.exr"
done

summary aov_cli
