#pragma once
// Where the command line's messages go: the log (information, warnings, errors) on standard
// error, results (summaries, `wrote ...`) on standard output, and with `--log FILE` the whole
// log, debug messages and the summary included, appended to FILE (README "The program").
#include <CLI/CLI.hpp>
#include <string>

namespace flotsam::cli {

/// Sends spdlog's default logger to standard error and adds the option `--log FILE`, which takes
/// effect as soon as it is parsed (before the command's callback runs).
void set_up_logging(CLI::App& app);

/// Prints `text` on standard output and, with `--log`, appends it to the log file.
void print_result(const std::string& text);

/// Prints `text` on standard error and, with `--log`, appends it to the log file.
void print_error(const std::string& text);

}  // namespace flotsam::cli
