#!/usr/bin/env python3
"""Signed distance of many points to a closed mesh, in one run: cga_collide against trimesh
(`trimesh.proximity.signed_distance` and `Trimesh.contains`), libigl (`igl.signed_distance`
with the generalized winding number) and Open3D (`RaycastingScene.compute_signed_distance`).

Two point sets per mesh:
* `--n` timing points (default 1e6): half generic (uniform in the mesh's box grown by 10%),
  half near the surface (a random face point moved along the face normal by up to 1% of the
  box's diagonal, either way). Each peer answers all of them (trimesh only `--trimesh-n` of
  them, it is far slower); the time per point is reported.
* `--adversarial` points (default 1,000) on or within an ulp of the surface: vertices, points
  of edges and faces (barycentric, rounded to float64), each as is, or moved one ulp up or down
  along a coordinate axis. The truth is the exact ray test (`Collider.contains_point`, exact
  predicates; a point on the surface is inside); every method's sign (inside = positive for
  trimesh and ours in trimesh's convention, negative for libigl and Open3D) is counted against
  it. A point on the surface counts as inside for every method (distance 0 counts as inside
  where the method gives 0).

Not part of CI. Needs `pip install numpy trimesh rtree scipy libigl open3d` and the package
built (`maturin develop --release` in cga-collide/python). From the repository root:

    python3 cga-collide/benches/signed_distance_peers.py [--n 1000000] [--meshes bunny00 ...]

Prints one JSON object per mesh and method.
"""
import argparse
import json
import os
import time

import numpy as np

import cga_collide as cc

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")
MESHES = {
    "bunny": "bunny.obj",
    "bunny00": "bunny00.off.gz",
    "armadillo": "armadillo.off.gz",
}


def timing_points(v, f, n, rng):
    lo, hi = v.min(axis=0), v.max(axis=0)
    pad = 0.1 * (hi - lo)
    generic = rng.uniform(lo - pad, hi + pad, size=(n - n // 2, 3))
    t = rng.integers(0, len(f), size=n // 2)
    a, b, c = v[f[t, 0]], v[f[t, 1]], v[f[t, 2]]
    s, u = rng.random((2, n // 2, 1))
    flip = (s + u) > 1
    s, u = np.where(flip, 1 - s, s), np.where(flip, 1 - u, u)
    nrm = np.cross(b - a, c - a)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True) + 1e-300
    h = rng.uniform(-1, 1, size=(n // 2, 1)) * 0.01 * np.linalg.norm(hi - lo)
    near = a + s * (b - a) + u * (c - a) + h * nrm
    return np.ascontiguousarray(np.vstack([generic, near]))


def adversarial_points(v, f, n, rng):
    out = []
    while len(out) < n:
        t = rng.integers(0, len(f))
        a, b, c = v[f[t, 0]], v[f[t, 1]], v[f[t, 2]]
        s, u = rng.random(2)
        if s + u > 1:
            s, u = 1 - s, 1 - u
        p = [a, a + rng.random() * (b - a), a + s * (b - a) + u * (c - a)][rng.integers(0, 3)]
        p = p.copy()
        k, move = rng.integers(0, 3), rng.integers(0, 3)
        if move == 1:
            p[k] = np.nextafter(p[k], np.inf)
        elif move == 2:
            p[k] = np.nextafter(p[k], -np.inf)
        out.append(p)
    return np.array(out)


def timed(fn, *args):
    t = time.perf_counter()
    r = fn(*args)
    return r, time.perf_counter() - t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--trimesh-n", type=int, default=20_000)
    ap.add_argument("--adversarial", type=int, default=1000)
    ap.add_argument("--meshes", nargs="+", default=["bunny00"])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--skip", nargs="*", default=[], help="methods to skip")
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)

    import igl
    import open3d as o3d
    import trimesh

    for name in args.meshes:
        collider, build = timed(cc.Collider.load, os.path.join(DATA, MESHES[name]))
        v, f = collider.vertices, collider.faces
        pts = timing_points(v, f, args.n, rng)
        adv = adversarial_points(v, f, args.adversarial, rng)
        truth = np.array([collider.contains_point(p) for p in adv])
        base = {"mesh": name, "triangles": int(len(f)), "points": args.n,
                "adversarial": args.adversarial, "truly_inside": int(truth.sum())}

        def report(method, n, seconds, wrong, extra=None):
            row = dict(base, method=method, timed_points=n,
                       micros_per_point=seconds * 1e6 / n, wrong_signs=int(wrong))
            row.update(extra or {})
            print(json.dumps(row), flush=True)

        # Ours (build outside the timing; the first query's one-time mesh check inside).
        r, s = timed(collider.signed_distance, pts)
        ra = collider.signed_distance(adv)
        report("cga_collide Collider.signed_distance", args.n, s,
               np.sum(ra.inside != truth),
               {"build_seconds": build, "max_error_bound": float(r.error_bound.max())})
        ours = r

        if "libigl" not in args.skip:
            vf, ff = np.ascontiguousarray(v), np.ascontiguousarray(f.astype(np.int64))
            st = igl.SIGNED_DISTANCE_TYPE_FAST_WINDING_NUMBER
            out, s = timed(igl.signed_distance, pts, vf, ff, st)
            sd = out[0]
            outa = igl.signed_distance(adv, vf, ff, st)
            report("libigl signed_distance (fast winding number)", args.n, s,
                   np.sum((outa[0] <= 0) != truth),
                   {"generic_sign_disagreements_with_ours": int(np.sum((sd < 0) != ours.inside))})

        if "open3d" not in args.skip:
            mesh = o3d.t.geometry.TriangleMesh()
            mesh.vertex.positions = o3d.core.Tensor(v.astype(np.float32))
            mesh.triangle.indices = o3d.core.Tensor(f.astype(np.int32))
            scene = o3d.t.geometry.RaycastingScene()
            scene.add_triangles(mesh)
            q = o3d.core.Tensor(pts.astype(np.float32))
            sd, s = timed(lambda x: scene.compute_signed_distance(x).numpy(), q)
            sda = scene.compute_signed_distance(o3d.core.Tensor(adv.astype(np.float32))).numpy()
            report("Open3D RaycastingScene.compute_signed_distance (float32)", args.n, s,
                   np.sum((sda <= 0) != truth),
                   {"generic_sign_disagreements_with_ours": int(np.sum((sd < 0) != ours.inside))})

        if "trimesh" not in args.skip:
            tm = trimesh.Trimesh(v, f, process=False)
            m = min(args.trimesh_n, args.n)
            sd, s = timed(trimesh.proximity.signed_distance, tm, pts[:m])
            sda = trimesh.proximity.signed_distance(tm, adv)
            report("trimesh proximity.signed_distance", m, s, np.sum((sda >= 0) != truth),
                   {"generic_sign_disagreements_with_ours":
                    int(np.sum((sd > 0) != ours.inside[:m]))})
            ins, s = timed(tm.contains, pts[:m])
            report("trimesh Trimesh.contains", m, s, np.sum(tm.contains(adv) != truth))


if __name__ == "__main__":
    main()
