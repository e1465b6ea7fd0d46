#include "io/csv_writer.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
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

CsvWriter::CsvWriter(const std::string& path, std::vector<std::string> columns, bool append)
    : path_(path), columns_(std::move(columns)) {
  file_ = std::fopen(path_.c_str(), append ? "a" : "w");
  if (file_ == nullptr) throw_input_error("cannot write '{}': {}", path_, std::strerror(errno));
  if (append) return;
  std::string header;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    if (c > 0) header += ',';
    header += quoted_if_needed(columns_[c]);
  }
  fmt::print(file_, "{}\n", header);
  std::fflush(file_);
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
