// Kernels built more than once, for wider vector instructions than the x86-64 baseline, pick their
// build at run time. Every build gives the same bits (integer arithmetic, and floating-point
// operations in the same order without fused multiply-adds); tests compare them, through `baseline`.
#pragma once

namespace dfvn {

enum class Simd {
  best,      // the widest build the CPU runs: AVX-512, then AVX2, as each kernel has them
  baseline,  // SSE2, which every x86-64 CPU has
};

// Whether this CPU runs the AVX2 builds (Sobol's scramble, the turning-bands evaluation kernel, the
// nearest-neighbour search) and the AVX-512 builds (F, DQ and VL: the turning-bands evaluation kernel, the
// nearest-neighbour search). False off x86-64, where only the baseline build exists. The kernels and the
// tests that compare their builds ask the same question here.
inline bool cpu_has_avx2() {
#if defined(__x86_64__)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

inline bool cpu_has_avx512() {
#if defined(__x86_64__)
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
#else
  return false;
#endif
}

}  // namespace dfvn
