#!/usr/bin/env bash
# `veduta twin` and `veduta compare` as a script would call them (docs/compare.md): a LoD1 box
# and its twin, the FZK-Haus when ../shared is there, and inputs that must write nothing.
# Usage: compare_cli_test.sh VEDUTA_BINARY SOURCE_DIR REPORT_DIR
# Leaves REPORT_DIR/box.html for the headless Chromium test (compare_report_chromium_test.sh).
set -u
veduta=$1 source=$2 reports=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"
box=$source/fuzz/corpus/citygml/lod1-box.gml

for sub in twin compare; do
    run $sub --help
    check "help $sub" rc_is 0
done

run twin "$box" -o "$work/twin.xml"
check "twin of the box" rc_is 0
check "twin says what it made" err_has "the twins of 1 of 1 buildings"
check "twin's building has the modelled one's footprint" grep -qF 'footprint="-5.000 -4.000  5.000 -4.000  5.000 4.000  -5.000 4.000"' "$work/twin.xml"
check "twin's walls are the box's 6 m, flat, in 2 storeys" grep -qF '<BuildingHeight>6.000</BuildingHeight><FloorHeight>3.000</FloorHeight><RoofHeight>0.000</RoofHeight>' "$work/twin.xml"
run info "$work/twin.xml"
check "the twin is a scene" rc_is 0

mkdir -p "$reports"
run compare "$box" "$work/twin.xml" -o "$reports/box.html" --res 96x54 --spp 2 --views 2 -q
check "compare the box and its twin" rc_is 0
check "json beside the report" test -s "$reports/box.json"
check "paired by id" out_has "buildings: 1 paired by id, 0 by overlap, 0 only in A, 0 only in B"
check "same footprint and heights" out_has "mean footprint IoU 1.0000, mean |eaves error| 0.000 m, mean |ridge error| 0.000 m"
check "two views" out_has "overview: relMSE"
check "json figure" grep -qF '"mean_footprint_iou": 1,' "$reports/box.json"
check "self-contained page" grep -qF 'src="data:image/png;base64,' "$reports/box.html"
# Effort: the box's 6 faces of 4 corners; the twin's rule file, line for line.
check "the model's surfaces and vertices" grep -qF '"rule_lines": 0, "parameters": 0, "surfaces": 6, "vertices": 24' "$reports/box.json"
lines=$(grep -c '[^[:space:]]' "$source/rules/gruenderzeit/FacadeStructure.xml")
check "the twin's rule-file lines" grep -qF "\"rule_lines\": $lines," "$reports/box.json"

# A scene against itself: every figure says equal.
run compare "$work/twin.xml" "$work/twin.xml" -o "$work/self.html" --res 64x36 --spp 1 --views 1 -q
check "a scene against itself" rc_is 0
check "itself: relMSE 0 and SSIM 1" out_has "overview: relMSE 0, PSNR inf dB, SSIM 1.0000, silhouette IoU 1.0000"

# Cameras from the command line replace the automatic views.
run compare "$box" "$work/twin.xml" -o "$work/cams.html" --camera "0 -20 5  0 0 3" --camera "20 0 5  0 0 3  50" \
    --res 64x36 --spp 1 -q
check "two --camera views" rc_is 0
check "the first --camera view" out_has "camera 1: relMSE"
check "the second --camera view" out_has "camera 2: relMSE"

# What must fail, and leave no report behind.
run compare "$box" "$box" -o "$work/bad1.html" -q
check "two CityGML files exit 1" rc_is 1
check "two CityGML files say why" err_has "one must be a scene"
run compare "$box" "$work/twin.xml" -o "$work/bad2.html" --camera "1 2 3" -q
check "a camera of three numbers exits 1" rc_is 1
check "the camera is named" err_has "--camera: '1 2 3' is no camera"
run compare "$box" "$work/twin.xml" -o "$work/bad2.html" --camera "0 -20 5  0 0 3  180" -q
check "a field of view of 180° exits 1" rc_is 1
check "the field of view is said" err_has "degrees between 0 and 180"
run compare "$box" "$work/twin.xml" -o "$work/bad3.pdf" -q
check "a report that is no .html exits 2" rc_is 2
run twin "$work/none.gml" -o "$work/bad4.xml"
check "twin of no file exits 1" rc_is 1
printf '<?xml version="1.0"?>\n<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;">]>\n<CityModel>&lol2;</CityModel>\n' >"$work/bomb.gml"
run twin "$work/bomb.gml" -o "$work/bad5.xml"
check "an entity-expansion DTD exits 1" rc_is 1
check "the DTD is named" err_has "bomb.gml:2:"
sed 's/ srsName="[^"]*"//' "$box" >"$work/nocrs.gml"
run twin "$work/nocrs.gml" -o "$work/bad6.xml"
check "no srsName and no --crs exits 1" rc_is 1
check "no CRS is said" err_has "names no CRS"
run twin "$work/nocrs.gml" -o "$work/nocrs.xml" --crs EPSG:25832
check "--crs gives it one" rc_is 0
for f in bad1.html bad1.json bad2.html bad2.json bad3.pdf bad4.xml bad5.xml bad6.xml; do
    check "nothing written: $f" test ! -e "$work/$f"
done

# The FZK-Haus: a real LoD2 file and its twin.
fzk=$source/../shared/data/citygml/FZK-House-LoD2-KIT-IAI-KHH-V2.gml
if [ -f "$fzk" ]; then
    run twin "$fzk" -o "$work/fzk.xml"
    check "twin of the FZK-Haus" rc_is 0
    check "its gable roof" grep -qF '<RoofHeight>2.887</RoofHeight><RoofType>gable</RoofType>' "$work/fzk.xml"
    run compare "$fzk" "$work/fzk.xml" -o "$work/fzk.html" --res 64x36 --spp 1 --views 1 -q
    check "compare the FZK-Haus and its twin" rc_is 0
    check "the FZK-Haus's heights" out_has "mean |eaves error| 0.000 m, mean |ridge error| 0.000 m"
    check "its roof type agrees" out_has "roof types agreeing 100.0 %"
else
    echo "skipped the FZK-Haus: ../shared/data is not there"
fi

summary compare_cli
