#pragma once
// A table of two columns in a CSV file, for a long series that a case gives by file
// (`value: {file: hydrograph.csv}`, docs/case-format.md "Tables from files"): one row per line,
// "x,value" (commas, or blanks), an optional header line of names first, '#' comments. A case
// file holds about 110 bytes of memory per byte of its text while it is read (yaml-cpp's nodes);
// a table read from a file holds 16 bytes per row.
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace flotsam {

/// The rows of `path`: strictly increasing x, each value checked by `check` (which returns ""
/// when the value is allowed, else what was expected, e.g. "a number >= 0"). An InputError names
/// "file:line" and what was wrong: a line that is not two numbers, an x that does not increase,
/// a value out of range, a file without rows. `abscissa` names x in messages ("t").
std::vector<std::pair<double, double>> read_table_file(
    const std::string& path, std::string_view abscissa,
    const std::function<std::string(double)>& check);

}  // namespace flotsam
