#!/usr/bin/env bash
# `cmake --install` into a scratch prefix, and the installed program run from a folder outside
# the source tree: it finds its plugin and veduta-diff in ../lib/veduta and its rules, materials
# and scenes in ../share/veduta, with nothing else copied; the man page and the bash completion
# are installed and complete; and a copy of bin/veduta without its lib/veduta fails, naming
# where it looked (docs/install.md).
# Usage: install_test.sh CMAKE BUILD_DIR
set -u
cmake=$1 build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"
prefix=$work/prefix
veduta=$prefix/bin/veduta
share=$prefix/share/veduta
# No plugin named by the environment: the program must find its own.
unset VEDUTA_IMAGE_PLUGIN

install_into_prefix() { "$cmake" --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; false; }; }
check "install exits 0" install_into_prefix
for file in bin/veduta lib/veduta/veduta-diff lib/veduta/veduta-images.so share/veduta/rules/gruenderzeit/FacadeStructure.xml \
    share/veduta/materials/palace.xml share/veduta/environments/clear_sky_up.exr share/veduta/scenes/default.xml \
    share/veduta/cities/gruenderzeit-district.xml share/veduta/data/landscape/dgm.asc share/man/man1/veduta.1.gz \
    share/bash-completion/completions/veduta share/doc/veduta/README.md share/doc/veduta/docs/install.md; do
    check "installed: $file" test -s "$prefix/$file"
done
check "no tests, renders or scripts installed" test -z "$(find "$prefix" -name '*_test*' -o -name renders -o -name '*.py')"

cd "$work" || exit 1  # outside the source tree: nothing found by searching upwards from here
run render --spp 2 --res 64x36 -o x.exr --image x.png
check "render with --image exits 0" rc_is 0
check "render wrote the EXR" test -s x.exr
check "the plugin wrote the PNG" test "$(head -c 4 x.png | tail -c 3)" = PNG
run diff x.exr x.exr
check "diff exits 0" rc_is 0
check "diff passes" out_line "verdict: pass"
run render -q --spp 2 --res 64x36 -o materials.exr "$share/scenes/materials.xml"
check "shipped scene with shipped materials and environment exits 0" rc_is 0
check "it wrote its EXR" test -s materials.exr
run render -q --spp 2 --res 64x36 -o street.exr "$share/scenes/gruenderzeit-street.xml"
check "shipped scene with shipped rules exits 0" rc_is 0
check "it wrote its EXR" test -s street.exr
run building "$share/rules/gruenderzeit/FacadeStructure.xml" --footprint 0 0 14 0 14 12 0 12 --res 64x36 -o building.png
check "building with the shipped rules exits 0" rc_is 0
check "building wrote its PNG" test -s building.png
run generate --radius 60 -o town.xml
check "generate finds the shipped street and building rules" rc_is 0
check "generate wrote the CityData" test -s town.xml

manpage=$prefix/share/man/man1/veduta.1.gz
man_has_every_subcommand() {
    local sub
    for sub in $("$veduta" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 { print $1 }'); do
        zcat "$manpage" | grep -qxF ".SS \"veduta $sub\"" || { echo "no section for $sub"; return 1; }
    done
}
man_has_renders_options() {
    local option
    for option in $("$veduta" render --help | grep -oE '^  -[-a-z,]+' | tr ',' ' '); do
        zcat "$manpage" | grep -qF "${option//-/\\-}" || { echo "no $option"; return 1; }
    done
}
check "man page names every subcommand" man_has_every_subcommand
check "man page has render's options as the program has them" man_has_renders_options
if command -v groff >/dev/null; then
    check "man page formats without warnings" test -z "$(zcat "$manpage" | preconv | groff -man -ww -z -Tutf8 2>&1)"
fi

completion=$prefix/share/bash-completion/completions/veduta
complete_words() {  # complete_words WORD...: what the completion offers for the last word
    bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _veduta; echo "${COMPREPLY[*]}"' _ \
        "$completion" "$@"
}
check "completes 're' to render" test "$(complete_words veduta re)" = render
check "completes render's options" test "$(complete_words veduta render --ima)" = --image
check "completes atkis's subcommand" test "$(complete_words veduta atkis '')" = info
check "completes diff --metric's values" test "$(complete_words veduta diff --metric r)" = relmse

# Moved without its lib/veduta: the image plugin and veduta-diff are missing, and the message
# names every place looked in.
mkdir -p moved/bin
cp "$veduta" moved/bin/
veduta=$work/moved/bin/veduta
run render --spp 2 --res 64x36 -o alone.exr --image alone.png
check "moved: --image fails" rc_is 3
check "moved: names the folder beside the program" err_has "$work/moved/bin"
check "moved: names ../lib/veduta" err_has "$work/moved/lib/veduta"
check "moved: nothing written" test ! -e alone.exr -a ! -e alone.png
run diff x.exr x.exr
check "moved: diff fails" rc_is 2
check "moved: diff names ../lib/veduta" err_has "$work/moved/lib/veduta"
run generate --radius 60 -o moved.xml
check "moved: generate fails without the shipped rules" rc_is 1
check "moved: names ../share/veduta" err_has "$work/moved/share/veduta"

summary install
