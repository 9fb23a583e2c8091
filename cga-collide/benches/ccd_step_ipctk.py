#!/usr/bin/env python3
"""Whole-step continuous collision with ipctk: `ipctk.compute_collision_free_stepsize` per scene.

Setup (once): python3 -m venv /tmp/venv-ccd && /tmp/venv-ccd/bin/pip install ipctk numpy

Run (with `--cga target/release/cga`, the same frames through this repository's exact whole
step in the same run; `cga ccd` reads the PLY itself, its time excludes reading):

    /tmp/venv-ccd/bin/python cga-collide/benches/ccd_step_ipctk.py [--repeat 3] [--cga PATH] \
        [--broad-phase hash-grid|sweep-and-prune|lbvh|brute-force] SCENE_DIR_OR_PLY_PAIR ...

A scene is a folder whose `frames/` (or itself) holds exactly two PLY files, the mesh at t = 0
and at t = 1 (sorted by name), same topology, every vertex moving linearly between them; or two
PLY paths given one after the other. PLY: ascii or binary (either byte order), `float` or
`double` coordinates (a float widens to a double exactly), extra vertex properties skipped,
faces as a list of vertex indices (triangles).

Per scene it prints the vertex/face counts and the time of `compute_collision_free_stepsize`
(minimum and median of `--repeat` runs, milliseconds; broad phase + Tight Inclusion narrow
phase with the CCD benchmark's settings: tolerance 1e-6, at most 1e6 iterations, minimum
distance 0) and the step size it returns (1.0: no collision over the step). Building the
`CollisionMesh` (edges, adjacency) is timed apart and not included. This is the ipctk side
only, to compare with the exact whole-step self-collision of the same frames.
"""

import argparse
import json
import pathlib
import subprocess
import statistics
import sys
import time

import numpy as np

try:
    import ipctk
except ImportError:  # pragma: no cover
    sys.exit("ipctk is missing: pip install ipctk numpy (see the top of this script)")

PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}


def read_ply(path):
    """(vertices (n, 3) float64, faces (m, 3) int32) of a triangle-mesh PLY."""
    data = pathlib.Path(path).read_bytes()
    end = data.index(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt = None
    elements = []  # [name, count, [(prop name, type) | (name, "list", count type, item type)]]
    for line in header:
        words = line.split()
        if not words:
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append([words[1], int(words[2]), []])
        elif words[0] == "property":
            if words[1] == "list":
                elements[-1][2].append((words[4], "list", words[2], words[3]))
            else:
                elements[-1][2].append((words[2], words[1]))
    body = data[end:]
    vertices = faces = None
    if fmt == "ascii":
        tokens = body.split()
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for p in props:
                    if p[1] == "list":
                        k = int(tokens[pos]); pos += 1
                        row.append([int(t) for t in tokens[pos : pos + k]]); pos += k
                    else:
                        row.append(float(tokens[pos])); pos += 1
                rows.append(row)
            if name == "vertex":
                names = [p[0] for p in props]
                idx = [names.index(a) for a in "xyz"]
                vertices = np.array([[r[i] for i in idx] for r in rows], dtype=np.float64)
            elif name == "face":
                faces = np.array([r[0] for r in rows], dtype=np.int32)
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        pos = 0
        for name, count, props in elements:
            if all(p[1] != "list" for p in props):
                dt = np.dtype([(p[0], order + PLY_TYPES[p[1]]) for p in props])
                arr = np.frombuffer(body, dtype=dt, count=count, offset=pos)
                pos += dt.itemsize * count
                if name == "vertex":
                    vertices = np.stack([arr[a].astype(np.float64) for a in "xyz"], axis=1)
            else:
                # Faces: fast path for "uchar count, 3 indices" rows, else row by row.
                (pname, _, ctype, itype), *rest = props
                if rest:
                    raise ValueError(f"{path}: list element with extra properties")
                cdt = np.dtype(order + PLY_TYPES[ctype])
                idt = np.dtype(order + PLY_TYPES[itype])
                row = np.dtype([("n", cdt), ("v", idt, (3,))])
                arr = np.frombuffer(body, dtype=row, count=count, offset=pos)
                if np.all(arr["n"] == 3):
                    pos += row.itemsize * count
                    out = arr["v"].astype(np.int32)
                else:
                    out = []
                    for _ in range(count):
                        k = int(np.frombuffer(body, cdt, 1, pos)[0]); pos += cdt.itemsize
                        out.append(np.frombuffer(body, idt, k, pos)); pos += idt.itemsize * k
                    out = np.array(out, dtype=np.int32)
                if name == "face":
                    faces = out
    return vertices, faces


def scenes(args):
    out = []
    paths = [pathlib.Path(a) for a in args]
    i = 0
    while i < len(paths):
        p = paths[i]
        if p.is_dir():
            frames = p / "frames" if (p / "frames").is_dir() else p
            plys = sorted(frames.glob("*.ply"))
            if len(plys) != 2:
                sys.exit(f"{frames}: expected two PLY files, found {len(plys)}")
            out.append((p.name, plys[0], plys[1]))
            i += 1
        else:
            out.append((p.stem, p, paths[i + 1]))
            i += 2
    return out


BROAD = {
    "hash-grid": lambda: ipctk.HashGrid(),
    "sweep-and-prune": lambda: ipctk.SweepAndPrune(),
    "lbvh": lambda: ipctk.LBVH(),
    "brute-force": lambda: ipctk.BruteForce(),
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--broad-phase", choices=sorted(BROAD), default="hash-grid")
    ap.add_argument(
        "--cga",
        help="also time `cga ccd --json FRAME0 FRAME1` (this repository's exact whole step: every "
        "colliding pair and the first contact) on the same frames, in the same run",
    )
    args = ap.parse_args()
    ipctk.set_logger_level(ipctk.LoggerLevel.error)
    narrow = ipctk.TightInclusionCCD(tolerance=1e-6, max_iterations=1_000_000)

    ours_cols = " cga ccd min ms | pairs (vf + ee) | ratio |" if args.cga else ""
    print(
        "| scene | vertices | faces | edges | mesh build ms | step min ms | step median ms "
        f"| step size |{ours_cols}"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|" + ("---:|---:|---:|" if args.cga else ""))
    for name, f0, f1 in scenes(args.scenes):
        v0, faces = read_ply(f0)
        v1, faces1 = read_ply(f1)
        if v0.shape != v1.shape or not np.array_equal(faces, faces1):
            sys.exit(f"{name}: the two frames differ in topology")
        v0 = np.asfortranarray(v0)
        v1 = np.asfortranarray(v1)
        t = time.perf_counter()
        fa = np.asfortranarray(faces)
        edges = np.asfortranarray(ipctk.edges(fa))
        mesh = ipctk.CollisionMesh(v0, edges, fa)
        build_ms = (time.perf_counter() - t) * 1e3
        times = []
        step = None
        for _ in range(args.repeat):
            broad = BROAD[args.broad_phase]()
            t = time.perf_counter()
            step = ipctk.compute_collision_free_stepsize(
                mesh, v0, v1, min_distance=0.0, broad_phase=broad, narrow_phase_ccd=narrow
            )
            times.append((time.perf_counter() - t) * 1e3)
        ours = ""
        if args.cga:
            best, pairs = float("inf"), None
            for _ in range(args.repeat):
                out = subprocess.run(
                    [args.cga, "ccd", "--json", str(f0), str(f1)],
                    check=True, capture_output=True, text=True,
                )
                report = json.loads(out.stdout)
                best = min(best, report["millis"])
                pairs = len(report["vertex_face"]) + len(report["edge_edge"])
            ours = f" {best:.1f} | {pairs} | {best / min(times):.2f} |"
        print(
            f"| {name} | {len(v0)} | {len(faces)} | {len(edges)} | {build_ms:.1f} | "
            f"{min(times):.1f} | {statistics.median(times):.1f} | {step:.6g} |{ours}"
        )


if __name__ == "__main__":
    main()
