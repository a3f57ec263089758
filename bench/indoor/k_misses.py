#!/usr/bin/env python3
"""Where K's misses are: bench/indoor/k_misses.py MAP.png OUT/world.json [misses.png]

Re-rasterises the units and doors of an indoor run's world.json (1-cell wall band inside each
unit, door rectangles 4 cells deep: the defaults of stdlib/indoor/likelihood.h), classifies the
map with the `drawn` thresholds (>= 250 free, < 89 occupied, the one grey painting >= 5 % of the
image unknown, other greys occupied), and prints the misses by observed -> predicted class and by
distance to the nearest unit edge. The rasterisation is the script's own (cell centres in
polygons), so its K differs from world.json's cell_prediction_rate in the 3rd decimal; the
binary's exact counts are world.json's cells_<observed>_predicted_<predicted> metrics.
Optional: misses.png, the misses in colour over the map. Needs numpy, scipy, PIL, matplotlib.
"""
import json
import sys

import numpy as np
from matplotlib.path import Path
from PIL import Image
from scipy import ndimage

FREE, UNKNOWN, OCC = 0, 1, 2


def classify(img):
    obs = np.full(img.shape, UNKNOWN, np.uint8)
    obs[img >= 250] = FREE
    obs[img < 89] = OCC
    grey = (img >= 89) & (img < 250)
    obs[grey] = OCC
    vals, cnt = np.unique(img[grey], return_counts=True)
    if len(vals) and cnt.max() >= 0.05 * img.size:
        obs[img == vals[cnt.argmax()]] = UNKNOWN
    return obs


def shrunk(corners, t):
    c = np.array(corners, float)
    ctr = c.mean(0)
    e1, e2 = c[1] - c[0], c[3] - c[0]
    l1, l2 = np.linalg.norm(e1), np.linalg.norm(e2)
    a, b = e1 / l1, e2 / l2
    return [ctr + s1 * a * (l1 / 2 - t) + s2 * b * (l2 / 2 - t) for s1, s2 in ((-1, -1), (1, -1), (1, 1), (-1, 1))]


def predict(world, h, w, band=1.0):
    """Predicted classes and the units' union; `band`: wall band width inside each unit, cells."""
    yy, xx = np.mgrid[0:h, 0:w]
    pts = np.stack([xx.ravel() + 0.5, yy.ravel() + 0.5], 1)
    area = np.zeros(h * w, bool)
    wall = np.zeros(h * w, bool)
    door = np.zeros(h * w, bool)
    for u in world["units"]:
        outer = Path(u["corners"]).contains_points(pts)
        inner = Path(shrunk(u["corners"], band)).contains_points(pts)
        area |= outer
        wall |= outer & ~inner
    for d in world["doors"]:
        p0, p1 = np.array(d["segment"][0], float), np.array(d["segment"][1], float)
        v = p1 - p0
        length = np.linalg.norm(v)
        if length == 0:
            continue
        n = np.array([-v[1], v[0]]) / length * 2.0
        door |= Path([p0 - n, p1 - n, p1 + n, p0 + n]).contains_points(pts)
    pred = np.where(door, FREE, np.where(wall, OCC, np.where(area, FREE, UNKNOWN)))
    return pred.reshape(h, w), area.reshape(h, w)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    img = np.array(Image.open(sys.argv[1]).convert("L"))
    world = json.load(open(sys.argv[2]))
    obs = classify(img)
    pred, inside = predict(world, *img.shape)
    k = float((pred == obs).mean())
    print(f"K (script) {k:.4f}; world.json {world['metrics'].get('cell_prediction_rate', float('nan')):.4f}; "
          f"cells {img.size}, misses {int((pred != obs).sum())}")
    d_in = ndimage.distance_transform_edt(inside)
    d_out = ndimage.distance_transform_edt(~inside)
    names = {FREE: "free", UNKNOWN: "unknown", OCC: "occupied"}
    pnames = {FREE: "free", UNKNOWN: "unknown", OCC: "wall"}
    print("| observed -> predicted | cells | within 10 cells of a unit edge | farther |")
    print("|---|---:|---:|---:|")
    for o in (FREE, UNKNOWN, OCC):
        for p in (FREE, UNKNOWN, OCC):
            if o == p:
                continue
            m = (obs == o) & (pred == p)
            d = np.where(inside, d_in, d_out)[m]
            print(f"| {names[o]} -> {pnames[p]} | {int(m.sum())} | {int((d < 10).sum())} | {int((d >= 10).sum())} |")
    if len(sys.argv) > 3:
        rgb = np.full(img.shape + (3,), 255, np.uint8)
        rgb[obs == OCC] = (0, 0, 0)
        rgb[obs == UNKNOWN] = (200, 200, 200)
        colours = {(FREE, UNKNOWN): (255, 0, 0), (FREE, OCC): (255, 160, 0), (OCC, FREE): (0, 0, 255),
                   (OCC, UNKNOWN): (0, 160, 255), (UNKNOWN, FREE): (0, 180, 0), (UNKNOWN, OCC): (160, 0, 160)}
        for (o, p), c in colours.items():
            rgb[(obs == o) & (pred == p)] = c
        Image.fromarray(rgb).save(sys.argv[3])


if __name__ == "__main__":
    main()
