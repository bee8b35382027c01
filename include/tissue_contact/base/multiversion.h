#pragma once

/**
 * @file
 * TC_MULTIVERSION: a function compiled three times, for AVX-512, AVX2 and
 * the baseline x86-64, the loader picking the copy the CPU can run (GCC's
 * function multiversioning, `target_clones`), with everything it calls
 * inlined into each copy (`flatten`). Only for hot kernels in source files
 * compiled with -ffp-contract=off (CMakeLists.txt): without contraction into
 * FMA and without reassociation the wider registers only vectorize
 * fixed-length loops, and all copies give the same bits as the baseline.
 * Elsewhere (another compiler, another CPU family) it expands to nothing.
 */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && \
  defined(__linux__)
#  define TC_MULTIVERSION \
    __attribute__((target_clones("avx512f", "avx2", "default"), flatten))
#else
#  define TC_MULTIVERSION
#endif
