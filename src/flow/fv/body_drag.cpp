#include "flow/fv/body_drag.hpp"

#include "flow/fv/fv_solver.hpp"

namespace flotsam {

void BodyDrag::reset(int n) {
  rate.assign(n, 0.0);
  target.assign(n, Vec2::Zero());
  velocity_time.assign(n, Vec2::Zero());
  time.assign(n, 0.0);
}

void BodyDrag::apply(ConservedState& U, int i, double dt, double dry_depth) {
  const double a = rate[i], h = U.h[i];
  if (a == 0.0 || h <= dry_depth) return;
  const double factor = 1.0 / (1.0 + dt * a / h);
  U.hu[i] = (U.hu[i] + dt * target[i].x()) * factor;
  U.hv[i] = (U.hv[i] + dt * target[i].y()) * factor;
  velocity_time[i] += (dt / h) * Vec2(U.hu[i], U.hv[i]);
  time[i] += dt;
}

}  // namespace flotsam
