// An ensemble's section, its members' draws and case files, and the member result's text form.
#include "ensemble/member_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "ensemble/ensemble_config.hpp"
#include "ensemble/member_result.hpp"
#include "io/case_file.hpp"

namespace flotsam {
namespace {

const char* case_text = R"(name: t
mesh:
  channel: {length: 240, width: 60, piers: [{x: 150, y: 30, radius: 8}]}
flow:
  initial: {eta_start: 4.0, eta_end: 3.9}
  boundaries:
    inflow: {type: discharge, value: [[0, 10], [60, 30]]}
    outflow: {type: elevation, value: 3.9}
    bank_right: {type: wall}
    bank_left: {type: wall}
    pier_1: {type: wall}
time: {end: 10, step: 1}
ensemble:
  members: 3
  seed: 5
  vary:
    log_density: [500, 800]
    restitution: {normal: [0.5, 0.1]}
    discharge_scale: {choice: [0.5, 2]}
  sweep: {input: log_length, values: [4, 8]}
bodies:
  release:
    - {line: [[120, 10], [120, 50]], count: 2, width: 0.5}
)";

TEST(EnsembleConfig, SplitKeepsLineNumbersAndReadsTheSection) {
  const SplitCaseText split = split_ensemble_text(case_text);
  EXPECT_EQ(std::count(split.case_text.begin(), split.case_text.end(), '\n'),
            std::count(split.ensemble_text.begin(), split.ensemble_text.end(), '\n'));
  EXPECT_EQ(split.case_text.find("ensemble"), std::string::npos);
  EXPECT_NE(split.case_text.find("bodies:"), std::string::npos);  // after the section
  const EnsembleConfig c = parse_ensemble(split.ensemble_text, "case.yaml");
  EXPECT_EQ(c.members, 3);
  EXPECT_EQ(c.total_members(), 6);
  ASSERT_EQ(c.vary.size(), 3u);  // in the inputs' order
  EXPECT_EQ(c.vary[0].input, EnsembleInput::log_density);
  EXPECT_EQ(c.vary[1].input, EnsembleInput::discharge_scale);
  EXPECT_EQ(c.vary[2].distribution.kind, Distribution::Kind::normal);
  EXPECT_EQ(c.line, 13);
  const Case base = parse_case(split.case_text, "case.yaml");  // the rest is an ordinary case
  EXPECT_EQ(base.bodies.releases.size(), 1u);
}

TEST(EnsembleConfig, UnknownInputNamesFileLineAndNearestInput) {
  std::string text = case_text;
  text.replace(text.find("log_density: [500"), 11, "log_densty:");
  const SplitCaseText split = split_ensemble_text(text);
  try {
    parse_ensemble(split.ensemble_text, "case.yaml");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("case.yaml:17: ensemble.vary.log_densty"), std::string::npos) << message;
    EXPECT_NE(message.find("did you mean 'log_density'"), std::string::npos) << message;
  }
}

TEST(MemberInputs, DrawsDependOnSeedAndDrawOnly) {
  const EnsembleConfig c = parse_ensemble(split_ensemble_text(case_text).ensemble_text, "c.yaml");
  const MemberInputs a = draw_member_inputs(c, 1, 1), b = draw_member_inputs(c, 4, 1);
  EXPECT_EQ(a.draw, 1);
  EXPECT_EQ(b.draw, 1);
  EXPECT_EQ(b.sweep_index, 1);
  EXPECT_EQ(a.value(EnsembleInput::log_length), 4.0);
  EXPECT_EQ(b.value(EnsembleInput::log_length), 8.0);
  // Common random numbers: the same draw at both sweep values, bit for bit.
  EXPECT_EQ(a.value(EnsembleInput::log_density), b.value(EnsembleInput::log_density));
  EXPECT_EQ(a.release_seeds, b.release_seeds);
  const double density = a.value(EnsembleInput::log_density);
  EXPECT_GE(density, 500.0);
  EXPECT_LT(density, 800.0);
  const double scale = a.value(EnsembleInput::discharge_scale);
  EXPECT_TRUE(scale == 0.5 || scale == 2.0);
  EXPECT_NE(draw_member_inputs(c, 0, 1).value(EnsembleInput::log_density), density);
  // Removing an input leaves the others' draws as they were.
  EnsembleConfig fewer = c;
  fewer.vary.erase(fewer.vary.begin() + 1);
  EXPECT_EQ(draw_member_inputs(fewer, 1, 1).value(EnsembleInput::log_density), density);
}

TEST(MemberCase, InputsWrittenInAndReadBackExactly) {
  const SplitCaseText split = split_ensemble_text(case_text);
  const EnsembleConfig c = parse_ensemble(split.ensemble_text, "c.yaml");
  const MemberInputs inputs = draw_member_inputs(c, 4, 1);
  MemberCaseContext context;
  context.directory = "/tmp/ensemble_dir";
  context.source = "c.yaml";
  const std::string text = member_case_text(YAML::Load(split.case_text), inputs, context);
  const Case m = parse_case(text, "/tmp/ensemble_dir/member_0004.yaml");
  EXPECT_EQ(m.name, "member_0004");
  EXPECT_EQ(m.output.directory, "/tmp/ensemble_dir");
  const Release& r = m.bodies.releases.at(0);
  EXPECT_EQ(r.length_min, 8.0);
  EXPECT_EQ(r.length_max, 8.0);
  EXPECT_EQ(r.density_min, inputs.value(EnsembleInput::log_density));  // bit for bit
  EXPECT_EQ(static_cast<long>(r.seed), inputs.release_seeds.at(0));
  EXPECT_EQ(m.bodies.contact.restitution, inputs.value(EnsembleInput::restitution));
  const double scale = inputs.value(EnsembleInput::discharge_scale);
  const BoundaryCondition& inflow = m.flow.boundaries.at(0);
  EXPECT_DOUBLE_EQ(inflow.value(0.0), 10.0 * scale);
  EXPECT_DOUBLE_EQ(inflow.value(60.0), 30.0 * scale);
}

TEST(MemberCase, ARateOnACountReleaseIsTheEnsemblesError) {
  const SplitCaseText split = split_ensemble_text(case_text);
  EnsembleConfig c = parse_ensemble(split.ensemble_text, "c.yaml");
  c.vary.push_back({EnsembleInput::release_rate, {}});
  EXPECT_THROW(member_case_text(YAML::Load(split.case_text), draw_member_inputs(c, 0, 1), {}),
               InputError);
}

TEST(MemberResult, TextFormRoundTripsBitForBit) {
  MemberResult r;
  r.inputs.member = 12;
  r.inputs.sweep_index = 1;
  r.inputs.draw = 2;
  r.inputs.values = {{EnsembleInput::log_length, 0.1 + 0.2}, {EnsembleInput::restitution, 1e-300}};
  r.inputs.release_seeds = {2147483647};
  r.released = 7;
  r.trapped = 3;
  r.bridges.push_back({true, 12.5, 3, 4, 0.6180339887498949, std::nan(""), 0.1 + 0.7});
  r.gaps = {{{true, 12.5, 0.75, 1.0 / 7.0}, {false, std::nan(""), 0.1, 0.0}}};
  r.bodies.push_back({9, {1.0 / 3.0, 2.0}, {100.25, -1e-17}, BodyFate::trapped, false});
  const MemberResult back = parse_member(serialize_member(r));
  EXPECT_EQ(serialize_member(back), serialize_member(r));
  EXPECT_EQ(back.inputs.values[0].second, 0.1 + 0.2);
  EXPECT_EQ(back.bodies[0].start.x(), 1.0 / 3.0);
  EXPECT_EQ(back.bridges[0].max_blockage, 0.6180339887498949);
  EXPECT_TRUE(std::isnan(back.bridges[0].max_rise));
  EXPECT_EQ(back.bridges[0].max_opening_closed, 0.1 + 0.7);
  EXPECT_EQ(back.gaps[0][0].max_opening_closed, 1.0 / 7.0);
  EXPECT_EQ(back.bodies[0].fate, BodyFate::trapped);
  // A half-written result (no end line) is refused.
  const std::string text = serialize_member(r);
  EXPECT_THROW(parse_member(text.substr(0, text.size() / 2)), std::invalid_argument);
}

}  // namespace
}  // namespace flotsam
