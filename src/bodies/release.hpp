#pragma once
// Bodies entering the domain (spec 5): given explicitly (position, angle, velocity), or released
// from a line or a zone (a polygon), at a rate or a given count at once, with sizes, densities
// and angles drawn uniformly in ranges from a seeded std::mt19937_64, so that the same seed gives
// the same bodies.
//
// Every body is checked where it is placed; a bad one is an InputError naming it:
//   * a non-positive length, width, height or density, or a width larger than the length;
//   * its centre or a corner outside the domain ("overlapping a pier" is the same: a pier is a
//     hole in the mesh);
//   * released with a count: overlapping a body already in the set (parked cars side by side).
// A body may start on a dry point (a log on a floodplain, finite-volume engine): it rests on the
// bed, grounded (spec 3.4), until water lifts or drags it.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "bodies/body_set.hpp"
#include "flow/flow_field.hpp"
#include "io/case.hpp"

namespace flotsam {

/// Where bodies are checked: the case file for messages.
struct PlacementCheck {
  std::string source;  // the case file ("" when built in code)
};

/// Checks the explicit bodies against the flow at time t and appends them; returns the index
/// of the first one. Messages name `bodies[k]` and the body's id.
int add_explicit_bodies(BodySet& bodies, const std::vector<BodySpec>& specs, const FlowField& flow,
                        double t, const PlacementCheck& check);

/// Checks one body spec; `what` names it in messages (e.g. "bodies[2] (id 7)").
void check_body_placement(const BodySpec& spec, const FlowField& flow, double t,
                          const PlacementCheck& check, const std::string& what);

/// Checks that a body placed by spec overlaps no body of the set that is not gone (bodies
/// released together with a count); `what` names it in messages.
void check_clear_of_bodies(const BodySpec& spec, const BodySet& bodies, const PlacementCheck& check,
                           const std::string& what);

/// The releases of a case (lines and zones), each with its own random stream.
class Releaser {
 public:
  /// Checks the releases (rate > 0 unless a count is given, ranges ordered and positive, a zone
  /// a simple polygon, a line of some length); messages name `releases[k]`, or the case file's
  /// line and key.
  Releaser(std::vector<Release> releases, const PlacementCheck& check);

  /// Checks, before the run writes anything, that every corner of every zone and every line (64
  /// points along it) lie in the domain of `flow` at time t.
  void check_inside(const FlowField& flow, double t) const;

  /// Appends the bodies whose release times fall in [t0, t1) (and any earlier one not yet
  /// released): t_k = start + k 60/rate (k = 0, 1, ..., t_k <= end), or t_k = start for the
  /// `count` bodies of a count. Each is placed at rest at a uniform point of its line or zone
  /// (a zone's by rejection in its bounding box) with uniform L, l, density and angle, clear of
  /// the walls and of every body (100 tries; then a count is an error, and a body due at a rate
  /// waits for the next call). Returns how many were released.
  int release(BodySet& bodies, const FlowField& flow, double t0, double t1);

  /// Bodies released so far by release r.
  long released(int r) const { return lines_[r].count; }
  /// Flow steps at which a body due at a rate found no room on its line or zone (every try
  /// overlapped a body released before it) and waited for the next step.
  long waits() const { return waits_; }

  /// The random streams and counts as text, and back (checkpoints: a restarted run releases
  /// the same bodies).
  std::string save_state() const;
  void restore_state(const std::string& text);

 private:
  struct Line {  // a release line or zone
    Release release;
    std::mt19937_64 random;
    long count = 0;  // bodies released so far
  };

  /// When body `line.count` of release r is due [s]; +infinity when the release is over.
  static double next_time(const Line& line);
  /// A uniform point of the release's line or zone, drawn from its stream [m].
  Vec2 draw_position(int r, Line& line) const;
  /// "case.yaml:14: bodies.release[2]" (a case file's release), else "case.yaml: releases[2]".
  std::string location(int r) const;

  std::vector<Line> lines_;
  PlacementCheck check_;
  long waits_ = 0;
};

}  // namespace flotsam
