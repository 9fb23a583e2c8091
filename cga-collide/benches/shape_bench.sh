#!/usr/bin/env bash
# The primitive-pair benchmark in one run: writes the pair sets with shape_pairs.py (unless
# OUT already holds them), then on the same files `cga shapes --json` (ours, exact), coal
# from Python (coal_shapes.py) and FCL from C++ (fcl_shapes.sh), and prints the Markdown
# table of shape_table.py. Each side's JSON lines are kept in OUT (cga.jsonl, coal.jsonl,
# fcl.jsonl), the wrong pairs of the peers in OUT/coal_wrong.jsonl and OUT/fcl_wrong.txt.
# Needs a Python with numpy, scipy and coal (PYTHON), g++ and libfcl-dev, and cargo.
# Usage: bash cga-collide/benches/shape_bench.sh [OUT]   (default OUT: ./shape_bench)
# Environment: PYTHON (default python3), REPEAT (calls per pair, default 200), GEN_ARGS
#   (extra shape_pairs.py options, e.g. "--scaled=-320,320"), CGA (path of the cga binary,
#   default: built here with cargo, release), SKIP_CGA=1 to run the peers only.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${1:-shape_bench}"
python="${PYTHON:-python3}"
repeat="${REPEAT:-200}"
if [ ! -d "$out/near_contact" ]; then
  mkdir -p "$out"
  # shellcheck disable=SC2086
  "$python" "$here/shape_pairs.py" -o "$out" ${GEN_ARGS:-} >"$out/sets.jsonl"
fi
files=()
for family in generic near_contact near_contact_scaled; do
  if [ -d "$out/$family" ]; then
    files+=("$out/$family"/*.jsonl)
  fi
done
results=()
if [ -z "${SKIP_CGA:-}" ]; then
  if [ -z "${CGA:-}" ]; then
    cargo build --release -q -p cga-cli --bin cga --manifest-path "$here/../../Cargo.toml"
    CGA="$here/../../target/release/cga"
  fi
  "$CGA" shapes "${files[@]}" --json >"$out/cga.jsonl"
  results+=("$out/cga.jsonl")
fi
"$python" "$here/coal_shapes.py" "${files[@]}" --repeat "$repeat" --wrong "$out/coal_wrong.jsonl" \
  >"$out/coal.jsonl"
PYTHON="$python" REPEAT="$repeat" WRONG="$out/fcl_wrong.txt" bash "$here/fcl_shapes.sh" "${files[@]}" \
  >"$out/fcl.jsonl"
results+=("$out/coal.jsonl" "$out/fcl.jsonl")
families="generic,near_contact"
if [ -d "$out/near_contact_scaled" ]; then
  families="$families,near_contact_scaled"
fi
"$python" "$here/shape_table.py" "${results[@]}" --families "$families"
