#pragma once
// The flow at one time: elevation on the P1 vertices, velocity on the P2 nodes (mesh.hpp
// numbering: the first vertex_count P2 nodes are the vertices).
#include <vector>

namespace flotsam {

struct FlowState {
  double time = 0.0;        // [s]
  std::vector<double> eta;  // [m] per vertex
  std::vector<double> u;    // [m/s] per P2 node
  std::vector<double> v;    // [m/s] per P2 node
};

}  // namespace flotsam
