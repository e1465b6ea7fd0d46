#include "bodies/release.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "mesh/simple_polygon.hpp"

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

/// `at` names the release ("c.yaml: releases[2]").
void check_range(const std::string& at, const char* key, double lo, double hi, bool positive) {
  if (positive && !(lo > 0.0)) throw_input_error("{}: {}_min = {} must be positive", at, key, lo);
  if (!(lo <= hi))
    throw_input_error("{}: {}_min = {} is larger than {}_max = {}", at, key, lo, key, hi);
}

/// True when the rectangles of two bodies (centre, long axis e, half extents h) overlap: no
/// separating axis among the four sides' normals. Touching is not overlapping.
bool rectangles_overlap(const Vec2& centre_a, const Vec2& e_a, const Vec2& h_a,
                        const Vec2& centre_b, const Vec2& e_b, const Vec2& h_b) {
  const Vec2 d = centre_b - centre_a;
  const Vec2 axes[4] = {e_a, perp(e_a), e_b, perp(e_b)};
  for (const Vec2& n : axes) {
    const double reach_a = h_a.x() * std::abs(e_a.dot(n)) + h_a.y() * std::abs(perp(e_a).dot(n));
    const double reach_b = h_b.x() * std::abs(e_b.dot(n)) + h_b.y() * std::abs(perp(e_b).dot(n));
    if (std::abs(d.dot(n)) >= reach_a + reach_b) return false;  // [m]
  }
  return true;
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

void check_clear_of_bodies(const BodySpec& spec, const BodySet& bodies, const PlacementCheck& check,
                           const std::string& what) {
  const Vec2 e{std::cos(spec.angle), std::sin(spec.angle)};
  const Vec2 h{0.5 * spec.length, 0.5 * spec.width};
  for (int i = 0; i < bodies.size(); ++i) {
    if (bodies.state[i] == BodyState::gone) continue;
    const Vec2 h_i = bodies.half_extents(i);
    if ((bodies.position[i] - spec.position).norm() >= h.norm() + h_i.norm()) continue;
    if (rectangles_overlap(spec.position, e, h, bodies.position[i], bodies.axis(i), h_i))
      throw_input_error("{}: {} at ({}, {}): overlaps body {} at ({}, {})", where(check), what,
                        spec.position.x(), spec.position.y(), bodies.id[i], bodies.position[i].x(),
                        bodies.position[i].y());
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
    lines_.push_back({releases[k], std::mt19937_64(releases[k].seed), 0});
    const Release& r = releases[k];
    const int ri = static_cast<int>(k);
    const std::string at = location(ri);
    if (r.count < 0) throw_input_error("{}: count = {} bodies must be positive", at, r.count);
    if (r.count == 0 && !(r.rate > 0.0))
      throw_input_error("{}: rate = {} bodies/min must be positive", at, r.rate);
    if (r.count == 0 && !(r.end_time >= r.start_time))
      throw_input_error("{}: end_time = {} s is before start_time = {} s", at, r.end_time,
                        r.start_time);
    if (!r.zone.empty()) {
      if (const std::string defect = polygon_defect(r.zone); !defect.empty())
        throw_input_error("{}.zone: {}", at, defect);
    } else if (r.line_start == r.line_end) {
      throw_input_error("{}.line: both ends are ({}, {}) m; a release line needs a length", at,
                        r.line_start.x(), r.line_start.y());
    }
    check_range(at, "length", r.length_min, r.length_max, true);
    check_range(at, "width", r.width_min, r.width_max, true);
    check_range(at, "density", r.density_min, r.density_max, true);
    check_range(at, "angle", r.angle_min_deg, r.angle_max_deg, false);
  }
}

std::string Releaser::location(int r) const {
  const int line = lines_[r].release.source_line;
  if (line > 0) return fmt::format("{}:{}: bodies.release[{}]", where(check_), line, r);
  return fmt::format("{}: releases[{}]", where(check_), r);
}

void Releaser::check_inside(const FlowField& flow, double t) const {
  constexpr int line_samples = 64;  // points along a line, ends included
  for (std::size_t r = 0; r < lines_.size(); ++r) {
    const Release& rel = lines_[r].release;
    int hint = -1;
    for (std::size_t k = 0; k < rel.zone.size(); ++k) {
      if (flow.sample(rel.zone[k], t, hint).inside) continue;
      throw_input_error(
          "{}.zone: corner {} at ({}, {}) m is outside the domain; a zone's corners must lie in "
          "the mesh",
          location(static_cast<int>(r)), k + 1, rel.zone[k].x(), rel.zone[k].y());
    }
    if (!rel.zone.empty()) continue;
    for (int k = 0; k < line_samples; ++k) {
      const Vec2 p = rel.line_start + (k / (line_samples - 1.0)) * (rel.line_end - rel.line_start);
      if (flow.sample(p, t, hint).inside) continue;
      throw_input_error(
          "{}.line: the point ({:.3f}, {:.3f}) m of the line from ({}, {}) to ({}, {}) m is "
          "outside the domain (beyond a bank, in a pier or a building); a release line must lie "
          "in the water's domain",
          location(static_cast<int>(r)), p.x(), p.y(), rel.line_start.x(), rel.line_start.y(),
          rel.line_end.x(), rel.line_end.y());
    }
  }
}

double Releaser::next_time(const Line& line) {
  const Release& rel = line.release;
  if (rel.count > 0)
    return line.count < rel.count ? rel.start_time : std::numeric_limits<double>::infinity();
  const double t_k = rel.start_time + static_cast<double>(line.count) * (60.0 / rel.rate);  // [s]
  return t_k <= rel.end_time ? t_k : std::numeric_limits<double>::infinity();
}

Vec2 Releaser::draw_position(int r, Line& line) const {
  const Release& rel = line.release;
  if (rel.zone.empty()) {
    const double s = uniform(line.random, 0.0, 1.0);
    return rel.line_start + s * (rel.line_end - rel.line_start);
  }
  // Uniform in the polygon: uniform in its bounding box, kept when inside (rejection). A valid
  // zone has a positive area, so a point comes; the bound only stops a sliver of a zone that
  // fills next to nothing of its box from looping for ever.
  constexpr long most_draws = 1'000'000;
  const BoundingBox box = bounding_box(rel.zone);
  for (long draw = 0; draw < most_draws; ++draw) {
    const Vec2 p{uniform(line.random, box.min.x(), box.max.x()),
                 uniform(line.random, box.min.y(), box.max.y())};
    if (polygon_contains(rel.zone, p)) return p;
  }
  const Vec2 size = box.max - box.min;
  throw_input_error(
      "{}.zone: no point inside the zone in {} draws; it fills {:.2g} of its bounding box (draw "
      "a thin zone as several)",
      location(r), most_draws, std::abs(signed_area(rel.zone)) / (size.x() * size.y()));
}

int Releaser::release(BodySet& bodies, const FlowField& flow, double /*t0*/, double t1) {
  // Every body due before t1 not yet released is released now (a late first call catches up).
  int released_now = 0;
  for (std::size_t r = 0; r < lines_.size(); ++r) {
    Line& line = lines_[r];
    const Release& rel = line.release;
    for (;;) {
      const double t_k = next_time(line);
      if (!(t_k < t1)) break;
      // Draw in a fixed order, so that body k of a release depends only on the seed and k.
      BodySpec spec;
      spec.shape = rel.shape;
      spec.length = uniform(line.random, rel.length_min, rel.length_max);
      spec.width = uniform(line.random, rel.width_min, rel.width_max);
      spec.height = rel.shape == Shape::log ? spec.width : rel.height;
      spec.density = uniform(line.random, rel.density_min, rel.density_max);
      ++line.count;
      // A body that does not fit where it is drawn (a long log across a bank near the line's
      // end, or on a log released before it that has not yet drifted off the line) is drawn
      // again in position and angle. When none of the tries fits, a count is an error; a body
      // released at a rate waits, and is drawn again at the next flow step: the water brings
      // no log onto another, and the contacts would push the two apart at once, through a bank
      // if one is near.
      constexpr int tries = 100;
      bool placed = false, fits_the_walls = false;
      for (int attempt = 1; !placed; ++attempt) {
        spec.position = draw_position(static_cast<int>(r), line);
        spec.angle = uniform(line.random, rel.angle_min_deg, rel.angle_max_deg) * pi / 180.0;
        const std::string what =
            fmt::format("releases[{}] body {} (released at t = {} s, {} tries)", r, line.count - 1,
                        t_k, attempt);
        try {
          check_body_placement(spec, flow, t_k, check_, what);
          fits_the_walls = true;
          check_clear_of_bodies(spec, bodies, check_, what);
          placed = true;
        } catch (const InputError&) {
          if (attempt < tries) continue;
          if (rel.count > 0 || !fits_the_walls) throw;
          break;
        }
      }
      if (!placed) {  // waits for room on its line
        if (waits_++ == 0)
          spdlog::warn(
              "{}: body {} due at t = {} s finds no room clear of the bodies released "
              "before it; it waits for the next flow step (said once per run)",
              location(static_cast<int>(r)), line.count - 1, t_k);
        --line.count;
        break;
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
    throw_input_error("the release state in the checkpoint does not fit the case's {} releases",
                      lines_.size());
}

}  // namespace flotsam
