#!/usr/bin/env bash
# `veduta generate` (issue 20): a grown town written as CityData, GeoJSON, a GeoPackage and DOT;
# the CityData loads as a <city>; the same seed writes the same files; bad input exits 1 and a
# bad command line 2, and neither touches what was written before.
# Usage: generate_cli_test.sh VEDUTA_BINARY
set -u
veduta=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

run generate --help
check "help" rc_is 0
check "help names the patterns" out_has "grid, organic, radial"
check "help names the tensor field" out_has "tensor (streets traced"

run generate --pattern grid --radius 200 --seed 3 -o "$work/town.xml" --geojson "$work/gis" \
    --gpkg "$work/town.gpkg" --dot "$work/streets.dot"
check "grid town" rc_is 0
check "summary" out_has "blocks: "
check "lots counted" bash -c "grep -q '^lots: [1-9]' '$work/out'"
for f in town.xml gis/streets.geojson gis/blocks.geojson gis/lots.geojson town.gpkg streets.dot; do
    check "wrote $f" test -s "$work/$f"
done
check "dot graph" bash -c "head -1 '$work/streets.dot' | grep -qx 'graph streets {'"
check "the town names its rules" grep -q "<Rulefile>.*FacadeStructure.xml</Rulefile>" "$work/town.xml"
check "the town says how it was made" grep -q "<!-- grown by veduta generate: pattern grid, centre 0 0, radius 200 m, seed 3 -->" "$work/town.xml"

# Relative to the working folder, as users type it.
(cd "$work" && "$veduta" generate --pattern grid --radius 200 --seed 3 -o again.xml -q >"$work/out" 2>"$work/err")
echo $? >"$work/rc"
check "again" rc_is 0
check "quiet" test ! -s "$work/out"
check "the same seed writes the same town" cmp -s "$work/town.xml" "$work/again.xml"
run generate --pattern grid --radius 200 --seed 4 -o "$work/other.xml" -q
check "another seed writes another town" bash -c "! cmp -s '$work/town.xml' '$work/other.xml'"

# The CityData is a <city>: it renders.
cat >"$work/scene.xml" <<XML
<scene version="1">
  <camera position="0 -400 300" look_at="0 0 0" up="0 0 1" fov="50" resolution="32 18"/>
  <city file="town.xml" seed="1"/>
</scene>
XML
run preview "$work/scene.xml" -q -o "$work/town.png"
check "the town previews" rc_is 0
check "preview written" test -s "$work/town.png"

# Through a tensor field (docs/tensor-streets.md): streamlines instead of expansions, the same
# outputs, the same town for the same seed.
run generate --pattern tensor --radius 300 --seed 5 -o "$work/tensor.xml" --geojson "$work/tensor-gis"
check "tensor town" rc_is 0
check "tensor streamlines" bash -c "grep -q '^streamlines: [1-9]' '$work/out'"
check "tensor lots" bash -c "grep -q '^lots: [1-9]' '$work/out'"
check "tensor layers" test -s "$work/tensor-gis/lots.geojson"
run generate --pattern tensor --radius 300 --seed 5 -o "$work/tensor-again.xml" -q
check "the same seed traces the same town" cmp -s "$work/tensor.xml" "$work/tensor-again.xml"

# In map coordinates: the CityData and the layers in the CRS given.
run generate --pattern radial --radius 150 --centre 487000 5425000 --crs EPSG:25832 -o "$work/utm.xml" \
    --geojson "$work/utm" -q
check "utm town" rc_is 0
check "utm eastings" grep -q 'e="48[67][0-9][0-9][0-9]' "$work/utm.xml"
check "geojson crs" grep -q "EPSG::25832" "$work/utm/streets.geojson"

# On a DGM (the hillside of scenes/hillside-town.xml: nodes from 499850 5330000 to 500150 5330300, rising 13 %
# to the north): no street leaves it.
dgm=$(dirname "$0")/../../data/hillside/dgm.asc
run generate --pattern grid --radius 400 --seed 4 --centre 500000 5330150 --crs EPSG:25832 --dgm "$dgm" -o "$work/hill.xml"
check "hillside town" rc_is 0
check "hillside streets" bash -c "grep -q '^streets: [1-9]' '$work/out'"
check "no point off the DGM" awk -F'"' '/<Point id=.* e=/ { if ($4 < 499850 || $4 > 500150 || $6 < 5330000 || $6 > 5330300) bad = 1 } END { exit bad }' "$work/hill.xml"
streets12=$(sed -n 's/^streets: //p' "$work/out")
run generate --pattern grid --radius 400 --seed 4 --centre 500000 5330150 --crs EPSG:25832 --dgm "$dgm" --max-grade 0.15 \
    -o "$work/hill15.xml"
check "hillside town at 15 %" rc_is 0
check "at 15 % the grid climbs the hill" bash -c "[ \$(sed -n 's/^streets: //p' '$work/out') -gt \$((3 * $streets12)) ]"
check "no point off the DGM at 15 %" awk -F'"' '/<Point id=.* e=/ { if ($4 < 499850 || $4 > 500150 || $6 < 5330000 || $6 > 5330300) bad = 1 } END { exit bad }' "$work/hill15.xml"
# With the ATKIS roads of data/landscape (a Straße through 530300 5326780, 120 m south of the
# centre): the road's points are static streets of the town, and the grid's streets end on it.
land=$(dirname "$0")/../../data/landscape
run generate --pattern grid --radius 250 --seed 2 --centre 530350 5326900 --crs EPSG:25832 --dgm "$land/dgm.asc" \
    --max-grade 0.5 --atkis "$land/traffic.geojson" -o "$work/road.xml"
check "town on a road" rc_is 0
check "the road is a street of the town" grep -q '<Point id="[0-9]*" e="530300" n="5326780" />' "$work/road.xml"
# The road runs 530000 5326760 – 530300 5326780 – 530600 5326790: no point lies south of it.
check "nothing grows south of the road" awk -F'"' '/<Point id=.* e=/ {
    road = $4 <= 530300 ? 5326760 + ($4 - 530000) * 20 / 300 : 5326780 + ($4 - 530300) * 10 / 300
    if ($6 < road - 0.01) bad = 1 } END { exit bad }' "$work/road.xml"

# With the highways of data/hillside/town.osm (a small town round 500000 5330150): its streets are
# the town's too, and they bound the grid that grows inside them.
run generate --pattern grid --radius 200 --seed 4 --centre 500000 5330150 --crs EPSG:25832 \
    --osm "$(dirname "$0")/../../data/hillside/town.osm" -o "$work/osm.xml"
check "town on OSM roads" rc_is 0
check "an OSM node is a point of the town" grep -q '<Point id="[0-9]*" e="500000" n="5330084.0037" />' "$work/osm.xml"
check "the grid keeps inside the OSM streets" awk -F'"' '/<Point id=.* e=/ { if ($6 < 5330080) bad = 1 } END { exit bad }' "$work/osm.xml"
run generate --pattern grid --radius 200 --osm "$work/none.osm" --crs EPSG:25832 -o "$work/x.xml"
check "a missing road file exits 1" rc_is 1
check "and says so" err_has "--osm: cannot read the road file"

run generate --crs EPSG:4326 --centre 9 48 -o "$work/x.xml"
check "a geographic CRS exits 1" rc_is 1
check "a geographic CRS says so" err_has "not a projected CRS"
run generate --dgm "$dgm" -o "$work/x.xml"
check "a DGM without a CRS exits 1" rc_is 1
check "a DGM without a CRS says so" err_has "needs --crs"

# Bad input: exit 1, nothing written, the older file kept.
cp "$work/town.xml" "$work/kept.xml"
run generate --pattern hexagons -o "$work/town.xml"
check "unknown pattern exits 1" rc_is 1
check "unknown pattern says so" err_has "'hexagons' is no pattern"
check "older file kept" cmp -s "$work/town.xml" "$work/kept.xml"
printf 'o: S(80)\np1: S(len) -> F(len' >"$work/bad.txt"
run generate --pattern "$work/bad.txt" -o "$work/town.xml"
check "bad rule file exits 1" rc_is 1
check "bad rule file names its place" err_has "bad.txt:2:"
run generate --lots hexagons -o "$work/town.xml" --radius 100
check "unknown lots exits 1" rc_is 1
check "unknown lots names the option" err_has "--lots"
check "older file still kept" cmp -s "$work/town.xml" "$work/kept.xml"
: >"$work/plain"
run generate --radius 100 -o "$work/town.xml" --gpkg "$work/plain/town.gpkg"
check "unwritable output exits 3" rc_is 3
check "older file kept after a failed write" cmp -s "$work/town.xml" "$work/kept.xml"

# A bad command line: exit 2.
run generate --radius 0 -o "$work/x.xml"
check "radius 0 exits 2" rc_is 2
run generate --centre 1 -o "$work/x.xml"
check "one centre number exits 2" rc_is 2
run generate
check "no output exits 2" rc_is 2

summary generate_cli
