// Local time stepping (flow.fv.time_levels > 1; docs/model.md "Local time stepping"): the
// finite-volume engine's Heun step (M-13), each cell with its own step 2^m dt0 (time_levels.hpp).
//
// A cycle of 2^top steps dt0 starts with every cell at t0. At tick k (t_k = t0 + k dt0) the cells
// whose step starts there (levels m with 2^m dividing k) take the rate L_i of the flux at t_k on
// their edges, and from it their predictor, the straight line
//   U_i(t) = U_i(t_s) + (t - t_s) (L_i + R_i / dt_i)            t_s the step's start,
// which is also what a neighbour reads of the cell at any time within its step. Every edge that
// touches such a cell is evaluated as Heun's step of its own level e (the finer of its cells'):
// at t_k and on the predictors at t_k + 2^e dt0, the two weighted by 2^e dt0 / 2, and both sides'
// shares are summed per cell and local edge. A cell whose step ends at t_{k+1} takes
//   U_i(t_s + dt_i) = U_i(t_s) + sum / A_i + dt_i/2 (S_i(U(t_s)) + S_i(predictor)) + R_i
// (S: Coriolis, wind, bodies; R: rain and sources), then infiltration and friction over dt_i.
// Each edge's flux enters its two cells with one weight: the volume is conserved to round-off, a
// lake at rest stays at rest as in the one-step scheme, and with one level this is that scheme.
// Every loop writes each cell or each (cell, edge) from one place and the balance is summed in
// a fixed order, so the result does not depend on the number of threads.
//
// Over MPI ranks (rank_split.hpp) each rank advances its own cells: it evaluates the edges beside
// them (rank_share), after each tick's starts and ends refreshes the two rings around them (the
// states, rates and steps' starts that a neighbour's prediction reads), and at a cycle's start
// where a cell's level or dryness changed gathers every cell's, so that every rank builds the
// same levels. The sums of the balance run over the whole mesh's lists in their order, on every
// rank alike: the result is the same bit for bit on any number of ranks.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>

#include "flow/fv/fv_solver.hpp"

namespace flotsam {

// The cells that take one level: each discharge boundary's cells (Q is shared along the group
// by the edges' depths, all at one time), and all the sources' cells (their depths are filled
// over one window).
std::vector<std::vector<int>> FiniteVolumeSolver::tied_cells() const {
  std::vector<std::vector<int>> ties;
  const auto& conditions = case_.flow.boundaries;
  std::vector<std::vector<int>> group_cells(mesh_.group_names.size());
  for (int e : cells_.boundary_edges) {
    const int k = boundaries_.group_condition[cells_.group[e]];
    if (k >= 0 && conditions[k].kind == BoundaryCondition::Kind::discharge)
      group_cells[cells_.group[e]].push_back(cells_.left[e]);
  }
  for (auto& g : group_cells)
    if (g.size() > 1) ties.push_back(std::move(g));
  std::vector<int> source_cells;
  for (int s = 0; s < sources_.count(); ++s)
    source_cells.insert(source_cells.end(), sources_.cells(s).begin(), sources_.cells(s).end());
  if (source_cells.size() > 1) ties.push_back(std::move(source_cells));
  return ties;
}

// The cycle's levels for the smallest step dt0 [s] (cell_step_ and dry_ filled on this rank's
// cells): each cell's largest level its Courant step allows, keeping its last one while that is
// still allowed and at most one below (the levels and their parts of L are built again only when
// one changes; over ranks, each cell's level and dryness then come from its owner).
void FiniteVolumeSolver::choose_levels(double dt0, int cap) {
  const int n = cells_.cell_count;
  const RankSplit* split = part();
  const std::span<const int> mine = my_cells();
  const bool before = static_cast<int>(raw_levels_.size()) == n;
  std::vector<int> raw = before ? raw_levels_ : std::vector<int>(n, 0);
  bool changed = !before;
  const auto count = static_cast<std::ptrdiff_t>(mine.size());
#pragma omp parallel for schedule(static) reduction(|| : changed)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const int i = mine[k];
    const double ratio = cell_step_[i] / dt0;  // >= 1
    int m = ratio >= std::ldexp(1.0, cap)
                ? cap
                : std::max(0, static_cast<int>(std::floor(std::log2(ratio))));
    if (before && raw_levels_[i] <= m && raw_levels_[i] >= m - 1) m = raw_levels_[i];
    raw[i] = m;
    changed = changed || (before && (m != raw_levels_[i] || dry_[i] != levels_dry_[i]));
  }
  if (split && (changed = split->any(changed))) {  // 2 m + dry, exact in a double
    level_inputs_.resize(static_cast<std::size_t>(n));
    for (const int i : mine) level_inputs_[i] = 2.0 * raw[i] + dry_[i];
    split->gather(level_inputs_.data(), 1);
    for (int i = 0; i < n; ++i) {
      const int packed = static_cast<int>(level_inputs_[i]);
      raw[i] = packed / 2;
      dry_[i] = static_cast<char>(packed % 2);
    }
  }
  if (changed) {
    raw_levels_ = raw;
    levels_dry_ = dry_;
    std::vector<int> level =
        cell_levels(cells_, std::move(raw), cap, level_ties_, dry_, cells_per_level);
    if (level != full_levels_.cell_level) {  // mostly they are the same (a front moved a cell)
      full_levels_ = build_time_levels(cells_, std::move(level));
      ++full_version_;
      ++levels_built_;
    }
  }
  levels_ = &full_levels_;
}

const TimeLevels& FiniteVolumeSolver::my_levels() {
  const RankSplit* split = part();
  if (!split) return *levels_;
  if (rank_levels_for_ != levels_ || rank_levels_built_ != levels_built_) {
    rank_levels_ = rank_share(cells_, *levels_, *split);
    rank_levels_for_ = levels_;
    rank_levels_built_ = levels_built_;
  }
  return rank_levels_;
}

// Over ranks: the rings around this rank's cells from their owners, after cells started
// (rates, feeds, steps' starts) or ended (`with_state`: their states too) a step.
void FiniteVolumeSolver::exchange_steps(bool with_state) {
  if (!part()) return;
  double* steps[] = {rate_h_.data(),     rate_hu_.data(), rate_hv_.data(), feed_.data(),
                     step_start_.data(), U1_.h.data(),    U1_.hu.data(),   U1_.hv.data()};
  split_->exchange(std::span<double* const>(steps, with_state ? 8 : 5));
}

void FiniteVolumeSolver::advance_local(double dt) {
  const int n = cells_.cell_count;
  const double t_end = U_.time + dt;
  for (auto* a : {&cell_step_, &step_start_, &feed_}) a->assign(n, 0.0);
  dry_.assign(n, 0);
  for (auto* a : {&side_h_, &side_hu_, &side_hv_, &sum_h_, &sum_hu_, &sum_hv_})
    a->assign(3 * static_cast<std::size_t>(n), 0.0);
  if (sources_.any()) source_depth_.assign(n, 0.0);
  const int cap = time_levels_ - 1;
  raw_levels_.clear();  // each step chooses from its own start: a restart continues bit for bit
  double shrink = 1.0;  // [-] of every cell's Courant step, halved at each retry
  while (U_.time < t_end - 1e-12 * dt) {
    const double t = U_.time, left = t_end - t;
    const WaterBalance balance_before = balance_;
    // Every cell starts at t: L(U) everywhere gives the Courant step of each (model.md (M-16)).
    evaluate_fluxes(U_, t);
    const double courant = case_.flow.fv.courant;
    double dt_courant = std::numeric_limits<double>::infinity();
    const RankSplit* split = part();
    const std::span<const int> mine = my_cells();
    const auto count = static_cast<std::ptrdiff_t>(mine.size());
#pragma omp parallel for schedule(static) reduction(min : dt_courant)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const int i = mine[k];
      dry_[i] = U_.h[i] <= dry_depth_;
      double speed = 0.0;
      for (int e : cells_.cell_edges[i]) speed = std::max(speed, edge_speed_[e]);
      const double step = speed > 0.0 ? courant * cells_.length_scale[i] / speed
                                      : std::numeric_limits<double>::infinity();
      dt_courant = std::min(dt_courant, step);
      cell_step_[i] = shrink * step;
    }
    if (split) dt_courant = split->min(dt_courant);
    double dt0 = std::min(shrink * dt_courant, left);
    choose_levels(dt0, cap);
    if (std::ldexp(dt0, levels_->top) > left) {  // the last cycle ends at t_end
      const int top = std::max(0, static_cast<int>(std::ceil(std::log2(left / dt0))));
      if (top < levels_->top) {
        if (capped_levels_.top != top || capped_from_ != full_version_) {
          std::vector<int> capped = full_levels_.cell_level;
          for (int& m : capped) m = std::min(m, top);  // still smooth, tied, ahead of fronts
          capped_levels_ = build_time_levels(cells_, std::move(capped));
          capped_from_ = full_version_;
          ++levels_built_;
        }
        levels_ = &capped_levels_;
      }
      dt0 = std::ldexp(left, -levels_->top);
    }
    const int bad = local_cycle(t, dt0);
    if (bad >= 0) {  // the unfinished steps' sums are left: clear them
      for (auto* a : {&sum_h_, &sum_hu_, &sum_hv_}) std::fill(a->begin(), a->end(), 0.0);
      balance_ = balance_before;
      ++stats_.rejected;
      shrink *= 0.5;
      if (shrink < 1.0 / 64.0) fail_at(U1_, bad, t + std::ldexp(dt0, levels_->top));
      continue;
    }
    const double cycle = std::ldexp(dt0, levels_->top);
    std::swap(U_, U1_);
    U_.time = cycle == left ? t_end : t + cycle;
    shrink = 1.0;
    stats_.count += 1L << levels_->top;
    stats_.total += cycle;
    if (std::isfinite(dt_courant) && (stats_.smallest == 0.0 || dt_courant < stats_.smallest))
      stats_.smallest = dt_courant;
    for (std::size_t g = 0; g < balance_.group_rate.size(); ++g)
      balance_.group_rate[g] =
          (balance_.group_outflow[g] - balance_before.group_outflow[g]) / cycle;
    if (sub_step_observer_) sub_step_observer_(U_.time, cycle);
  }
  U_.time = t_end;
  gather_step();
  balance_.volume = volume();
}

// One cycle from t0 (every cell at U_, L(U_) evaluated) into U1_. Returns a cell whose depth
// went negative beyond round-off or whose state is not finite (the cycle is then to be
// retried), or -1.
int FiniteVolumeSolver::local_cycle(double t0, double dt0) {
  const TimeLevels& lv = *levels_;
  const TimeLevels& mine = my_levels();  // lv on one rank
  const RankSplit* split = part();
  U1_ = U_;
  std::fill(step_start_.begin(), step_start_.end(), t0);
  level_step_.resize(lv.top + 1);
  for (int m = 0; m <= lv.top; ++m) level_step_[m] = std::ldexp(dt0, m);
  if (rain_.infiltrating()) infiltrated_.assign(cells_.cell_count, 0.0);
  const int ticks = 1 << lv.top;
  for (int k = 0; k < ticks; ++k) {
    const int a = k == 0 ? lv.top : std::countr_zero(static_cast<unsigned>(k));
    const double t = t0 + k * dt0;
    if (k > 0)  // the first stage of the cells starting
      evaluate_part(mine.upto[a], lv.upto[a].boundary_edges, t, {0, a}, true);
    else  // the fluxes of U_ are evaluated
      take_shares(split ? split->edges() : all_edges_, cells_.boundary_edges, true);
    start_steps(lv.cells_upto[a], mine.cells_upto[a], t);
    exchange_steps(false);
    stats_.cell_updates += static_cast<double>(lv.cells_upto[a].size());
    for (int e = 0; e <= a; ++e) {  // the second stage of each level's edges
      evaluate_part(mine.at[e], lv.at[e].boundary_edges, t + level_step_[e], {e, e}, false);
    }
    const int b = k + 1 == ticks ? lv.top : std::countr_zero(static_cast<unsigned>(k + 1));
    const int bad = finish_steps(lv.cells_upto[b], mine.cells_upto[b], t0 + (k + 1) * dt0);
    if (bad >= 0) return bad;
    exchange_steps(true);
  }
  if (rain_.infiltrating()) {  // each cell's from its owner, summed in the cells' order
    if (split) split->gather(infiltrated_.data(), 1);
    for (double v : infiltrated_) balance_.infiltration += v;
  }
  return -1;
}

// L on `part` at time t: the cells' states on their predicted lines, the reconstruction, the
// fluxes, and the edges' shares (take_shares); `boundary_edges`: the whole part's, for the balance.
void FiniteVolumeSolver::evaluate_part(const EdgeSet& part, std::span<const int> boundary_edges,
                                       double t, LevelRange levels, bool first_stage) {
  const auto loaded = static_cast<std::ptrdiff_t>(part.loaded.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < loaded; ++k) {
    const int i = part.loaded[k];
    const double s = t - step_start_[i];  // [s] into the cell's step
    const double h = std::max(0.0, U1_.h[i] + s * (rate_h_[i] + feed_[i]));
    load_cell(i, h, U1_.hu[i] + s * rate_hu_[i], U1_.hv[i] + s * rate_hv_[i]);
  }
  reconstruct(cells_, case_.flow.fv.order, dry_depth_, field_, part.cells);
  compute_edge_fluxes(part.edges, boundary_edges, t, levels);
  take_shares(part.edges, boundary_edges, first_stage);
}

// Each evaluated edge's shares for its cells (EdgeRate; over ranks, this rank's), times half its
// level's step, into the cells' sums, and kept in side_* at a first stage (the rates of the cells
// starting); the boundary's outflow into the balance, in the edges' order (over ranks, every
// rank's edges: compute_edge_fluxes gathered their fluxes).
void FiniteVolumeSolver::take_shares(std::span<const int> part_edges,
                                     std::span<const int> boundary_edges, bool first_stage) {
  const RankSplit* split = part();
  const auto edges = static_cast<std::ptrdiff_t>(part_edges.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < edges; ++k) {
    const int e = part_edges[k];
    const double w = 0.5 * level_step_[levels_->edge_level[e]];  // [s]
    for (const int side : {0, 1}) {
      const int i = side == 0 ? cells_.left[e] : cells_.right[e];
      if (i < 0 || (split && !split->owns(i))) continue;
      const int slot = side == 0 ? cells_.left_slot[e] : cells_.right_slot[e];
      const std::size_t j = 3 * static_cast<std::size_t>(i) + slot;
      const EdgeRate r = edge_rate(i, slot);
      sum_h_[j] += w * r.h;
      sum_hu_[j] += w * r.hu;
      sum_hv_[j] += w * r.hv;
      if (first_stage) side_h_[j] = r.h, side_hu_[j] = r.hu, side_hv_[j] = r.hv;
    }
  }
  for (int e : boundary_edges) {
    const double v = 0.5 * level_step_[levels_->edge_level[e]] * cells_.length[e] * flux_mass_[e];
    balance_.group_outflow[cells_.group[e]] += v;
    balance_.outflow += v;
  }
}

// The cells of `all` start a step at t: their rate from the shares just evaluated (side_*), and
// the rain and sources over their step; this rank's of them, `mine` (all on one rank), are set.
void FiniteVolumeSolver::start_steps(const std::vector<int>& all, const std::vector<int>& mine,
                                     double t) {
  const int top = levels_->top;
  std::array<double, 8> rain{};  // [m] per level (time_levels <= 8), on a cell of weight 1
  const std::vector<double>& w = rain_.weights();
  if (rain_.raining()) {
    for (int m = 0; m <= top; ++m) rain[m] = rain_.depth(t, t + level_step_[m]);
    double rain_volume = 0.0;  // [m^3], in the cells' order
    for (int i : all) rain_volume += rain[levels_->cell_level[i]] * w[i] * cells_.area[i];
    balance_.rain += rain_volume;
  }
  if (sources_.any()) {  // their cells share one level (tied_cells)
    const int m = levels_->cell_level[sources_.cells(0).front()];
    if (std::binary_search(all.begin(), all.end(), sources_.cells(0).front()))
      balance_.sources += sources_.depths(t, t + level_step_[m], source_depth_);
  }
  const auto count = static_cast<std::ptrdiff_t>(mine.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const int i = mine[k];
    const std::size_t j = 3 * static_cast<std::size_t>(i);
    const double A = cells_.area[i], step = level_step_[levels_->cell_level[i]];
    rate_h_[i] = (side_h_[j] + side_h_[j + 1] + side_h_[j + 2]) / A;
    rate_hu_[i] = (side_hu_[j] + side_hu_[j + 1] + side_hu_[j + 2]) / A;
    rate_hv_[i] = (side_hv_[j] + side_hv_[j + 1] + side_hv_[j + 2]) / A;
    add_local_rate(i, U1_.h[i], U1_.hu[i], U1_.hv[i], rate_hu_[i], rate_hv_[i]);
    const double R =
        rain[levels_->cell_level[i]] * w[i] + (sources_.any() ? source_depth_[i] : 0.0);
    feed_[i] = R / step;
    step_start_[i] = t;
  }
}

// The cells of `all` end their step at t_end (this rank's of them, `mine`, updated): the update,
// the round-off below zero set to zero (counted as a source), infiltration and friction over
// their step. Returns a cell that failed, or -1 (over ranks, the same on every rank).
int FiniteVolumeSolver::finish_steps(const std::vector<int>& all, const std::vector<int>& mine,
                                     double t_end) {
  const auto count = static_cast<std::ptrdiff_t>(mine.size());
  bool suspect = false;
#pragma omp parallel for schedule(static) reduction(|| : suspect)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const int i = mine[k];
    const std::size_t j = 3 * static_cast<std::size_t>(i);
    const double A = cells_.area[i], step = level_step_[levels_->cell_level[i]];
    const double h = U1_.h[i], hu = U1_.hu[i], hv = U1_.hv[i];
    // S at the step's start and at the predictor (Heun's weights)
    double s_u = 0.0, s_v = 0.0;
    add_local_rate(i, h, hu, hv, s_u, s_v);
    add_local_rate(i, h + step * (rate_h_[i] + feed_[i]), hu + step * rate_hu_[i],
                   hv + step * rate_hv_[i], s_u, s_v);
    U1_.h[i] = h + (sum_h_[j] + sum_h_[j + 1] + sum_h_[j + 2]) / A + step * feed_[i];
    U1_.hu[i] = hu + (sum_hu_[j] + sum_hu_[j + 1] + sum_hu_[j + 2]) / A + 0.5 * step * s_u;
    U1_.hv[i] = hv + (sum_hv_[j] + sum_hv_[j + 1] + sum_hv_[j + 2]) / A + 0.5 * step * s_v;
    for (int s = 0; s < 3; ++s) sum_h_[j + s] = sum_hu_[j + s] = sum_hv_[j + s] = 0.0;
    rate_h_[i] = rate_hu_[i] = rate_hv_[i] = feed_[i] = 0.0;  // U(t) = U1_ until it starts again
    step_start_[i] = t_end;
    suspect = suspect || !(U1_.h[i] >= 0.0) || !std::isfinite(U1_.hu[i] + U1_.hv[i]);
  }
  if (const RankSplit* split = part()) {
    suspect = split->any(suspect);
    if (suspect) gather(U1_);  // every rank looks at every cell (clamp_round_off)
  }
  if (suspect) {
    const int bad = clamp_round_off(U1_, 1.0, all);
    if (bad >= 0) return bad;
  }
  if (rain_.infiltrating()) {  // the cycle's volume per cell, summed when it ends (local_cycle)
    const double f = rain_.infiltration_rate();
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const int i = mine[k];
      infiltrated_[i] +=
          cells_.area[i] * RainSource::infiltrate_cell(U1_.h[i], U1_.hu[i], U1_.hv[i],
                                                       f * level_step_[levels_->cell_level[i]]);
    }
  }
  if (friction_.law != FrictionLaw::none) {
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k)
      apply_friction(U1_, mine[k], level_step_[levels_->cell_level[mine[k]]]);
  }
  if (!pier_drag_.empty()) {
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k)
      apply_pier_drag(U1_, mine[k], level_step_[levels_->cell_level[mine[k]]]);
  }
  if (!body_drag_.empty()) {
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k)
      body_drag_.apply(U1_, mine[k], level_step_[levels_->cell_level[mine[k]]], dry_depth_);
  }
  return -1;
}

}  // namespace flotsam
