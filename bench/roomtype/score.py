#!/usr/bin/env python3
"""bench/roomtype/score.py LABELS KIND SEGMENTATION WORLD_JSON

Scores the unit types of an indoor run against a Bormann et al. training map
(../shared/data/maps/bormann_ipa/training_maps): a copy of the map with one class painted
grey. KIND says which: "hallway" (the grey cells are hallway, the white ones room) or "room"
(the other way round). Black cells are not free and are not scored.

Each scored cell takes the type of the unit segmentation.png gives it (0: no unit); Corr is
"hallway", Room, Hall and Other are "room". Prints one line:
  hallway_cells room_cells corr_P corr_R corr_F1 room_acc accuracy unsegmented
where corr_P / corr_R are over cells (of the cells typed Corr, the share that are hallway; of
the hallway cells, the share typed Corr), room_acc is the share of room cells not typed Corr,
accuracy the share of all scored cells whose type class is right, and unsegmented the share
of scored cells with no unit (counted as wrong in accuracy and in corr_R, not in corr_P).
"""
import json
import sys

import numpy as np
from PIL import Image


def main(argv):
    if len(argv) != 5 or argv[2] not in ("hallway", "room"):
        sys.stderr.write(__doc__)
        return 2
    labels_path, kind, seg_path, world_path = argv[1:]
    grey = np.asarray(Image.open(labels_path).convert("L"))
    seg = np.asarray(Image.open(seg_path)).astype(np.int64)
    if grey.shape != seg.shape:
        sys.stderr.write(f"{seg_path}: {seg.shape[1]} x {seg.shape[0]} cells, but {labels_path} has "
                         f"{grey.shape[1]} x {grey.shape[0]}\n")
        return 1
    with open(world_path) as f:
        world = json.load(f)
    corr_ids = np.array(sorted(u["id"] for u in world["units"] if u.get("type") == "Corr"), dtype=np.int64)
    painted = (grey > 0) & (grey < 255)
    white = grey == 255
    hallway = painted if kind == "hallway" else white
    room = white if kind == "hallway" else painted
    unit = seg > 0
    corr = unit & np.isin(seg, corr_ids)
    n_h, n_r = int(hallway.sum()), int(room.sum())
    tp = int((corr & hallway).sum())
    pred = int((corr & (hallway | room)).sum())
    p = tp / pred if pred else float("nan")
    r = tp / n_h if n_h else float("nan")
    f1 = 2 * p * r / (p + r) if pred and n_h and p + r > 0 else 0.0
    room_ok = int((unit & ~corr & room).sum())
    room_acc = room_ok / n_r if n_r else float("nan")
    acc = (tp + room_ok) / (n_h + n_r)
    unseg = int((~unit & (hallway | room)).sum()) / (n_h + n_r)
    print(f"{n_h} {n_r} {p:.4f} {r:.4f} {f1:.4f} {room_acc:.4f} {acc:.4f} {unseg:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
