#!/bin/bash
# Checkpoints: a render killed with SIGKILL after its first checkpoint and resumed gives the
# very image an uninterrupted render gives; a checkpoint of another render is refused.
# Usage: checkpoint_cli_test.sh VEDUTA
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/test_lib.sh"

size=(--res 320x180 --spp 128 -q)

# Starts a render with checkpoints, waits for its first checkpoint and kills it.
render_and_kill() {
    local out=$1; shift
    "$veduta" render "${size[@]}" -o "$out" --checkpoint-every 0.05 "$@" &
    local pid=$! waited=0
    while [ ! -s "$out.checkpoint" ] && [ $waited -lt 600 ]; do sleep 0.02; waited=$((waited + 1)); done
    kill -KILL $pid 2>/dev/null
    wait $pid 2>/dev/null
    [ -s "$out.checkpoint" ] || { echo "no checkpoint appeared"; return 1; }
}

same_pixels() { idiff -fail 0 -failpercent 0 -warn 0 "$1" "$2" >"$work/idiff" || { cat "$work/idiff"; false; }; }

check "uninterrupted render" "$veduta" render "${size[@]}" -o "$work/full.exr"
check "render killed after a checkpoint" render_and_kill "$work/part.exr"
check "a killed render leaves no image" test ! -e "$work/part.exr"
run render "${size[@]}" -o "$work/part.exr" --checkpoint-every 0.05 --resume
rc=$(cat "$work/rc")
check "resume succeeds" rc_is 0
check "resumed image equals the uninterrupted one, bit for bit" same_pixels "$work/full.exr" "$work/part.exr"
check "the checkpoint is removed once the image is written" test ! -e "$work/part.exr.checkpoint"
check "resume says where it continues" bash -c "'$veduta' render ${size[*]/-q/} -o '$work/again.exr' --resume 2>&1 |
    grep -q 'no checkpoint at'"

check "second killed render" render_and_kill "$work/other.exr"
cp "$work/other.exr.checkpoint" "$work/saved.checkpoint"
run render "${size[@]}" -o "$work/other.exr" --resume --seed 5
check "a checkpoint of other settings is refused" rc_is 1
check "the refusal names what differs" err_has "seed: 0 there, 5 here"
check "nothing is written when refused" test ! -e "$work/other.exr"
run render --res 330x180 --spp 128 -q -o "$work/other.exr" --resume
check "a checkpoint of another image size is refused" err_has "image: 320x180 there, 330x180 here"
run render "$(dirname "$0")/../../scenes/materials.xml" "${size[@]}" -o "$work/other.exr" --resume
check "a checkpoint of another scene is refused" err_has "scene: "
head -c 1000 "$work/saved.checkpoint" >"$work/other.exr.checkpoint"
run render "${size[@]}" -o "$work/other.exr" --resume
check "a damaged checkpoint is refused" err_has "the checkpoint is cut short"
check "with exit code 1" rc_is 1

summary checkpoint_cli
