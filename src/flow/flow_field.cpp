#include "flow/flow_field.hpp"

#include "flow/flow_batch.hpp"

namespace flotsam {

void FlowField::sample_batch(const double* x, const double* y, const double* t, const bool* active,
                             int* hints, BatchFlow& out) const {
  const FlowSample outside{.inside = false};
  for (int k = 0; k < batch_width; ++k)
    out.set(k, active[k] ? sample({x[k], y[k]}, t[k], hints[k]) : outside);
}

}  // namespace flotsam
