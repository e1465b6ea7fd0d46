#include "ensemble/ensemble_pictures.hpp"

namespace flotsam {

std::vector<std::string> draw_ensemble_pictures(const std::string&,
                                                const std::vector<MemberResult>&,
                                                const EnsembleStatistics&, const EnsembleConfig&,
                                                const Mesh&) {
  return {};
}

}  // namespace flotsam
