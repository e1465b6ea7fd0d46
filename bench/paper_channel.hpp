#pragma once
// The paper's channel (spec 8.2, examples/bridge_piers.yaml) at another element size, for the
// flow benchmarks (flow_channel.cpp, linear_system_scatter.cpp).
#include <omp.h>

#include "io/case_file.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {

/// The case with far-field element size mesh_size [m] (0: the case's 14.5 m) and the pier
/// element size scaled with it; with scale_refinement, the refinement distance too (the
/// scaling study's meshes).
inline Case paper_channel_case(double mesh_size, bool scale_refinement = false) {
  Case c = read_case(FLOTSAM_SOURCE_DIR "/examples/bridge_piers.yaml");
  if (mesh_size > 0.0) {
    const double scale = mesh_size / c.mesh.channel.mesh_size;
    c.mesh.channel.mesh_size = mesh_size;
    c.mesh.channel.pier_mesh_size *= scale;
    if (scale_refinement) c.mesh.channel.refine_distance *= scale;
  }
  return c;
}

/// generate_mesh leaves the process at one OpenMP thread (Gmsh's General.NumThreads = 1): this
/// restores the thread count the benchmark runs with.
inline Mesh paper_channel_mesh(const Case& c) {
  const int threads = omp_get_max_threads();
  Mesh mesh = generate_mesh(c.mesh);
  omp_set_num_threads(threads);
  return mesh;
}

}  // namespace flotsam
