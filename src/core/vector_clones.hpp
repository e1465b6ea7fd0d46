#pragma once
// Run-time dispatch of vector loops: a function marked FLOTSAM_VECTOR_CLONES is built for the
// default x86-64 (SSE2), AVX2 and AVX-512 (x86-64-v4), and the best one the processor has is
// chosen when the program loads (GCC's target_clones). A file holding such functions is compiled
// with -fno-math-errno, -fno-trapping-math and -ffp-contract=off (CMakeLists.txt), so that no
// a * b + c becomes an FMA and every clone gives the same bits. Under AddressSanitizer (the
// sanitizer and fuzz builds) the clones are off: GCC 12's UBSan reports a member access through a
// null pointer in the AVX clones of the soft step's lane solver, on references to locals, which the
// default build of the same source does not.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__)
#define FLOTSAM_VECTOR_CLONES __attribute__((target_clones("default", "avx2", "arch=x86-64-v4")))
#else
#define FLOTSAM_VECTOR_CLONES
#endif
