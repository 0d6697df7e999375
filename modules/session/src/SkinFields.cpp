// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/SkinFields.h"

#include "tetskin/core/ArrayNames.h"
#include "tetskin/deformation/SurfaceFields.h"

namespace tetskin {

std::vector<PointScalars> skinFields(const TetMesh& rest, Index firstNode,
                                     const SurfaceBinding& binding, const Eigen::VectorXd& stress,
                                     const Eigen::VectorXd& strain) {
  std::vector<PointScalars> fields;
  if (stress.size() > 0)
    fields.push_back(
        {arrays::kVonMisesStress, boundValues(binding, firstNode, nodeMeans(rest, stress))});
  if (strain.size() > 0)
    fields.push_back(
        {arrays::kEquivalentStrain, boundValues(binding, firstNode, nodeMeans(rest, strain))});
  return fields;
}

}  // namespace tetskin
