#pragma once
// What a flow engine gives the UGRID NetCDF results (io/ugrid_writer.hpp, docs/output-format.md
// "UGRID NetCDF"): its mesh as linear triangles over the mesh's nodes, and its fields at one
// output, the same variables at every output.
#include <array>
#include <utility>
#include <vector>

#include "io/ugrid_variable.hpp"

namespace flotsam {

struct ResultMesh {
  std::vector<std::array<int, 3>> faces;  // mesh node indices, counter-clockwise
  std::vector<double> node_bed;           // [m] z_b per mesh node
};

struct ResultFields {
  std::vector<UgridVariable> variables;
  std::vector<std::vector<double>> values;  // per variable, sized as its location

  void add(UgridVariable variable, std::vector<double> data) {
    variables.push_back(std::move(variable));
    values.push_back(std::move(data));
  }
};

}  // namespace flotsam
