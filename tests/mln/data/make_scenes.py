#!/usr/bin/env python3
"""Regenerates the table-top evidence scenes used by tests/mln and bench/mln.

scene3/scene7 are hand-written layouts (scene7 is the seed's example, section 4.5.1);
scene20/scene100 are random layouts from a fixed seed: stacks on the table or on
earlier objects, hovering boxes, ~15% unstable poses, a few intersecting pairs.
Run from this folder: python3 make_scenes.py
"""
import random


def scene(name, comment, objs, facts):
    lines = [f"// {comment}", f"// constants: {', '.join(objs)}"] + facts
    with open(name, "w") as f:
        f.write("\n".join(lines) + "\n")


def sym(p, a, b):
    return [f"{p}({a}, {b})", f"{p}({b}, {a})"]


def hand_written():
    f = ["table(Table)", "stable(Table)", "stable(O0)", "stable(O1)", "!stable(O2)"]
    f += sym("contact", "Table", "O0") + sym("contact", "O0", "O1")
    f += ["higher(O0, Table)", "higher(O1, Table)", "higher(O1, O0)", "higher(O2, Table)", "hover(O2)"]
    scene("scene3.db", "3 objects: O0 on the table, O1 on O0, O2 unstable and hovering",
          ["Table", "O0", "O1", "O2"], f)

    objs = ["Table"] + [f"O{i}" for i in range(7)]
    f = ["table(Table)", "stable(Table)"] + [f"stable(O{i})" for i in range(6)] + ["!stable(O6)"]
    for i in range(4):
        f += sym("contact", "Table", f"O{i}")
    f += sym("contact", "O3", "O4")
    for i in range(7):
        f.append(f"higher(O{i}, Table)")
    f += ["higher(O4, O3)", "higher(O4, O2)", "higher(O5, O2)"]
    f += ["hover(O5)"]
    f += sym("intersect", "O6", "O1") + ["higher(O6, O1)"]
    scene("scene7.db", "7 objects, the seed's example: O0-O5 stable, O0-O3 on the table, O4 on O3, "
          "O5 hovering, O6 unstable and intersecting O1", objs, f)


def generated(n, seed, fname):
    rnd = random.Random(seed)
    objs = ["Table"] + [f"O{i}" for i in range(n)]
    f = ["table(Table)", "stable(Table)"]
    support = {}
    for i in range(n):
        o = f"O{i}"
        kind = rnd.random()
        if kind < 0.55 or i == 0:
            support[o] = "Table"
        elif kind < 0.8:
            support[o] = f"O{rnd.randrange(i)}"
        else:
            support[o] = None
    for i in range(n):
        o = f"O{i}"
        st = rnd.random() < 0.85
        f.append(("" if st else "!") + f"stable({o})")
        if support[o]:
            f += sym("contact", support[o], o)
        else:
            f.append(f"hover({o})")
        f.append(f"higher({o}, Table)")
        if support[o] and support[o] != "Table":
            f.append(f"higher({o}, {support[o]})")
    for _ in range(max(1, n // 7)):
        a, b = rnd.sample(range(n), 2)
        f += sym("intersect", f"O{a}", f"O{b}")
    scene(fname, f"{n} objects, generated (seed {seed}): stacks, hovering boxes, intersections", objs, f)


if __name__ == "__main__":
    hand_written()
    generated(20, 20, "scene20.db")
    generated(100, 100, "scene100.db")
