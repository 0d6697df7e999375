// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Frames of a control level for the tests that write them without a
// simulation behind them.
#include "tetskin/core/FrameFields.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin::test {

// `rest` at `positions` moving with `velocities` (none: still), without
// forces or stresses.
inline FrameFields unloadedFrame(const TetMesh& rest, const Points3& positions,
                                 const Points3& velocities = {}) {
  const Points3 zero = Points3::Zero(rest.nodeCount(), 3);
  return {positions,
          velocities.size() ? velocities : zero,
          zero,
          zero,
          Eigen::VectorXd::Zero(rest.elementCount()),
          Eigen::VectorXd::Zero(rest.elementCount())};
}

}  // namespace tetskin::test
