#include "coupling/backwater.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "core/error.hpp"
#include "mesh/interpolation.hpp"

namespace flotsam {

std::vector<Vec2> line_sample_points(const Vec2& a, const Vec2& b, int samples) {
  if (samples < 1)
    throw std::invalid_argument(fmt::format("line_sample_points: {} samples", samples));
  std::vector<Vec2> points;
  points.reserve(static_cast<std::size_t>(samples));
  for (int k = 0; k < samples; ++k)
    points.push_back(a + (k + 0.5) / static_cast<double>(samples) * (b - a));
  return points;
}

namespace {

double check_mean(double sum, int inside, const Vec2& a, const Vec2& b) {
  if (inside == 0)
    throw std::invalid_argument(
        fmt::format("mean_eta_along: no point of ({}, {}) -> ({}, {}) m lies inside the domain",
                    a.x(), a.y(), b.x(), b.y()));
  return sum / static_cast<double>(inside);
}

void check_size(const Mesh& mesh, std::span<const double> eta) {
  if (eta.size() != static_cast<std::size_t>(mesh.vertex_count))
    throw std::invalid_argument(fmt::format("backwater: eta of {} values for {} vertices of '{}'",
                                            eta.size(), mesh.vertex_count, mesh.source));
}

double mean_at(const Mesh& mesh, const std::vector<Location>& locations,
               std::span<const double> eta) {
  check_size(mesh, eta);
  double sum = 0.0;  // [m]
  for (const Location& l : locations) sum += interpolate_p1(mesh, l, eta);
  return sum / static_cast<double>(locations.size());
}

}  // namespace

double mean_eta_along(const Mesh& mesh, const PointLocator& locator, std::span<const double> eta,
                      const Vec2& a, const Vec2& b, int samples) {
  check_size(mesh, eta);
  double sum = 0.0;  // [m]
  int inside = 0, hint = -1;
  for (const Vec2& p : line_sample_points(a, b, samples)) {
    const Location l = locator.locate(p, hint);
    hint = l.element;
    if (!l.inside) continue;
    sum += interpolate_p1(mesh, l, eta);
    ++inside;
  }
  return check_mean(sum, inside, a, b);
}

double mean_eta_along(const FlowField& flow, double t, const Vec2& a, const Vec2& b, int samples) {
  double sum = 0.0;  // [m]
  int inside = 0, hint = -1;
  for (const Vec2& p : line_sample_points(a, b, samples)) {
    const FlowSample s = flow.sample(p, t, hint);
    if (!s.inside) continue;
    sum += s.eta;
    ++inside;
  }
  return check_mean(sum, inside, a, b);
}

BackwaterProbe::BackwaterProbe(const Mesh& mesh, const JamGeometry& geometry, int samples)
    : mesh_(&mesh) {
  const PointLocator locator(mesh);
  for (const Bridge& bridge : geometry.bridges) {
    const Vec2 offset = bridge.backwater_distance * bridge.downstream;  // [m]
    Section section{.bridge = bridge.name,
                    .a = bridge.start - offset,
                    .b = bridge.end - offset,
                    .locations = {}};
    int hint = -1;
    for (const Vec2& p : line_sample_points(section.a, section.b, samples)) {
      const Location l = locator.locate(p, hint);
      hint = l.element;
      if (l.inside) section.locations.push_back(l);
    }
    if (section.locations.empty())
      throw_input_error(
          "{}: the backwater section of bridge '{}', {} m upstream of its axis, from ({}, {}) to "
          "({}, {}) m, lies outside the mesh; set the bridge's backwater_distance so that it "
          "crosses the river",
          mesh.source, bridge.name, bridge.backwater_distance, section.a.x(), section.a.y(),
          section.b.x(), section.b.y());
    sections_.push_back(std::move(section));
  }
}

std::vector<double> BackwaterProbe::mean_eta(std::span<const double> eta) const {
  std::vector<double> means;
  for (const Section& s : sections_) means.push_back(mean_at(*mesh_, s.locations, eta));
  return means;
}

std::vector<double> BackwaterProbe::rise(std::span<const double> eta,
                                         std::span<const double> reference_eta) const {
  std::vector<double> with_bodies = mean_eta(eta);
  const std::vector<double> without = mean_eta(reference_eta);
  for (std::size_t b = 0; b < with_bodies.size(); ++b) with_bodies[b] -= without[b];
  return with_bodies;
}

}  // namespace flotsam
