#!/usr/bin/env python3
"""How far K can rise around a run's units: bench/indoor/k_oracles.py MAP.png OUT/world.json

Takes an indoor run's world as it is and asks what extra world content, or moved unit edges,
could add to the cell prediction rate K, each chosen by an oracle that sees the observed map:

* furniture: every 8-connected blob of non-free cells (occupied or unknown) inside the units'
  free part gets the box over it that gains most of three: none, a solid box predicting its
  majority class (occupied or unknown), or a hollow box (a 1-cell occupied rim around an unknown
  inside, the way a laser sees a table or a cupboard). "closing 1" first joins blobs one cell
  apart (fewer, larger boxes);
* wall bands: the band inside each unit 1, 1.5 or 2 cells wide, and optionally one more occupied
  cell outside every unit;
* unit edges: each side of each unit moved up to 3 cells along its normal where that raises K
  (coordinate ascent, two sweeps): how far the run's rectangles are from a local optimum of K.

The first two are upper estimates for a world model with such objects: the oracle picks each
box knowing the answer and pays nothing for it, and a sampler would also have to find them. Prints K
and the misses allowed by K >= 0.95 first. Uses k_misses.py's classification and rasterisation.
Needs numpy, scipy, PIL, matplotlib.
"""
import json
import sys

import numpy as np
from PIL import Image
from matplotlib.path import Path
from scipy import ndimage

from k_misses import FREE, OCC, UNKNOWN, classify, predict, shrunk


def furniture_gain(obs, interior, closing):
    """Total K gain (cells) of the best box per blob, and the number of boxes used."""
    mask = interior & (obs != FREE)
    if closing:
        mask = ndimage.binary_closing(mask, iterations=closing) & interior
    labels, _ = ndimage.label(mask, structure=np.ones((3, 3)))
    gain, boxes = 0, 0
    for sl in ndimage.find_objects(labels):
        o, inside = obs[sl], interior[sl]
        rim = np.zeros(o.shape, bool)
        rim[0, :] = rim[-1, :] = rim[:, 0] = rim[:, -1] = True
        free = int(((o == FREE) & inside).sum())
        solid = max(int(((o == OCC) & inside).sum()), int(((o == UNKNOWN) & inside).sum())) - free
        hollow = int(((o == OCC) & rim & inside).sum() + ((o == UNKNOWN) & ~rim & inside).sum()) - free
        best = max(solid, hollow)
        if best > 0:
            gain += best
            boxes += 1
    return gain, boxes


def wall_band_k(obs, world, band, outer):
    pred, area = predict(world, *obs.shape, band=band)
    if outer:  # cells just outside every unit read as the outer half of a wall
        pred = pred.copy()
        pred[ndimage.binary_dilation(area, iterations=outer) & ~area & (pred == UNKNOWN)] = OCC
    return float((pred == obs).mean())


def edge_gain(obs, world, step=3, sweeps=2):
    """Coordinate ascent on the units' edges: each side of each unit moved -step..step cells
    along its normal where that raises the cell hits, the other units and the doors fixed."""
    h, w = obs.shape
    pts = np.stack(np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5), -1)  # (h, w, 2): x, y

    def masks(corners, y0, y1, x0, x1):
        p = pts[y0:y1, x0:x1].reshape(-1, 2)
        outer = Path(corners).contains_points(p)
        inner = Path(shrunk(corners, 1.0)).contains_points(p)
        return outer.reshape(y1 - y0, x1 - x0), (outer & ~inner).reshape(y1 - y0, x1 - x0)

    units = [np.array(u["corners"], float) for u in world["units"]]
    area = [masks(c, 0, h, 0, w)[0] for c in units]
    band = [masks(c, 0, h, 0, w)[1] for c in units]
    n_area = sum(a.astype(np.int16) for a in area)
    n_band = sum(b.astype(np.int16) for b in band)
    pred, _ = predict(world, h, w)
    door = (pred == FREE) & ((n_band > 0) | (n_area == 0))  # free under a band or outside units: doors

    def classes(na, nb, dr):
        return np.where(dr, FREE, np.where(nb > 0, OCC, np.where(na > 0, FREE, UNKNOWN)))

    def moved(c, side, d):
        c = c.copy()
        a, b = (c[1] - c[0]) / np.linalg.norm(c[1] - c[0]), (c[3] - c[0]) / np.linalg.norm(c[3] - c[0])
        rows, shift = [([0, 3], -a), ([1, 2], a), ([0, 1], -b), ([2, 3], b)][side]
        c[rows] += d * shift
        return c

    total = 0
    for _ in range(sweeps):
        for k in range(len(units)):
            for side in range(4):
                best = (0, None)
                for d in [x for x in range(-step, step + 1) if x]:
                    c = moved(units[k], side, d)
                    lo = np.floor(np.minimum(units[k].min(0), c.min(0))).astype(int) - 2
                    hi = np.ceil(np.maximum(units[k].max(0), c.max(0))).astype(int) + 2
                    x0, y0, x1, y1 = max(lo[0], 0), max(lo[1], 0), min(hi[0], w), min(hi[1], h)
                    if x1 <= x0 or y1 <= y0:
                        continue
                    win = (slice(y0, y1), slice(x0, x1))
                    a, b = masks(c, y0, y1, x0, x1)
                    na = n_area[win] - area[k][win] + a
                    nb = n_band[win] - band[k][win] + b
                    gain = int((classes(na, nb, door[win]) == obs[win]).sum() -
                               (classes(n_area[win], n_band[win], door[win]) == obs[win]).sum())
                    if gain > best[0]:
                        best = (gain, (c, win, a, b))
                if best[1] is not None:
                    c, win, a, b = best[1]
                    n_area[win] += a.astype(np.int16) - area[k][win]
                    n_band[win] += b.astype(np.int16) - band[k][win]
                    area[k][win], band[k][win], units[k] = a, b, c
                    total += best[0]
    return total


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    img = np.array(Image.open(sys.argv[1]).convert("L"))
    world = json.load(open(sys.argv[2]))
    obs = classify(img)
    pred, area = predict(world, *img.shape)
    n = img.size
    hits = int((pred == obs).sum())
    print(f"K (script) {hits / n:.4f}: {n - hits} misses of {n} cells; K >= 0.95 allows {int(0.05 * n)}")
    interior = area & (pred == FREE)
    labels, _ = ndimage.label(interior & (obs == OCC), structure=np.ones((3, 3)))
    sizes = np.bincount(labels.ravel())[1:]
    print("occupied blobs inside the units' free part, by size: " + ", ".join(
        f"{name}: {int(((sizes >= lo) & (sizes < hi)).sum())} ({int(sizes[(sizes >= lo) & (sizes < hi)].sum())} cells)"
        for name, lo, hi in (("1", 1, 2), ("2-4", 2, 5), ("5-9", 5, 10), ("10-49", 10, 50), ("50+", 50, 1 << 30))))
    fills = [sizes[i] / interior[sl].sum() for i, sl in enumerate(ndimage.find_objects(labels)) if sizes[i] >= 50]
    if fills:
        print(f"blobs of 50 cells or more: median share of their bounding box {np.median(fills):.2f}")
    for closing in (0, 1):
        gain, boxes = furniture_gain(obs, interior, closing)
        print(f"furniture oracle, closing {closing}: {boxes} boxes, +{gain} cells, K {(hits + gain) / n:.4f}")
    for band in (1.0, 1.5, 2.0):
        for outer in (0, 1):
            print(f"wall band {band} cells, outer ring {outer}: K {wall_band_k(obs, world, band, outer):.4f}")
    gain = edge_gain(obs, world)
    print(f"unit edges moved up to 3 cells (2 sweeps): +{gain} cells, K {(hits + gain) / n:.4f}")


if __name__ == "__main__":
    main()
