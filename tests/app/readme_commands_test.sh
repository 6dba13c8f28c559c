#!/usr/bin/env bash
# Every command README.md shows in its ```sh blocks, as a user would type it.
# Usage: readme_commands_test.sh VEDUTA_BINARY SOURCE_DIR BUILD_DIR
#
# `build/release/src/veduta …`, `cmake --install` and `cpack` lines run, in the README's order,
# in a scratch copy of the project folder (its files linked, renders/ empty, HOME a scratch
# folder) where build/release is the build under test; each must exit 0 and write every
# renders/ file it names. The other commands are the set-up, the build and the benchmarks,
# which CI runs itself or which take minutes: for them the test checks that what they name
# exists (setup.sh's modes, the CMake presets, the benchmark programs). A command of any other
# kind fails the test, so that a new example in the README cannot go untested.
set -u
veduta=$1 source=$2 build=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

project=$work/project
mkdir -p "$project/renders" "$project/build" "$work/home"
for entry in "$source"/*; do
    case "$(basename "$entry")" in build | renders) continue ;; esac
    ln -s "$entry" "$project/$(basename "$entry")"
done
# The README's build/release is the build under test; ~ is a scratch home, for the install.
ln -s "$build" "$project/build/release"
[ "$build/src/veduta" -ef "$veduta" ] || { echo "$veduta is not the program of $build"; exit 1; }

# The lines of the README's ```sh blocks, as "LINE_NUMBER<TAB>COMMAND".
readme_commands() {
    awk '/^```sh$/ { inside = 1; next } /^```$/ { inside = 0; next } inside && NF { print NR "\t" $0 }' \
        "$source/README.md"
}

# The renders/ files a command line names.
named_outputs() { grep -oE "renders/[A-Za-z0-9_./-]+\.(exr|png|jpg|tif|glb|gltf|obj|ply)" <<<"$1" | sort -u; }

runs_and_writes() {  # runs_and_writes COMMAND: exit 0, and every renders/ file it names exists
    (cd "$project" && HOME=$work/home timeout 600 bash -c "$1" </dev/null >"$work/out" 2>"$work/err")
    local rc=$? file
    if [ $rc != 0 ]; then
        echo "exit code $rc:"
        tail -n 20 "$work/err"
        return 1
    fi
    for file in $(named_outputs "$1"); do
        [ -s "$project/$file" ] || { echo "$file was not written"; return 1; }
    done
}

# setup.sh's modes are the words of its `case "$mode" in render | test | stills) ;;` line.
setup_has_mode() { grep -E '^ *render \|.*\) ;;$' "$source/setup.sh" | tr -d ' );' | tr '|' '\n' | grep -qx "$1"; }
has_preset() { (cd "$source" && cmake --list-presets=all 2>/dev/null) | grep -qF "\"$1\""; }
is_program() { [ -x "$1" ] && [ -f "$1" ]; }

commands=0
while IFS=$'\t' read -r number line; do
    commands=$((commands + 1))
    command=${line%%#*}  # the comment after the command is for the reader
    command=${command%"${command##*[![:space:]]}"}
    case "$command" in
        "build/release/src/veduta"* | "cmake --install build/release "* | "cpack --config build/release/"*)
            start=$SECONDS
            check "README.md:$number: $command" runs_and_writes "$command"
            echo "README.md:$number ran in $((SECONDS - start)) s: $command"
            ;;
        "build/release/bench/"*)
            program=${command%% *}
            check "README.md:$number: $program is built" is_program "$build/bench/${program##*/}"
            ;;
        "./setup.sh" | "./setup.sh "*)
            mode=${command#./setup.sh}
            mode=${mode# }
            check "README.md:$number: setup.sh exists" is_program "$source/setup.sh"
            check "README.md:$number: setup.sh has the mode '${mode:-render}'" setup_has_mode "${mode:-render}"
            ;;
        "cmake --preset "*)
            for preset in $(grep -oE -- "--preset [a-z]+" <<<"$command" | cut -d' ' -f2 | sort -u); do
                check "README.md:$number: CMake preset '$preset' exists" has_preset "$preset"
            done
            ;;
        *)
            check "README.md:$number: a command this test knows how to check" false
            echo "  $command"
            ;;
    esac
done < <(readme_commands)

check "the README shows commands" test "$commands" -gt 20
summary readme_commands
