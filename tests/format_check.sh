#!/usr/bin/env bash
# The tree is formatted as .clang-format says: lists every file clang-format would change.
# Exit 77 (skipped) without clang-format.
set -euo pipefail
root=${1:?usage: format_check.sh ROOT}
command -v clang-format >/dev/null || { echo "clang-format is not installed (Debian: clang-format)"; exit 77; }
cd "$root"
mapfile -t files < <(find src tests bench fuzz -name '*.h' -o -name '*.cpp' | sort)
# One clang-format per batch of files, a batch per core; each finding starts "file:line:col:".
status=0
report=$(printf '%s\0' "${files[@]}" | xargs -0 -n 40 -P "$(nproc)" clang-format --dry-run --Werror 2>&1 >/dev/null) ||
    status=$?
mapfile -t bad < <(grep -oE '^[^:[:space:]]+\.(h|cpp):[0-9]+:[0-9]+: error' <<<"$report" | cut -d: -f1 | sort -u)
if [ $status -ne 0 ] && [ ${#bad[@]} -eq 0 ]; then echo "format_check: clang-format failed:"; echo "$report"; exit 1; fi
for f in "${bad[@]}"; do echo "$f: not formatted (clang-format -i $f)"; done
[ ${#bad[@]} -eq 0 ] || { echo "format_check: ${#bad[@]} of ${#files[@]} files differ from .clang-format"; exit 1; }
echo "format_check: ${#files[@]} files formatted"
