"""Agreement and speed of `cga_collide.Robot` against pinocchio + coal, robot by robot.

Robots: the Franka Panda (9 STL link meshes, finger boxes, an SRDF; and its primitive model
of cylinders and spheres, `panda_primitives`) and the UR5 (7 STL meshes, an SRDF) of the
`example-robot-data` wheel, and the KUKA iiwa (8 STL meshes, no SRDF)
of the `pybullet` wheel's `pybullet_data`; all read at run time, nothing of them committed. Configurations are sampled uniformly within
the joint limits. Both sides test the same link pairs: ours (every pair of links on different,
non-adjacent bodies, minus the SRDF's `disable_collisions`), given to pinocchio as the
collision pairs of the links' geometry objects.

Agreement: on configurations far from contact (no pair within 0.1 mm that does not touch,
by our exact `pairs_within_distance`), the colliding link pairs must equal those of
pinocchio's `computeCollisions`, configuration by configuration.

Each robot is checked against itself and against an environment of a table, a box, a ball
and a cylinder (the same shapes given to pinocchio as geometry objects on the universe). The
far-from-contact filter measures the cylinder's clearance on its capsule (a superset, so the
filter only sets more configurations aside).

Speed, one thread, per configuration, interleaved in rounds over the same configurations (so
that a changing load on the machine hits both sides alike): ours for all pairs and to the first
hit, pinocchio's `computeCollisions` (all pairs) and its broad-phase manager (dynamic AABB
tree; all pairs); the nearest pair (ours, certified) against `computeDistances` (self pairs)
on the first `--distance-configs` configurations. Each figure is the median over the rounds.

    pip install pin example-robot-data pybullet numpy   # plus cga_collide (maturin develop)
    RAYON_NUM_THREADS=1 python cga-collide/benches/robot_pinocchio.py --configs 10000
"""

import argparse
import json
import os
import pathlib
import sysconfig
import time

import numpy as np


def _erd(folder, urdf, srdf):
    for base in {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]}:
        share = pathlib.Path(base) / "cmeel.prefix" / "share"
        robot = share / "example-robot-data" / "robots" / folder
        if robot.is_dir():
            return robot / "urdf" / urdf, robot / "srdf" / srdf, share
    raise FileNotFoundError("example-robot-data is not installed (pip install example-robot-data)")


def panda_files():
    """The Panda's URDF, SRDF and package directory inside the example-robot-data wheel."""
    return _erd("panda_description", "panda.urdf", "panda.srdf")


def panda_primitive_files():
    """The Panda's primitive model (each link a cylinder between two spheres: a capsule as
    URDF writes it) in example-robot-data, with the same SRDF."""
    urdf, srdf, share = panda_files()
    return urdf.parent / "panda_collision.urdf", srdf, share


def ur5_files():
    """The UR5's URDF, SRDF and package directory inside the example-robot-data wheel."""
    return _erd("ur_description", "ur5_robot.urdf", "ur5.srdf")


def iiwa_files():
    """The KUKA iiwa's URDF (no SRDF) and its folder inside the pybullet wheel."""
    try:
        import pybullet_data
    except ImportError as e:
        raise FileNotFoundError("pybullet is not installed (pip install pybullet)") from e
    folder = pathlib.Path(pybullet_data.getDataPath()) / "kuka_iiwa"
    return folder / "model.urdf", None, folder


ROBOTS = {
    "panda": panda_files,
    "panda_primitives": panda_primitive_files,
    "ur5": ur5_files,
    "iiwa": iiwa_files,
}

# The environment: (kind, centre, size): a table top, a box, a ball, an upright cylinder.
ENVIRONMENT = [
    ("box", (0.55, 0.0, 0.25), (0.4, 0.8, 0.04)),
    ("box", (-0.35, 0.35, 0.5), (0.2, 0.2, 0.2)),
    ("ball", (0.3, -0.4, 0.6), 0.1),
    ("cylinder", (-0.3, -0.4, 0.35), (0.08, 0.5)),
]


def load(name):
    """Our robot (with the environment set) and the same files for pinocchio."""
    import cga_collide as cc

    urdf, srdf, share = ROBOTS[name]()
    robot = cc.Robot.from_urdf(
        str(urdf), package_dirs=[str(share)], srdf=None if srdf is None else str(srdf)
    )
    return robot, urdf, share


def our_scene(capsules=False):
    """The environment as a scene (`capsules`: each cylinder as its capsule)."""
    import cga_collide as cc

    scene = cc.Scene()
    for kind, c, size in ENVIRONMENT:
        c = np.array(c)
        if kind == "box":
            scene.add_shape(cc.Cuboid.axis_aligned(c, np.array(size) / 2))
        elif kind == "ball":
            scene.add_shape(cc.Ball(c, size))
        else:
            r, h = size
            a, b = c - [0, 0, h / 2], c + [0, 0, h / 2]
            scene.add_shape(cc.Capsule(a, b, r) if capsules else cc.Cylinder(a, b, r))
    return scene


class Pinocchio:
    """pinocchio + coal on the same URDF and the same link pairs."""

    def __init__(self, urdf, share, allowed_pairs, environment=False):
        """`allowed_pairs`: the link pairs to test; `environment`: also every geometry
        object against every object of `ENVIRONMENT` (on the universe)."""
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
        if environment:
            import coal

            for e, (kind, c, size) in enumerate(ENVIRONMENT):
                shape = {
                    "box": lambda: coal.Box(*size),
                    "ball": lambda: coal.Sphere(size),
                    "cylinder": lambda: coal.Cylinder(*size),
                }[kind]()
                placement = pin.SE3(np.eye(3), np.array(c, dtype=float))
                g = self.geom.addGeometryObject(
                    pin.GeometryObject(f"env:{e}", 0, 0, placement, shape)
                )
                for i in range(n):
                    self.geom.addCollisionPair(pin.CollisionPair(i, g))
                    self.pair_links.append(tuple(sorted((link_of[i], f"env:{e}"))))
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

    def time_distances(self, qs):
        pin, m, d, g, gd = self.pin, self.model, self.data, self.geom, self.gdata
        t = time.perf_counter()
        for q in qs:
            pin.computeDistances(m, d, g, gd, q)
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


def agreement(robot, peer, qs, near=1e-4, against="self", filter_robot=None):
    """(far configurations, mismatches among them, near ones, colliding far ones).
    `filter_robot` (default `robot`) answers the far-from-contact filter."""
    import cga_collide as cc

    near_robot = robot if filter_robot is None else filter_robot
    far = mismatches = colliding = 0
    examples = []
    undecided = 0
    for q in qs:
        ours = robot.colliding_pairs(q, against=against)
        try:
            near_pairs = near_robot.pairs_within_distance(q, near, against=against)
        except cc.CgaError:
            # A clearance the exact tests cannot decide yet (two cylinders about `near`
            # apart): set aside like a near configuration, and counted.
            undecided += 1
            continue
        if near_pairs != ours:
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
        "far_filter_undecided": undecided,
        "examples": examples,
    }


def per_config(f, qs):
    t = time.perf_counter()
    for q in qs:
        f(q)
    return (time.perf_counter() - t) / len(qs) * 1e6


def timings(robot, peer, qs, against="self", rounds=5, distance_configs=0):
    """Medians over `rounds` rounds, each timing every side on the same configurations."""
    pqs = [peer.q_of(robot.joint_names, q) for q in qs]
    rows = []
    for _ in range(rounds):
        row = {
            "ours_all_pairs_us": per_config(lambda q: robot.colliding_pairs(q, against), qs),
            "ours_first_hit_us": per_config(lambda q: robot.collides(q, against), qs),
            "pinocchio_computeCollisions_us": peer.time_plain(pqs),
            "pinocchio_broad_phase_us": peer.time_broad_phase(pqs),
        }
        t = time.perf_counter()
        batch = robot.colliding_pairs_batch(qs, against)
        row["ours_batch_all_cores_us"] = (time.perf_counter() - t) / len(qs) * 1e6
        assert len(batch) == len(qs)
        if distance_configs:
            few = qs[:distance_configs]
            row["ours_nearest_us"] = per_config(lambda q: robot.nearest(q), few)
            row["pinocchio_computeDistances_us"] = peer.time_distances(pqs[:distance_configs])
        row["ratio_all_pairs_to_broad_phase"] = (
            row["ours_all_pairs_us"] / row["pinocchio_broad_phase_us"]
        )
        if distance_configs:
            row["ratio_nearest_to_computeDistances"] = (
                row["ours_nearest_us"] / row["pinocchio_computeDistances_us"]
            )
        rows.append(row)
    return {k: float(np.median([r[k] for r in rows])) for k in rows[0]}


def main():
    import cga_collide

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--configs", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--robots", default="panda,panda_primitives,ur5,iiwa")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--timing-configs", type=int, default=2000)
    ap.add_argument("--distance-configs", type=int, default=100)
    # The environment rows cost far more per configuration (a link near the cylinder takes
    # milliseconds: the exact triangle-cylinder test), so they may be given fewer.
    ap.add_argument("--env-configs", type=int, default=None,
                    help="configurations for the environment rows' agreement (default --configs)")
    ap.add_argument("--env-timing-configs", type=int, default=None,
                    help="configurations timed in the environment rows (default --timing-configs)")
    args = ap.parse_args()
    out = []
    for name in args.robots.split(","):
        robot, urdf, share = load(name)
        filter_robot = load(name)[0]
        robot.set_environment(our_scene())
        filter_robot.set_environment(our_scene(capsules=True))
        qs = sample(robot, args.configs, args.seed)
        for against in ("self", "environment"):
            if against == "self":
                peer = Pinocchio(urdf, share, robot.allowed_pairs())
                checked, timed = qs, qs[: args.timing_configs]
            else:  # every link's geometry against every environment object
                peer = Pinocchio(urdf, share, [], environment=True)
                checked = qs[: args.env_configs or args.configs]
                timed = qs[: args.env_timing_configs or args.timing_configs]
            out.append(
                {
                    "robot": name,
                    "against": against,
                    "pairs": robot.pairs_checked(against),
                    "pinocchio_geometry_pairs": len(peer.pair_links),
                    "agreement": agreement(robot, peer, checked, against=against,
                                           filter_robot=filter_robot),
                    "load_average_1_5_15": os.getloadavg(),
                    "timing": timings(robot, peer, timed, against, args.rounds,
                                      args.distance_configs if against == "self" else 0),
                }
            )
            print(json.dumps(out[-1]), flush=True)
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
