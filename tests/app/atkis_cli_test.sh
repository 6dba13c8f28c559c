#!/usr/bin/env bash
# `veduta atkis info`: the ALK sample in ../shared/data when present, small files, bad files.
# Usage: atkis_cli_test.sh VEDUTA_BINARY SOURCE_DIR
set -u
veduta=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

run atkis --help
check "help" rc_is 0
run atkis
check "no subcommand exits 2" rc_is 2

sample="$source/../shared/data/edbs/alk_muster_part1.edbs"
if [ -f "$sample" ]; then
    run atkis info "$sample"
    check "sample reads" rc_is 0
    check "sample records" out_line "records BSPE ULOBNN: 2997"
    check "sample elements" out_line "vector_elements: 2870"
    check "sample parcels" out_line "objects ---- ALK 0233 F: 129"
    check "sample incomplete" out_line "incomplete_objects: 51"
    check "sample crs" out_has "Gauss-Krüger zone 5"
    check "sample no error" bash -c "! grep -q 'error' '$work/err'"
else
    echo "skipping the sample: $sample is not there"
fi

# A record whose length field is wrong: exit 1, the record number and line in the message.
printf 'EDBS00240000AKND000000  0000ULQA0000\nEDBS00990000BSPE000007  0000ULOBNN  0000\n' >"$work/bad.edbs"
run atkis info "$work/bad.edbs"
check "bad length exits 1" rc_is 1
check "bad length names record" err_has "bad.edbs:2:5: record 7: length field says 99 characters"

# A cut continuation: the start record is named.
printf 'EDBS00280000BSPE000003A 0000ULOBNN  0001\n' >"$work/cut.edbs"
run atkis info "$work/cut.edbs"
check "cut exits 1" rc_is 1
check "cut names record" err_has "record 3: continued record has no end record"

# Something that is neither EDBS nor a vector file.
echo "hello" >"$work/hello.txt"
run atkis info "$work/hello.txt"
check "junk exits 1" rc_is 1
run atkis info "$work/missing.edbs"
check "missing exits 1" rc_is 1

# GDAL's "billion laughs" NAS test, rebuilt: refused at once, before GDAL expands anything.
{
    printf '<?xml version="1.0"?>\n<!DOCTYPE lolz [\n<!ENTITY lol "lol">\n'
    previous=lol
    for level in 1 2 3 4 5 6 7 8 9; do
        printf '<!ENTITY lol%s "%s">\n' $level "$(printf "&$previous;%.0s" 1 2 3 4 5 6 7 8 9 10)"
        previous=lol$level
    done
    printf ']>\n<AX_Bestandsdatenauszug>&lol9;</AX_Bestandsdatenauszug>\n'
} >"$work/laughs.xml"
timeout 10 "$veduta" atkis info "$work/laughs.xml" >"$work/out" 2>"$work/err"
echo $? >"$work/rc"
check "billion laughs exits 1" rc_is 1
check "billion laughs names the declaration" err_has "laughs.xml:2:1: the XML file has a document type declaration"
run atkis info /dev/zero
check "a device exits 1" rc_is 1
check "a device is named" err_has "/dev/zero: is not a regular file"

# GeoJSON through GDAL: a road with OBJART and BRF.
cat >"$work/road.geojson" <<'JSON'
{"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
 "features": [{"type": "Feature", "properties": {"OBJART": "3101", "BRF": "0065"},
   "geometry": {"type": "LineString", "coordinates": [[400000, 5600000], [400100, 5600000]]}}]}
JSON
run atkis info "$work/road.geojson"
check "geojson reads" rc_is 0
check "geojson road" out_line "objects 3101 Straße L: 1"
check "geojson crs" out_line "crs: EPSG:25832"
check "geojson extent" out_line "extent: 400000.000 5600000.000 400100.000 5600000.000"

summary atkis_cli
