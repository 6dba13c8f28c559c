#!/usr/bin/env bash
# `veduta facade`, `veduta building` and `veduta export --rules` with the Gründerzeit rule set:
# help, images written, the warning of seed 000's own rule, and the exit codes of bad rules
# (1, with file:line:col), a bad footprint (1) and a bad command line (2), none leaving a file.
# Usage: buildings_cli_test.sh VEDUTA_BINARY SOURCE_DIR
set -u
veduta=$1
rules=$2/rules/gruenderzeit/FacadeStructure.xml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

for command in facade building; do
    run $command --help
    check "$command help exits 0" rc_is 0
    check "$command help names --seed" out_has "--seed"
done

for bad in "--width nan" "--height inf" "--width 1e-9"; do
    run facade "$rules" $bad -o "$work/bad.png"
    check "facade $bad exits 2" rc_is 2
    check "facade $bad writes nothing" test ! -e "$work/bad.png"
done

run facade "$rules" --width 12 --height 15 --res 320x400 -o "$work/facade.png"
check "facade exits 0" rc_is 0
check "facade png written" test -s "$work/facade.png"
check "facade summary" err_has "facade.png: 320x400"
check "seed 000's probability sum is warned about" err_has "FacadeStructure.xml:369:3: the probabilities of rule 'GroundfloorWindowTileChoice' sum to 0.5"

run building "$rules" --footprint 0 0 16 0 16 14 0 14 --street 0 --id 4 --set FloorHeight=3.5 -q -o "$work/building.png"
check "building exits 0" rc_is 0
check "building png written" test -s "$work/building.png"

run export --rules "$rules" --footprint 0 0 16 0 16 14 0 14 --street 0 -o "$work/building.glb"
check "export of a building exits 0" rc_is 0
check "glb written" test "$(head -c 4 "$work/building.glb")" = glTF

cat >"$work/forever.xml" <<'XML'
<Rulefile name="forever">
  <Rule>
    <Predecessor>FrontFacade</Predecessor>
    <Rules><Probability value="1"><Split axis="u"/><Symbol size="3">Wall0.wrl</Symbol><Symbol size="1r">FrontFacade</Symbol></Probability></Rules>
  </Rule>
</Rulefile>
XML
run facade "$work/forever.xml" -o "$work/forever.png"
check "a rule that derives itself forever exits 1" rc_is 1
check "it is named at its place" err_has "forever.xml:2:3: rule 'FrontFacade' can never finish"
check "no image for it" test ! -e "$work/forever.png"

cat >"$work/vectors.xml" <<'XML'
<Rulefile name="vectors">
  <Rule>
    <Predecessor>FrontFacade</Predecessor>
    <Rules><Probability value="1"><Symbol scale="1 x 1">Wall0.wrl</Symbol></Probability></Rules>
  </Rule>
</Rulefile>
XML
run facade "$work/vectors.xml" -o "$work/vectors.png"
check "a malformed vector exits 1" rc_is 1
check "it is named at its place" err_has "vectors.xml:4:"

sed 's/scale="1 x 1"/size="-2"/; s/<Probability value="1">/<Probability value="1"><Split axis="r"\/>/' "$work/vectors.xml" >"$work/negative.xml"
run facade "$work/negative.xml" -o "$work/negative.png"
check "a negative size exits 1" rc_is 1
check "it is named at its place" err_has "negative.xml:4:"

sed 's/scale="1 x 1"//; s/Wall0.wrl/Nothing/' "$work/vectors.xml" >"$work/unknown.xml"
run facade "$work/unknown.xml" -o "$work/unknown.png"
check "an unknown symbol exits 1" rc_is 1
check "it is named at its place" err_has "unknown.xml:4:"
check "and said what it is" err_has "unknown symbol 'Nothing'"

run building "$rules" --footprint 0 0 10 0 0 10 10 10 -o "$work/crossed.png"
check "a footprint that crosses itself exits 1" rc_is 1
check "no image for it" test ! -e "$work/crossed.png"

run facade "$rules" --width -3 -o "$work/negative-width.png"
check "a negative width is a usage error" rc_is 2

summary buildings_cli
