// flotsam: the command-line program. Subcommands are registered by cli/commands.hpp.
#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include <exception>

#include "core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"flotsam: floating debris carried by 2D shallow-water flows"};
  app.set_version_flag("--version", std::string("flotsam ") + FLOTSAM_VERSION);
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const flotsam::InputError& e) {
    fmt::print(stderr, "flotsam: error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "flotsam: error: {}\n", e.what());
    return 2;
  }
  return 0;
}
