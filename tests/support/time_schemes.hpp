#pragma once
// The flow's two time schemes as the parameter of a test (TEST_P), named in the test list:
//   INSTANTIATE_TEST_SUITE_P(TimeSchemes, Suite, test::both_time_schemes, test::time_scheme_name);
#include <gtest/gtest.h>

#include <string>

#include "io/case.hpp"

namespace flotsam::test {

inline const auto both_time_schemes = testing::Values(TimeScheme::theta, TimeScheme::bdf2);

/// The scheme's name, as in the test list and the case file's time.scheme.
inline std::string scheme_name(TimeScheme scheme) {
  return scheme == TimeScheme::bdf2 ? "bdf2" : "theta";
}

inline std::string time_scheme_name(const testing::TestParamInfo<TimeScheme>& scheme) {
  return scheme_name(scheme.param);
}

}  // namespace flotsam::test
