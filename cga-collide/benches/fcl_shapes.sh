#!/usr/bin/env bash
# FCL's collide() on the primitive pair files of shape_pairs.py (see fcl_shapes.cpp): one JSON
# line per (pair type, family) with its time per pair and its wrong answers, the fields of
# coal_shapes.py with "who": "fcl". Needs g++, FCL's headers (`apt-get install libfcl-dev` on
# Debian, FCL 0.7) and a Python with numpy and scipy for the conversion (peer_shapes.py).
# Usage: bash cga-collide/benches/fcl_shapes.sh [FILE.jsonl...]
#   With no files, writes the default sets with shape_pairs.py (into KEEP if set, else a
#   temporary folder) and runs on all of them.
# Environment: PYTHON (default python3), REPEAT (calls per pair, default 200),
#   KEEP=DIR keeps the pair files and FCL's input there, WRONG=FILE lists FCL's wrong answers.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
python="${PYTHON:-python3}"
# shellcheck source=fcl_build.sh
source "$here/fcl_build.sh"
build_fcl_driver "$here/fcl_shapes.cpp" "$work/fcl_shapes"
if [ "$#" -eq 0 ]; then
  "$python" "$here/shape_pairs.py" -o "$work/pairs" >/dev/null
  set -- "$work"/pairs/generic/*.jsonl "$work"/pairs/near_contact/*.jsonl
fi
"$python" "$here/peer_shapes.py" --fcl-text "$work/fcl_input.txt" "$@"
args=("$work/fcl_input.txt" --repeat "${REPEAT:-200}")
if [ -n "${WRONG:-}" ]; then
  args+=(--wrong "$WRONG")
fi
"$work/fcl_shapes" "${args[@]}"
