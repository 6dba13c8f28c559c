#!/usr/bin/env bash
# `veduta crs`: coordinates from arguments and from standard input, the output format, a bad
# line (exit 1 with <stdin>:LINE:COLUMN), a bad command line (exit 2), --help.
# The expected values are PROJ's (cs2cs, BeTA2007), as in tests/geo/crs_test.cpp; the exact
# lines pin veduta's own output. Outside the grid the Helmert is used, with a warning.
# Usage: crs_cli_test.sh VEDUTA_BINARY
set -u
veduta=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/test_lib.sh"

# near X Y WANT_X WANT_Y TOLERANCE: the first output line's X Y lie within TOLERANCE of the wanted.
near() {
    awk -v x="$1" -v y="$2" -v t="$3" 'NR == 1 { d = sqrt(($1 - x)^2 + ($2 - y)^2); if (d > t) { print "off by " d; exit 1 } }' \
        "$work/out"
}

run crs --help
check "help exits 0" rc_is 0
check "help usage" out_has "Usage"
check "help axis order" out_has "easting before northing"
check "help exit codes" out_has "Exit codes"

# Koblenz in GK zone 3 to UTM 32: cs2cs gives 397573.8526 5579649.8598 (BeTA2007).
run crs --from EPSG:31467 --to EPSG:25832 3397608 5581442
check "arguments" rc_is 0
check "arguments near BeTA2007" near 397573.8526 5579649.8598 0.001
check "arguments: X Y Z, 3 decimals" out_line "397573.853 5579649.860 0.000"
check "inside the grid no warning" test ! -s "$work/err"
run crs --from 31467 --to epsg:25832 3397608 5581442 64.5
check "Z passes through" out_line "397573.853 5579649.860 64.500"
# Paris, outside BeTA2007: the Helmert, and a warning saying so.
run crs --from EPSG:4314 --to EPSG:4258 2.3522 48.8566
check "outside the grid exits 0" rc_is 0
check "outside the grid warns" err_has "1 point outside the BeTA2007 grid"

# Degrees: 9 decimals, longitude first. The thesis point as DHDN is exactly GK3 (3397491.868, 5581721.397).
run crs --from EPSG:4314 --to EPSG:31467 7.55913333 50.36368611
check "degrees in" out_line "3397491.868 5581721.397 0.000"
# Back, from the millimetre-rounded GK values: 1 mm is about 1e-8 degrees.
run crs --from EPSG:31467 --to EPSG:4314 3397491.868 5581721.397
check "degrees out" out_line "7.559133331 50.363686111 0.000"

# Standard input: comments and blank lines copied, every line converted in order.
printf '# GK5 to UTM33\n5391532 5821963\n\n  5411785\t5657958  112.25\r\n' >"$work/in.txt"
run crs --from EPSG:31469 --to EPSG:25833 <"$work/in.txt"
check "stdin" rc_is 0
check "stdin lines" test "$(wc -l <"$work/out")" = 4
check "stdin comment copied" bash -c "head -1 '$work/out' | grep -qx '# GK5 to UTM33'"
check "stdin first point near BeTA2007" bash -c "sed -n 2p '$work/out' | awk '{ d = sqrt((\$1 - 391440.3301)^2 + (\$2 - 5820079.6561)^2); exit d > 0.001 }'"
check "stdin blank line copied" bash -c "sed -n 3p '$work/out' | grep -qx ''"
check "stdin height kept" bash -c "sed -n 4p '$work/out' | grep -q ' 112.250\$'"

# A bad line: what came before is written, then <stdin>:LINE:COLUMN and exit 1.
printf '3397608 5581442\n3397608 55814x2\n3397608 5581442\n' >"$work/bad.txt"
run crs --from EPSG:31467 --to EPSG:25832 <"$work/bad.txt"
check "bad number exits 1" rc_is 1
check "bad number place" err_has "<stdin>:2:9: '55814x2' is not a number"
check "stops at the bad line" test "$(wc -l <"$work/out")" = 1
printf '4397608 5581442\n' | run crs --from EPSG:31467 --to EPSG:25832
check "wrong zone exits 1" rc_is 1
check "wrong zone message" err_has "<stdin>:1:1: Rechtswert 4397608 is in Gauss-Kruger zone 4, not in zone 3"
printf '3397608\n' | run crs --from EPSG:31467 --to EPSG:25832
check "one field exits 1" rc_is 1
check "one field message" err_has "<stdin>:1:9: expected X Y [Z]"
printf '1 2 3 4\n' | run crs --from EPSG:4326 --to EPSG:25832
check "four fields" err_has "<stdin>:1:7: expected X Y [Z]"
printf '9 95\n' | run crs --from EPSG:4326 --to EPSG:25832
check "latitude beyond 90" err_has "<stdin>:1:3: latitude 95 is beyond"
printf 'nan 50\n' | run crs --from EPSG:4326 --to EPSG:25832
check "nan" err_has "<stdin>:1:1: 'nan' is not a number"

# A bad command line: exit 2.
run crs --from EPSG:3857 --to EPSG:25832 1 2
check "unknown EPSG exits 2" rc_is 2
check "unknown EPSG named" err_has "EPSG:3857 is not supported"
run crs --from EPSG:31467 --to GK3 1 2
check "not an EPSG code exits 2" rc_is 2
run crs --to EPSG:25832 1 2
check "missing --from exits 2" rc_is 2
run crs --from EPSG:31467 --to EPSG:25832 3397608
check "one coordinate argument exits 2" rc_is 2
run crs --from EPSG:31467 --to EPSG:25832 3397608 abc
check "bad coordinate argument exits 2" rc_is 2
check "bad coordinate argument named" err_has "coordinate argument 2: 'abc' is not a number"

summary crs_cli
