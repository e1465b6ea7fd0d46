// Formulas in x and y parsed by muParser (see expression.hpp). The parser is built once per
// formula and shared by the copies; it reads x and y from the Impl, which evaluation writes.
#include "core/expression.hpp"

#include <fmt/format.h>
#include <muParser.h>

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>
#include <numbers>
#include <regex>
#include <vector>

#include "core/error.hpp"

namespace flotsam {

struct Expression::Impl {
  std::string text;
  std::string origin;
  double x = 0.0;  // [m], bound to the parser's variable x
  double y = 0.0;  // [m], bound to the parser's variable y
  double z = 0.0;  // [m], bound to z when the formula may use it
  mu::Parser parser;
};

namespace {

// The longest formula muParser takes [characters].
constexpr std::size_t longest_formula = mu::MaxLenExpression - 1;

// muParser's messages end with "found at position N" (counted from 0); the message built here
// gives the position counted from 1 instead, so that part is dropped.
std::string without_position(const std::string& message) {
  static const std::regex suffix(R"(\s*(found )?at position \d+\.?$)");
  return std::regex_replace(message, suffix, "");
}

// A formula as messages quote it: whole up to `room` characters, else its start and its length,
// so that a long formula's message stays readable.
std::string shown(const std::string& text, std::size_t room = 120) {
  if (text.size() <= room) return text;
  return fmt::format("{}... ({} characters)", text.substr(0, room - 20), text.size());
}

[[noreturn]] void throw_syntax_error(const std::string& origin, const std::string& text,
                                     const mu::ParserError& error) {
  const int pos = error.GetPos();
  const std::string message = without_position(error.GetMsg());
  if (pos < 0) throw_input_error("{}: syntax error in '{}': {}", origin, shown(text), message);
  if (static_cast<std::size_t>(pos) >= text.size())
    throw_input_error("{}: syntax error at the end of '{}': {}", origin, shown(text), message);
  throw_input_error("{}: syntax error in '{}' at character {} ('{}'): {}", origin, shown(text),
                    pos + 1, shown(text.substr(static_cast<std::size_t>(pos)), 40), message);
}

}  // namespace

Expression::Expression(std::string text, std::string origin, bool uses_z)
    : impl_(std::make_shared<Impl>()) {
  Impl& e = *impl_;
  e.text = std::move(text);
  e.origin = std::move(origin);
  const bool blank = std::all_of(e.text.begin(), e.text.end(), [](char c) {
    return std::isspace(static_cast<unsigned char>(c));
  });
  if (blank) throw_input_error("{}: expected a formula in x and y, got an empty text", e.origin);
  if (e.text.size() > longest_formula)
    throw_input_error(
        "{}: the formula '{}' is longer than the {} characters a formula may hold (the limit of "
        "muParser, which reads it): give the field as a raster or a table instead",
        e.origin, shown(e.text), longest_formula);
  std::vector<std::string> unknown;
  try {
    // muParser built with GCC defines _pi to 12 digits only; both constants are redefined exact.
    e.parser.DefineConst("_pi", std::numbers::pi);
    e.parser.DefineConst("_e", std::numbers::e);
    e.parser.DefineVar("x", &e.x);
    e.parser.DefineVar("y", &e.y);
    if (uses_z) e.parser.DefineVar("z", &e.z);
    e.parser.SetExpr(e.text);
    // Parses the whole formula, collecting its variables instead of failing on unknown ones.
    for (const auto& [name, address] : e.parser.GetUsedVar())
      if (name != "x" && name != "y" && !(uses_z && name == "z")) unknown.push_back(name);
  } catch (const mu::ParserError& error) {
    throw_syntax_error(e.origin, e.text, error);
  }
  if (!unknown.empty()) {
    throw_input_error("{}: unknown variable{} {} in '{}'; a formula may use only {} [m]", e.origin,
                      unknown.size() > 1 ? "s" : "",
                      fmt::format("'{}'", fmt::join(unknown, "', '")), shown(e.text),
                      uses_z ? "x, y and z (the terrain raster's elevation)" : "x and y");
  }
}

const std::string& Expression::text() const {
  static const std::string none;
  return impl_ ? impl_->text : none;
}

const std::string& Expression::origin() const {
  static const std::string none;
  return impl_ ? impl_->origin : none;
}

double Expression::operator()(double x, double y, double z) const {
  assert(impl_ && "an empty Expression has no value; check empty() first");
  Impl& e = *impl_;
  e.x = x;
  e.y = y;
  e.z = z;
  double value = 0.0;
  try {
    value = e.parser.Eval();
  } catch (const mu::ParserError& error) {
    throw_input_error("{}: '{}' cannot be evaluated at (x, y) = ({}, {}) m: {}", e.origin,
                      shown(e.text), x, y, without_position(error.GetMsg()));
  }
  if (!std::isfinite(value)) {
    throw_input_error("{}: '{}' is not finite at (x, y) = ({}, {}) m: its value is {}", e.origin,
                      shown(e.text), x, y, std::isnan(value) ? "nan" : fmt::format("{}", value));
  }
  return value;
}

}  // namespace flotsam
