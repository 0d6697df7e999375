// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Where the AVX2 versions of the kernels exist (SimdKernel.h): on x86-64 with
// GCC or Clang, whose target attribute compiles one function for AVX2/FMA
// inside an otherwise baseline translation unit.
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define TETSKIN_AVX2_KERNELS 1
#define TETSKIN_AVX2_TARGET __attribute__((target("avx2,fma")))
#else
#define TETSKIN_AVX2_KERNELS 0
#define TETSKIN_AVX2_TARGET
#endif
