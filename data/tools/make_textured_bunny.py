"""Makes data/bunny_8k_tex.obj and data/bunny_texture.png (the report's "BunnyTex").

Texture coordinates: a cylindrical projection about the bunny's vertical axis
(u = angle, v = height), one pair per vertex. Texture: 256x256 procedural
pattern (soft spots on a warm base), deterministic.
Usage: python3 make_textured_bunny.py bunny_8k.obj bunny_8k_tex.obj bunny_texture.png
"""
import math
import sys

import vtk


def main():
    src, out_obj, out_png = sys.argv[1], sys.argv[2], sys.argv[3]
    reader = vtk.vtkOBJReader()
    reader.SetFileName(src)
    reader.Update()
    mesh = reader.GetOutput()
    points = mesh.GetPoints()
    bounds = mesh.GetBounds()
    cx, cz = (bounds[0] + bounds[1]) / 2, (bounds[4] + bounds[5]) / 2
    with open(out_obj, "w", encoding="ascii") as f:
        f.write("# Stanford bunny (public domain), bunny_8k.obj with cylindrical texture\n")
        f.write("# coordinates, made by data/tools/make_textured_bunny.py\n")
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            f.write(f"v {x:.6f} {y:.6f} {z:.6f}\n")
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            u = (math.atan2(z - cz, x - cx) + math.pi) / (2 * math.pi)
            v = (y - bounds[2]) / (bounds[3] - bounds[2])
            f.write(f"vt {u:.6f} {v:.6f}\n")
        ids = vtk.vtkIdList()
        polys = mesh.GetPolys()
        polys.InitTraversal()
        while polys.GetNextCell(ids):
            f.write("f %s\n" % " ".join("%d/%d" % (ids.GetId(k) + 1, ids.GetId(k) + 1) for k in range(3)))
    size = 256
    image = vtk.vtkImageData()
    image.SetDimensions(size, size, 1)
    image.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 3)
    scalars = image.GetPointData().GetScalars()
    spots = [((37 * k) % size, (91 * k + 17) % size, 10 + (13 * k) % 18) for k in range(40)]
    for j in range(size):
        for i in range(size):
            shade = 0.0
            for sx, sy, r in spots:
                dx = min(abs(i - sx), size - abs(i - sx))
                dy = min(abs(j - sy), size - abs(j - sy))
                shade = max(shade, max(0.0, 1.0 - math.hypot(dx, dy) / r))
            base = (235, 205, 170)
            spot = (120, 75, 45)
            rgb = [int(b + (s - b) * min(1.0, 1.5 * shade)) for b, s in zip(base, spot)]
            scalars.SetTuple3(j * size + i, *rgb)
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(out_png)
    writer.SetInputData(image)
    writer.Write()


if __name__ == "__main__":
    main()
