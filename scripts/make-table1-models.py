#!/usr/bin/env python3
"""Generates the control meshes of the paper's Table 1 in assets/table1/ and checks each of them.

    python3 scripts/make-table1-models.py            write assets/table1/*.json, self-check them
    python3 scripts/make-table1-models.py --check    self-check and compare with the files on disk

McDonnell & Qin 2007, Table 1, lists eight models by their control-cell counts. These meshes have
exactly those counts and shapes close to the paper's figures: hexahedra on integer lattices
(merged vertices), bent or rounded by a smooth map, plus four pyramids on the chair. y is up
(bench table1 pins the lowest layer and pulls along -y). The checks are those of
scripts/make_assets.py (closed cells, positive volumes, conformity, manifold boundary).
"""

import argparse
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import make_assets  # noqa: E402  (the JSON writer and the self-check)

OUT_DIR = make_assets.ROOT / "assets" / "table1"

# The lattice offsets of a hex's corners in VTK order.
HEX_CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
               (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def triple(a, b, c):
    return make_assets.dot(make_assets.cross(a, b), c)


class Lattice:
    """Hexes at integer lattice cells, with vertex keys merged before the map to space.

    `position(i, j, k)` maps a lattice vertex to space; `wrap` identifies i with i + wrap (a
    ring around an axis)."""

    def __init__(self, position, wrap=None):
        self.position = position
        self.wrap = wrap
        self.points = {}  # key -> position
        self.cells = []   # (type, [keys])

    def key(self, i, j, k):
        return (i % self.wrap if self.wrap else i, j, k)

    def vertex(self, key):
        if key not in self.points:
            self.points[key] = tuple(round(c, 6) + 0.0 for c in self.position(*key))
        return key

    def hex_keys(self, cell):
        i, j, k = cell
        keys = [self.vertex(self.key(i + a, j + b, k + c)) for a, b, c in HEX_CORNERS]
        p = [self.points[q] for q in keys]
        sub = make_assets.sub
        if triple(sub(p[1], p[0]), sub(p[3], p[0]), sub(p[4], p[0])) < 0:
            keys = keys[4:] + keys[:4]  # the map mirrors: list the other layer first
        return keys

    def add_hexes(self, cells):
        for cell in sorted(cells, key=lambda c: (c[1], c[2], c[0])):
            self.cells.append(("hex", self.hex_keys(cell)))

    def add_pyramid(self, cell, axis, side, height):
        """A pyramid on the face of hex `cell` normal to `axis` (0, 1, 2) on `side` (0 or 1),
        its apex `height` out from the face centre."""
        keys = self.hex_keys(cell)
        face = next(f for f in make_assets.STANDARD_FACES["hex"]
                    if all(HEX_CORNERS[n][axis] == side for n in f))
        # The hex's outward loop runs counter-clockwise seen from the apex, as the base must.
        base = [keys[n] for n in face]
        centre = make_assets.mean([self.points[q] for q in base])
        apex = list(centre)
        apex[axis] += height if side else -height
        apex_key = ("apex", len(self.cells))
        self.points[apex_key] = tuple(round(c, 6) + 0.0 for c in apex)
        self.cells.append(("pyramid", base + [apex_key]))

    def mesh(self):
        keys = sorted(self.points, key=lambda q: tuple(reversed(self.points[q])))
        ids = {q: n for n, q in enumerate(keys)}
        return {
            "vertices": [list(self.points[q]) for q in keys],
            "cells": [{"type": t, "vertices": [ids[q] for q in qs]} for t, qs in self.cells],
            "creases": [],
            "corners": [],
        }


def box(xs, ys, zs):
    return [(x, y, z) for x in xs for y in ys for z in zs]


def smoothstep(t):
    t = min(max(t, 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


def soccer_player():
    """24 cells: legs, feet pointing forward (-z), a torso, arms held out and down, a head."""
    cells = (box(range(3), range(3, 6), [0])        # torso, 9
             + box([0, 2], range(3), [0])           # legs, 6
             + [(0, 0, -1), (2, 0, -1)]             # feet, 2
             + box([-3, -2, -1, 3, 4, 5], [5], [0])  # arms, 6
             + [(1, 6, 0)])                         # head, 1

    def position(i, j, k):
        x, y, z = float(i), float(j), float(k)
        y -= 0.35 * max(-x, x - 3.0, 0.0)  # arms slope down away from the shoulders
        if j == 7:  # one cell rounds to a small blob: make the head bigger
            x = 1.5 + 1.4 * (x - 1.5)
            y += 0.4
            z = 0.5 + 1.2 * (z - 0.5)
        return (0.8 * x, y, 0.8 * z)

    lattice = Lattice(position)
    lattice.add_hexes(cells)
    return lattice.mesh()


def sea_monster():
    """38 cells: a ribbon body 1 thick and 2 wide along 17 segments, lying on the water at the
    tail and between two humps, rising to a head 2 thick (4 cells) at the front."""
    def centre_height(u):  # and its derivative
        y, dy = 0.0, 0.0
        for start, length, height in ((1.0, 6.0, 2.2), (8.0, 5.0, 1.6)):
            if start <= u <= start + length:
                a = math.pi * (u - start) / length
                y += height * math.sin(a) ** 2
                dy += height * math.pi / length * math.sin(2.0 * a)
        if u > 13.0:  # the neck
            t = min((u - 13.0) / 3.0, 1.0)
            y += 2.6 * smoothstep(t)
            dy += 2.6 * 6.0 * t * (1.0 - t) / 3.0 if t < 1.0 else 0.0
        return y, dy

    def position(i, j, k):
        y, dy = centre_height(i)
        norm = math.hypot(1.0, dy)
        normal = (-dy / norm, 1.0 / norm)
        offset = j - 0.5
        width = 0.6 * (0.5 + 0.5 * min(1.0, i / 3.0)) * (1.3 if i >= 15 else 1.0)
        return (i + offset * normal[0], y + offset * normal[1], (k - 1.0) * width)

    lattice = Lattice(position)
    lattice.add_hexes(box(range(17), [0], range(2)) + box([15, 16], [1], range(2)))
    return lattice.mesh()


def block(n):
    lattice = Lattice(lambda i, j, k: (float(i), float(j), float(k)))
    lattice.add_hexes(box(range(n), range(n), range(n)))
    return lattice.mesh()


def chair():
    """76 cells: a 5x5 seat, four legs of 3, a 5x5 back, armrests on posts, and four pyramids
    (finials on the back's top corners, rounded armrest ends)."""
    cells = (box(range(5), [3], range(5))             # seat, 25
             + box([0, 4], range(3), [0, 4])          # legs, 12
             + box(range(5), range(4, 9), [4])        # back, 25
             + box([0, 4], [4], [0])                  # armrest posts, 2
             + box([0, 4], [5], range(4)))            # armrests, 8
    lattice = Lattice(lambda i, j, k: (float(i), float(j), float(k)))
    lattice.add_hexes(cells)
    for x in (0, 4):
        lattice.add_pyramid((x, 8, 4), 1, 1, 0.6)
        lattice.add_pyramid((x, 5, 0), 2, 0, 0.6)
    return lattice.mesh()


def head():
    """123 cells: a 5x5x5 block without its 8 corner cells, rounded towards an ellipsoid, with
    a nose (-z) and a neck of 5 cells in a plus below it."""
    cells = [c for c in box(range(5), range(5), range(5))
             if not (c[0] in (0, 4) and c[1] in (0, 4) and c[2] in (0, 4))]
    cells += [(2, 2, -1)] + [(2, -1, 2), (1, -1, 2), (3, -1, 2), (2, -1, 1), (2, -1, 3)]

    def position(i, j, k):
        d = (i - 2.5, j - 2.5, k - 2.5)
        length = math.sqrt(sum(c * c for c in d))
        scale = 1.0 if length == 0.0 else 0.6 + 0.4 * max(abs(c) for c in d) / length
        return (d[0] * scale, 1.15 * d[1] * scale, d[2] * scale)

    lattice = Lattice(position)
    lattice.add_hexes(cells)
    return lattice.mesh()


def bridge():
    """150 cells: a deck 16 long, 3 wide and 2 thick on three piers 2x3x3, its spans arched."""
    cells = box(range(16), [3, 4], range(3)) + box([0, 1, 7, 8, 14, 15], range(3), range(3))
    spans = ((2.0, 7.0), (9.0, 14.0))

    def position(i, j, k):
        y = float(j)
        for start, end in spans:
            if start < i < end and j in (3, 4):
                y += (0.8 if j == 3 else 0.4) * math.sin(math.pi * (i - start) / (end - start))
        return (float(i), y, float(k))

    lattice = Lattice(position)
    lattice.add_hexes(cells)
    return lattice.mesh()


def nozzle():
    """99 cells: a convergent tube about the y axis, 11 cells around and 6 layers high, its wall
    2 cells thick in the lower 3 layers and 1 in the upper 3."""
    around = 11
    walls = [2, 2, 2, 1, 1, 1]

    def position(i, j, k):
        inner = 2.2 - 1.2 * smoothstep(k / len(walls))
        r = inner + 0.6 * j
        a = 2.0 * math.pi * i / around
        return (r * math.cos(a), 1.0 * k, r * math.sin(a))

    lattice = Lattice(position, wrap=around)
    lattice.add_hexes([(i, j, k) for k, wall in enumerate(walls)
                       for j in range(wall) for i in range(around)])
    return lattice.mesh()


def block3():
    # Byte for byte assets/block3.json, so that the table's models share one folder.
    return make_assets.block(3, 3, 3).finish()


# File, generator and the paper's control-cell count.
MODELS = {
    "soccer-player.json": (soccer_player, 24),
    "sea-monster.json": (sea_monster, 38),
    "block3.json": (block3, 27),
    "chair.json": (chair, 76),
    "block4.json": (lambda: block(4), 64),
    "head.json": (head, 123),
    "bridge.json": (bridge, 150),
    "nozzle.json": (nozzle, 99),
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="do not write; fail if a file differs from the generator")
    parser.add_argument("--out", type=Path, default=OUT_DIR, help="output folder")
    args = parser.parse_args()

    failures = 0
    if not args.check:
        args.out.mkdir(parents=True, exist_ok=True)
    for name, (make, paper_cells) in MODELS.items():
        text = make_assets.to_json_text(make())
        path = args.out / name
        try:
            stats = make_assets.check_mesh(name, json.loads(text))
            if stats["cells"] != paper_cells:
                raise make_assets.CheckError(
                    f"{name}: {stats['cells']} cells, the paper's model has {paper_cells}")
            if args.check:
                if not path.exists() or path.read_text() != text:
                    raise make_assets.CheckError(f"{name}: missing or differs from the generator")
            else:
                path.write_text(text)
        except make_assets.CheckError as err:
            print(f"FAIL {err}", file=sys.stderr)
            failures += 1
            continue
        print(("ok   " if args.check else "wrote ") + make_assets.describe(name, stats))
    if failures:
        print(f"self-check FAILED for {failures} model(s)", file=sys.stderr)
        return 1
    print(f"self-check passed for all {len(MODELS)} models")
    return 0


if __name__ == "__main__":
    sys.exit(main())
