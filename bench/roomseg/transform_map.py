#!/usr/bin/env python3
"""bench/roomseg/transform_map.py MAP GT TRANSFORM OUT_DIR

Writes a transformed copy of a Bormann et al. benchmark map and of its ground truth, for
bench/roomseg/transforms.sh: OUT_DIR/map.png, OUT_DIR/gt.png, and prints the map's resolution
in metres per cell (the originals are 0.05). TRANSFORM is one of

  none      the map as it is;
  rotN      turned by N degrees counter-clockwise about its centre (nearest neighbour, the
            canvas grown to hold it, the new corners filled with the map's corner colour): a
            SLAM map whose building is not aligned with the image axes;
  half      2 x 2 cells to one, 0.1 m per cell: a cell is the darkest of its four (a wall or
            unknown cell wins over free), as a coarser occupancy grid would mark it;
  double    each cell split in 2 x 2, 0.025 m per cell;
  speckleN  N per mille of the free cells (>= 250) turned occupied (0), single cells drawn
            uniformly with a generator seeded by the map's file name: the specks a SLAM map
            keeps where a person passed or a beam returned early. The ground truth is unchanged
            (a speck is no longer free; the scorer's rooms stay whole).

Transforms joined by + are applied left to right: rot20+speckle10 turns the map, then speckles
its free cells.

The ground truth is moved as room regions, not as an image: the rooms the scorer sees in the
original (8-connected regions of pixels >= 250 larger than 100 pixels, bench/roomseg/score.h)
are labelled, the labels transformed (a half-size cell keeps a label only when all four of its
cells have it), and the output is white where a cell has a label and no 8-neighbour with
another label, black elsewhere. Without that, a thin boundary turned by nearest neighbour
leaves diagonal gaps through which the scorer's 8-connected regions would join two rooms.
Needs numpy, scipy and PIL.
"""
import re
import sys
import zlib

import numpy as np
from PIL import Image
from scipy import ndimage

MIN_REGION = 100  # pixels: bench/roomseg/score.h kMinRegionPixels


def rooms(gt):
    labels, n = ndimage.label(gt >= 250, structure=np.ones((3, 3)))
    sizes = ndimage.sum(np.ones_like(labels), labels, range(1, n + 1))
    keep = np.zeros(n + 1, np.int32)
    keep[1:][sizes > MIN_REGION] = np.arange(1, int((sizes > MIN_REGION).sum()) + 1)
    return keep[labels]


def rotate(a, degrees, fill):
    mode = "I" if a.dtype == np.int32 else "L"
    img = Image.fromarray(a, mode)
    return np.asarray(img.rotate(degrees, resample=Image.NEAREST, expand=True, fillcolor=int(fill)))


def gt_image(labels):
    """White where a cell has a room label and no 8-neighbour with another label."""
    lab = labels.astype(np.int64)
    mixed = np.zeros(lab.shape, bool)
    pad = np.pad(lab, 1)
    h, w = lab.shape
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            nb = pad[1 + dr:1 + dr + h, 1 + dc:1 + dc + w]
            mixed |= (nb != 0) & (nb != lab)
    return np.where((lab != 0) & ~mixed, 255, 0).astype(np.uint8)


def apply_step(step, grid, labels, resolution, map_path):
    """One transform: the moved map, room labels and resolution, or None for an unknown name."""
    rot = re.fullmatch(r"rot(-?\d+(?:\.\d+)?)", step)
    speckle = re.fullmatch(r"speckle(\d+(?:\.\d+)?)", step)
    if step == "none":
        pass
    elif rot:
        deg = float(rot.group(1))
        grid = rotate(grid, deg, grid[0, 0])
        labels = rotate(labels.astype(np.int32), deg, 0)
    elif step == "half":
        h, w = (grid.shape[0] // 2) * 2, (grid.shape[1] // 2) * 2
        grid = grid[:h, :w].reshape(h // 2, 2, w // 2, 2).min(axis=(1, 3))
        blocks = labels[:h, :w].reshape(h // 2, 2, w // 2, 2)
        first = blocks[:, 0, :, 0]
        same = (blocks == first[:, None, :, None]).all(axis=(1, 3))
        labels = np.where(same, first, 0)
        resolution *= 2
    elif step == "double":
        grid = np.kron(grid, np.ones((2, 2), np.uint8))
        labels = np.kron(labels, np.ones((2, 2), labels.dtype))
        resolution /= 2
    elif speckle:
        rng = np.random.default_rng(zlib.crc32(map_path.rsplit("/", 1)[-1].encode()))
        free = np.flatnonzero(grid >= 250)
        specks = rng.choice(free, size=int(round(len(free) * float(speckle.group(1)) / 1000.0)), replace=False)
        grid = grid.copy()
        grid.flat[specks] = 0
    else:
        return None
    return grid, labels, resolution


def main(argv):
    if len(argv) != 5:
        sys.stderr.write(__doc__)
        return 2
    map_path, gt_path, transform, out = argv[1:]
    grid = np.asarray(Image.open(map_path).convert("L"))
    gt = np.asarray(Image.open(gt_path).convert("L"))
    if grid.shape != gt.shape:
        sys.stderr.write(f"{map_path}: {grid.shape[1]} x {grid.shape[0]}, but {gt_path} is {gt.shape[1]} x {gt.shape[0]}\n")
        return 1
    labels = rooms(gt)
    resolution = 0.05
    for step in transform.split("+"):
        moved = apply_step(step, grid, labels, resolution, map_path)
        if moved is None:
            sys.stderr.write(f"transform_map.py: unknown transform '{step}' (none, rotN, half, double, speckleN; "
                             "joined by +)\n")
            return 2
        grid, labels, resolution = moved
    Image.fromarray(np.ascontiguousarray(grid, dtype=np.uint8)).save(f"{out}/map.png")
    Image.fromarray(gt_image(labels)).save(f"{out}/gt.png")
    print(resolution)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
