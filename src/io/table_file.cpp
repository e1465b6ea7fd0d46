#include "io/table_file.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace flotsam {

namespace {

/// The numbers of a line split at commas and blanks (two expected); false when a field is not a
/// number.
bool parse_numbers(std::string_view line, std::vector<double>& numbers) {
  numbers.clear();
  std::size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && (line[k] == ',' || line[k] == ' ' || line[k] == '\t')) ++k;
    if (k == line.size()) break;
    std::size_t end = k;
    while (end < line.size() && line[end] != ',' && line[end] != ' ' && line[end] != '\t') ++end;
    double value = 0.0;
    const auto [last, error] = std::from_chars(line.data() + k, line.data() + end, value);
    if (error != std::errc() || last != line.data() + end || !std::isfinite(value)) return false;
    numbers.push_back(value);
    k = end;
  }
  return true;
}

}  // namespace

std::vector<std::pair<double, double>> read_table_file(
    const std::string& path, std::string_view abscissa,
    const std::function<std::string(double)>& check) {
  std::ifstream in(path);
  if (!in)
    throw_input_error("cannot open the table file '{}': {}", path,
                      std::filesystem::exists(path) ? "not readable" : "no such file");
  std::vector<std::pair<double, double>> rows;
  std::vector<double> numbers;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t comment = line.find('#');
    const std::string_view text = std::string_view(line).substr(0, comment);
    if (text.find_first_not_of(" \t,") == std::string_view::npos) continue;
    if (!parse_numbers(text, numbers)) {
      if (rows.empty() && number == 1) continue;  // the header
      throw_input_error("{}:{}: expected two numbers '{}, value', got '{}'", path, number, abscissa,
                        line);
    }
    if (numbers.size() != 2)
      throw_input_error("{}:{}: expected two numbers '{}, value', got {}", path, number, abscissa,
                        numbers.size());
    if (!rows.empty() && !(numbers[0] > rows.back().first))
      throw_input_error(
          "{}:{}: {} = {} does not come after the previous row's {} = {}; a table's {} must be "
          "strictly increasing",
          path, number, abscissa, numbers[0], abscissa, rows.back().first, abscissa);
    if (const std::string expected = check(numbers[1]); !expected.empty())
      throw_input_error("{}:{}: expected {}, got {}", path, number, expected, numbers[1]);
    rows.emplace_back(numbers[0], numbers[1]);
  }
  if (in.bad()) throw_input_error("{}: read error: {}", path, std::strerror(errno));
  if (rows.empty()) throw_input_error("{}: the table has no rows", path);
  return rows;
}

}  // namespace flotsam
