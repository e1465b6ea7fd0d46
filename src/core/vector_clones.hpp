#pragma once
// Run-time dispatch of vector loops: a function marked FLOTSAM_VECTOR_CLONES is built for the
// default x86-64 (SSE2), AVX2 and AVX-512 (x86-64-v4), and the best one the processor has is
// chosen when the program loads (GCC's target_clones). A file holding such functions is compiled
// with -fno-math-errno, -fno-trapping-math and -ffp-contract=off (CMakeLists.txt), so that no
// a * b + c becomes an FMA and every clone gives the same bits.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define FLOTSAM_VECTOR_CLONES __attribute__((target_clones("default", "avx2", "arch=x86-64-v4")))
#else
#define FLOTSAM_VECTOR_CLONES
#endif
