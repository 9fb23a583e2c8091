#!/usr/bin/env bash
# This library against CGAL 5.5 on every mesh of CGAL's demo data, both on one thread, the same
# files, in the same run:
#   - self-intersection of every mesh (`Collider::self_intersections` against
#     `PMP::self_intersections`), the tree/box building included on both sides;
#   - mesh against mesh (`Collider::intersecting_pairs` against `box_intersection_d` +
#     `do_intersect(Triangle_3, Triangle_3)`) on a few meshes against themselves, against
#     another mesh, and against a moved-and-turned copy of themselves.
# The pair sets are compared item by item and a markdown table is printed
# (benches/demo_meshes_table.py). The C++ side is benches/cgal_demo_meshes.cpp, ours
# benches/demo_meshes.rs.
#
# Needs g++, CGAL's headers and demo data (Debian: `apt-get install libcgal-dev libcgal-demo`),
# python3, cargo.
#
# Usage: bash cga-collide/benches/demo_meshes.sh [REPEAT]      (best of REPEAT runs, default 3)
# Environment:
#   DEMO_MESHES_DIR   where the meshes are (extracted there if it has none; default: a temp dir)
#   DEMO_MESHES_TAR   CGAL's data archive (default /usr/share/doc/libcgal-dev/data.tar.gz)
#   DEMO_MESHES_BUILD our tree build: unset for `Collider::new`'s (binned SAH), `morton` for
#                     the one-shot `BuildStrategy::Morton`
#   DEMO_MESHES_OUT   where the JSON lines, pair files and tables go (default: a new
#                     /tmp/demo_meshes.XXXXXX, kept and printed at the end)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
repeat="${1:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
out="${DEMO_MESHES_OUT:-$(mktemp -d /tmp/demo_meshes.XXXXXX)}"
mkdir -p "$out"/{ours,cgal}/{self,pair}
rm -f "$out"/{ours,cgal}_{self,pair}.jsonl

# (a) The meshes.
meshes="${DEMO_MESHES_DIR:-$work/meshes}"
tarball="${DEMO_MESHES_TAR:-/usr/share/doc/libcgal-dev/data.tar.gz}"
mkdir -p "$meshes"
if ! ls "$meshes" | grep -qE '\.(off|ply|stl)$'; then
  echo "extracting the meshes of $tarball into $meshes" >&2
  tar xzf "$tarball" -C "$work" data/meshes
  cp "$work"/data/meshes/* "$meshes"/
  rm -rf "$work/data"
fi
find "$meshes" -maxdepth 1 -type f \( -name '*.off' -o -name '*.ply' -o -name '*.stl' \) | LC_ALL=C sort > "$work/list.txt"
echo "$(wc -l < "$work/list.txt") mesh files in $meshes" >&2

# (b) CGAL's program.
echo "building benches/cgal_demo_meshes.cpp" >&2
g++ -O3 -DNDEBUG -std=c++17 "$here/cgal_demo_meshes.cpp" -o "$work/cgal_demo_meshes" -lgmp -lmpfr
cgal="$work/cgal_demo_meshes"

# (c) Ours: the bench target, built once and then run directly.
echo "building the demo_meshes bench target" >&2
ours="$(cd "$repo" && cargo bench -p cga-collide --bench demo_meshes --no-run --message-format=json |
  python3 -c '
import json, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m["target"]["name"] == "demo_meshes" and m.get("executable"):
        print(m["executable"])
')"
[ -x "$ours" ] || { echo "could not find the demo_meshes bench executable" >&2; exit 1; }

# (d) Moved-and-turned copies: 0.3 rad about an axis through the centroid, then a shift of 1% of
# the box diagonal, so that the copy overlaps the original.
moved_meshes=(cube-meshed.off fandisk.off blade.off bunny00.off cheese.off anchor.off)
mkdir -p "$work/moved"
for m in "${moved_meshes[@]}"; do
  python3 - "$meshes/$m" "$work/moved/${m%.off}-moved.off" <<'EOF'
import math, sys
src, dst = sys.argv[1], sys.argv[2]
with open(src) as f:
    lines = [ln.split("#")[0].split() for ln in f]
lines = [ln for ln in lines if ln]
assert lines[0][0].endswith("OFF"), src
if len(lines[0]) >= 3:
    counts, k = lines[0][1:], 1
else:
    counts, k = lines[1], 2
nv, nf = int(counts[0]), int(counts[1])
verts = [[float(x) for x in lines[k + i][:3]] for i in range(nv)]
faces = []
for i in range(nf):
    ln = lines[k + nv + i]
    faces.append(ln[1 : 1 + int(ln[0])])
centre = [sum(v[a] for v in verts) / nv for a in range(3)]
lo = [min(v[a] for v in verts) for a in range(3)]
hi = [max(v[a] for v in verts) for a in range(3)]
diag = math.sqrt(sum((hi[a] - lo[a]) ** 2 for a in range(3)))
axis = [2.0, 3.0, 6.0]  # norm 7
axis = [x / 7.0 for x in axis]
angle = 0.3
c, s = math.cos(angle), math.sin(angle)
shift = [0.01 * diag * x for x in (0.6, -0.48, 0.64)]

def turn(v):
    # Rodrigues: v cos + (k x v) sin + k (k . v)(1 - cos), about `centre`, then the shift.
    p = [v[a] - centre[a] for a in range(3)]
    kx, ky, kz = axis
    cross = [ky * p[2] - kz * p[1], kz * p[0] - kx * p[2], kx * p[1] - ky * p[0]]
    dot = kx * p[0] + ky * p[1] + kz * p[2]
    return [p[a] * c + cross[a] * s + axis[a] * dot * (1 - c) + centre[a] + shift[a] for a in range(3)]

with open(dst, "w") as f:
    f.write(f"OFF\n{nv} {nf} 0\n")
    for v in verts:
        f.write(" ".join(repr(x) for x in turn(v)) + "\n")
    for face in faces:
        f.write(f"{len(face)} {' '.join(face)}\n")
EOF
done

# (e) Both libraries. Self-intersection: all of CGAL, then all of ours.
echo "self-intersection, CGAL ($(wc -l < "$work/list.txt") meshes, best of $repeat)" >&2
"$cgal" self "$work/list.txt" "$repeat" "$out/cgal/self" > "$out/cgal_self.jsonl" 2> "$out/cgal_self.stderr"
echo "self-intersection, this library" >&2
"$ours" self "$work/list.txt" "$repeat" "$out/ours/self" > "$out/ours_self.jsonl" 2> "$out/ours_self.stderr"

# Mesh against mesh, the two libraries one after the other on each item.
items=(
  "cube-meshed.off cube-meshed.off"
  "lion.off lion-head.off"
  "fandisk.off fandisk.off"
  "blade.off blade.off"
  "elephant.off elephant.off"
  "knot1.off knot1.off"
  "dino.off dino.off"
  "homer.off homer.off"
  "bull.off bull.off"
  "camel.off camel.off"
)
for m in "${moved_meshes[@]}"; do
  items+=("$m moved:${m%.off}-moved.off")
done
for item in "${items[@]}"; do
  read -r a b <<< "$item"
  pa="$meshes/$a"
  case "$b" in
    moved:*) b="${b#moved:}"; pb="$work/moved/$b" ;;
    *) pb="$meshes/$b" ;;
  esac
  echo "mesh-mesh: $a x $b" >&2
  "$cgal" pair "$pa" "$pb" "$repeat" "$out/cgal/pair/${a}__${b}.pairs" >> "$out/cgal_pair.jsonl" 2>> "$out/cgal_pair.stderr"
  "$ours" pair "$pa" "$pb" "$repeat" "$out/ours/pair/${a}__${b}.pairs" >> "$out/ours_pair.jsonl" 2>> "$out/ours_pair.stderr"
done

# (f) + (g) Compare the pair sets and print the tables (kept in $out/table.md).
python3 "$here/demo_meshes_table.py" "$out" --meshes "$meshes" | tee "$out/table.md"
echo "results in $out (JSON lines, pair files, table.md)" >&2
