#include "flow/fv/time_levels.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>

namespace flotsam {

namespace {

// Lowers levels until no cell stands more than one level above a neighbour: a breadth-first
// sweep from the lowest levels up (each cell is final when its bucket is reached).
void smooth(const CellMesh& c, std::vector<int>& level, int cap) {
  std::vector<std::vector<int>> bucket(cap + 1);
  for (int i = 0; i < c.cell_count; ++i) bucket[level[i]].push_back(i);
  for (int m = 0; m < cap; ++m)
    for (std::size_t k = 0; k < bucket[m].size(); ++k) {
      const int i = bucket[m][k];
      if (level[i] != m) continue;  // lowered since it was put here
      for (int j : c.neighbour[i])
        if (j >= 0 && level[j] > m + 1) {
          level[j] = m + 1;
          bucket[m + 1].push_back(j);
        }
    }
}

// Appends cell i to the sets whose bits `mask` holds: at[e] for each bit e, upto[a] for every a
// from the lowest bit up (`member` picks the list: the cells, or the loaded cells).
void add_cell(TimeLevels& t, int i, unsigned mask, std::vector<int> EdgeSet::*member) {
  if (mask == 0) return;
  for (int e = 0; e <= t.top; ++e)
    if (mask & (1u << e)) (t.at[e].*member).push_back(i);
  for (int a = std::countr_zero(mask); a <= t.top; ++a) (t.upto[a].*member).push_back(i);
}

}  // namespace

std::vector<int> cell_levels(const CellMesh& c, std::vector<int> level, int cap,
                             const std::vector<std::vector<int>>& ties, std::span<const char> dry,
                             int width) {
  // In steps of 1/width of a level, so that smoothing lets a level rise once per `width` cells.
  for (int& m : level) m *= width;
  const int top = cap * width;
  for (int ring = 0; ring < 2; ++ring) {
    const std::vector<int> before = level;
    for (int i = 0; i < c.cell_count; ++i)
      if (dry[i])
        for (int j : c.neighbour[i])
          if (j >= 0) level[i] = std::min(level[i], before[j]);
  }
  // Ties lower their cells, which smoothing may lower further: repeat until both hold.
  for (bool changed = true; changed;) {
    smooth(c, level, top);
    changed = false;
    for (const std::vector<int>& group : ties) {
      int m = top;
      for (int i : group) m = std::min(m, level[i]);
      for (int i : group)
        if (level[i] != m) level[i] = m, changed = true;
    }
  }
  for (int& m : level) m /= width;
  return level;
}

TimeLevels build_time_levels(const CellMesh& c, std::vector<int> levels) {
  TimeLevels t;
  const int n = c.cell_count;
  t.cell_level = std::move(levels);
  t.top = n > 0 ? *std::max_element(t.cell_level.begin(), t.cell_level.end()) : 0;
  t.edge_level.resize(c.edge_count);
  for (int e = 0; e < c.edge_count; ++e)
    t.edge_level[e] = c.right[e] < 0 ? t.cell_level[c.left[e]]
                                     : std::min(t.cell_level[c.left[e]], t.cell_level[c.right[e]]);
  t.cells_upto.resize(t.top + 1);
  for (int i = 0; i < n; ++i)
    for (int a = t.cell_level[i]; a <= t.top; ++a) t.cells_upto[a].push_back(i);
  // One pass over the edges and two over the cells: each edge in at[its level] and in upto[a]
  // for a >= it; each cell in the sets of the edges it touches (bit e of `touches`), and loaded
  // by the sets of its own and its neighbours' edges.
  t.at.resize(t.top + 1);
  t.upto.resize(t.top + 1);
  std::vector<unsigned> touches(n, 0u);
  for (int e = 0; e < c.edge_count; ++e) {
    const int m = t.edge_level[e];
    const bool boundary = c.right[e] < 0;
    t.at[m].edges.push_back(e);
    if (boundary) t.at[m].boundary_edges.push_back(e);
    for (int a = m; a <= t.top; ++a) {
      t.upto[a].edges.push_back(e);
      if (boundary) t.upto[a].boundary_edges.push_back(e);
    }
    touches[c.left[e]] |= 1u << m;
    if (!boundary) touches[c.right[e]] |= 1u << m;
  }
  for (int i = 0; i < n; ++i) {
    add_cell(t, i, touches[i], &EdgeSet::cells);
    unsigned loaded = touches[i];
    for (int j : c.neighbour[i])
      if (j >= 0) loaded |= touches[j];
    add_cell(t, i, loaded, &EdgeSet::loaded);
  }
  return t;
}

std::vector<int> size_weights(const CellMesh& c, int time_levels) {
  const int n = c.cell_count, cap = time_levels - 1;
  if (n == 0 || cap < 1) return {};
  const double smallest = *std::min_element(c.length_scale.begin(), c.length_scale.end());
  std::vector<int> raw(n);
  for (int i = 0; i < n; ++i)
    raw[i] = std::min(cap, static_cast<int>(std::floor(std::log2(c.length_scale[i] / smallest))));
  const std::vector<int> level =
      cell_levels(c, std::move(raw), cap, {}, std::vector<char>(n, 0), cells_per_level);
  const int top = *std::max_element(level.begin(), level.end());
  std::vector<int> weight(n);
  for (int i = 0; i < n; ++i) weight[i] = 1 << (top - level[i]);
  return weight;
}

double size_gain(const CellMesh& c, int time_levels) {
  const std::vector<int> weight = size_weights(c, time_levels);
  if (weight.empty()) return 1.0;
  double work = 0.0;  // [cell updates per cycle]
  for (int w : weight) work += w;
  const int steps = *std::max_element(weight.begin(), weight.end());  // 2^top
  return static_cast<double>(c.cell_count) * steps / work;
}

int choose_time_levels(const CellMesh& c, int configured) {
  if (configured > 0) return configured;
  return size_gain(c, auto_levels) >= auto_gain ? auto_levels : 1;
}

TimeLevels rank_share(const CellMesh& c, const TimeLevels& levels, const RankSplit& split) {
  const auto owned = [&split](int i) { return split.ring(i) == 0; };
  const auto reconstructed = [&split](int i) { return split.ring(i) <= 1; };
  const auto loaded = [&split](int i) { return split.ring(i) <= 2; };
  const auto beside = [&](int e) {
    return owned(c.left[e]) || (c.right[e] >= 0 && owned(c.right[e]));
  };
  const auto keep = [](const std::vector<int>& all, const auto& member) {
    std::vector<int> kept;
    std::copy_if(all.begin(), all.end(), std::back_inserter(kept), member);
    return kept;
  };
  const auto share = [&](const EdgeSet& s) {
    return EdgeSet{keep(s.edges, beside), keep(s.boundary_edges, beside),
                   keep(s.cells, reconstructed), keep(s.loaded, loaded)};
  };
  TimeLevels t;
  t.top = levels.top;
  for (const auto& cells : levels.cells_upto) t.cells_upto.push_back(keep(cells, owned));
  for (const EdgeSet& s : levels.upto) t.upto.push_back(share(s));
  for (const EdgeSet& s : levels.at) t.at.push_back(share(s));
  return t;
}

}  // namespace flotsam
