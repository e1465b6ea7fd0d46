#include "contact/contact_solver.hpp"

#include "contact/sequential_impulses.hpp"
#include "contact/soft_step.hpp"

namespace flotsam {

std::unique_ptr<ContactSolver> make_contact_solver(const ContactConfig& config) {
  if (config.solver == ContactSolverKind::soft_step) return std::make_unique<SoftStep>(config);
  return std::make_unique<SequentialImpulses>(config);
}

}  // namespace flotsam
