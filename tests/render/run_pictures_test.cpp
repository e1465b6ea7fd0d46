// render_run (render/run_pictures.hpp) refuses a state file that does not belong to the run's
// mesh, naming the file (a state copied from another run).
#include "render/run_pictures.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "io/run_state.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

/// The description of a run called `name` on a 10 m x 4 m rectangle of 5 x 2 squares, every
/// boundary group open (1) or a wall (0).
RunDescription small_run(const std::string& name, std::uint8_t open) {
  RunDescription run;
  run.name = name;
  run.mesh = make_rectangle_mesh({.length = 10, .width = 4, .nx = 5, .ny = 2});
  run.open_group.assign(run.mesh.group_names.size(), open);
  return run;
}

TEST(RunPictures, AStateFileOfAnotherRunIsRefusedNamingTheFile) {
  const auto dir = test::fresh_test_folder("flotsam_run_pictures_test");
  const RunDescription run = small_run("small", 0);
  write_run_description((dir / "run.bin").string(), run);
  const Mesh other = make_rectangle_mesh({.length = 10, .width = 4, .nx = 6, .ny = 2});
  const auto n = static_cast<std::size_t>(other.node_count());
  write_run_snapshot((dir / "state_000000.bin").string(), 0.0,
                     std::vector<double>(static_cast<std::size_t>(other.vertex_count), 1.0),
                     std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), {}, BodySet{}, {});
  std::string message = "no error";
  try {
    render_run(dir.string(), PictureOptions{}, {});
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_THAT(message,
              HasSubstr((dir / "state_000000.bin").string() + "' does not belong to the run in"));
  EXPECT_THAT(message, HasSubstr("the run's mesh 18 vertices"));
  std::filesystem::remove_all(dir);
}

TEST(RunDescription, DecksRoundTripAndARunWithoutThemReadsAsBefore) {
  const auto dir = test::fresh_test_folder("flotsam_run_description_decks");
  RunDescription run = small_run("bridge", 1);
  write_run_description((dir / "plain.bin").string(), run);
  run.decks = {{Vec2(4, -1), Vec2(4, 5), Vec2(6, 5), Vec2(6, -1)}};
  write_run_description((dir / "deck.bin").string(), run);
  const RunDescription plain = read_run_description((dir / "plain.bin").string());
  const RunDescription deck = read_run_description((dir / "deck.bin").string());
  EXPECT_TRUE(plain.decks.empty());
  EXPECT_EQ(plain.open_group, run.open_group);
  ASSERT_EQ(deck.decks.size(), 1u);
  EXPECT_EQ(deck.decks[0], run.decks[0]);
  EXPECT_EQ(deck.mesh.nodes, run.mesh.nodes);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
