#!/usr/bin/env bash
# The tree is formatted as .clang-format says: lists every file clang-format would change.
# Exit 77 (skipped) without clang-format.
set -euo pipefail
root=${1:?usage: format_check.sh ROOT}
command -v clang-format >/dev/null || { echo "clang-format is not installed (Debian: clang-format)"; exit 77; }
cd "$root"
mapfile -t files < <(find src tests bench -name '*.h' -o -name '*.cpp' | sort)
bad=0
for f in "${files[@]}"; do
    if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then echo "$f: not formatted (clang-format -i $f)"; bad=$((bad + 1)); fi
done
[ $bad -eq 0 ] || { echo "format_check: $bad of ${#files[@]} files differ from .clang-format"; exit 1; }
echo "format_check: ${#files[@]} files formatted"
