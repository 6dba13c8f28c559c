#!/usr/bin/env bash
# Bad CityData files end to end (issue 7): `veduta render` and `veduta preview` of a scene whose
# <city> has a self-intersecting block, a point id given twice, a missing point, a lot outside
# its block or a lot of no area stop with the place in the city file and exit 1, and leave the
# output file as it was. A good city renders, and `--seed` redraws the sampler and the city, the
# seeds the file gives them included.
# Usage: city_cli_test.sh VEDUTA_BINARY SOURCE_DIR
set -u
veduta=$1
rules=$2/rules/gruenderzeit/FacadeStructure.xml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

cat >"$work/scene.xml" <<XML
<scene version="1">
  <camera position="20 -60 40" look_at="20 20 0" up="0 0 1" fov="50" resolution="32 18"/>
  <render spp="1"/>
  <city file="city.xml" rules="$rules" seed="1"/>
</scene>
XML

# write_city EXTRA_POINTS BLOCK_POINTS LOTS: city.xml with points 0-3 round a 40 m square,
# points 4 and 5 east of it, two streets, and one block.
write_city() {
    cat >"$work/city.xml" <<XML
<CityData>
  <Points>
    <Point id="0" e="0" n="0"/><Point id="1" e="40" n="0"/><Point id="2" e="40" n="40"/><Point id="3" e="0" n="40"/>
    <Point id="4" e="60" n="0"/><Point id="5" e="60" n="12"/>
    $1
  </Points>
  <StreetNetwork><Streets>
    <Street id="0" startPoint="0" endPoint="1"/><Street id="1" startPoint="1" endPoint="2"/>
  </Streets><Width>6</Width></StreetNetwork>
  <Blocks><Block>
    <Points>$2</Points>
    <Lots>$3</Lots>
  </Block></Blocks>
</CityData>
XML
}
square='<Point id="0"/><Point id="1"/><Point id="2"/><Point id="3"/>'

# Each bad city must fail both commands with its message and leave the old output alone.
expect_city_error() {  # NAME MESSAGE
    for command in render preview; do
        local output=$work/out.exr
        [ $command = preview ] && output=$work/out.png
        echo "an earlier image" >"$output"
        run $command "$work/scene.xml" -q -o "$output"
        check "$1: $command exits 1" rc_is 1
        check "$1: $command says where" err_has "$2"
        check "$1: $command keeps the old output" grep -qx "an earlier image" "$output"
    done
}

write_city '' '<Point id="0"/><Point id="2"/><Point id="1"/><Point id="3"/>' ''
expect_city_error "self-intersecting block" "city.xml:11:5: the block's outline crosses or touches itself"

write_city '<Point id="4" e="1" n="1"/>' "$square" ''
expect_city_error "point id given twice" "city.xml:5:16: point id 4 is already used at $work/city.xml:4:5"

write_city '' '<Point id="0"/><Point id="1"/><Point id="9"/>' ''
expect_city_error "missing point" "city.xml:11:54: there is no point with id 9"

write_city '' "$square" '<Lot><Points><Point id="1"/><Point id="4"/><Point id="5"/></Points></Lot>'
expect_city_error "lot outside its block" "city.xml:12:16: the lot's point (60 0) lies outside its block"

write_city '' "$square" '<Lot><Points><Point id="0"/><Point id="1"/><Point id="0"/></Points></Lot>'
expect_city_error "lot of no area" "city.xml:12:16: footprint point 3 repeats point 1"

write_city '' "$square" ''
run preview "$work/scene.xml" -q -o "$work/good.png"
check "a good city previews" rc_is 0
check "its image is written" test -s "$work/good.png"

# --seed is the seed of every random choice (issue 16): the sampler's and the city's.
# write_seeded_scene RENDER_SEED CITY_SEED: each an attribute or nothing.
write_seeded_scene() {
    cat >"$work/seeded.xml" <<XML
<scene version="1">
  <camera position="20 -60 40" look_at="20 20 0" up="0 0 1" fov="50" resolution="32 18"/>
  <render spp="2" $1/>
  <city file="city.xml" rules="$rules" $2/>
</scene>
XML
}
render_seed() {  # render_seed SEED NAME: seeded.xml rendered with --seed SEED into NAME.exr
    run render "$work/seeded.xml" --seed "$1" -q -o "$work/$2.exr"
    check "render --seed $1" rc_is 0
}
recorded_seed() { oiiotool --info -v "$1" | sed -n 's/^ *veduta.seed: //p'; }

write_seeded_scene '' ''
render_seed 0 zero
render_seed 5 five
run diff "$work/zero.exr" "$work/five.exr"
check "--seed 5 renders another image than --seed 0" bash -c "! grep -qx 'max_error: 0' '$work/out'"
check "--seed 0 is recorded" test "$(recorded_seed "$work/zero.exr")" = 0
check "--seed 5 is recorded" test "$(recorded_seed "$work/five.exr")" = 5

# Seeds of the file's own are replaced too: the image is the one of the scene without them.
write_seeded_scene 'seed="7"' 'seed="1"'
render_seed 5 pinned
check "--seed 5 replaces <render seed>" test "$(recorded_seed "$work/pinned.exr")" = 5
run diff "$work/five.exr" "$work/pinned.exr"
check "--seed 5 replaces <render seed> and <city seed>" out_line "max_error: 0"

summary city_cli
