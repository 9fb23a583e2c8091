#!/usr/bin/env python3
"""Write a scene file of N copies of one mesh at random (seeded) poses, for the scene
benchmarks (fcl_scene.sh and our own scene CLI read the same files).

Scene file format, one object per line, objects numbered from 0 in line order:

    MESH rx ry rz tx ty tz        rotate rx degrees about x, then ry about y, then rz
                                  about z (fixed axes: R = Rz * Ry * Rx), then translate
    MESH r00 r01 r02 t0 r10 r11 r12 t1 r20 r21 r22 t2
                                  row-major 3x4 [R | t]

MESH is a path relative to the scene file's folder (no whitespace in it); `#` starts a
comment; blank lines are ignored; a mesh named on several lines is loaded once.

The objects are placed so that the centre of the mesh's bounding box lands uniformly in a
cube of side k * N^(1/3) * D, where D is the diagonal of the mesh's bounding box, under a
uniformly random rotation. The density is constant in N, so each object touches about the
same number of others whatever N is (with the bunny, about 2.7 to 2.9 for the default k and about 9
for --dense); the fraction of touching pairs is a few percent at N = 100 and falls as 1/N.

--separated places the objects so that no two bounding spheres (about the bounding-box
centre) overlap, by rejection, with k = 1.5 by default: no pair touches, so the nearest pair
is a real distance query rather than the first touching pair found.

--moved FILE writes the same objects each moved by a small random step (translation of at
most --step * D, each angle changed by at most --turn degrees), for the "move every object
and ask again" measurement.

Usage: python3 make_scene.py [--n N] [--seed S] [--dense | --separated] [--k K] [--mesh MESH]
                             [--matrix] [--moved FILE] -o FILE
"""
import argparse
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, "..", "data", "bunny.obj")
SPARSE_K = 0.6
DENSE_K = 0.4
SEPARATED_K = 1.5


def mesh_vertices(path):
    """Vertices of an OBJ or OFF file (only what is needed for the bounding box)."""
    with open(path) as f:
        text = f.read()
    if path.lower().endswith(".off"):
        words = []
        for line in text.splitlines():
            words.extend(line.split("#", 1)[0].split())
        if not words or not words[0].endswith("OFF"):
            raise ValueError(f"{path}: not an OFF file")
        rest = words[1:] if words[0] == "OFF" else [words[0][:-3]] + words[1:]
        nv = int(rest[0])
        coords = rest[3:3 + 3 * nv]
        return [tuple(map(float, coords[3 * i:3 * i + 3])) for i in range(nv)]
    verts = []
    for line in text.splitlines():
        parts = line.split()
        if parts and parts[0] == "v":
            verts.append(tuple(map(float, parts[1:4])))
    return verts


def rotation(rx, ry, rz):
    """R = Rz(rz) * Ry(ry) * Rx(rx), angles in degrees, as a row-major 3x3 list."""
    a, b, c = (math.radians(x) for x in (rx, ry, rz))
    ca, sa, cb, sb, cc, sc = math.cos(a), math.sin(a), math.cos(b), math.sin(b), math.cos(c), math.sin(c)
    return [
        [cc * cb, cc * sb * sa - sc * ca, cc * sb * ca + sc * sa],
        [sc * cb, sc * sb * sa + cc * ca, sc * sb * ca - cc * sa],
        [-sb, cb * sa, cb * ca],
    ]


def apply(r, v):
    return [sum(r[i][j] * v[j] for j in range(3)) for i in range(3)]


def fmt(x):
    return f"{x:.6f}"


def write_scene(path, mesh_path, poses, header, matrix):
    rel = os.path.relpath(os.path.abspath(mesh_path), os.path.dirname(os.path.abspath(path)))
    if any(ch.isspace() for ch in rel):
        sys.exit(f"mesh path {rel!r} contains whitespace")
    with open(path, "w") as f:
        for line in header:
            f.write(f"# {line}\n")
        for angles, t in poses:
            if matrix:
                r = rotation(*angles)
                nums = [r[0][0], r[0][1], r[0][2], t[0], r[1][0], r[1][1], r[1][2], t[1],
                        r[2][0], r[2][1], r[2][2], t[2]]
                f.write(rel + " " + " ".join(repr(x) for x in nums) + "\n")
            else:
                f.write(rel + " " + " ".join(fmt(x) for x in list(angles) + list(t)) + "\n")


def random_angles(rng):
    # Uniform on SO(3) for R = Rz * Ry * Rx: the Haar measure is cos(ry) drx dry drz.
    return [rng.uniform(0.0, 360.0), math.degrees(math.asin(rng.uniform(-1.0, 1.0))),
            rng.uniform(0.0, 360.0)]


def random_ball(rng, radius):
    while True:
        v = [rng.uniform(-1.0, 1.0) for _ in range(3)]
        if sum(x * x for x in v) <= 1.0:
            return [radius * x for x in v]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1000, help="number of objects (default 1000)")
    ap.add_argument("--seed", type=int, default=1, help="random seed (default 1)")
    ap.add_argument("--dense", action="store_true", help=f"k = {DENSE_K} instead of {SPARSE_K}")
    ap.add_argument("--separated", action="store_true",
                    help=f"no two bounding spheres overlap; k = {SEPARATED_K} unless --k")
    ap.add_argument("--k", type=float, help="cube side = k * N^(1/3) * bounding-box diagonal")
    ap.add_argument("--mesh", default=DEFAULT_MESH, help="OBJ or OFF mesh (default ../data/bunny.obj)")
    ap.add_argument("--matrix", action="store_true", help="write 12-number [R | t] poses")
    ap.add_argument("--moved", metavar="FILE", help="also write the moved poses here")
    ap.add_argument("--step", type=float, default=0.05, help="largest move, times the diagonal (0.05)")
    ap.add_argument("--turn", type=float, default=3.0, help="largest change of each angle, degrees (3)")
    ap.add_argument("-o", dest="out", required=True, help="scene file to write")
    args = ap.parse_args()

    verts = mesh_vertices(args.mesh)
    lo = [min(v[i] for v in verts) for i in range(3)]
    hi = [max(v[i] for v in verts) for i in range(3)]
    centre = [(lo[i] + hi[i]) / 2 for i in range(3)]
    diag = math.dist(lo, hi)
    k = args.k if args.k is not None else (
        SEPARATED_K if args.separated else DENSE_K if args.dense else SPARSE_K)
    side = k * args.n ** (1.0 / 3.0) * diag

    radius = max(math.dist(v, centre) for v in verts)
    cell = 2.0 * radius
    grid = {}  # for --separated: cell -> centres already placed

    def clear(p):
        c = tuple(int(math.floor(x / cell)) for x in p)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for q in grid.get((c[0] + dx, c[1] + dy, c[2] + dz), ()):
                        if math.dist(p, q) <= 2.0 * radius:
                            return False
        grid.setdefault(c, []).append(p)
        return True

    rng = random.Random(args.seed)
    poses = []
    for _ in range(args.n):
        angles = random_angles(rng)
        for _attempt in range(100000):
            p = [rng.uniform(0.0, side) for _ in range(3)]
            if not args.separated or clear(p):
                break
        else:
            sys.exit("--separated: no room left; use a larger --k")
        rc = apply(rotation(*angles), centre)
        poses.append((angles, [p[i] - rc[i] for i in range(3)]))
    flags = " --separated" if args.separated else ""
    header = [f"make_scene.py --n {args.n} --seed {args.seed} --k {k}{flags} --mesh {os.path.basename(args.mesh)}",
              f"{args.n} objects, bounding-box centres uniform in a cube of side {side:.6f}"]
    write_scene(args.out, args.mesh, poses, header, args.matrix)

    if args.moved:
        moved = []
        for angles, _t in poses:
            new_angles = [a + rng.uniform(-args.turn, args.turn) for a in angles]
            # Move the bounding-box centre by a random step, whatever the change of rotation.
            old_c = [x + y for x, y in zip(apply(rotation(*angles), centre), _t)]
            step = random_ball(rng, args.step * diag)
            rc = apply(rotation(*new_angles), centre)
            moved.append((new_angles, [old_c[i] + step[i] - rc[i] for i in range(3)]))
        write_scene(args.moved, args.mesh, moved,
                    header + [f"moved: each object by at most {args.step} * {diag:.6f} "
                              f"and {args.turn} degrees per angle"], args.matrix)


if __name__ == "__main__":
    main()
