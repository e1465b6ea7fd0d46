#pragma once
// Time series for spreadsheets and plotting scripts (trajectories, statistics): a CSV file with
// one header line of column names with units, "time [s],x [m],...", then one line per row in
// %.9g. Each row is flushed, so the file is readable while the run goes on and complete up to
// the last row if the run is interrupted. See docs/output-format.md.
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace flotsam {

/// How a table of a restarted run continues (docs/output-format.md "Restarting a run"): the rows
/// whose first column (the time) is at most `time` [s], the checkpoint's, are kept; later rows,
/// written after the checkpoint by the run that stopped, and a cut last line are dropped, so
/// that the restarted run writes them once. A missing table is written again with its header
/// (the rows before `time` are lost; a warning says so); one with another header is an
/// InputError naming it.
struct CsvResume {
  double time = 0.0;  // [s]
};

class CsvWriter {
 public:
  /// Creates (replaces) the file and writes the header. Column names should carry their unit,
  /// "speed [m/s]"; a name with a comma or a double quote is quoted (RFC 4180). Throws
  /// InputError naming the path when the file cannot be created. With `resume` (a restarted
  /// run) the file is rewound to the checkpoint's time (CsvResume) and rows go after it.
  CsvWriter(const std::string& path, std::vector<std::string> columns,
            std::optional<CsvResume> resume = std::nullopt);
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
  std::string header() const;
  /// Keeps the rows up to `time`; true when the file exists.
  bool rewind(double time) const;
  std::string path_;
  std::vector<std::string> columns_;
  std::FILE* file_ = nullptr;
};

}  // namespace flotsam
