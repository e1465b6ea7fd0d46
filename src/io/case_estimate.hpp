#pragma once
// How large a run will be, from its case alone, before anything is meshed or computed (issue 20
// item 4): elements from the domain's area and mesh size (or counted in the mesh file), flow
// steps, outputs and the bytes they take. `flotsam run` prints it when the run is large, and
// refuses a mesh too large for memory.
#include <string>

#include "io/case.hpp"

namespace flotsam {

struct RunEstimate {
  double elements = 0.0;      // [-] triangles
  bool counted = false;       // elements counted in the case's mesh file, not estimated
  double steps = 0.0;         // [-] flow steps to time.end
  double outputs = 0.0;       // [-] outputs (every output.interval, and the start)
  double output_bytes = 0.0;  // [bytes] fields, states and checkpoints on disk, about
};

/// Equilateral triangles of side mesh_size over the domain's area: A / (sqrt(3)/4 h^2); the
/// refinement near piers and buildings adds to this (a lower bound). A mesh file's triangles are
/// counted by check_msh (mesh/msh_check.hpp), which also refuses a damaged file here.
RunEstimate estimate_run(const Case& c);

/// True when the run deserves a word before it starts: over 200 000 elements, 1 000 000 steps
/// or 10 GB of output.
bool is_large(const RunEstimate& e);

/// "about 1.2e+06 elements, 36000 steps, 61 outputs, 14 GB of output" ("1203456 elements" when
/// counted in the mesh file).
std::string describe_estimate(const RunEstimate& e);

/// Refuses a mesh of more than 5e7 elements (several GB of memory before the first step),
/// naming the case file and the mesh size key.
void check_estimate(const Case& c, const RunEstimate& e);

}  // namespace flotsam
