#!/usr/bin/env bash
# CGAL's self-intersection test on the built-in bunny meshes (see cgal_self_intersection.cpp).
# Needs g++ and CGAL's headers: `apt-get install libcgal-dev` on Debian.
# Usage: bash cga-collide/benches/cgal_self_intersection.sh [REPEAT]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
data="$here/../data"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
g++ -O3 -DNDEBUG -std=c++17 "$here/cgal_self_intersection.cpp" -o "$work/cgal_self_intersection" -lgmp -lmpfr
gunzip -c "$data/bunny00.off.gz" > "$work/bunny00.off"
"$work/cgal_self_intersection" "$data/bunny.obj" "${1:-5}"
"$work/cgal_self_intersection" "$work/bunny00.off" "${1:-5}"
