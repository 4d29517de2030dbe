// Kernels built more than once, for wider vector instructions than the x86-64 baseline, pick their
// build at run time. Every build gives the same bits (integer arithmetic, and floating-point
// operations in the same order without fused multiply-adds); tests compare them, through `baseline`.
#pragma once

namespace dfvn {

enum class Simd {
  best,      // the widest build the CPU runs: AVX-512 or AVX2, depending on the kernel
  baseline,  // SSE2, which every x86-64 CPU has
};

}  // namespace dfvn
