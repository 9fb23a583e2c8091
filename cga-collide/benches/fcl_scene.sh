#!/usr/bin/env bash
# FCL's DynamicAABBTreeCollisionManager on scenes of many bunnies (see fcl_scene.cpp and
# make_scene.py): N = 100, 1000, 10000 copies at the default density, N = 1000 at --dense,
# and N = 1000 --separated (no touching pair, so the nearest pair is a real distance query).
# Prints one JSON line per scene. Each side's touching pairs, before and after the move, are
# compared as sorted lists of index pairs (not only counts): a difference prints both sets'
# differences and the script fails. Needs g++, python3 and FCL's headers:
# `apt-get install libfcl-dev` on Debian (FCL 0.7).
# Then, on the same files in the same run, ours: `cga scene` (exact) on all cores and on one
# (RAYON_NUM_THREADS=1), one JSON line each, labelled "cga" and "cga_1_thread".
# Usage: bash cga-collide/benches/fcl_scene.sh [REPEAT]
# Environment: SCENE_NS (default "100 1000 10000"), KEEP=DIR to keep the scene files there,
# CGA=path of the cga binary (default: built here with cargo, release).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repeat="${1:-5}"
# shellcheck source=fcl_build.sh
source "$here/fcl_build.sh"
build_fcl_driver "$here/fcl_scene.cpp" "$work/fcl_scene"
if [ -z "${CGA:-}" ]; then
  cargo build --release -q -p cga-cli --bin cga --manifest-path "$here/../../Cargo.toml"
  CGA="$here/../../target/release/cga"
fi
summary() {  # LABEL FCL_JSON: our JSON on stdin, one line out (pair lists as counts); fails
  # unless our pair lists equal FCL's (`fcl_scene --pairs`), before and after the move.
  python3 -c 'import json, sys
d = json.load(sys.stdin)
fcl = json.loads(sys.argv[2])
d = {"who": sys.argv[1], **d}
ok = True
for ours_key, fcl_key in (("pairs", "pairs_list"), ("moved_pairs", "pairs_moved_list")):
    if ours_key not in d:
        continue
    ours = sorted(tuple(sorted(p)) for p in d[ours_key])
    theirs = sorted(tuple(p) for p in fcl.get(fcl_key, []))
    if ours != theirs:
        ok = False
        print(f"{sys.argv[1]} {ours_key}: only ours {sorted(set(ours) - set(theirs))[:20]}, "
              f"only FCL {sorted(set(theirs) - set(ours))[:20]}", file=sys.stderr)
    d[ours_key] = len(ours)
    d[ours_key + "_equal_fcl"] = ours == theirs
print(json.dumps(d))
sys.exit(0 if ok else 1)' "$1" "$2"
}
run() {  # NAME MAKE_SCENE_ARGS...
  local name="$1"
  shift
  python3 "$here/make_scene.py" "$@" -o "$work/$name.txt" --moved "$work/$name.moved.txt"
  local fcl
  fcl="$("$work/fcl_scene" "$work/$name.txt" --moved "$work/$name.moved.txt" --repeat "$repeat" --pairs)"
  # FCL's line without its pair lists (they are compared below, not printed).
  python3 -c 'import json, sys
d = json.loads(sys.argv[1])
for k in ("pairs_list", "pairs_moved_list"):
    d.pop(k, None)
print(json.dumps({"who": "fcl", **d}))' "$fcl"
  local ours=("$CGA" scene "$work/$name.txt" --moved "$work/$name.moved.txt" --nearest --json --repeat "$repeat")
  "${ours[@]}" | summary cga "$fcl"
  RAYON_NUM_THREADS=1 "${ours[@]}" | summary cga_1_thread "$fcl"
}
for n in ${SCENE_NS:-100 1000 10000}; do
  run "bunnies_$n" --n "$n"
done
run bunnies_1000_dense --n 1000 --dense
run bunnies_1000_separated --n 1000 --separated
