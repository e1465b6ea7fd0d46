#include "flow/fv/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace flotsam {

std::vector<int> partition_cells(const CellMesh& cells, int parts, std::span<const int> weights) {
  const int n = cells.cell_count;
  if (parts < 1) throw std::invalid_argument("partition_cells: parts must be >= 1");
  if (!weights.empty() && static_cast<int>(weights.size()) != n)
    throw std::invalid_argument("partition_cells: one weight per cell");
  if (parts == 1 || n <= parts) {
    std::vector<int> part(static_cast<std::size_t>(n), 0);
    for (int i = 0; i < n && parts > 1; ++i) part.at(static_cast<std::size_t>(i)) = i;
    return part;
  }
  // The cells' graph in METIS's compressed rows: each cell's neighbours across its inner edges.
  std::vector<idx_t> xadj{0}, adjncy, vwgt(weights.begin(), weights.end());
  xadj.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i < n; ++i) {
    for (const int j : cells.neighbour[static_cast<std::size_t>(i)])
      if (j >= 0) adjncy.push_back(j);
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
  }
  idx_t nvtxs = n, ncon = 1, nparts = parts, cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // the same parts on every run
  std::vector<idx_t> part(static_cast<std::size_t>(n));
  const int status = METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(),
                                         vwgt.empty() ? nullptr : vwgt.data(), nullptr, nullptr,
                                         &nparts, nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK)
    throw std::runtime_error("METIS could not split " + std::to_string(n) + " cells into " +
                             std::to_string(parts) + " parts (status " + std::to_string(status) +
                             ")");
  return {part.begin(), part.end()};
}

PartitionSummary summarize_partition(const CellMesh& cells, const std::vector<int>& part, int parts,
                                     std::span<const int> weights) {
  const auto P = static_cast<std::size_t>(parts);
  PartitionSummary s;
  s.cells.assign(P, 0), s.weight.assign(P, 0), s.halo.assign(P, 0), s.neighbours.assign(P, 0);
  std::vector<std::vector<int>> halo(P), from(P);
  for (int i = 0; i < cells.cell_count; ++i) {
    const int p = part.at(static_cast<std::size_t>(i));
    const auto P_i = static_cast<std::size_t>(p);
    ++s.cells.at(P_i);
    s.weight.at(P_i) += weights.empty() ? 1 : weights[static_cast<std::size_t>(i)];
    const auto read = [&](int q) {  // a cell that part p's step reads
      const int other = part[static_cast<std::size_t>(q)];
      if (other == p) return;
      halo[P_i].push_back(q);
      from[P_i].push_back(other);
    };
    for (const int j : cells.neighbour[static_cast<std::size_t>(i)]) {
      if (j < 0) continue;
      if (i < j && part[static_cast<std::size_t>(j)] != p) ++s.cut_edges;
      read(j);                                                          // ring 1
      for (const int k : cells.neighbour[static_cast<std::size_t>(j)])  // ring 2
        if (k >= 0) read(k);
    }
  }
  long largest = 0, total = 0;
  for (std::size_t p = 0; p < P; ++p) {
    for (auto* list : {&halo[p], &from[p]}) {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    s.halo[p] = static_cast<int>(halo[p].size());
    s.neighbours[p] = static_cast<int>(from[p].size());
    largest = std::max(largest, s.weight[p]);
    total += s.weight[p];
  }
  s.imbalance = total > 0 ? static_cast<double>(largest) * parts / static_cast<double>(total) : 1.0;
  return s;
}

}  // namespace flotsam
