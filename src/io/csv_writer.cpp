#include "io/csv_writer.hpp"

#include <fmt/format.h>

#include <spdlog/spdlog.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "core/error.hpp"

namespace flotsam {

namespace {

std::string quoted_if_needed(const std::string& name) {
  if (name.find_first_of(",\"\n") == std::string::npos) return name;
  std::string out = "\"";
  for (const char c : name) {
    if (c == '"') out += '"';  // a quote inside a quoted field is doubled
    out += c;
  }
  out += '"';
  return out;
}

}  // namespace

CsvWriter::CsvWriter(const std::string& path, std::vector<std::string> columns,
                     std::optional<CsvResume> resume)
    : path_(path), columns_(std::move(columns)) {
  const bool continued = resume && rewind(resume->time);
  if (resume && !continued)
    spdlog::warn("'{}' was missing: written again from t = {} s on, with its header", path_,
                 resume->time);
  file_ = std::fopen(path_.c_str(), continued ? "a" : "w");
  if (file_ == nullptr) throw_input_error("cannot write '{}': {}", path_, std::strerror(errno));
  if (continued) return;
  fmt::print(file_, "{}\n", header());
  if (std::fflush(file_) != 0)
    throw_input_error("cannot write '{}': {}", path_, std::strerror(errno));
}

std::string CsvWriter::header() const {
  std::string header;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    if (c > 0) header += ',';
    header += quoted_if_needed(columns_[c]);
  }
  return header;
}

// Rows are compared through their text: the checkpoint's time printed as the rows print it
// (%.9g) and read back, so that its own rows are kept and every later one dropped.
bool CsvWriter::rewind(double time) const {
  std::ifstream in(path_, std::ios::binary);
  if (!in) return false;
  std::string line, kept;
  if (!std::getline(in, line) || line != header() || in.eof())
    throw_input_error(
        "cannot continue '{}': its header is not the one this run writes ({}); the table belongs "
        "to another case or was edited; run afresh (--overwrite) or restore the file",
        path_, header());
  kept = line + '\n';
  const std::string cut_text = fmt::format("{:.9g}", time);
  const double cut = std::strtod(cut_text.c_str(), nullptr);
  while (std::getline(in, line) && !in.eof()) {  // a last line without its newline was cut
    double t = 0.0;
    const auto [end, error] = std::from_chars(line.data(), line.data() + line.size(), t);
    if (error != std::errc() || end == line.data() || t > cut) break;
    kept += line + '\n';
  }
  in.close();
  const std::string part = path_ + ".part";
  {
    std::ofstream out(part, std::ios::binary);
    out << kept;
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(part, ignored);
      throw_input_error("cannot write '{}' (disk full?)", part);
    }
  }
  std::filesystem::rename(part, path_);
  return true;
}

CsvWriter::~CsvWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

CsvWriter::CsvWriter(CsvWriter&& other) noexcept
    : path_(std::move(other.path_)),
      columns_(std::move(other.columns_)),
      file_(std::exchange(other.file_, nullptr)) {}

CsvWriter& CsvWriter::operator=(CsvWriter&& other) noexcept {
  if (this != &other) {
    if (file_ != nullptr) std::fclose(file_);
    path_ = std::move(other.path_);
    columns_ = std::move(other.columns_);
    file_ = std::exchange(other.file_, nullptr);
  }
  return *this;
}

void CsvWriter::row(std::span<const double> values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument(fmt::format("CsvWriter '{}': row of {} values for {} columns",
                                            path_, values.size(), columns_.size()));
  fmt::memory_buffer line;
  for (std::size_t c = 0; c < values.size(); ++c)
    fmt::format_to(std::back_inserter(line), "{}{:.9g}", c ? "," : "", values[c]);
  line.push_back('\n');
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0)
    throw_input_error("cannot write '{}': {}", path_, std::strerror(errno));
}

}  // namespace flotsam
