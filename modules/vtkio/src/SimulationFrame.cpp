// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/SimulationFrame.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin {
vtkSmartPointer<vtkUnstructuredGrid> simulationFrame(const TetMesh& rest, const Points3& positions,
                                                     const Points3& velocities,
                                                     const Points3& externalForces,
                                                     const Eigen::VectorXd& vonMisesStress,
                                                     int level) {
  TetMesh deformed{positions, rest.elements};
  vtkSmartPointer<vtkUnstructuredGrid> grid = toVtkUnstructuredGrid(deformed);
  grid->GetPointData()->AddArray(toVtkVectors("Displacement", positions - rest.nodes));
  grid->GetPointData()->AddArray(toVtkVectors("Velocity", velocities));
  grid->GetPointData()->AddArray(toVtkVectors("ExternalForce", externalForces));
  auto stress = vtkSmartPointer<vtkDoubleArray>::New();
  stress->SetName("VonMisesStress");
  auto ratio = vtkSmartPointer<vtkDoubleArray>::New();
  ratio->SetName("VolumeRatio");
  auto levels = vtkSmartPointer<vtkIntArray>::New();
  levels->SetName("Level");
  stress->SetNumberOfValues(rest.elementCount());
  ratio->SetNumberOfValues(rest.elementCount());
  levels->SetNumberOfValues(rest.elementCount());
  for (Index e = 0; e < rest.elementCount(); ++e) {
    stress->SetValue(e, vonMisesStress[e]);
    ratio->SetValue(e, elementVolume(deformed, e) / elementVolume(rest, e));
    levels->SetValue(e, level);
  }
  grid->GetCellData()->AddArray(stress);
  grid->GetCellData()->AddArray(ratio);
  grid->GetCellData()->AddArray(levels);
  return grid;
}

}  // namespace tetskin
