#!/usr/bin/env python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Writes a closed bowl (a thick spherical cap, opening up +y) as an OBJ.

The cap spans polar angles 0..MAX_DEGREES from the bottom (-y); its inside
has radius R, its outside R + T, and a rim joins the two. Every triangle is
wound counter-clockwise seen from outside the solid, so the surface is a
closed, consistently wound obstacle.

usage: make_bowl.py OUT.obj [R T MAX_DEGREES RINGS SEGMENTS]
"""
import math
import sys


def bowl(radius, thickness, max_degrees, rings, segments):
    top = math.radians(max_degrees)
    vertices, faces = [], []

    def cap(r):
        first = len(vertices)
        vertices.append((0.0, -r, 0.0))  # the pole
        for i in range(1, rings + 1):
            theta = top * i / rings
            for j in range(segments):
                phi = 2 * math.pi * j / segments
                vertices.append((r * math.sin(theta) * math.cos(phi), -r * math.cos(theta),
                                 r * math.sin(theta) * math.sin(phi)))
        return first

    def ring(first, i, j):  # vertex j of ring i (1-based rings)
        return first + 1 + (i - 1) * segments + j % segments

    outer, inner = cap(radius + thickness), cap(radius)
    for first, outward in ((outer, True), (inner, False)):
        for j in range(segments):
            a, b = ring(first, 1, j), ring(first, 1, j + 1)
            faces.append((first, a, b) if outward else (first, b, a))
        for i in range(1, rings):
            for j in range(segments):
                a, b = ring(first, i, j), ring(first, i, j + 1)
                c, d = ring(first, i + 1, j), ring(first, i + 1, j + 1)
                faces += [(a, d, b), (a, c, d)] if outward else [(a, b, d), (a, d, c)]
    for j in range(segments):  # the rim, from the outside ring to the inside one
        a, b = ring(outer, rings, j), ring(outer, rings, j + 1)
        c, d = ring(inner, rings, j), ring(inner, rings, j + 1)
        faces += [(a, d, b), (a, c, d)]
    return vertices, faces


def main():
    out = sys.argv[1]
    r, t, top, rings, segments = (float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]),
                                  int(sys.argv[5]), int(sys.argv[6])) if len(sys.argv) > 2 else (
                                      9.0, 0.6, 75.0, 40, 80)
    vertices, faces = bowl(r, t, top, rings, segments)
    with open(out, "w") as f:
        f.write(f"# bowl: inner radius {r}, thickness {t}, cap {top} degrees "
                f"({len(vertices)} vertices, {len(faces)} triangles)\n")
        for v in vertices:
            f.write("v %.6g %.6g %.6g\n" % v)
        for a, b, c in faces:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")


if __name__ == "__main__":
    main()
