// SPDX-License-Identifier: AGPL-3.0-or-later
// Reading the 64k-triangle bunny: TetSkin's strict OBJ reader against VTK's
// vtkOBJReader (the baseline a VTK user would reach for), and the TetGen .node
// round trip.
#include <benchmark/benchmark.h>
#include <vtkOBJReader.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <filesystem>

#include "tetskin/io/ObjFormat.h"
#include "tetskin/io/TetGenFormat.h"

namespace {

const std::string kBunny = std::string(TETSKIN_SOURCE_DIR) + "/data/bunny_64k.obj";

void BM_TetSkinReadObj(benchmark::State& state) {
  for (auto _ : state) {
    tetskin::SurfaceMesh mesh = tetskin::readObj(kBunny);
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  state.SetBytesProcessed(state.iterations() *
                          static_cast<int64_t>(std::filesystem::file_size(kBunny)));
}
BENCHMARK(BM_TetSkinReadObj)->Unit(benchmark::kMillisecond);

void BM_VtkObjReader(benchmark::State& state) {
  for (auto _ : state) {
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(kBunny.c_str());
    reader->Update();
    benchmark::DoNotOptimize(reader->GetOutput()->GetNumberOfPoints());
  }
  state.SetBytesProcessed(state.iterations() *
                          static_cast<int64_t>(std::filesystem::file_size(kBunny)));
}
BENCHMARK(BM_VtkObjReader)->Unit(benchmark::kMillisecond);

void BM_NodeFileRoundTrip(benchmark::State& state) {
  const tetskin::SurfaceMesh mesh = tetskin::readObj(kBunny);
  tetskin::NodeFile nodes;
  nodes.points = mesh.positions;
  const auto path = std::filesystem::temp_directory_path() / "tetskin-bench.node";
  for (auto _ : state) {
    tetskin::writeNode(path, nodes);
    tetskin::NodeFile back = tetskin::readNode(path);
    benchmark::DoNotOptimize(back.points.data());
  }
  std::filesystem::remove(path);
  state.SetItemsProcessed(state.iterations() * nodes.points.rows());
}
BENCHMARK(BM_NodeFileRoundTrip)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
