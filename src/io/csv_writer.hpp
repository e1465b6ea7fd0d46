#pragma once
// Time series for spreadsheets and plotting scripts (trajectories, statistics): a CSV file with
// one header line of column names with units, "time [s],x [m],...", then one line per row in
// %.9g. Each row is flushed, so the file is readable while the run goes on and complete up to
// the last row if the run is interrupted. See docs/output-format.md.
#include <cstdio>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace flotsam {

class CsvWriter {
 public:
  /// Creates (replaces) the file and writes the header. Column names should carry their unit,
  /// "speed [m/s]"; a name with a comma or a double quote is quoted (RFC 4180). Throws
  /// InputError naming the path when the file cannot be created. With `append` (a restarted
  /// run) the rows go after those already in the file, and no header is written.
  CsvWriter(const std::string& path, std::vector<std::string> columns, bool append = false);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  CsvWriter(CsvWriter&& other) noexcept;
  CsvWriter& operator=(CsvWriter&& other) noexcept;

  /// One line, one value per column. Throws std::invalid_argument when the count differs from
  /// the number of columns (a programming error), InputError when the write fails (disk full).
  void row(std::span<const double> values);
  void row(std::initializer_list<double> values) { row(std::span(values.begin(), values.size())); }

  const std::string& path() const { return path_; }
  std::size_t column_count() const { return columns_.size(); }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::FILE* file_ = nullptr;
};

}  // namespace flotsam
