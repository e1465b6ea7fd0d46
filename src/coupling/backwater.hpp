#pragma once
// Backwater (spec 6.3): the rise of the water surface upstream of each bridge that the
// bodies cause, measured as the mean of eta over a cross-section of the channel, with bodies,
// minus the same mean in a reference flow without bodies (the caller runs it alongside and
// hands its eta field over). Definitions in docs/model.md, "Jam statistics".
//
// The mean along a line a -> b is the midpoint rule over `samples` equal pieces,
//   mean eta = (1/n_in) sum_{k inside} eta(a + (k + 1/2)/n (b - a)),   k = 0 .. n-1,
// over the sample points inside the domain (points in a pier or beyond a bank are skipped).
// It is exact for a field linear along the line when every point is inside, and converges to
// the line average of the P1 field as (h/n)^2 otherwise.
#include <span>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "coupling/jam_statistics.hpp"
#include "flow/flow_field.hpp"
#include "mesh/mesh.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

/// The points of the midpoint rule on a -> b: a + (k + 1/2)/samples (b - a) [m].
std::vector<Vec2> line_sample_points(const Vec2& a, const Vec2& b, int samples);

/// Mean of the P1 field `eta` [m] (vertex_count values) over the sample points of a -> b inside
/// the mesh. std::invalid_argument when samples < 1 or no point is inside.
double mean_eta_along(const Mesh& mesh, const PointLocator& locator, std::span<const double> eta,
                      const Vec2& a, const Vec2& b, int samples);

/// The same through the engine's interface, at time t [s] of its current step.
double mean_eta_along(const FlowField& flow, double t, const Vec2& a, const Vec2& b, int samples);

/// One cross-section per bridge, parallel to its axis and as long, bridge.backwater_distance
/// upstream of it (bridges/bridge.hpp; on the paper's channel two diameters of the widest pier
/// upstream of the piers' centres, across the full width). The sample points are located once;
/// evaluating a field is then a sum over them.
class BackwaterProbe {
 public:
  static constexpr int default_samples = 200;  // [-] points on a section (midpoint rule)

  /// Keeps a pointer to `mesh`, which must outlive the probe. InputError naming the bridge and
  /// the section when a section has no point inside the mesh.
  BackwaterProbe(const Mesh& mesh, const JamGeometry& geometry, int samples = default_samples);

  struct Section {
    std::string bridge;               // the bridge's name
    Vec2 a = Vec2::Zero();            // [m] section end on the right bank
    Vec2 b = Vec2::Zero();            // [m] section end on the left bank
    std::vector<Location> locations;  // the sample points inside the mesh
  };

  /// Mean eta [m] on each bridge's section, for the P1 field `eta` on the probe's mesh.
  std::vector<double> mean_eta(std::span<const double> eta) const;

  /// Backwater rise [m] per bridge: mean_eta(eta) - mean_eta(reference_eta), the reference
  /// being the same case without bodies on the same mesh.
  std::vector<double> rise(std::span<const double> eta,
                           std::span<const double> reference_eta) const;

  const std::vector<Section>& sections() const { return sections_; }

 private:
  const Mesh* mesh_;
  std::vector<Section> sections_;
};

}  // namespace flotsam
