#pragma once
// What a run leaves for `flotsam render` (and for people's own scripts), next to the ParaView
// files:
//   run.bin              once: the case's name, the mesh, and which boundary groups are open
//   state_NNNNNN.bin     at every output: time, flow fields, bodies (pose, size, state, jammed)
// Both are binary archives (io/binary_archive.hpp) of named arrays.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bodies/body_set.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

struct RunDescription {
  std::string name;  // the case's name
  Mesh mesh;
  std::vector<std::uint8_t> open_group;    // per Mesh::group_names: 1 inflow/outflow, 0 wall
  std::vector<std::array<Vec2, 4>> decks;  // [m] each bridge deck's footprint, corners in order
                                           // (none: the record is not written)
};

/// One output time of a run.
struct RunSnapshot {
  double time = 0.0;              // [s]
  std::vector<double> eta;        // [m] per vertex (P1)
  std::vector<double> u, v;       // [m/s] per P2 node
  std::vector<std::uint8_t> wet;  // per P2 node: 1 wet, 0 dry; empty: all wet
  // Bodies (all, including gone ones), as BodySet.
  std::vector<long> id;
  std::vector<Vec2> position;         // [m]
  std::vector<double> angle;          // [rad]
  std::vector<double> length, width;  // [m]
  std::vector<BodyState> state;
  std::vector<std::uint8_t> jammed;  // 1: in a jam (spec 6.3)
};

void write_run_description(const std::string& path, const RunDescription& run);
RunDescription read_run_description(const std::string& path);

/// `wet` has one flag per P2 node (or is empty: all wet); `jammed` one per body (or is empty:
/// none).
void write_run_snapshot(const std::string& path, double time, const std::vector<double>& eta,
                        const std::vector<double>& u, const std::vector<double>& v,
                        const std::vector<std::uint8_t>& wet, const BodySet& bodies,
                        const std::vector<std::uint8_t>& jammed);
RunSnapshot read_run_snapshot(const std::string& path);

}  // namespace flotsam
