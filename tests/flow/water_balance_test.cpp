// Unit tests of the water balance (flow/water_balance.hpp, spec 6.2): its error counts rain and
// infiltration, a basin that starts dry has a relative error measured against the rain, and a
// checkpoint keeps every sum (one written before rain was counted reads with none).
#include "flow/water_balance.hpp"

#include <gtest/gtest.h>

#include "../support/scratch_path.hpp"
#include "io/binary_archive.hpp"

namespace flotsam {
namespace {

TEST(WaterBalance, ErrorCountsRainAndInfiltration) {
  WaterBalance b;
  b.initial_volume = 100.0;
  b.outflow = 30.0;
  b.source = 1.0;
  b.rain = 50.0;
  b.infiltration = 5.0;
  b.volume = 100.0 - 30.0 + 1.0 + 50.0 - 5.0;  // every m^3 accounted for
  EXPECT_EQ(b.error(), 0.0);
  b.volume += 0.232;
  EXPECT_NEAR(b.error(), 0.232, 1e-12);
  EXPECT_NEAR(b.relative_error(), 0.232 / b.volume, 1e-15);  // V(t) > V(0): against V(t)
}

TEST(WaterBalance, BasinStartingDryIsMeasuredAgainstTheRain) {
  WaterBalance b;
  b.rain = 8.0;
  b.infiltration = 8.0;  // all of it soaked away: nothing left
  EXPECT_EQ(b.reference_volume(), 8.0);
  EXPECT_EQ(b.relative_error(), 0.0);
  b.volume = 1e-3;
  EXPECT_NEAR(b.relative_error(), 1e-3 / 8.0, 1e-15);  // the sum rounds at ~1e-15 m^3
  EXPECT_EQ(WaterBalance{}.relative_error(), 0.0);     // no water at all
}

TEST(WaterBalance, CheckpointKeepsEverySum) {
  WaterBalance b;
  b.initial_volume = 1.5, b.volume = 2.5, b.outflow = -0.25, b.source = 1e-17, b.lag = 0.125;
  b.rain = 1.25, b.infiltration = 0.375;
  b.group_outflow = {0.5, -0.75};
  b.group_rate = {0.01, -0.02};
  const std::string path = test::scratch_path("water_balance.bin").string();
  {
    ArchiveWriter w(path);
    write_water_balance(w, "flow", b);
    w.close();
  }
  ArchiveReader r(path);
  const WaterBalance read = read_water_balance(r, "flow");
  EXPECT_EQ(read.initial_volume, b.initial_volume);
  EXPECT_EQ(read.volume, b.volume);
  EXPECT_EQ(read.outflow, b.outflow);
  EXPECT_EQ(read.source, b.source);
  EXPECT_EQ(read.lag, b.lag);
  EXPECT_EQ(read.rain, b.rain);
  EXPECT_EQ(read.infiltration, b.infiltration);
  EXPECT_EQ(read.group_outflow, b.group_outflow);
  EXPECT_EQ(read.group_rate, b.group_rate);
}

TEST(WaterBalance, CheckpointWithoutRainReadsAsNone) {
  const std::string path = test::scratch_path("water_balance_before_rain.bin").string();
  {
    ArchiveWriter w(path);
    w.write("flow.balance", std::vector<double>{1.0, 2.0, 0.5, 0.0, 0.0});
    w.write("flow.group_outflow", std::vector<double>{0.5});
    w.write("flow.group_rate", std::vector<double>{0.0});
    w.close();
  }
  ArchiveReader r(path);
  const WaterBalance read = read_water_balance(r, "flow");
  EXPECT_EQ(read.volume, 2.0);
  EXPECT_EQ(read.rain, 0.0);
  EXPECT_EQ(read.infiltration, 0.0);
}

}  // namespace
}  // namespace flotsam
