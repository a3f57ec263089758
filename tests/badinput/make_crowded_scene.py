#!/usr/bin/env python3
"""A table-top scene of N mutually intersecting boxes (issue 16: its initial MC-SAT ran for
more than 10 minutes and ignored SIGINT). Copies the first object of SCENE N times, each
shifted by a tenth of a millimetre, so every pair of boxes overlaps.
    make_crowded_scene.py SCENE N > crowded.json"""
import copy
import json
import sys

scene = json.load(open(sys.argv[1]))
n = int(sys.argv[2])
first = scene["objects"][0]
objects = []
for i in range(n):
    o = copy.deepcopy(first)
    o["id"] = str(i)
    t = o["pose"]["t"]
    o["pose"]["t"] = [t[0] + 1e-4 * (i % 10), t[1] + 1e-4 * (i // 10 % 10), t[2] + 1e-4 * (i // 100)]
    objects.append(o)
scene["objects"] = objects
json.dump(scene, sys.stdout)
