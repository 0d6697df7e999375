// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the filter tests share: the sample dataset, its level 1 as a VTK grid
// numbered from 0, bunny_8k as VTK poly data, and an error observer.

#include <vtkCallbackCommand.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <string>

#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin::test {

inline const std::string kFilterData = std::string(TETSKIN_SOURCE_DIR) + "/data/";
constexpr int kBoundLevel = 1;

inline const Dataset& sampleDataset() {
  static const Dataset d = loadDataset(kFilterData + "bunny.json");
  return d;
}

inline const SurfaceMesh& bunnySurface() {
  static const SurfaceMesh s = readObj(kFilterData + "bunny_8k.obj");
  return s;
}

// Level 1 of the sample dataset with level-local node ids (as `tetskin
// convert --level 1` writes it).
inline vtkSmartPointer<vtkUnstructuredGrid> controlLevelGrid() {
  return toVtkUnstructuredGrid(extractLevel(sampleDataset().mesh, kBoundLevel));
}

// Collects the error messages an object reports (and keeps them off stderr).
class ErrorLog {
 public:
  explicit ErrorLog(vtkObject* object) {
    callback_->SetClientData(&text_);
    callback_->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
      *static_cast<std::string*>(client) += static_cast<const char*>(call);
    });
    object->AddObserver(vtkCommand::ErrorEvent, callback_);
  }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
  vtkNew<vtkCallbackCommand> callback_;
};

}  // namespace tetskin::test
