"""Makes the finer bunny surfaces of data/ from data/bunny.obj with VTK.

Loop subdivision smooths and refines (4x triangles per step); quadric decimation
then brings the count to the requested target while keeping the shape.
Usage: python3 refine_bunny.py bunny.obj TARGET_TRIANGLES SUBDIVISIONS out.obj
"""
import sys

import vtk


def main():
    src, target, steps, out = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    reader = vtk.vtkOBJReader()
    reader.SetFileName(src)
    clean = vtk.vtkCleanPolyData()  # OBJReader splits nothing here, but be safe
    clean.SetInputConnection(reader.GetOutputPort())
    loop = vtk.vtkLoopSubdivisionFilter()
    loop.SetNumberOfSubdivisions(steps)
    loop.SetInputConnection(clean.GetOutputPort())
    loop.Update()
    fine = loop.GetOutput()
    decimate = vtk.vtkQuadricDecimation()
    decimate.SetInputData(fine)
    decimate.SetTargetReduction(1.0 - target / fine.GetNumberOfPolys())
    decimate.VolumePreservationOn()
    decimate.Update()
    mesh = decimate.GetOutput()
    points, polys = mesh.GetPoints(), mesh.GetPolys()
    ids = vtk.vtkIdList()
    with open(out, "w", encoding="ascii") as f:
        f.write("# Stanford bunny (public domain), refined by data/tools/refine_bunny.py:\n")
        f.write(f"# {steps}x Loop subdivision of bunny.obj, quadric decimation to {target} triangles.\n")
        f.write(f"# {points.GetNumberOfPoints()} vertices, {polys.GetNumberOfCells()} triangles\n")
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            f.write(f"v {x:.6f} {y:.6f} {z:.6f}\n")
        polys.InitTraversal()
        while polys.GetNextCell(ids):
            f.write("f %d %d %d\n" % tuple(ids.GetId(k) + 1 for k in range(3)))


if __name__ == "__main__":
    main()
