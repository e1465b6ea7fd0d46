// flotsam: the command-line program. Errors in the input (InputError) and runs that stop
// (RunError) print one message on stderr and exit with 1; a parse error of the command line
// exits as CLI11 says (usage on stderr).
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <exception>

#include "cli/commands.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "flotsam: floating debris (logs, branches, cars) carried by 2D shallow-water flows,\n"
      "colliding, and jamming at bridge piers. Run `flotsam COMMAND --help` for each command."};
  app.set_version_flag("--version", std::string("flotsam ") + FLOTSAM_VERSION);
  app.require_subcommand(1);
  flotsam::cli::add_mesh_command(app);
  flotsam::cli::add_info_command(app);
  flotsam::cli::add_run_command(app);
  flotsam::cli::add_render_command(app);
  flotsam::cli::add_ensemble_command(app);
  try {
    app.parse(argc, argv);  // runs the chosen command's callback
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const flotsam::InputError& e) {
    fmt::print(stderr, "flotsam: error: {}\n", e.what());
    return 1;
  } catch (const flotsam::RunError& e) {
    fmt::print(stderr, "flotsam: run stopped: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "flotsam: internal error: {}\n", e.what());
    return 2;
  }
  return 0;
}
