// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The corotated element pass's kernel (CorotatedFem::update): groups of four
// elements through the lane arithmetic of CorotatedLanes.h, compiled for
// AVX2/FMA and for the baseline (SimdKernel.h), then added into the forces
// element by element and into the matrix a block row of four elements at a
// time.

#include <cstddef>

#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin::corotated {

// What one element pass reads and writes, as plain pointers: the kernels are
// compiled for two targets, so no Eigen code is shared between them (only
// the scalar rotation fallback, compiled for the baseline, uses Eigen).
struct PassArgs {
  const ElementGroup* groups;
  RotationEstimates* estimates;
  const ElementScatter* scatter;
  std::size_t elementCount;
  const double* x;
  const double* velocity;  // null: no velocity term
  double velocityWeight;
  double stiffnessScale;          // s: the matrix is s K + D
  double rotationScale;           // q: the matrix gains q K_rot
  double rotationVelocityWeight;  // u: the force gains -u K_rot v
  double* force;
  double* values;     // the matrix's
  double* rotations;  // 9 per stored element, column-major (Eigen::Matrix3d)
};

// Assembles groups [first, last): the caller makes sure that no other
// thread adds into the same nodes meanwhile (CorotatedFem's colouring).
using GroupsKernel = void (*)(const PassArgs& args, std::size_t first, std::size_t last);
GroupsKernel groupsKernel(SimdKernel kernel);

}  // namespace tetskin::corotated
