#pragma once
// A formula in x and y [m] written in a case file (muParser's syntax: + - * / ^, sin, exp, sqrt,
// min, max, the ternary `c ? a : b`, comparisons), for bed.expression and flow.initial.eta / u /
// v (docs/case-format.md). A formula that edits a terrain raster may also use z, the raster's
// bed elevation at (x, y) [m]. Parsed once when the case is read: a syntax error is an InputError
// naming `origin` (file, line, key) and the position in the text. Evaluated at setup, point by
// point; a value that is not finite is an InputError naming the origin and the point.
//
// Not for hot loops and not thread-safe: one evaluation at a time (the parser binds x, y to
// members it writes before each evaluation).
#include <memory>
#include <string>

namespace flotsam {

class Expression {
 public:
  Expression() = default;  // empty: no formula given
  /// Parses `text`; `origin` names where it was written, e.g. "case.yaml:12: flow.initial.eta".
  /// With `uses_z` the formula may also use the variable z.
  Expression(std::string text, std::string origin, bool uses_z = false);

  bool empty() const { return impl_ == nullptr; }
  const std::string& text() const;
  const std::string& origin() const;
  /// The formula's value at (x, y) [m], with z [m] where the formula may use it.
  double operator()(double x, double y, double z = 0.0) const;

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
};

}  // namespace flotsam
