#!/usr/bin/env python3
"""Writes the hand-built table-top example scenes (scene.json schema) in this folder.

Each scene is described in the TABLE frame (z up, table top at z = 0): object
centre, full size, yaw about z and an optional tilt about the object's x axis.
This script only converts to the camera frame the schema asks for and adds the
eight OBB corners as keypoints (exact projections plus 0.3 px seeded noise).
The evidence each scene is meant to produce is written down independently in
tests/tabletop/test_examples.cpp. Run: python3 make_examples.py
"""
import json
import math
import os
import random

CAMERA = {"fx": 615.0, "fy": 615.0, "cx": 320.0, "cy": 240.0, "width": 640, "height": 480}


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def matvec(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def rotz(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]


def rotx(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]


def normalize(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def quat(r):
    """Unit quaternion [w, x, y, z] of a rotation matrix (Shepperd's method)."""
    tr = r[0][0] + r[1][1] + r[2][2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = [0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s]
    elif r[0][0] > r[1][1] and r[0][0] > r[2][2]:
        s = math.sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]) * 2
        q = [(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s]
    elif r[1][1] > r[2][2]:
        s = math.sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]) * 2
        q = [(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s]
    else:
        s = math.sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]) * 2
        q = [(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s]
    if q[0] < 0:
        q = [-x for x in q]
    return q


def camera_looking_at_table(eye):
    """Table pose in the camera frame for a camera at `eye` (table frame) aimed at the origin."""
    z = normalize([-c for c in eye])
    x = normalize(cross(z, [0.0, 0.0, 1.0]))
    y = cross(z, x)
    r_table_cam = [[x[i], y[i], z[i]] for i in range(3)]
    r_cam_table = transpose(r_table_cam)
    t_cam_table = [-c for c in matvec(r_cam_table, eye)]
    return r_cam_table, t_cam_table


def rnd(v, nd=9):
    return [round(x, nd) for x in v]


def build(objects, eye, seed):
    rng = random.Random(seed)
    r_ct, t_ct = camera_looking_at_table(eye)
    out = []
    for o in objects:
        r_to = matmul(rotz(o.get("yaw", 0.0)), rotx(o.get("tilt", 0.0)))
        r_co = matmul(r_ct, r_to)
        t_co = [a + b for a, b in zip(matvec(r_ct, o["center"]), t_ct)]
        half = [s / 2 for s in o["size"]]
        model, image = [], []
        for k in range(8):
            p = [half[i] if (k >> i) & 1 else -half[i] for i in range(3)]
            pc = [a + b for a, b in zip(matvec(r_co, p), t_co)]
            u = CAMERA["fx"] * pc[0] / pc[2] + CAMERA["cx"] + rng.gauss(0.0, 0.3)
            v = CAMERA["fy"] * pc[1] / pc[2] + CAMERA["cy"] + rng.gauss(0.0, 0.3)
            model.append(rnd(p, 6))
            image.append(rnd([u, v], 3))
        out.append({"id": o["id"], "model": o.get("model", "box"), "size": o["size"],
                    "pose": {"t": rnd(t_co), "q": rnd(quat(r_co))},
                    "keypoints": {"model": model, "image": image}})
    return {"camera": CAMERA, "table": {"pose": {"t": rnd(t_ct), "q": rnd(quat(r_ct))}}, "objects": out}


EYE = [0.0, -0.6, 0.7]

SCENES = {
    # Seed situation: 0-5 stable, 0-3 on the table, 4 on 3, 5 hovering,
    # 6 unstable (tilted 35 deg) resting on the table and intersecting 1.
    "seed_example.json": [
        {"id": "0", "model": "cereal", "center": [-0.30, -0.10, 0.075], "size": [0.10, 0.08, 0.15], "yaw": 10},
        {"id": "1", "model": "tea", "center": [-0.10, -0.15, 0.05], "size": [0.12, 0.12, 0.10]},
        {"id": "2", "model": "rice", "center": [0.10, -0.15, 0.03], "size": [0.08, 0.16, 0.06], "yaw": 30},
        {"id": "3", "model": "tray", "center": [0.20, 0.10, 0.025], "size": [0.20, 0.15, 0.05], "yaw": -15},
        {"id": "4", "model": "soap", "center": [0.21, 0.11, 0.09], "size": [0.10, 0.08, 0.08], "yaw": 5},
        {"id": "5", "model": "cube", "center": [-0.20, 0.15, 0.20], "size": [0.08, 0.08, 0.08]},
        {"id": "6", "model": "bottle", "center": [-0.10, -0.12, 0.0745], "size": [0.06, 0.06, 0.14], "tilt": 35},
    ],
    # A simple stack of three boxes (2 mm gaps, a few degrees of yaw) and one box beside it.
    "stack.json": [
        {"id": "base", "center": [0.0, 0.0, 0.03], "size": [0.20, 0.16, 0.06], "yaw": 5},
        {"id": "middle", "center": [0.01, 0.0, 0.062 + 0.04], "size": [0.14, 0.12, 0.08], "yaw": -3},
        {"id": "top", "center": [0.0, 0.01, 0.144 + 0.025], "size": [0.08, 0.08, 0.05], "yaw": 20},
        {"id": "beside", "center": [0.25, 0.0, 0.05], "size": [0.06, 0.06, 0.10]},
    ],
    # A single level: four boxes on the table; two flat boxes side by side with
    # exactly parallel edges, 2 mm apart (contact, not support).
    "single_level.json": [
        {"id": "flat_a", "center": [-0.08, 0.0, 0.02], "size": [0.12, 0.16, 0.04]},
        {"id": "flat_b", "center": [0.042, 0.02, 0.02], "size": [0.12, 0.16, 0.04]},
        {"id": "can", "center": [-0.25, -0.10, 0.06], "size": [0.07, 0.07, 0.12]},
        {"id": "carton", "center": [0.25, 0.15, 0.10], "size": [0.07, 0.07, 0.20], "yaw": 40},
    ],
}

if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for i, (name, objs) in enumerate(sorted(SCENES.items())):
        with open(os.path.join(here, name), "w") as f:
            json.dump(build(objs, EYE, seed=i + 1), f, indent=1)
            f.write("\n")
