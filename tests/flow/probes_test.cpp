// Verifies that ProbeWriter writes <name>_probes.csv: the header of t and each probe's eta, H, u,
// v with units, rows equal to the sampled flow (a test flow known in closed form, eta = 1 + 0.1 x,
// u = (0.5, -0.2 y) on [0, 10] x [0, 2] m), zero depth and velocity at a dry point, rows
// appended without a second header on a restart, and a probe outside the domain refused with its
// name, position, line and case file. The CSV holds 9 significant digits, so the probes stand
// where every value has fewer: then the values read back equal the formula to 1e-12 (relative).
#include "flow/probes.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

/// eta = 1 + 0.1 x [m], u = (0.5, -0.2 y) [m/s] over a flat bed z_b = 0 inside [0, 10] x [0, 2]
/// m, except a dry bank at x >= 8 m with z_b = 3 m: there H = 0 and eta = z_b (as the
/// finite-volume engine returns a dry cell), the velocity left at the formula's nonzero value.
/// The hint is the unit strip floor(x) + 1 holding the point; the last hint received per strip
/// is recorded.
class TestFlow final : public FlowField {
 public:
  static constexpr double bank_x = 8.0;      // [m]
  static constexpr double bank_level = 3.0;  // [m]

  FlowSample sample(const Vec2& p, double /*t*/, int& hint) const override {
    FlowSample out;
    if (p.x() < 0.0 || p.x() > 10.0 || p.y() < 0.0 || p.y() > 2.0) {
      out.inside = false;
      return out;
    }
    hints_received.push_back(hint);
    hint = static_cast<int>(std::floor(p.x())) + 1;
    out.u = Vec2(0.5, -0.2 * p.y());
    if (p.x() >= bank_x) {
      out.eta = bank_level;
      out.H = 0.0;
      return out;
    }
    out.eta = 1.0 + 0.1 * p.x();
    out.H = out.eta;  // z_b = 0
    return out;
  }
  double time_begin() const override { return begin; }
  double time_end() const override { return end; }

  double begin = 0.0, end = 1.0;  // [s] current step
  mutable std::vector<int> hints_received;
};

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> values;
  std::istringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) values.push_back(std::stod(cell));
  return values;
}

void expect_relative(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-12 * std::abs(expected)) << what;
}

// Two wet gauges and one on the dry bank.
const std::vector<Probe> gauges = {
    {.name = "upstream", .position = Vec2(2.0, 0.5), .line = 30},
    {.name = "bridge", .position = Vec2(7.5, 1.25), .line = 31},
    {.name = "bank", .position = Vec2(9.0, 1.0), .line = 32},
};

constexpr const char* header =
    "t [s],upstream_eta [m],upstream_H [m],upstream_u [m/s],upstream_v [m/s],"
    "bridge_eta [m],bridge_H [m],bridge_u [m/s],bridge_v [m/s],"
    "bank_eta [m],bank_H [m],bank_u [m/s],bank_v [m/s]";

void expect_row(const std::string& line, double t) {
  const std::vector<double> row = parse_row(line);
  ASSERT_EQ(row.size(), 13u) << line;
  expect_relative(row[0], t, "t");
  for (std::size_t k = 0; k < gauges.size(); ++k) {
    const Vec2 p = gauges[k].position;
    const bool dry = p.x() >= TestFlow::bank_x;
    const double eta = dry ? TestFlow::bank_level : 1.0 + 0.1 * p.x();  // [m]
    const double H = dry ? 0.0 : eta;                                   // [m]
    const double u = dry ? 0.0 : 0.5, v = dry ? 0.0 : -0.2 * p.y();     // [m/s]
    const std::string& name = gauges[k].name;
    expect_relative(row[1 + 4 * k], eta, name + "_eta");
    expect_relative(row[2 + 4 * k], H, name + "_H");
    expect_relative(row[3 + 4 * k], u, name + "_u");
    expect_relative(row[4 + 4 * k], v, name + "_v");
  }
}

TEST(ProbeWriter, WritesHeaderAndSampledValues) {
  const fs::path path = test::fresh_test_folder("probes") / "river_probes.csv";
  TestFlow flow;
  {
    ProbeWriter probes(path.string(), gauges, flow, "river.yaml", std::nullopt);
    EXPECT_EQ(probes.probe_count(), 3u);
    EXPECT_EQ(probes.path(), path.string());
    EXPECT_EQ(read_lines(path), std::vector<std::string>{header});  // header written at once
    probes.write(0.5);
    flow.begin = 1.0;
    flow.end = 2.0;
    probes.write(1.5);
  }
  const auto lines = read_lines(path);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], header);
  expect_row(lines[1], 0.5);
  expect_row(lines[2], 1.5);
  EXPECT_EQ(lines[1], "0.5,1.2,1.2,0.5,-0.1,1.75,1.75,0.5,-0.25,3,0,0,0");
}

TEST(ProbeWriter, KeepsOneHintPerProbe) {
  const fs::path path = test::fresh_test_folder("probes") / "river_probes.csv";
  TestFlow flow;
  ProbeWriter probes(path.string(), gauges, flow, "river.yaml", std::nullopt);
  probes.write(0.25);
  // The check at construction starts without a hint; write passes back each probe's own strip.
  EXPECT_EQ(flow.hints_received, (std::vector<int>{-1, -1, -1, 3, 8, 10}));
}

TEST(ProbeWriter, AppendAddsRowsWithoutASecondHeader) {
  const fs::path path = test::fresh_test_folder("probes") / "river_probes.csv";
  TestFlow flow;
  {
    ProbeWriter probes(path.string(), gauges, flow, "river.yaml", std::nullopt);
    probes.write(0.0);
    probes.write(1.0);
  }
  flow.begin = 1.0;
  flow.end = 2.0;
  {
    ProbeWriter restarted(path.string(), gauges, flow, "river.yaml", CsvResume{1.0});
    restarted.write(2.0);
  }
  const auto lines = read_lines(path);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], header);
  expect_row(lines[1], 0.0);
  expect_row(lines[2], 1.0);
  expect_row(lines[3], 2.0);
}

TEST(ProbeWriter, ProbeOutsideTheDomainNamesProbeLineAndFile) {
  const fs::path path = test::fresh_test_folder("probes") / "river_probes.csv";
  TestFlow flow;
  std::vector<Probe> probes = gauges;
  probes.push_back({.name = "culvert", .position = Vec2(12.5, 1.0), .line = 42});
  try {
    ProbeWriter writer(path.string(), probes, flow, "cases/river.yaml", std::nullopt);
    FAIL() << "a probe outside the domain was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cases/river.yaml:42: "));
    EXPECT_THAT(e.what(), HasSubstr("probe 'culvert' at (12.5, 1) m is outside the domain"));
  }
  EXPECT_FALSE(fs::exists(path));  // checked before the file is created

  // A probe built in code (line 0) names the file alone.
  const std::vector<Probe> below = {{.name = "deep", .position = Vec2(5.0, -0.25), .line = 0}};
  try {
    ProbeWriter writer(path.string(), below, flow, "river.yaml", std::nullopt);
    FAIL() << "a probe outside the domain was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("river.yaml: output.probes: probe 'deep' at (5, -0.25) m"));
  }
}

}  // namespace
}  // namespace flotsam
