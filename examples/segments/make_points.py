#!/usr/bin/env python3
"""Simulated 2D point clouds for the segments example (the product is C++; this only makes
the bundled data; standard library only). A room outline seen by a planar scanner: walls sampled every `spacing`
metres with Gaussian noise, a door gap, an inner partition wall, clutter points.

Writes room.txt (points, `x y` per line in metres) and room_truth.json (true segments and
their corners). Usage: python3 make_points.py [--seed 7] [--out DIR]
"""
import argparse
import json
import os

import math
import random


def walls():
    # A 6 m x 4 m room; the bottom wall has a 0.9 m door gap (x in [2.0, 2.9]); a 2 m
    # partition wall stands on the top wall at x = 4.
    return [
        ((0.0, 0.0), (2.0, 0.0)),   # 0 bottom, left of the door
        ((2.9, 0.0), (6.0, 0.0)),   # 1 bottom, right of the door
        ((6.0, 0.0), (6.0, 4.0)),   # 2 right
        ((6.0, 4.0), (0.0, 4.0)),   # 3 top
        ((0.0, 4.0), (0.0, 0.0)),   # 4 left
        ((4.0, 4.0), (4.0, 2.0)),   # 5 partition
    ]


CORNERS = [[0, 4], [1, 2], [2, 3], [3, 4]]  # the partition meets the top wall in a T, not a corner


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--spacing", type=float, default=0.05)
    ap.add_argument("--noise", type=float, default=0.01)
    ap.add_argument("--clutter", type=int, default=25)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    pts = []
    for a, b in walls():
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        n = int(round(length / args.spacing)) + 1
        for k in range(n):
            t = k / (n - 1)
            pts.append((a[0] + t * (b[0] - a[0]) + rng.gauss(0.0, args.noise),
                        a[1] + t * (b[1] - a[1]) + rng.gauss(0.0, args.noise)))
    # Clutter: uniform inside the room, away from the walls.
    for _ in range(args.clutter):
        pts.append((rng.uniform(0.3, 5.7), rng.uniform(0.3, 3.7)))
    rng.shuffle(pts)
    with open(os.path.join(args.out, "room.txt"), "w") as f:
        f.write("# Simulated room outline (examples/segments/make_points.py --seed %d): x y in metres\n" % args.seed)
        for x, y in pts:
            f.write("%.3f %.3f\n" % (x, y))
    truth = {
        "segments": [[a[0], a[1], b[0], b[1]] for a, b in walls()],
        "corners": CORNERS,
        "tolerances": {"distance_m": 0.15, "angle_deg": 5.0, "max_spurious": 3},
    }
    with open(os.path.join(args.out, "room_truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
