// Flood envelopes (flow/flood_envelope.hpp): running maxima, arrival at the end of the step that
// wets a cell, wet duration from then on, speeds only where wet; checkpoints.
#include "flow/flood_envelope.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "io/binary_archive.hpp"

namespace flotsam {
namespace {

TEST(FloodEnvelope, RunningMaximaArrivalAndWetDuration) {
  FloodEnvelope e;
  e.reset(3, 0.05);
  // cell 0 wets at t = 1 s and stays wet; cell 1 wets at 2 s and dries at 3 s; cell 2 only a film
  e.update({0.1, 0.0, 1e-4}, {0.3, 0.0, 1e-3}, {0.4, 0.0, 0.0}, 1.0, 1.0);
  e.update({0.2, 0.08, 1e-4}, {0.2, 0.04, 0.0}, {0.0, 0.03, 0.0}, 2.0, 1.0);
  e.update({0.15, 0.01, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 3.0, 1.0);
  EXPECT_EQ(e.max_depth[0], 0.2);
  EXPECT_EQ(e.max_unit_discharge[0], 0.5);  // |(0.3, 0.4)| at t = 1 s
  EXPECT_EQ(e.max_speed[0], 5.0);           // 0.5 / 0.1
  EXPECT_EQ(e.arrival[0], 1.0);
  EXPECT_EQ(e.wet_duration[0], 2.0);  // from 1 s to 3 s
  EXPECT_EQ(e.arrival[1], 2.0);
  EXPECT_EQ(e.wet_duration[1], 0.0);  // wet at 2 s, dry at 3 s
  EXPECT_DOUBLE_EQ(e.max_speed[1], 0.05 / 0.08);
  EXPECT_TRUE(std::isnan(e.arrival[2]));  // never deeper than 5 cm
  EXPECT_EQ(e.max_speed[2], 0.0);         // a film, not wet: no speed
  EXPECT_EQ(e.max_unit_discharge[2], 1e-3);
}

TEST(FloodEnvelope, CheckpointKeepsTheRunningMaxima) {
  const auto dir = test::fresh_test_folder("flotsam_flood_envelope_test");
  FloodEnvelope e;
  e.reset(2, 0.01);
  e.update({0.3, 0.0}, {0.1, 0.0}, {0.0, 0.0}, 4.0, 0.5);
  const std::string path = (dir / "envelope.bin").string();
  {
    ArchiveWriter w(path);
    e.save(w, "flow");
    w.close();
  }
  FloodEnvelope back;
  back.reset(2, 0.01);
  ArchiveReader r(path);
  back.restore(r, "flow");
  EXPECT_EQ(back.max_depth, e.max_depth);
  EXPECT_EQ(back.max_unit_discharge, e.max_unit_discharge);
  EXPECT_EQ(back.arrival[0], 4.0);
  EXPECT_TRUE(std::isnan(back.arrival[1]));
  FloodEnvelope other;
  other.reset(3, 0.01);
  ArchiveReader again(path);
  EXPECT_THROW(other.restore(again, "flow"), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
