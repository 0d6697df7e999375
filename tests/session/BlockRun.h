// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The run layer's tests' small scene: an upright block (y up), one level of
// 2x4x2 cubes, wobbling.

#include "Shapes.h"
#include "tetskin/session/SimulationSession.h"

namespace tetskin::test {

inline MultiLevelTetMesh uprightBlock() {
  MultiLevelTetMesh mesh;
  appendLevel(mesh, tetGrid(2, 4, 2, {0.2, 0.4, 0.2}));
  return mesh;
}

inline RunSpec blockWobble(double timeStep = 0.01) {
  RunSpec spec;
  spec.level = 0;
  spec.options.timeStep = timeStep;
  spec.options.material.youngsModulus = 2e4;
  spec.scenario = "wobble";
  spec.datasetName = "block";
  return spec;
}

}  // namespace tetskin::test
