// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Where the AVX2 versions of the kernels are AVX2 code (SimdKernel.h): on
// x86-64 with GCC or Clang, whose target attribute compiles one function
// for AVX2/FMA inside an otherwise baseline translation unit. Elsewhere they
// compile as baseline code and are never chosen.
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define TETSKIN_AVX2_KERNELS 1
#define TETSKIN_AVX2_TARGET __attribute__((target("avx2,fma")))
#else
#define TETSKIN_AVX2_KERNELS 0
#define TETSKIN_AVX2_TARGET
#endif

#include "tetskin/simulation/SimdKernel.h"

namespace tetskin {

// The AVX2 version of a kernel where `choice` and the CPU allow it, else the
// baseline one.
template <typename Function>
Function chooseKernel(SimdKernel choice, Function avx2, Function baseline) {
  return choice == SimdKernel::Fastest && usesAvx2Kernels() ? avx2 : baseline;
}

}  // namespace tetskin
