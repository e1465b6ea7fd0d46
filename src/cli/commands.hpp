#pragma once
// The subcommands of `flotsam`. Each registers itself on the app with its options and a callback
// that CLI11 runs once the command line is parsed.
#include <CLI/CLI.hpp>
#include <string>

namespace flotsam::cli {

void add_mesh_command(CLI::App& app);
void add_info_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_ensemble_command(CLI::App& app);

/// Refuses to replace an existing file unless `overwrite` (nothing the user wrote is lost
/// without asking).
void check_can_write(const std::string& path, bool overwrite);

}  // namespace flotsam::cli
