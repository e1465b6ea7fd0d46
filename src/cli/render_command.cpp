// flotsam render RUN_DIR: the pictures of a run (water surface, velocity through the bridges,
// bodies among the piers, a frame per output and a movie when ffmpeg is installed).
#include <fmt/core.h>

#include "cli/commands.hpp"
#include "cli/logging.hpp"
#include "render/frame.hpp"
#include "render/run_pictures.hpp"

namespace flotsam::cli {

void add_render_command(CLI::App& app) {
  struct Options {
    std::string run_directory;
    int width = 1600, height = 600;
    bool no_frames = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Draw the pictures of a run into its folder (PNG, with Cairo): water_surface.png,\n"
      "velocity.png, bodies.png at the last output, frames/frame_NNNNNN.png at every output,\n"
      "and movie.mp4 when ffmpeg is installed.\n"
      "Example: flotsam render out/bridge_piers");
  cmd->add_option("run", options->run_directory, "folder written by `flotsam run`")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--width", options->width, "picture width [px]")->check(CLI::Range(200, 8000));
  cmd->add_option("--height", options->height, "picture height [px]")->check(CLI::Range(150, 8000));
  cmd->add_flag("--no-frames", options->no_frames, "only the three pictures of the last output");
  cmd->callback([options] {
    PictureOptions picture{options->width, options->height, !options->no_frames, true};
    const auto files = render_run(options->run_directory, picture, [](const std::string& f) {
      print_result(fmt::format("wrote {}\n", f));
    });
    release_font_caches();
    print_result(fmt::format("{} pictures in {}\n", files.size(), options->run_directory));
  });
}

}  // namespace flotsam::cli
