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
#include <omp.h>

namespace flotsam {

class SerialBlas {
 public:
  SerialBlas() : threads_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~SerialBlas() { omp_set_num_threads(threads_); }
  SerialBlas(const SerialBlas&) = delete;
  SerialBlas& operator=(const SerialBlas&) = delete;

 private:
  int threads_;
};

}  // namespace flotsam
