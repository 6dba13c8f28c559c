#!/usr/bin/env bash
# The report of `veduta compare` opened as a user opens it, from disk in a browser without a
# server: headless Chromium loads it, and the page's own script says in its title how many of
# its pictures loaded ("veduta compare: N images loaded, M failed"); every one must, and at
# least one. With SCREENSHOT, Chromium also draws the page into that PNG. Skips (77) without
# Chromium (Debian: chromium).
# Usage: compare_report_chromium_test.sh REPORT.html [SCREENSHOT.png]
set -u
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
    echo "usage: $0 REPORT.html [SCREENSHOT.png]" >&2
    exit 2
fi
report=$1 screenshot=${2:-}
browser=
for name in chromium chromium-browser google-chrome; do
    if command -v "$name" >/dev/null; then
        browser=$(command -v "$name")
        break
    fi
done
if [ -z "$browser" ]; then
    echo "skipped: no chromium, chromium-browser or google-chrome on PATH (Debian: apt-get install chromium)"
    exit 77
fi
[ -s "$report" ] || { echo "FAILED: no report at $report"; exit 1; }

# A private profile, and a private home for what Chromium keeps outside it (crash reports, caches).
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
mkdir -p "$profile/home"
chromium() {
    HOME=$profile/home XDG_CONFIG_HOME=$profile/home/.config XDG_CACHE_HOME=$profile/home/.cache \
        timeout 120 "$browser" --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
        --user-data-dir="$profile/data" --virtual-time-budget=10000 "$@" 2>>"$profile/messages"
}
url="file://$(realpath "$report")"

dom=$(chromium --dump-dom "$url")
status=$?
title=$(tr -d '\n' <<<"$dom" | sed -n 's:.*<title>\([^<]*\)</title>.*:\1:p')
echo "title: $title"
if [ $status -ne 0 ]; then
    echo "FAILED: Chromium exits with $status on $report (its last messages follow)"
    grep -v -e dbus -e "Fontconfig" "$profile/messages" | tail -n 20
    exit 1
fi
if ! [[ "$title" =~ ^"veduta compare: "([0-9]+)" images loaded, "([0-9]+)" failed"$ ]]; then
    echo "FAILED: the title is not 'veduta compare: N images loaded, M failed': the page's script did not" \
         "run or some pictures neither loaded nor failed (Chromium's last messages follow)"
    grep -v -e dbus -e "Fontconfig" "$profile/messages" | tail -n 20
    exit 1
fi
if [ "${BASH_REMATCH[2]}" -ne 0 ]; then
    echo "FAILED: ${BASH_REMATCH[2]} of the report's pictures did not load"
    exit 1
fi
if [ "${BASH_REMATCH[1]}" -lt 1 ]; then
    echo "FAILED: the report has no pictures"
    exit 1
fi

if [ -n "$screenshot" ]; then
    rm -f "$screenshot"
    chromium --hide-scrollbars --window-size=1400,2000 --screenshot="$screenshot" "$url" >/dev/null
    if [ ! -s "$screenshot" ] || [ "$(head -c 8 "$screenshot" | od -An -tx1 | tr -d ' \n')" != 89504e470d0a1a0a ]; then
        echo "FAILED: no PNG screenshot at $screenshot (Chromium's last messages follow)"
        grep -v -e dbus -e "Fontconfig" "$profile/messages" | tail -n 20
        exit 1
    fi
    echo "screenshot: $screenshot ($(stat -c %s "$screenshot") bytes)"
fi
echo "compare_report_chromium: passed"
