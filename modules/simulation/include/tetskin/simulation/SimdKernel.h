// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The simulation's hot loops (CG's block product, the corotated element
// pass) exist in two versions in one binary: an AVX2/FMA one, chosen at run
// time where the CPU has both, and a baseline (SSE2) one that runs on every
// x86-64 CPU. No -march flag: the package runs everywhere.

namespace tetskin {

// Which version runs: the fastest this CPU has, or the baseline one (for
// tests and benchmarks of both on one machine).
enum class SimdKernel { Fastest, Baseline };

// Whether SimdKernel::Fastest means the AVX2 versions on this CPU.
bool usesAvx2Kernels();

}  // namespace tetskin
