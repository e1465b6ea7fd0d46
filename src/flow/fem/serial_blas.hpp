#pragma once
// The sparse direct solvers (UMFPACK, KLU, CHOLMOD) call BLAS for their dense blocks, and
// Debian's OpenBLAS (libopenblas0-openmp) takes as many threads as OpenMP offers at each call,
// whatever OPENBLAS_NUM_THREADS says. A threaded matrix-vector product splits its sums by thread,
// so a factorisation or a solve on 2 threads differed from one on 1 thread in the last bit (the
// paper's channel after one step, either step; with the reference BLAS the states were
// bit-identical). Held around every call into those solvers, SerialBlas gives BLAS one thread
// and gives back the thread count after: the flow state does not depend on the threads
// (tests/flow/fem/thread_count_determinism_test.cpp), at no measured cost (the solves' blocks are
// too small for a second thread to pay; docs/performance.md).
#include "core/thread_governor.hpp"

namespace flotsam {

class SerialBlas : ThreadCountScope {
 public:
  SerialBlas() : ThreadCountScope(1) {}
};

}  // namespace flotsam
