#include "bodies/release.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace flotsam {

namespace {

std::string where(const PlacementCheck& check) {
  return check.source.empty() ? std::string("case") : check.source;
}

/// A uniform draw in [lo, hi] from the top 53 bits of one 64-bit draw: the same numbers on
/// every standard library (std::uniform_real_distribution is implementation-defined).
double uniform(std::mt19937_64& random, double lo, double hi) {
  const double unit = static_cast<double>(random() >> 11) * 0x1.0p-53;  // [0, 1)
  return lo + (hi - lo) * unit;
}

void check_range(const PlacementCheck& check, int r, const char* key, double lo, double hi,
                 bool positive) {
  if (positive && !(lo > 0.0))
    throw_input_error("{}: releases[{}]: {}_min = {} must be positive", where(check), r, key, lo);
  if (!(lo <= hi))
    throw_input_error("{}: releases[{}]: {}_min = {} is larger than {}_max = {}", where(check), r,
                      key, lo, key, hi);
}

}  // namespace

void check_body_placement(const BodySpec& spec, const FlowField& flow, double t,
                          const PlacementCheck& check, const std::string& what) {
  const auto fail = [&](const std::string& why) {
    throw_input_error("{}: {} at ({}, {}): {}", where(check), what, spec.position.x(),
                      spec.position.y(), why);
  };
  if (!(spec.length > 0.0)) fail(fmt::format("length {} m must be positive", spec.length));
  if (!(spec.width > 0.0)) fail(fmt::format("width {} m must be positive", spec.width));
  if (spec.shape == Shape::box && !(spec.height > 0.0))
    fail(fmt::format("height {} m must be positive", spec.height));
  if (!(spec.density > 0.0)) fail(fmt::format("density {} kg/m^3 must be positive", spec.density));
  if (spec.width > spec.length)
    fail(fmt::format("width {} m is larger than length {} m (L is the long side)", spec.width,
                     spec.length));

  int hint = -1;
  const FlowSample at_G = flow.sample(spec.position, t, hint);
  if (!at_G.inside) fail("outside the domain");
  const Vec2 e{std::cos(spec.angle), std::sin(spec.angle)};
  const Vec2 half_L = 0.5 * spec.length * e, half_l = 0.5 * spec.width * perp(e);
  const Vec2 corners[4] = {spec.position + half_L + half_l, spec.position + half_L - half_l,
                           spec.position - half_L - half_l, spec.position - half_L + half_l};
  for (const Vec2& corner : corners) {
    int corner_hint = hint;
    if (!flow.sample(corner, t, corner_hint).inside)
      fail(fmt::format("corner ({}, {}) is outside the domain (overlapping a pier or a bank)",
                       corner.x(), corner.y()));
  }
}

int add_explicit_bodies(BodySet& bodies, const std::vector<BodySpec>& specs, const FlowField& flow,
                        double t, const PlacementCheck& check) {
  const int first = bodies.size();
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const BodySpec& spec = specs[k];
    const std::string what =
        spec.id >= 0 ? fmt::format("bodies[{}] (id {})", k, spec.id) : fmt::format("bodies[{}]", k);
    check_body_placement(spec, flow, t, check, what);
    bodies.add(spec);
  }
  return first;
}

Releaser::Releaser(std::vector<Release> releases, const PlacementCheck& check) : check_(check) {
  for (std::size_t k = 0; k < releases.size(); ++k) {
    const Release& r = releases[k];
    const int ri = static_cast<int>(k);
    if (!(r.rate > 0.0))
      throw_input_error("{}: releases[{}]: rate = {} bodies/min must be positive", where(check), ri,
                        r.rate);
    if (!(r.end_time >= r.start_time))
      throw_input_error("{}: releases[{}]: end_time = {} s is before start_time = {} s",
                        where(check), ri, r.end_time, r.start_time);
    check_range(check, ri, "length", r.length_min, r.length_max, true);
    check_range(check, ri, "width", r.width_min, r.width_max, true);
    check_range(check, ri, "density", r.density_min, r.density_max, true);
    check_range(check, ri, "angle", r.angle_min_deg, r.angle_max_deg, false);
    lines_.push_back({r, std::mt19937_64(r.seed), 0});
  }
}

int Releaser::release(BodySet& bodies, const FlowField& flow, double /*t0*/, double t1) {
  // Every body due before t1 not yet released is released now (a late first call catches up).
  int released_now = 0;
  for (std::size_t r = 0; r < lines_.size(); ++r) {
    Line& line = lines_[r];
    const Release& rel = line.release;
    const double interval = 60.0 / rel.rate;  // [s] between two bodies
    for (;;) {
      const double t_k = rel.start_time + static_cast<double>(line.count) * interval;
      if (t_k >= t1 || t_k > rel.end_time) break;
      // Draw in a fixed order, so that body k of a line depends only on the seed and k.
      BodySpec spec;
      spec.shape = rel.shape;
      spec.length = uniform(line.random, rel.length_min, rel.length_max);
      spec.width = uniform(line.random, rel.width_min, rel.width_max);
      spec.height = rel.shape == Shape::log ? spec.width : rel.height;
      spec.density = uniform(line.random, rel.density_min, rel.density_max);
      ++line.count;
      // A body that does not fit where it is drawn (a long log across a bank near the line's
      // end) is drawn again along the line and in angle; only when none of the tries fits is
      // the release an error.
      constexpr int tries = 100;
      for (int attempt = 1;; ++attempt) {
        const double s = uniform(line.random, 0.0, 1.0);
        spec.position = rel.line_start + s * (rel.line_end - rel.line_start);
        spec.angle = uniform(line.random, rel.angle_min_deg, rel.angle_max_deg) * pi / 180.0;
        try {
          check_body_placement(spec, flow, t_k, check_,
                               fmt::format("releases[{}] body {} (released at t = {} s, {} tries)",
                                           r, line.count - 1, t_k, attempt));
          break;
        } catch (const InputError&) {
          if (attempt == tries) throw;
        }
      }
      bodies.add(spec);
      ++released_now;
    }
  }
  return released_now;
}

std::string Releaser::save_state() const {
  std::ostringstream out;
  for (const Line& line : lines_) out << line.count << ' ' << line.random << '\n';
  return out.str();
}

void Releaser::restore_state(const std::string& text) {
  std::istringstream in(text);
  for (Line& line : lines_) in >> line.count >> line.random;
  if (!in)
    throw_input_error(
        "the release state in the checkpoint does not fit the case's {} "
        "release lines",
        lines_.size());
}

}  // namespace flotsam
