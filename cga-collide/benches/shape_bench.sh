#!/usr/bin/env bash
# The primitive-pair benchmark in one run: writes the pair sets with shape_pairs.py (unless
# OUT already holds them), then on the same files, one after the other: ours natively
# (`cga shapes --json --repeat REPEAT`, exact), ours from Python (cga_py_shapes.py, the
# package's `intersects`, its call cost shown apart), coal from Python (coal_shapes.py, its
# call cost shown apart) and FCL from C++ (fcl_shapes.sh), all timed alike (best of 5 loops
# of REPEAT / 5 calls per pair, median over the pairs of a type), and prints the Markdown
# table of shape_table.py. Each side's JSON lines are kept in OUT (cga.jsonl, cga_py.jsonl,
# coal.jsonl, fcl.jsonl), the wrong pairs of the peers in OUT/coal_wrong.jsonl and
# OUT/fcl_wrong.txt.
# Needs a Python with numpy, scipy and coal (PYTHON), g++ and libfcl-dev, and cargo; the
# Python side of ours needs the package importable from PYTHON (`maturin develop --release`
# in cga-collide/python), else it is skipped with a note.
# Usage: bash cga-collide/benches/shape_bench.sh [OUT]   (default OUT: ./shape_bench)
# Environment: PYTHON (default python3), REPEAT (calls per pair, default 200), GEN_ARGS
#   (extra shape_pairs.py options, e.g. "--scaled=-320,320"), CGA (path of the cga binary,
#   default: built here with cargo, release), SKIP_CGA=1 to run the peers only, PAIRS=REGEX
#   to time only the pair types whose file name matches (grep -E; e.g. "cylinder|cone" or,
#   with GREP_V=1, all but those).
# A file `cga shapes` refuses (a pair type without an exact test yet) is reported on stderr
# and left out of our native column; the other files still run.
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
if [ -n "${PAIRS:-}" ]; then
  mapfile -t files < <(printf '%s\n' "${files[@]}" | grep -E ${GREP_V:+-v} "$PAIRS")
fi
results=()
if [ -z "${SKIP_CGA:-}" ]; then
  if [ -z "${CGA:-}" ]; then
    cargo build --release -q -p cga-cli --bin cga --manifest-path "$here/../../Cargo.toml"
    CGA="${CARGO_TARGET_DIR:-$here/../../target}/release/cga"
  fi
  : >"$out/cga.jsonl"
  for f in "${files[@]}"; do
    "$CGA" shapes "$f" --json --repeat "$repeat" >>"$out/cga.jsonl" || echo "cga refused $f" >&2
  done
  results+=("$out/cga.jsonl")
  if "$python" -c "import cga_collide" 2>/dev/null; then
    "$python" "$here/cga_py_shapes.py" "${files[@]}" --repeat "$repeat" >"$out/cga_py.jsonl"
    results+=("$out/cga_py.jsonl")
  else
    echo "cga_collide is not importable from $python: ours from Python skipped" >&2
  fi
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
