#include "flow/flow_engine.hpp"

#include <spdlog/spdlog.h>

#include "core/error.hpp"

namespace flotsam {

void finish_march(double change, double t) {
  if (change > settled_change)
    throw_run_error(
        "frozen mode: the flow still changes by {:.3g} of its largest velocity per step after "
        "{} s of marching (time.spin_up_end); raise it or check the case",
        change, t);
  spdlog::info("steady flow by marching: change {:.3g} per step at t = {} s", change, t);
}

}  // namespace flotsam
