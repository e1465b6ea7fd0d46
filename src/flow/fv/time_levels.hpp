#pragma once
// Local time stepping's levels (docs/model.md "Local time stepping"): over a cycle of 2^top
// steps dt0, cell i advances in steps of 2^m_i dt0, m_i the largest level its Courant step
// allows, rising by at most one level every `width` cells (so a coarse cell always borders
// cells that advance at most twice as often), and the same level for cells tied together (the cells
// of one discharge boundary, which share the discharge; the cells of the sources). An edge advances
// with the finer of its two cells.
#include <span>
#include <vector>

#include "flow/fv/cell_mesh.hpp"
#include "flow/fv/rank_split.hpp"

namespace flotsam {

/// A part of the operator L: the edges whose fluxes are computed, the cells whose
/// reconstruction those fluxes read (the edges' cells) and the cells whose values that
/// reconstruction reads (those and their neighbours).
struct EdgeSet {
  std::vector<int> edges;
  std::vector<int> boundary_edges;  // those of `edges` on the boundary, in order
  std::vector<int> cells;
  std::vector<int> loaded;
};

/// A level rises at most once every two cells away from a finer one. With one cell, four levels
/// let Stoker's shock, running from fine cells into the coarser still water, overshoot: the
/// envelope's largest depth +2.08 % against +1.32 % with one level (tolerance 2 %); with two
/// cells and three levels +1.32 %, as with one level (fv_flood_envelope_stoker.cpp).
inline constexpr int cells_per_level = 2;

struct TimeLevels {
  int top = 0;                  // the highest level of any cell
  std::vector<int> cell_level;  // [-] per cell, 0..top
  std::vector<int> edge_level;  // [-] per edge: the smaller of its cells' (its one cell's)
  std::vector<std::vector<int>> cells_upto;  // [a]: the cells of level <= a
  std::vector<EdgeSet> upto;                 // [a]: the edges of level <= a
  std::vector<EdgeSet> at;                   // [e]: the edges of level e
};

/// The cells' levels from the largest each Courant step allows, `raw` (0..cap): lowered so
/// that a level rises at most once every `width` cells away from a lower one; `ties`: groups of
/// cells that take one level, the smallest among them; `dry` (per cell, 1 when dry): the two rings
/// of dry cells ahead of a shoreline take its level, so a front advancing into them finds them
/// stepping as often as the water behind it.
std::vector<int> cell_levels(const CellMesh& cells, std::vector<int> raw, int cap,
                             const std::vector<std::vector<int>>& ties, std::span<const char> dry,
                             int width);

/// The edges' levels and the parts of L for the cells' `levels`.
TimeLevels build_time_levels(const CellMesh& cells, std::vector<int> levels);

/// Each cell's work per cycle of `time_levels` levels, 2^(top - m), at the level m its size alone
/// gives it (one wave speed everywhere; smoothed as cell_levels does): the weights of the parts
/// for MPI ranks, so that fine and coarse cells balance. Empty with one level (every cell 1).
std::vector<int> size_weights(const CellMesh& cells, int time_levels);

/// The cell updates one level makes over those of `time_levels` levels, as their sizes alone
/// predict (size_weights): 1 on a mesh whose cells all lie within a factor 2 of the smallest.
double size_gain(const CellMesh& cells, int time_levels);

/// `flow.fv.time_levels: auto` (the default, 0): three levels where the cells' sizes predict at
/// least `auto_gain` times fewer updates, else one (docs/model.md "Local time stepping"). A cell
/// update of local time stepping costs 1.5-1.7 times one of the one-level step (the parts' rings
/// re-read at every tick; docs/performance.md), so below that gain one level is as fast. Three
/// levels, not more: with four, Stoker's envelope overshoots by 2.03 % (tolerance 2 %). Levels
/// set (`configured`, 1..8) are taken as they are.
inline constexpr int auto_levels = 3;
inline constexpr double auto_gain = 1.6;  // [-]
int choose_time_levels(const CellMesh& cells, int configured);

/// One MPI rank's share of `levels` (rank_split.hpp): of each part, the edges beside the rank's
/// own cells (and their boundary edges), the cells whose reconstruction those read, the cells
/// loaded for it; of each cells_upto, the own cells. cell_level and edge_level stay `levels`'.
TimeLevels rank_share(const CellMesh& cells, const TimeLevels& levels, const RankSplit& split);

}  // namespace flotsam
