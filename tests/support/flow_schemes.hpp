#pragma once
// The FEM engine's two steps (flow.scheme) as the parameter of a test (TEST_P), named in the
// test list:
//   INSTANTIATE_TEST_SUITE_P(FlowSchemes, Suite, test::both_flow_schemes, test::flow_scheme_name);
#include <gtest/gtest.h>

#include <string>

#include "io/case.hpp"

namespace flotsam::test {

inline const auto both_flow_schemes = testing::Values(FlowScheme::coupled, FlowScheme::segregated);

/// The step's name, as in the test list and the case file's flow.scheme.
inline std::string scheme_name(FlowScheme scheme) {
  return scheme == FlowScheme::segregated ? "segregated" : "coupled";
}

inline std::string flow_scheme_name(const testing::TestParamInfo<FlowScheme>& scheme) {
  return scheme_name(scheme.param);
}

}  // namespace flotsam::test
