#!/usr/bin/env python3
"""Generates the default control meshes in assets/ and checks each of them.

    python3 scripts/make_assets.py            write assets/*.json, then self-check them
    python3 scripts/make_assets.py --check    self-check and compare with the files on disk
                                              (exit 1 if a file is missing or out of date)

The format is documented in docs/file-formats.md, the assets in assets/README.md. Standard
library only. The self-check (independent of the C++ validator) verifies for every asset:

  * indices in range, finite coordinates, no duplicate positions, every vertex used;
  * every cell is closed: each directed edge of its faces appears once and its reverse once;
  * every face lies in at most two cells, and two cells sharing it use opposite orientations;
  * conformity: two cells share nothing, one vertex, one edge or one whole face;
  * every cell has positive volume (divergence theorem over centroid fans of its faces), and
    every centroid-fan tetrahedron (cell centroid, face centroid, face edge) is positive;
  * every interior edge has at least three faces around it;
  * the boundary is a closed 2-manifold: each boundary edge has exactly two boundary faces and
    each boundary vertex a single fan of boundary faces;
  * creases are boundary edges and corners boundary vertices.

It exits with a message naming the asset, the element and the problem if anything fails.
"""

import argparse
import json
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ASSET_DIR = ROOT / "assets"

# Outward face loops of the standard cells, in VTK vertex numbering (docs/file-formats.md).
#   hex:     0-3 bottom counter-clockwise seen from above, 4-7 above 0-3.
#   tet:     (0,1,2) counter-clockwise seen from 3.
#   prism:   VTK wedge; the right-hand normal of (0,1,2) points away from (3,4,5).
#   pyramid: 0-3 base counter-clockwise seen from the apex 4.
STANDARD_FACES = {
    "hex": [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]],
    "tet": [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]],
    "prism": [[0, 1, 2], [3, 5, 4], [0, 3, 4, 1], [1, 4, 5, 2], [2, 5, 3, 0]],
    "pyramid": [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
}
STANDARD_SIZE = {"hex": 8, "tet": 4, "prism": 6, "pyramid": 5}


class CheckError(Exception):
    pass


# ---------------------------------------------------------------------------------------------
# Building meshes
# ---------------------------------------------------------------------------------------------
class MeshBuilder:
    """Collects vertices (deduplicated by position), typed cells and tags."""

    def __init__(self):
        self.positions = []
        self.index = {}
        self.cells = []  # (type, [vertex ids])
        self.creases = []
        self.corners = []

    def vertex(self, p):
        key = tuple(round(float(c), 9) for c in p)
        if key not in self.index:
            self.index[key] = len(self.positions)
            self.positions.append([float(c) for c in p])
        return self.index[key]

    def cell(self, kind, points):
        assert len(points) == STANDARD_SIZE[kind], (kind, points)
        self.cells.append((kind, [self.vertex(p) for p in points]))

    def hex_at(self, x, y, z, size=1.0):
        s = size
        self.cell("hex", [(x, y, z), (x + s, y, z), (x + s, y + s, z), (x, y + s, z),
                          (x, y, z + s), (x + s, y, z + s), (x + s, y + s, z + s),
                          (x, y + s, z + s)])

    def finish(self, sort_vertices=True):
        """Returns the mesh as a dict; vertices renumbered in (z, y, x) order if asked."""
        order = list(range(len(self.positions)))
        if sort_vertices:
            order.sort(key=lambda i: (self.positions[i][2], self.positions[i][1],
                                      self.positions[i][0]))
        new_id = {old: new for new, old in enumerate(order)}
        creases = sorted(sorted((new_id[a], new_id[b])) for a, b in self.creases)
        return {
            "vertices": [self.positions[i] for i in order],
            "cells": [{"type": k, "vertices": [new_id[v] for v in vs]} for k, vs in self.cells],
            "creases": [list(e) for e in creases],
            "corners": sorted(new_id[v] for v in self.corners),
        }


def hex_grid(cells):
    """A mesh of unit hexes, one at each integer (x, y, z) in `cells` (its lowest corner)."""
    b = MeshBuilder()
    for x, y, z in sorted(cells, key=lambda c: (c[2], c[1], c[0])):
        b.hex_at(x, y, z)
    return b


def block(nx, ny, nz):
    return hex_grid([(x, y, z) for x in range(nx) for y in range(ny) for z in range(nz)])


# ---------------------------------------------------------------------------------------------
# The assets
# ---------------------------------------------------------------------------------------------
def make_cube():
    return block(1, 1, 1).finish()


def make_block3():
    return block(3, 3, 3).finish()


def make_block10():
    return block(10, 10, 10).finish()


def make_block12():
    return block(12, 12, 12).finish()


def make_beam():
    """10x1x1 hexes of [0,10]x[0,1]x[0,1]; all 12 box edges creased, the 8 box corners tagged."""
    n = 10
    b = block(n, 1, 1)
    v = lambda x, y, z: b.index[(float(x), float(y), float(z))]
    for y in (0, 1):
        for z in (0, 1):
            for x in range(n):  # the 4 long box edges, 10 segments each
                b.creases.append((v(x, y, z), v(x + 1, y, z)))
    for x in (0, n):
        for t in (0, 1):  # the 4 edges of each end square
            b.creases.append((v(x, 0, t), v(x, 1, t)))
            b.creases.append((v(x, t, 0), v(x, t, 1)))
    b.corners = [v(x, y, z) for x in (0, n) for y in (0, 1) for z in (0, 1)]
    return b.finish()


def make_ring():
    """A square ring: the 4x4 square [0,4]^2 minus the central 2x2 hole, 2 layers high."""
    cells = [(x, y, z) for x in range(4) for y in range(4) for z in range(2)
             if not (1 <= x <= 2 and 1 <= y <= 2)]
    return hex_grid(cells).finish()


def make_chair():
    """Seat 3x3x1 at z in [2,3], four legs of 2 hexes under the corner cells of the seat,
    a back of 3x1x3 hexes standing on the back row (y in [2,3]) of the seat."""
    cells = [(x, y, 2) for x in range(3) for y in range(3)]
    cells += [(x, y, z) for x in (0, 2) for y in (0, 2) for z in (0, 1)]
    cells += [(x, 2, z) for x in range(3) for z in (3, 4, 5)]
    return hex_grid(cells).finish()


def make_house():
    """A 2x2x2 block of hexes on [0,2]^3 and a hip roof of 4 pyramids on its 4 top faces,
    sharing one apex at (1, 1, 3)."""
    b = block(2, 2, 2)
    apex = (1.0, 1.0, 3.0)
    for x in (0, 1):
        for y in (0, 1):
            # Base counter-clockwise seen from the apex above, i.e. seen from above.
            b.cell("pyramid", [(x, y, 2), (x + 1, y, 2), (x + 1, y + 1, 2), (x, y + 1, 2), apex])
    return b.finish()


def make_tet():
    """The regular tetrahedron inscribed in the cube [-1,1]^3. The cell lists the vertices as
    0, 2, 1, 3 because (1,1,1),(1,-1,-1),(-1,1,-1) is clockwise seen from (-1,-1,1)."""
    b = MeshBuilder()
    for p in [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]:
        b.vertex(p)
    b.cells.append(("tet", [0, 2, 1, 3]))
    return b.finish(sort_vertices=False)


def make_mixed():
    """Three unit cubes in a row along x:
      [0,1]: one hex;
      [1,2]: six pyramids, one per cube face, sharing the apex at the cube centre;
      [2,3]: two prisms, split by the vertical plane through (2,0)-(3,1) in xy."""
    b = MeshBuilder()
    b.hex_at(0, 0, 0)
    # Middle cube: a pyramid on each face. Its base must be counter-clockwise seen from the apex
    # (inside), i.e. the reverse of the face's outward loop.
    corners = [(1, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0), (1, 0, 1), (2, 0, 1), (2, 1, 1), (1, 1, 1)]
    centre = (1.5, 0.5, 0.5)
    for face in STANDARD_FACES["hex"]:
        base = [corners[i] for i in reversed(face)]
        b.cell("pyramid", base + [centre])
    # Right cube: triangles T1 = (2,0),(3,0),(3,1) and T2 = (2,0),(3,1),(2,1) in xy. VTK wedge
    # order wants (0,1,2) on z = 0 with its normal pointing down (away from z = 1), i.e.
    # clockwise seen from above.
    for tri in ([(2, 0), (3, 0), (3, 1)], [(2, 0), (3, 1), (2, 1)]):
        cw = [tri[0], tri[2], tri[1]]
        b.cell("prism", [(x, y, 0) for x, y in cw] + [(x, y, 1) for x, y in cw])
    return b.finish()


ASSETS = {
    "cube.json": make_cube,
    "block3.json": make_block3,
    "beam.json": make_beam,
    "ring.json": make_ring,
    "chair.json": make_chair,
    "house.json": make_house,
    "tet.json": make_tet,
    "mixed.json": make_mixed,
    "block10.json": make_block10,
    "block12.json": make_block12,
}


# ---------------------------------------------------------------------------------------------
# Writing: one vertex, cell or crease per line
# ---------------------------------------------------------------------------------------------
def to_json_text(mesh):
    def num(x):
        return json.dumps(float(x))

    lines = ["{", '  "format": "sculpt-control-mesh",', '  "version": 1,', '  "vertices": [']
    vs = mesh["vertices"]
    for i, p in enumerate(vs):
        lines.append("    [" + ", ".join(num(c) for c in p) + "]" + ("," if i + 1 < len(vs) else ""))
    lines.append("  ],")
    lines.append('  "cells": [')
    cs = mesh["cells"]
    for i, c in enumerate(cs):
        sep = "," if i + 1 < len(cs) else ""
        if isinstance(c, dict):
            lines.append('    {"type": "%s", "vertices": [%s]}%s'
                         % (c["type"], ", ".join(str(v) for v in c["vertices"]), sep))
        else:
            lines.append("    " + json.dumps(c) + sep)
    lines.append("  ],")
    if mesh["creases"]:
        lines.append('  "creases": [')
        es = mesh["creases"]
        for i, e in enumerate(es):
            lines.append("    [%d, %d]%s" % (e[0], e[1], "," if i + 1 < len(es) else ""))
        lines.append("  ],")
    else:
        lines.append('  "creases": [],')
    lines.append('  "corners": [' + ", ".join(str(v) for v in mesh["corners"]) + "]")
    lines.append("}")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# Self-check (works on the parsed file, so it also checks the writer)
# ---------------------------------------------------------------------------------------------
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def mean(points):
    n = len(points)
    return tuple(sum(p[k] for p in points) / n for k in range(3))


def cell_faces(cell, name, ci):
    """Face loops of a parsed cell (a list of faces, or a typed cell)."""
    if isinstance(cell, dict):
        kind = cell.get("type")
        if kind not in STANDARD_FACES:
            raise CheckError(f"{name}: cell {ci}: unknown type {kind!r}")
        vs = cell.get("vertices")
        if not isinstance(vs, list) or len(vs) != STANDARD_SIZE[kind]:
            raise CheckError(f"{name}: cell {ci}: a {kind} needs {STANDARD_SIZE[kind]} vertices")
        return [[vs[i] for i in loop] for loop in STANDARD_FACES[kind]]
    return cell


def check_mesh(name, data):
    """Raises CheckError on the first problem; returns a dict of statistics."""
    if data.get("format") != "sculpt-control-mesh" or data.get("version") != 1:
        raise CheckError(f"{name}: wrong format or version")
    P = [tuple(p) for p in data["vertices"]]
    nv = len(P)
    for i, p in enumerate(P):
        if len(p) != 3 or not all(isinstance(c, (int, float)) and math.isfinite(c) for c in p):
            raise CheckError(f"{name}: vertex {i}: not three finite numbers")
    if len(set(P)) != nv:
        raise CheckError(f"{name}: two vertices have the same position")

    cells = [cell_faces(c, name, ci) for ci, c in enumerate(data["cells"])]
    used = set()
    face_cells = {}  # canonical vertex set -> list of (cell, loop)
    cell_vertex_sets = []
    cell_edge_sets = []
    cell_face_sets = []
    total_volume = 0.0
    for ci, faces in enumerate(cells):
        directed = {}
        for fi, f in enumerate(faces):
            if len(f) < 3 or len(set(f)) != len(f):
                raise CheckError(f"{name}: cell {ci}, face {fi}: needs >= 3 distinct vertices")
            for v in f:
                if not isinstance(v, int) or v < 0 or v >= nv:
                    raise CheckError(f"{name}: cell {ci}, face {fi}: vertex index {v} out of range")
            for k in range(len(f)):
                e = (f[k], f[(k + 1) % len(f)])
                if e in directed:
                    raise CheckError(f"{name}: cell {ci}: directed edge {e} appears twice")
                directed[e] = fi
        for (a, b) in directed:
            if (b, a) not in directed:
                raise CheckError(f"{name}: cell {ci}: not closed at edge ({a}, {b})")
        # Volume by the divergence theorem over centroid fans; each fan tetrahedron with the
        # cell centroid must be positive as well (cells here are convex).
        verts = sorted({v for f in faces for v in f})
        c = mean([P[v] for v in verts])
        vol = 0.0
        for fi, f in enumerate(faces):
            fc = mean([P[v] for v in f])
            for k in range(len(f)):
                a, b = P[f[k]], P[f[(k + 1) % len(f)]]
                t = dot(fc, cross(a, b)) / 6.0
                vol += t
                local = dot(sub(fc, c), cross(sub(a, c), sub(b, c))) / 6.0
                if local <= 1e-12:
                    raise CheckError(f"{name}: cell {ci}, face {fi}: fan tetrahedron of volume "
                                     f"{local:g} (face not outward or cell folded)")
        if vol <= 1e-12:
            raise CheckError(f"{name}: cell {ci}: volume {vol:g} is not positive")
        total_volume += vol
        used.update(verts)
        cell_vertex_sets.append(frozenset(verts))
        cell_edge_sets.append({frozenset(e) for e in directed})
        cell_face_sets.append({frozenset(f) for f in faces})
        for f in faces:
            face_cells.setdefault(frozenset(f), []).append((ci, f))
    if len(used) != nv:
        raise CheckError(f"{name}: vertices {sorted(set(range(nv)) - used)[:5]} are unused")

    # Shared faces: at most two cells, opposite orientations.
    def directed_edges(loop):
        return {(loop[k], loop[(k + 1) % len(loop)]) for k in range(len(loop))}

    boundary_faces = []
    interior_faces = 0
    for key, users in face_cells.items():
        if len(users) > 2:
            raise CheckError(f"{name}: face {sorted(key)} is shared by {len(users)} cells")
        if len(users) == 2:
            (c0, f0), (c1, f1) = users
            if c0 == c1:
                raise CheckError(f"{name}: cell {c0} has the face {sorted(key)} twice")
            rev = {(b, a) for (a, b) in directed_edges(f1)}
            if directed_edges(f0) != rev:
                raise CheckError(f"{name}: cells {c0} and {c1} share face {sorted(key)} "
                                 "without opposite orientation")
            interior_faces += 1
        else:
            boundary_faces.append(users[0][1])

    # Conformity: two cells share nothing, a vertex, an edge of both, or a whole face of both.
    vertex_cells = {}
    for ci, vs in enumerate(cell_vertex_sets):
        for v in vs:
            vertex_cells.setdefault(v, []).append(ci)
    pairs = set()
    for cs in vertex_cells.values():
        for i in range(len(cs)):
            for j in range(i + 1, len(cs)):
                pairs.add((cs[i], cs[j]))
    for c0, c1 in pairs:
        common = cell_vertex_sets[c0] & cell_vertex_sets[c1]
        ok = (len(common) == 1
              or (len(common) == 2 and common in cell_edge_sets[c0] and common in cell_edge_sets[c1])
              or (common in cell_face_sets[c0] and common in cell_face_sets[c1]))
        if not ok:
            raise CheckError(f"{name}: cells {c0} and {c1} share the vertices {sorted(common)}, "
                             "which is not a vertex, an edge or a face of both")

    # Edges: faces around each edge; boundary edges need exactly two boundary faces.
    edge_faces = {}
    for key, users in face_cells.items():
        loop = users[0][1]
        for k in range(len(loop)):
            e = frozenset((loop[k], loop[(k + 1) % len(loop)]))
            edge_faces.setdefault(e, [0, 0])
            edge_faces[e][0 if len(users) == 2 else 1] += 1
    boundary_edges = set()
    for e, (n_int, n_bnd) in edge_faces.items():
        if n_bnd == 0:
            if n_int < 3:
                raise CheckError(f"{name}: interior edge {sorted(e)} has only {n_int} faces")
        elif n_bnd != 2:
            raise CheckError(f"{name}: boundary edge {sorted(e)} has {n_bnd} boundary faces")
        else:
            boundary_edges.add(e)

    # Boundary vertices: one fan of boundary faces each.
    vertex_bfaces = {}
    for fi, f in enumerate(boundary_faces):
        for v in f:
            vertex_bfaces.setdefault(v, []).append(fi)
    for v, fs in vertex_bfaces.items():
        parent = {f: f for f in fs}

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x

        by_edge = {}
        for fi in fs:
            f = boundary_faces[fi]
            k = f.index(v)
            for w in (f[k - 1], f[(k + 1) % len(f)]):
                by_edge.setdefault(w, []).append(fi)
        for w, owners in by_edge.items():
            for o in owners[1:]:
                parent[find(o)] = find(owners[0])
        if len({find(f) for f in fs}) != 1:
            raise CheckError(f"{name}: boundary vertex {v} has more than one fan of boundary "
                             "faces (non-manifold boundary)")

    # Tags.
    creases = data.get("creases", [])
    corners = data.get("corners", [])
    for e in creases:
        if frozenset(e) not in boundary_edges:
            raise CheckError(f"{name}: crease {e} is not a boundary edge")
    if len({frozenset(e) for e in creases}) != len(creases):
        raise CheckError(f"{name}: a crease is listed twice")
    for v in corners:
        if v not in vertex_bfaces:
            raise CheckError(f"{name}: corner {v} is not a boundary vertex")
    if len(set(corners)) != len(corners):
        raise CheckError(f"{name}: a corner is listed twice")

    bv = len(vertex_bfaces)
    euler = bv - len(boundary_edges) + len(boundary_faces)
    types = {}
    for c in data["cells"]:
        t = c["type"] if isinstance(c, dict) else "polyhedron"
        types[t] = types.get(t, 0) + 1
    return {
        "vertices": nv, "edges": len(edge_faces), "faces": len(face_cells),
        "cells": len(cells), "types": types, "volume": total_volume,
        "boundary": (bv, len(boundary_edges), len(boundary_faces)), "euler": euler,
        "creases": len(creases), "corners": len(corners),
    }


def describe(name, s):
    types = ", ".join(f"{n} {t}" for t, n in sorted(s["types"].items()))
    bv, be, bf = s["boundary"]
    genus = (2 - s["euler"]) // 2
    return (f"{name:13s} V={s['vertices']:5d} E={s['edges']:5d} F={s['faces']:5d} "
            f"C={s['cells']:4d} ({types}); volume {s['volume']:g}; boundary V/E/F {bv}/{be}/{bf}, "
            f"Euler {s['euler']} (genus {genus}); creases {s['creases']}, corners {s['corners']}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="do not write; fail if a file in assets/ differs from the generator")
    parser.add_argument("--out", type=Path, default=ASSET_DIR, help="output folder (assets/)")
    args = parser.parse_args()

    failures = 0
    if not args.check:
        args.out.mkdir(parents=True, exist_ok=True)
    for name, make in ASSETS.items():
        text = to_json_text(make())
        path = args.out / name
        try:
            stats = check_mesh(name, json.loads(text))
            if args.check:
                if not path.exists():
                    raise CheckError(f"{name}: missing in {args.out}")
                disk = path.read_text()
                check_mesh(name, json.loads(disk))
                if disk != text:
                    raise CheckError(f"{name}: differs from scripts/make_assets.py's output "
                                     "(run it to regenerate)")
            else:
                path.write_text(text)
        except CheckError as err:
            print(f"FAIL {err}", file=sys.stderr)
            failures += 1
            continue
        print(("ok   " if args.check else "wrote ") + describe(name, stats))
    if failures:
        print(f"self-check FAILED for {failures} asset(s)", file=sys.stderr)
        return 1
    print(f"self-check passed for all {len(ASSETS)} assets")
    return 0


if __name__ == "__main__":
    sys.exit(main())
