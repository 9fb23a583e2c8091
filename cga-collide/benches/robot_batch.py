"""How a batch of configurations scales with the cores: `colliding_pairs_batch` (self and
environment) on `--configs` configurations of each robot of `robot_pinocchio.py`, timed with
the thread count rayon is given (`RAYON_NUM_THREADS`); run it once per thread count.

    for t in 1 2; do RAYON_NUM_THREADS=$t python cga-collide/benches/robot_batch.py; done
"""

import argparse
import json
import os
import pathlib
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import robot_pinocchio as bench  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--configs", type=int, default=100_000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--robots", default="panda,panda_primitives,ur5,iiwa")
    # Against the environment a link near the cylinder costs milliseconds (the exact
    # triangle-cylinder test): "both" may be given fewer configurations.
    ap.add_argument("--against", default="self,both")
    ap.add_argument("--both-configs", type=int, default=None,
                    help="configurations for against='both' (default --configs)")
    args = ap.parse_args()
    threads = os.environ.get("RAYON_NUM_THREADS", "all")
    for name in args.robots.split(","):
        robot = bench.load(name)[0]
        robot.set_environment(bench.our_scene())
        qs = bench.sample(robot, args.configs, args.seed)
        for against in args.against.split(","):
            if against == "both" and args.both_configs:
                qs_used = qs[: args.both_configs]
            else:
                qs_used = qs
            t = time.perf_counter()
            hits = robot.collides_batch(qs_used, against)
            first = time.perf_counter() - t
            t = time.perf_counter()
            pairs = robot.colliding_pairs_batch(qs_used, against)
            every = time.perf_counter() - t
            row = {
                "robot": name,
                "against": against,
                "threads": threads,
                "configs": len(qs_used),
                "load_average": os.getloadavg()[0],
                "colliding": int(hits.sum()),
                "first_hit_s": first,
                "all_pairs_s": every,
            }
            assert sum(bool(p) for p in pairs) == row["colliding"]
            print(json.dumps(row), flush=True)


if __name__ == "__main__":
    main()
