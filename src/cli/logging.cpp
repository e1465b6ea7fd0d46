#include "cli/logging.hpp"

#include <fmt/core.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>

#include "core/error.hpp"

namespace flotsam::cli {

namespace {

std::shared_ptr<spdlog::sinks::basic_file_sink_mt> log_file;  // with --log

// Appends `text` to the log file alone, as one record of the log's pattern.
void log_to_file(const std::string& text) {
  if (!log_file) return;
  std::string line = text;
  if (!line.empty() && line.back() == '\n') line.pop_back();
  log_file->log(spdlog::details::log_msg("", spdlog::level::info, line));
  log_file->flush();
}

void open_log_file(const std::string& path) {
  try {
    log_file = std::make_shared<spdlog::sinks::basic_file_sink_mt>(path, false);  // append
  } catch (const spdlog::spdlog_ex& e) {
    throw_input_error("--log {}: cannot open the log file: {}", path, e.what());
  }
  log_file->set_level(spdlog::level::debug);
  auto logger = spdlog::default_logger();
  logger->sinks().push_back(log_file);
  logger->set_level(spdlog::level::debug);  // the console keeps its own level, info
  log_to_file(fmt::format("flotsam {} starts", FLOTSAM_VERSION));
}

void print_to(std::FILE* stream, const std::string& text) {
  fmt::print(stream, "{}", text);
  std::fflush(stream);
  log_to_file(text);
}

}  // namespace

void set_up_logging(CLI::App& app) {
  auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  console->set_level(spdlog::level::info);
  auto logger = std::make_shared<spdlog::logger>("", console);  // unnamed: "[time] [level] text"
  logger->set_level(spdlog::level::info);
  spdlog::set_default_logger(logger);
  app.add_option_function<std::string>("--log", open_log_file,
                                       "append the whole log (debug messages and the summary "
                                       "included) to this file")
      ->trigger_on_parse();
  app.fallthrough();  // `flotsam run case.yaml --log run.log` as well as before the command
}

void print_result(const std::string& text) {
  print_to(stdout, text);
}

void print_error(const std::string& text) {
  print_to(stderr, text);
}

}  // namespace flotsam::cli
