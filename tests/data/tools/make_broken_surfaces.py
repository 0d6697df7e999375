#!/usr/bin/env python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Writes the broken surfaces of the alpha-wrapping tests into tests/data/:
surfaces as real scans and CAD exports come, which repair alone cannot close.

    python3 tests/data/tools/make_broken_surfaces.py   (from the repository root)

bunny_holed.obj       data/bunny.obj with its base and one ear's tip cut off (3 holes: the
                      base comes off in two pieces)
overlapping_spheres.obj  three closed spheres overlapping deeply (a union of parts)
soup_with_gaps.obj    a sphere's triangles, each with vertices of its own, shrunk apart
nonmanifold_fins.obj  a sphere with a hole and three fins on each edge of its rim
                      (edges shared by four triangles)
inverted_part.obj     three overlapping closed spheres, the second wound inward
open_sheet.obj        a curved open patch (a scanned face's kind of input)
no_area.obj           triangles whose corners all lie on one line
"""
import math
import os

ROOT = os.path.join(os.path.dirname(__file__), "..", "..", "..")
OUT = os.path.join(ROOT, "tests", "data")


def write(name, vertices, triangles, comment):
    with open(os.path.join(OUT, name), "w") as f:
        f.write("# %s\n# made by tests/data/tools/make_broken_surfaces.py\n" % comment)
        for v in vertices:
            f.write("v %.9g %.9g %.9g\n" % tuple(v))
        for t in triangles:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def read_obj(path):
    vertices, triangles = [], []
    for line in open(path):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            vertices.append([float(x) for x in parts[1:4]])
        elif parts[0] == "f":
            triangles.append([int(p.split("/")[0]) - 1 for p in parts[1:4]])
    return vertices, triangles


def sphere(center, radius, rings=16, segments=24):
    """A closed UV sphere wound outward."""
    cx, cy, cz = center
    vertices = [[cx, cy + radius, cz]]
    for i in range(1, rings):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2 * math.pi * j / segments
            vertices.append([cx + radius * math.sin(theta) * math.cos(phi),
                             cy + radius * math.cos(theta),
                             cz + radius * math.sin(theta) * math.sin(phi)])
    vertices.append([cx, cy - radius, cz])
    bottom = len(vertices) - 1
    ring = lambda i, j: 1 + (i - 1) * segments + j % segments
    triangles = []
    for j in range(segments):
        triangles.append([0, ring(1, j + 1), ring(1, j)])
        triangles.append([bottom, ring(rings - 1, j), ring(rings - 1, j + 1)])
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b = ring(i, j), ring(i, j + 1)
            c, d = ring(i + 1, j), ring(i + 1, j + 1)
            triangles.append([a, b, d])
            triangles.append([a, d, c])
    return vertices, triangles


def join(*parts):
    vertices, triangles = [], []
    for v, t in parts:
        base = len(vertices)
        vertices += v
        triangles += [[base + i for i in tri] for tri in t]
    return vertices, triangles


def bunny_holed():
    v, t = read_obj(os.path.join(ROOT, "data", "bunny.obj"))
    # The base (lowest 6% of the height: y) and the top of the tallest ear.
    ys = [p[1] for p in v]
    low = min(ys) + 0.06 * (max(ys) - min(ys))
    high = max(ys) - 0.05 * (max(ys) - min(ys))
    kept = [tri for tri in t
            if not all(v[i][1] < low for i in tri) and not all(v[i][1] > high for i in tri)]
    used = sorted({i for tri in kept for i in tri})
    new_index = {old: new for new, old in enumerate(used)}
    write("bunny_holed.obj", [v[i] for i in used], [[new_index[i] for i in tri] for tri in kept],
          "data/bunny.obj with its base and one ear's tip cut off: %d of %d triangles, 3 holes"
          % (len(kept), len(t)))


def overlapping_spheres():
    v, t = join(sphere((0, 0, 0), 1.0), sphere((0.9, 0.2, 0), 0.9), sphere((0.4, 0.8, 0.3), 0.8))
    write("overlapping_spheres.obj", v, t, "three closed spheres overlapping deeply")


def soup_with_gaps():
    v, t = sphere((0, 0, 0), 1.0, 12, 18)
    vertices, triangles = [], []
    for tri in t:
        c = [sum(v[i][k] for i in tri) / 3 for k in range(3)]
        for i in tri:
            vertices.append([c[k] + 0.9 * (v[i][k] - c[k]) for k in range(3)])
        triangles.append([len(vertices) - 3, len(vertices) - 2, len(vertices) - 1])
    write("soup_with_gaps.obj", vertices, triangles,
          "a sphere's triangles, each shrunk by 10% toward its centre: a soup with gaps")


def nonmanifold_fins():
    rings, segments = 16, 24
    v, t = sphere((0, 0, 0), 1.0, rings, segments)
    # Open the sphere at its north pole, then stand three fins on each of the
    # hole's rim edges (each rim edge then has four triangles): sheets with
    # open edges, as a scan's stray flaps are.
    t = [tri for tri in t if 0 not in tri]
    rim = [1 + j for j in range(segments)]
    for k in range(3):
        for j in range(segments):
            a, b = v[rim[j]], v[rim[(j + 1) % segments]]
            lean = 0.3 * (k - 1)
            apex = [0.5 * (a[0] + b[0]) * (1 + lean), a[1] + 0.4, 0.5 * (a[2] + b[2]) * (1 + lean)]
            v.append(apex)
            t.append([rim[j], rim[(j + 1) % segments], len(v) - 1])
    write("nonmanifold_fins.obj", v, t,
          "a sphere with a hole and three fins on each edge of its rim (non-manifold edges)")


def inverted_part():
    v2, t2 = sphere((0.9, 0.2, 0), 0.9)
    v, t = join(sphere((0, 0, 0), 1.0), (v2, [[a, c, b] for a, b, c in t2]),
                sphere((0.4, 0.8, 0.3), 0.8))
    write("inverted_part.obj", v, t,
          "three closed spheres overlapping deeply, the second wound inward")


def open_sheet():
    n = 12
    v = []
    for i in range(n + 1):
        for j in range(n + 1):
            x, y = -1 + 2 * i / n, -1 + 2 * j / n
            v.append([x, y, 0.3 * (x * x + y * y)])
    t = []
    for i in range(n):
        for j in range(n):
            a = i * (n + 1) + j
            t.append([a, a + n + 1, a + n + 2])
            t.append([a, a + n + 2, a + 1])
    write("open_sheet.obj", v, t, "an open, curved patch (as a scanned face is)")


def no_area():
    v = [[0, 0, 0], [1, 1, 1], [2, 2, 2], [3, 3, 3]]
    write("no_area.obj", v, [[0, 1, 2], [1, 2, 3], [0, 2, 3]],
          "triangles whose corners all lie on one line: no area")


if __name__ == "__main__":
    bunny_holed()
    overlapping_spheres()
    soup_with_gaps()
    nonmanifold_fins()
    inverted_part()
    open_sheet()
    no_area()
