#!/usr/bin/env bash
# Checks the layer graph of a veduta tree: every include of src/<folder>/ that names another
# folder must be an arrow of docs/ARCHITECTURE.md's "Layers" table, and the USES lists of
# src/CMakeLists.txt (what each folder's library links) must be exactly those arrows.
#   check_layers.sh ROOT      exit 0: clean; 1: violations, each "file:line: what"; 2: usage
set -euo pipefail
root=${1:?usage: check_layers.sh ROOT}
doc=$root/docs/ARCHITECTURE.md
cmake=$root/src/CMakeLists.txt
for f in "$doc" "$cmake"; do [ -f "$f" ] || { echo "check_layers: no $f" >&2; exit 2; }; done

# The table between the markers: "| folder | uses, uses |"; "—" for none.
declare -A allowed
while IFS='|' read -r _ folder uses _; do
    folder=$(echo "$folder" | tr -d ' `')
    uses=$(echo "$uses" | tr -d ' `' | tr ',' ' ' | sed 's/—//g')
    [ -n "$folder" ] && allowed[$folder]=" $uses "
done < <(sed -n '/<!-- layers -->/,/<!-- \/layers -->/p' "$doc" | grep -E '^\| *`?[a-z]+`? *\|' | grep -vE '^\| *Folder')
[ ${#allowed[@]} -gt 0 ] || { echo "$doc: no layer table between <!-- layers --> and <!-- /layers -->" >&2; exit 2; }

failures=0
include_re='^[[:space:]]*#[[:space:]]*include[[:space:]]*"([a-z_]+)/'
fail() { echo "$1"; failures=$((failures + 1)); }

for dir in "$root"/src/*/; do
    folder=$(basename "$dir")
    if [ -z "${allowed[$folder]+x}" ]; then
        fail "src/$folder: a folder that the layer table of docs/ARCHITECTURE.md does not list"
        continue
    fi
    while IFS=: read -r file line text; do
        [[ $text =~ $include_re ]] || continue
        target=${BASH_REMATCH[1]}
        [ "$target" = "$folder" ] && continue
        [ -z "${allowed[$target]+x}" ] && continue  # not a folder of ours (a generated file's own path)
        case "${allowed[$folder]}" in
            *" $target "*) ;;
            *) fail "${file#"$root"/}:$line: $folder may not include $target/ (docs/ARCHITECTURE.md, Layers): ${text#"${text%%[![:space:]]*}"}" ;;
        esac
    done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"[a-z_]+/' "$dir" --include='*.h' --include='*.cpp' --include='*.in' || true)
done

# The libraries' link lists: "veduta_layer(folder" … "USES a b c" and veduta_layer_headers(folder a b c).
while read -r folder uses; do
    want=$(echo ${allowed[$folder]:-} | tr ' ' '\n' | sort | tr '\n' ' ')
    have=$(echo $uses | tr ' ' '\n' | sort | tr '\n' ' ')
    if [ -z "${allowed[$folder]+x}" ]; then
        fail "src/CMakeLists.txt: layer $folder is not in the table of docs/ARCHITECTURE.md"
    elif [ "$want" != "$have" ]; then
        fail "src/CMakeLists.txt: layer $folder links [ ${have}] but docs/ARCHITECTURE.md allows [ ${want}]"
    fi
done < <(awk '
    /^veduta_layer\(/ { sub(/^veduta_layer\(/, ""); folder = $1; uses = ""; inlayer = 1; next }
    /^veduta_layer_headers\(/ { sub(/^veduta_layer_headers\(/, ""); sub(/\)$/, ""); print; next }
    inlayer && /^[[:space:]]*USES / {
        closing = /\)[[:space:]]*$/; sub(/^[[:space:]]*USES /, ""); sub(/\).*/, ""); uses = $0
        if (closing) { print folder, uses; inlayer = 0 }
        next
    }
    inlayer && /\)[[:space:]]*$/ { print folder, uses; inlayer = 0 }
' "$cmake")

if [ $failures -gt 0 ]; then
    echo "check_layers: $failures violation(s)"
    exit 1
fi
echo "check_layers: ${#allowed[@]} layers, every include and link list follows the graph"
