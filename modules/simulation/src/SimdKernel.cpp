// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/SimdKernel.h"

#include "SimdTarget.h"

namespace tetskin {

bool usesAvx2Kernels() {
#if TETSKIN_AVX2_KERNELS
  static const bool avx2 = [] {
    __builtin_cpu_init();  // (needed where this runs before the other constructors)
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return avx2;
#else
  return false;
#endif
}

}  // namespace tetskin
