// SPDX-License-Identifier: AGPL-3.0-or-later
// Binding and deformation speed, each next to its baseline from the same run.
// Prints tables; asserts nothing.
#include <tbb/global_control.h>
#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>

#include "CgalClosest.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/deformation/NormalTransforms.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/filters/vtkTetSkinDeformSurface.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/spatial/TriangleDistance.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/VtkConversion.h"

using namespace tetskin;
using Clock = std::chrono::steady_clock;

namespace {

template <typename F>
double seconds(F&& f, int repeat = 1) {
  const auto t = Clock::now();
  for (int i = 0; i < repeat; ++i) f();
  return std::chrono::duration<double>(Clock::now() - t).count() / repeat;
}

// What a VTK user would write: the boundary as vtkPolyData, a
// vtkStaticCellLocator, FindClosestPoint per vertex, then barycentric weights.
SurfaceBinding bindWithVtkLocator(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh,
                                  int level) {
  const LevelRange& r = mesh.levels[static_cast<std::size_t>(level)];
  const BoundaryFaces boundary = boundaryFaces(extractLevel(mesh, level));
  SurfaceMesh faces;
  faces.positions = mesh.nodes.middleRows(r.firstNode, r.nodeCount);
  faces.triangles = boundary.faces;
  vtkSmartPointer<vtkPolyData> pd = toVtkPolyData(faces);
  auto locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator->SetDataSet(pd);
  locator->BuildLocator();
  auto cell = vtkSmartPointer<vtkGenericCell>::New();
  SurfaceBinding b;
  b.resize(surface.vertexCount());
  for (Index v = 0; v < surface.vertexCount(); ++v) {
    double p[3] = {surface.positions(v, 0), surface.positions(v, 1), surface.positions(v, 2)};
    double closest[3], d2;
    vtkIdType cellId;
    int subId;
    locator->FindClosestPoint(p, closest, cell, cellId, subId, d2);
    const Eigen::Vector3d a = faces.positions.row(faces.triangles(cellId, 0)),
                          bb = faces.positions.row(faces.triangles(cellId, 1)),
                          c = faces.positions.row(faces.triangles(cellId, 2));
    const Eigen::Vector3d w = planeBarycentric(Eigen::Vector3d(p[0], p[1], p[2]), a, bb, c);
    for (int k = 0; k < 3; ++k) {
      b.controlIds(v, k) = faces.triangles(cellId, k) + static_cast<int>(r.firstNode);
      b.weights(v, k) = w[k];
    }
    b.faceId[v] = static_cast<int>(cellId);
  }
  return b;
}

SurfaceMesh subdivided(const SurfaceMesh& m, int steps) {
  auto loop = vtkSmartPointer<vtkLoopSubdivisionFilter>::New();
  loop->SetInputData(toVtkPolyData(m));
  loop->SetNumberOfSubdivisions(steps);
  loop->Update();
  return fromVtkPolyData(loop->GetOutput(), "subdivided");
}

void deformationRow(const char* name, const SurfaceMesh& surface, const SurfaceBinding& binding,
                    const Dataset& d) {
  SurfaceDeformer deformer(surface, binding, d.mesh.nodes);
  Points3 control = d.mesh.nodes * 1.01;
  Points3 positions, normals;
  deformer.deform(control, positions, normals);  // warm up, allocate once
  const int repeat = surface.vertexCount() > 200000 ? 10 : 100;
  const double frame = seconds([&] { deformer.deform(control, positions, normals); }, repeat);
  const double positionsOnly =
      seconds([&] { deformer.deformPositions(control, positions); }, repeat);
  const std::size_t bytes = deformer.bytesPerFrame();
  std::vector<char> from(bytes, 1), to(bytes);
  const double copy = seconds([&] { std::memcpy(to.data(), from.data(), bytes); }, repeat);
  std::printf("%-22s %9lld %10.2f %10.2f %10.2f %8.2fx %9.1f\n", name,
              static_cast<long long>(surface.vertexCount()), 1e3 * frame, 1e3 * positionsOnly,
              1e3 * copy, frame / copy, static_cast<double>(bytes) / 1e6);
}

// The deform filter's update per frame (the control mesh's points change,
// the bound surface does not) against the kernel alone and against the
// filter with its bound surface marked modified every frame, so that all it
// derives from input 0 is derived again.
void deformFilterRow(const char* name, const SurfaceMesh& surface, SurfaceBinding binding,
                     OffsetMode offset, const Dataset& d) {
  binding.offset = offset;
  vtkSmartPointer<vtkPolyData> bound = toVtkPolyData(surface);
  addBindingArrays(bound, binding);
  auto rest = vtkSmartPointer<vtkUnstructuredGrid>::New();
  rest->SetPoints(toVtkPoints(d.mesh.nodes));
  auto control = vtkSmartPointer<vtkUnstructuredGrid>::New();
  control->SetPoints(toVtkPoints(d.mesh.nodes));
  auto filter = vtkSmartPointer<vtkTetSkinDeformSurface>::New();
  filter->SetInputData(0, bound);
  filter->SetControlMeshData(control);
  filter->SetRestControlMeshData(rest);
  const Points3 moved = d.mesh.nodes * 1.01;
  vtkPoints* points = control->GetPoints();
  auto nextFrame = [&, frame = 0]() mutable {
    const double scale = 1.0 + 1e-3 * (++frame % 2);
    for (Index i = 0; i < moved.rows(); ++i)
      points->SetPoint(i, scale * moved(i, 0), scale * moved(i, 1), scale * moved(i, 2));
    points->Modified();
  };
  const int repeat = surface.vertexCount() > 200000 ? 10 : 50;
  nextFrame();
  filter->Update();  // warm up
  const double pointsOnly = seconds(nextFrame, repeat);
  const double cached = seconds(
                            [&] {
                              nextFrame();
                              filter->Update();
                            },
                            repeat) -
                        pointsOnly;
  const double rebuilt = seconds(
                             [&] {
                               nextFrame();
                               bound->Modified();
                               filter->Update();
                             },
                             repeat) -
                         pointsOnly;
  SurfaceDeformer deformer(surface, binding, d.mesh.nodes);
  Points3 positions, normals;
  deformer.deform(moved, positions, normals);
  const double kernel = seconds([&] { deformer.deform(moved, positions, normals); }, repeat);
  std::printf("%-22s %-12s %10.2f %10.2f %10.2f %9.2fx %9.2fx\n", name, toString(offset),
              1e3 * cached, 1e3 * rebuilt, 1e3 * kernel, rebuilt / cached, cached / kernel);
}

}  // namespace

int main() {
  const std::string data = std::string(TETSKIN_SOURCE_DIR) + "/data/";
  const Dataset d = loadDataset(data + "bunny.json");
  const int level = d.mesh.finestLevel();
  const SurfaceMesh fine = readObj(data + "bunny_64k.obj");
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("binding %lld vertices (bunny_64k) to level %d (%lld tetrahedra), %d cores\n",
              static_cast<long long>(fine.vertexCount()), level,
              static_cast<long long>(d.mesh.levels[static_cast<std::size_t>(level)].elementCount),
              cores);
  std::printf("%-41s %10s %10s\n", "method", "seconds", "vs closest");
  SurfaceBinding closest;
  const double tClosest = seconds([&] { closest = bindSurface(fine, d.mesh, level); });
  double tClosest1 = 0;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    tClosest1 = seconds([&] { bindSurface(fine, d.mesh, level); });
  }
  SurfaceBinding brute;
  const double tBrute = seconds([&] { brute = bindClosestBruteForce(fine, d.mesh, level); });
  BindingOptions seed;
  seed.method = BindingMethod::Seed;
  const double tSeed = seconds([&] { bindSurface(fine, d.mesh, level, seed); });
  SurfaceBinding locator;
  const double tLocator = seconds([&] { locator = bindWithVtkLocator(fine, d.mesh, level); });
  SurfaceBinding cgal;
  const double tCgal = seconds([&] { cgal = bench::bindWithCgal(fine, d.mesh, level); });
  // (Twice each, the faster: the first run of a process pays for first touches.)
  const double tClosestAgain = seconds([&] { bindSurface(fine, d.mesh, level); });
  const double tCgalAgain = seconds([&] { bench::bindWithCgal(fine, d.mesh, level); });
  const auto sameTriangles = [&](const SurfaceBinding& other) {
    Index same = 0;
    for (Index v = 0; v < fine.vertexCount(); ++v)
      same += (closest.controlIds.row(v).head<3>() == other.controlIds.row(v).head<3>()) ? 1 : 0;
    return 100.0 * static_cast<double>(same) / static_cast<double>(fine.vertexCount());
  };
  const double tClosestBest = std::min(tClosest, tClosestAgain);
  auto row = [&](const char* name, double t) {
    std::printf("%-41s %10.4f %9.2fx\n", name, t, t / tClosestBest);
  };
  row("closest (BVH, all cores)", tClosestBest);
  row("closest (BVH, 1 thread)", tClosest1);
  row("brute force over all faces", tBrute);
  row("seed (report's octants)", tSeed);
  row("vtkStaticCellLocator (1 thread)", tLocator);
  row("CGAL AABB_tree closest point (all cores)", std::min(tCgal, tCgalAgain));
  std::printf(
      "closest == brute force: %s; same triangle as the VTK locator: %.2f%%, as CGAL: %.2f%%\n",
      closest.controlIds == brute.controlIds && closest.weights == brute.weights ? "yes" : "NO",
      sameTriangles(locator), sameTriangles(cgal));

  const SurfaceMesh million = subdivided(readObj(data + "bunny_8k.obj"), 4);
  SurfaceBinding millionBinding;
  const double tMillion = seconds([&] { millionBinding = bindSurface(million, d.mesh, level); });
  const double tMillionCgal = seconds([&] { bench::bindWithCgal(million, d.mesh, level); });
  std::printf(
      "closest, %lld-vertex surface: %.3f s; CGAL AABB_tree closest point: %.3f s (%.2fx)\n\n",
      static_cast<long long>(million.vertexCount()), tMillion, tMillionCgal,
      tMillion / tMillionCgal);

  std::printf("per-frame deformation (positions + normals) vs memcpy of the bytes it touches\n");
  std::printf("%-22s %9s %10s %10s %10s %9s %9s\n", "surface", "vertices", "frame ms", "pos ms",
              "copy ms", "vs copy", "MB");
  deformationRow("bunny_64k", fine, closest, d);
  deformationRow("1M (bunny_8k, Loop x4)", million, millionBinding, d);

  std::printf(
      "\nvtkTetSkinDeformSurface per frame (control points changed): its update against the\n"
      "same with input 0 marked modified (all derived from it again) and the kernel alone\n");
  std::printf("%-22s %-12s %10s %10s %10s %10s %10s\n", "surface", "offset", "update ms",
              "rebuilt ms", "kernel ms", "rebuilt/", "/kernel");
  for (OffsetMode offset : {OffsetMode::Normal, OffsetMode::Displacement})
    deformFilterRow("bunny_64k", fine, closest, offset, d);
  for (OffsetMode offset : {OffsetMode::Normal, OffsetMode::Displacement})
    deformFilterRow("1M (bunny_8k, Loop x4)", million, millionBinding, offset, d);

  // gpu-1pass's CPU work per frame for the control mesh, before the upload:
  // triangle bindings need the level's boundary vertex normals, embed
  // bindings its nodes' normal transforms.
  const LevelRange& finest = d.mesh.levels[static_cast<std::size_t>(level)];
  const Points3 control = d.mesh.nodes * 1.01;
  const Triangles boundary =
      boundaryFaces(extractLevel(d.mesh, level), static_cast<int>(finest.firstNode)).faces;
  const VertexTriangleAdjacency adjacency = vertexTriangleAdjacency(boundary, control.rows());
  Points3 faceScratch(boundary.rows(), 3), controlNormals(control.rows(), 3);
  const NodeNormalTransforms transforms(
      d.mesh.elements.middleRows(finest.firstElement, finest.elementCount), d.mesh.nodes);
  NormalTransformRows nodeTransforms(control.rows(), 9);
  const double tNormals = seconds(
      [&] { computeVertexNormals(control, boundary, adjacency, faceScratch, controlNormals); },
      200);
  const double tTransforms = seconds([&] { transforms.compute(control, nodeTransforms); }, 200);
  std::printf(
      "\ngpu-1pass per frame, level %d: control vertex normals (%lld boundary triangles) %.3f ms; "
      "node normal transforms (embed bindings, %lld tetrahedra) %.3f ms, %.2fx\n",
      level, static_cast<long long>(boundary.rows()), 1e3 * tNormals,
      static_cast<long long>(finest.elementCount), 1e3 * tTransforms, tTransforms / tNormals);
  return 0;
}
