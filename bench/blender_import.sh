#!/usr/bin/env bash
# Imports veduta exports into Blender and prints what arrived (bench/blender_import.py): object,
# mesh and material counts, camera, sun, glass. Exits 77 when Blender is not installed; its glTF
# importer also needs Debian's python3-numpy.
# Usage: bench/blender_import.sh FILE.obj|FILE.gltf|FILE.glb...
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v blender >/dev/null; then
    echo "blender_import: skipped: blender is not installed (Debian: apt-get install blender)"
    exit 77
fi
[ $# -gt 0 ] || { echo "usage: $0 FILE..." >&2; exit 2; }
# Blender prints its own start-up and importer lines; the report's lines are kept.
blender -b --factory-startup --python-exit-code 1 -P bench/blender_import.py -- "$@" 2>&1 |
    grep -E '^(  |[^ ].*: imported in|Error|Traceback)' || true
exit "${PIPESTATUS[0]}"
