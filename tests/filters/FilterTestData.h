// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the filter tests share besides the sample dataset: its level 1 as a VTK grid
// numbered from 0, and bunny_8k as VTK poly data.

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <string>

#include "SampleData.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin::test {

constexpr int kBoundLevel = 1;

inline const SurfaceMesh& bunnySurface() {
  static const SurfaceMesh s = readObj(kSampleData + "bunny_8k.obj");
  return s;
}

// Level 1 of the sample dataset with level-local node ids (as `tetskin
// convert --level 1` writes it).
inline vtkSmartPointer<vtkUnstructuredGrid> controlLevelGrid() {
  return toVtkUnstructuredGrid(extractLevel(sampleDataset().mesh, kBoundLevel));
}

}  // namespace tetskin::test
