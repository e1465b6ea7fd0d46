#pragma once
// f(k) for every k in [0, n): on the threads (OpenMP, static schedule: each thread a run of the
// indices) when n is at least `threshold`, else on this thread with no parallel region at all
// (one costs about a microsecond even on one thread, and a small contact group meets many). For
// loops whose iterations are independent: the result is the same either way.

namespace flotsam {

template <class Index, class F>
void parallel_for(Index n, Index threshold, F&& f) {
  if (n >= threshold) {
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < n; ++k) f(k);
  } else {
    for (Index k = 0; k < n; ++k) f(k);
  }
}

}  // namespace flotsam
