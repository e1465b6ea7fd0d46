// flotsam: the command-line program. Exit codes (README "The program"): 0 done;
// 1 an error in the input (InputError) or a run that stopped (RunError), one message on stderr;
// 2 an internal error; a command line CLI11 cannot parse exits with CLI11's code (100 and up)
// and the usage on stderr. The log goes to stderr (and --log FILE), results to stdout.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <exception>

#include "cli/commands.hpp"
#include "cli/logging.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "flotsam: floating debris (logs, branches, cars) carried by 2D shallow-water flows,\n"
      "colliding, and jamming at bridge piers. Run `flotsam COMMAND --help` for each command."};
  app.set_version_flag("--version", std::string("flotsam ") + FLOTSAM_VERSION);
  app.require_subcommand(1);
  flotsam::cli::set_up_logging(app);
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
    flotsam::cli::print_error(fmt::format("flotsam: error: {}\n", e.what()));
    return 1;
  } catch (const flotsam::RunError& e) {
    flotsam::cli::print_error(fmt::format("flotsam: run stopped: {}\n", e.what()));
    return 1;
  } catch (const std::exception& e) {
    flotsam::cli::print_error(fmt::format("flotsam: internal error: {}\n", e.what()));
    return 2;
  }
  return 0;
}
