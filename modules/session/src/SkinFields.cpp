// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/SkinFields.h"

#include "tetskin/core/ArrayNames.h"
#include "tetskin/deformation/SurfaceFields.h"

namespace tetskin {

std::vector<PointScalars> skinFields(const MultiLevelTetMesh& dataset, int level,
                                     const SurfaceBinding& binding, const Eigen::VectorXd& stress,
                                     const Eigen::VectorXd& strain) {
  const Index firstNode = dataset.levels.at(static_cast<std::size_t>(level)).firstNode;
  const TetMesh rest = extractLevel(dataset, level);
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
