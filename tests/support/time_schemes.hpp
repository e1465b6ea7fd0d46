#pragma once
// The flow's two time schemes as the parameter of a test (TEST_P), named in the test list:
//   INSTANTIATE_TEST_SUITE_P(TimeSchemes, Suite, test::both_time_schemes, test::time_scheme_name);
// and each with either step of the FEM engine (test::all_steps_and_times).
#include <gtest/gtest.h>

#include <string>

#include "flow_schemes.hpp"
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

/// A step (flow.scheme) with a time scheme: the four pairs, named "coupled_theta" and so on.
struct StepAndTime {
  FlowScheme flow;
  TimeScheme time;
};

inline const auto all_steps_and_times =
    testing::Values(StepAndTime{FlowScheme::coupled, TimeScheme::theta},
                    StepAndTime{FlowScheme::coupled, TimeScheme::bdf2},
                    StepAndTime{FlowScheme::segregated, TimeScheme::theta},
                    StepAndTime{FlowScheme::segregated, TimeScheme::bdf2});

inline std::string step_and_time_name(const testing::TestParamInfo<StepAndTime>& p) {
  return scheme_name(p.param.flow) + "_" + scheme_name(p.param.time);
}

}  // namespace flotsam::test
