"""Agreement and speed of `cga_collide.Robot` against pinocchio + coal on the Franka Panda.

The Panda (9 STL link meshes, finger boxes, an SRDF) comes from the `example-robot-data`
wheel at run time; nothing of it is committed. Configurations are sampled uniformly within
the joint limits. Both sides test the same link pairs: ours (every pair of links on different,
non-adjacent bodies, minus the SRDF's `disable_collisions`), given to pinocchio as the
collision pairs of the links' geometry objects.

Agreement: on configurations far from contact (no pair within 0.1 mm that does not touch,
by our exact `pairs_within_distance`), the colliding link pairs must equal those of
pinocchio's `computeCollisions`, configuration by configuration.

Speed, one thread, per configuration in the same run: ours for all pairs and to the first
hit, pinocchio's `computeCollisions` (all pairs) and its broad-phase manager (dynamic AABB
tree; all pairs).

    pip install pin example-robot-data numpy   # plus the cga_collide package (maturin develop)
    RAYON_NUM_THREADS=1 python cga-collide/benches/robot_pinocchio.py --configs 10000
"""

import argparse
import json
import pathlib
import sysconfig
import time

import numpy as np


def panda_files():
    """The Panda's URDF, SRDF and package directory inside the example-robot-data wheel."""
    for base in {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]}:
        share = pathlib.Path(base) / "cmeel.prefix" / "share"
        robot = share / "example-robot-data" / "robots" / "panda_description"
        if robot.is_dir():
            return robot / "urdf" / "panda.urdf", robot / "srdf" / "panda.srdf", share
    raise FileNotFoundError("example-robot-data is not installed (pip install example-robot-data)")


class Pinocchio:
    """pinocchio + coal on the same URDF and the same link pairs."""

    def __init__(self, urdf, share, allowed_pairs):
        import pinocchio as pin

        self.pin = pin
        self.model = pin.buildModelFromUrdf(str(urdf))
        self.geom = pin.buildGeomFromUrdf(
            self.model, str(urdf), pin.GeometryType.COLLISION, package_dirs=[str(share)]
        )
        link_of = [self.model.frames[g.parentFrame].name for g in self.geom.geometryObjects]
        allowed = {tuple(sorted(p)) for p in allowed_pairs}
        self.pair_links = []
        n = len(link_of)
        for i in range(n):
            for j in range(i + 1, n):
                key = tuple(sorted((link_of[i], link_of[j])))
                if key in allowed:
                    self.geom.addCollisionPair(pin.CollisionPair(i, j))
                    self.pair_links.append(key)
        self.data = self.model.createData()
        self.gdata = pin.GeometryData(self.geom)
        self.manager = pin.BroadPhaseManager_DynamicAABBTreeCollisionManager(
            self.model, self.geom, self.gdata
        )

    def q_of(self, joint_names, q):
        """Our configuration (in `joint_names` order) as pinocchio's q."""
        out = self.pin.neutral(self.model)
        for name, value in zip(joint_names, q):
            out[self.model.joints[self.model.getJointId(name)].idx_q] = value
        return out

    def colliding_pairs(self, q):
        self.pin.computeCollisions(self.model, self.data, self.geom, self.gdata, q, False)
        hits = {
            self.pair_links[k]
            for k, r in enumerate(self.gdata.collisionResults)
            if r.isCollision()
        }
        return sorted(hits)

    def time_plain(self, qs):
        pin, m, d, g, gd = self.pin, self.model, self.data, self.geom, self.gdata
        t = time.perf_counter()
        for q in qs:
            pin.computeCollisions(m, d, g, gd, q, False)
        return (time.perf_counter() - t) / len(qs) * 1e6

    def time_broad_phase(self, qs):
        pin, m, d, mgr = self.pin, self.model, self.data, self.manager
        t = time.perf_counter()
        for q in qs:
            pin.computeCollisions(m, d, mgr, q, False)
        return (time.perf_counter() - t) / len(qs) * 1e6


def sample(robot, k, seed):
    rng = np.random.default_rng(seed)
    lim = robot.joint_limits
    return rng.uniform(lim[:, 0], lim[:, 1], size=(k, robot.dof))


def agreement(robot, peer, qs, near=1e-4):
    """(far configurations, mismatches among them, near ones, colliding far ones)."""
    far = mismatches = colliding = 0
    examples = []
    for q in qs:
        ours = robot.colliding_pairs(q)
        if robot.pairs_within_distance(q, near) != ours:
            continue
        far += 1
        colliding += bool(ours)
        theirs = peer.colliding_pairs(peer.q_of(robot.joint_names, q))
        if [tuple(p) for p in ours] != theirs:
            mismatches += 1
            if len(examples) < 5:
                examples.append({"q": list(q), "ours": ours, "pinocchio": theirs})
    return {
        "configs": len(qs),
        "far": far,
        "colliding_far": colliding,
        "mismatches": mismatches,
        "examples": examples,
    }


def timings(robot, peer, qs):
    t = time.perf_counter()
    for q in qs:
        robot.colliding_pairs(q)
    ours_all = (time.perf_counter() - t) / len(qs) * 1e6
    t = time.perf_counter()
    for q in qs:
        robot.collides(q)
    ours_first = (time.perf_counter() - t) / len(qs) * 1e6
    pqs = [peer.q_of(robot.joint_names, q) for q in qs]
    t = time.perf_counter()
    batch = robot.colliding_pairs_batch(qs)
    ours_batch = (time.perf_counter() - t) / len(qs) * 1e6
    assert len(batch) == len(qs)
    return {
        "ours_all_pairs_us": ours_all,
        "ours_first_hit_us": ours_first,
        "ours_batch_all_cores_us": ours_batch,
        "pinocchio_computeCollisions_us": peer.time_plain(pqs),
        "pinocchio_broad_phase_us": peer.time_broad_phase(pqs),
    }


def main():
    import cga_collide

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--configs", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    urdf, srdf, share = panda_files()
    robot = cga_collide.Robot.from_urdf(str(urdf), package_dirs=[str(share)], srdf=str(srdf))
    peer = Pinocchio(urdf, share, robot.allowed_pairs())
    qs = sample(robot, args.configs, args.seed)
    out = {
        "robot": "panda (example-robot-data)",
        "pairs": len(robot.allowed_pairs()),
        "pinocchio_geometry_pairs": len(peer.pair_links),
        "agreement": agreement(robot, peer, qs),
        "timing": timings(robot, peer, qs),
    }
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
