// Verifies that CsvWriter writes a header of column names with units and rows in %.9g that read
// back to the written values within %.9g's rounding (relative 5e-9), flushed after every row.
#include "io/csv_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

fs::path scratch_file(const std::string& name) {
  const fs::path dir = test::scratch_path("flotsam_csv_test");
  fs::create_directories(dir);
  return dir / name;
}

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> values;
  std::istringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) values.push_back(std::stod(cell));
  return values;
}

TEST(CsvWriter, RowsRoundTripToNineSignificantDigits) {
  const fs::path path = scratch_file("trajectory.csv");
  const std::vector<std::vector<double>> rows = {
      {0.0, 1.0, -2.5},
      {0.1, 123456.789012345, 1e-300},
      {3600.0, -7.0 / 3.0, 6.02214076e23},
  };
  {
    CsvWriter csv(path.string(), {"time [s]", "x [m]", "y [m]"});
    for (const auto& row : rows) csv.row(row);
  }
  const auto lines = read_lines(path);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "time [s],x [m],y [m]");
  EXPECT_EQ(lines[1], "0,1,-2.5");
  EXPECT_EQ(lines[2], "0.1,123456.789,1e-300");
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto values = parse_row(lines[r + 1]);
    ASSERT_EQ(values.size(), 3u);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(values[c], rows[r][c], 5e-9 * std::abs(rows[r][c])) << "row " << r;
  }
}

TEST(CsvWriter, EachRowIsOnDiskBeforeTheNext) {
  const fs::path path = scratch_file("live.csv");
  CsvWriter csv(path.string(), {"time [s]", "speed [m/s]"});
  EXPECT_EQ(read_lines(path), std::vector<std::string>{"time [s],speed [m/s]"});
  csv.row({1.0, 0.5});
  EXPECT_EQ(read_lines(path), (std::vector<std::string>{"time [s],speed [m/s]", "1,0.5"}));
}

TEST(CsvWriter, NamesWithCommasOrQuotesAreQuoted) {
  const fs::path path = scratch_file("quoted.csv");
  { CsvWriter csv(path.string(), {"force x, y [N]", "say \"hi\"", "plain"}); }
  EXPECT_EQ(read_lines(path)[0], "\"force x, y [N]\",\"say \"\"hi\"\"\",plain");
}

TEST(CsvWriter, RowOfTheWrongLengthIsRefused) {
  CsvWriter csv(scratch_file("short.csv").string(), {"a", "b"});
  EXPECT_THROW(csv.row({1.0}), std::invalid_argument);
}

TEST(CsvWriter, UnwritablePathIsAnInputErrorNamingIt) {
  const std::string path = (scratch_file("x").parent_path() / "no_such_dir" / "a.csv").string();
  try {
    CsvWriter csv(path, {"a"});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + path + "': No such file or directory");
  }
}

}  // namespace
}  // namespace flotsam
