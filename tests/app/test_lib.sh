# Shared by the command-line test scripts: source it after setting `work` to a scratch folder
# and `veduta` to the program. Each check counts as passed or failed; end with `summary NAME`.
passed=0 failed=0

check() {  # check NAME COMMAND...: passes when COMMAND succeeds
    local name=$1; shift
    if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $name"; fi
}

# Runs veduta, keeping stdout, stderr and the exit code.
run() { "$veduta" "$@" >"$work/out" 2>"$work/err"; echo $? >"$work/rc"; }
rc_is() { [ "$(cat "$work/rc")" = "$1" ] || { echo "exit code $(cat "$work/rc"), expected $1"; cat "$work/err"; false; }; }
err_has() { grep -qF -- "$1" "$work/err" || { echo "stderr lacks '$1':"; cat "$work/err"; false; }; }
out_has() { grep -qF -- "$1" "$work/out" || { echo "stdout lacks '$1':"; cat "$work/out"; false; }; }
out_line() { grep -qxF -- "$1" "$work/out" || { echo "stdout lacks the line '$1':"; cat "$work/out"; false; }; }

# The closing line test runners are read by: "NAME: N passed, M failed"; fails if any failed.
summary() {
    echo "$1: $passed passed, $failed failed"
    [ "$failed" = 0 ]
}
