#include "flow/fv/rank_split.hpp"

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "flow/fv/partition.hpp"

#if FLOTSAM_MPI
#include <mpi.h>
#endif

namespace flotsam {

namespace {

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// The cells within `rings` rings of `cells` (themselves included), ascending.
std::vector<int> grow(const CellMesh& c, std::vector<int> cells, int rings) {
  std::vector<int> front = cells;
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next;
    for (const int i : front)
      for (const int j : c.neighbour[static_cast<std::size_t>(i)])
        if (j >= 0) next.push_back(j);
    sort_unique(next);
    std::vector<int> grown;
    std::set_union(cells.begin(), cells.end(), next.begin(), next.end(), std::back_inserter(grown));
    cells = std::move(grown);
    front = std::move(next);
  }
  return cells;
}

}  // namespace

RankSplit::RankSplit(const CellMesh& cells, int rank, int size, std::span<const int> weights,
                     std::span<const char> gathered)
    : rank_(rank), size_(size), made_(omp_get_wtime()) {
  if (size < 1 || rank < 0 || rank >= size)
    throw std::invalid_argument("RankSplit: rank outside 0 .. size - 1");
#if !FLOTSAM_MPI
  if (size > 1) throw std::invalid_argument("RankSplit: this build has no MPI");
#endif
  const std::vector<int> part = partition_cells(cells, size, weights);
  const auto P = static_cast<std::size_t>(size);
  own_of_.assign(P, {});
  for (int i = 0; i < cells.cell_count; ++i)
    own_of_[static_cast<std::size_t>(part[static_cast<std::size_t>(i)])].push_back(i);
  bedges_of_.assign(P, {});
  for (std::size_t k = 0; k < cells.boundary_edges.size(); ++k) {
    if (!gathered.empty() && !gathered[k]) continue;
    gathered_.push_back(static_cast<int>(k));
    const int owner = part[static_cast<std::size_t>(cells.left[cells.boundary_edges[k]])];
    bedges_of_[static_cast<std::size_t>(owner)].push_back(static_cast<int>(k));
  }
  for (std::size_t q = 0; q < P; ++q)
    if (own_of_[q].empty())
      throw std::invalid_argument("RankSplit: more ranks than the mesh can give each a part");
  own_ = own_of_[static_cast<std::size_t>(rank)];
  ring1_ = grow(cells, own_, 1);
  ring2_ = grow(cells, ring1_, 1);
  ring_.assign(static_cast<std::size_t>(cells.cell_count), 3);
  for (const auto& [cells_in, r] : {std::pair{&ring2_, 2}, {&ring1_, 1}, {&own_, 0}})
    for (const int i : *cells_in) ring_[static_cast<std::size_t>(i)] = static_cast<char>(r);
  for (const int i : own_)
    for (const int e : cells.cell_edges[static_cast<std::size_t>(i)]) edges_.push_back(e);
  sort_unique(edges_);
  bedges_ = bedges_of_[static_cast<std::size_t>(rank)];

  // Messages: what this rank reads from each other part (its rings), and what each other part
  // reads from this one (computed the same way on both sides, so the lists match).
  send_.assign(P, {}), recv_.assign(P, {});
  for (const int i : ring2_) {
    const int owner = part[static_cast<std::size_t>(i)];
    if (owner != rank) recv_[static_cast<std::size_t>(owner)].push_back(i);
  }
  for (int q = 0; q < size; ++q) {
    if (q == rank) continue;
    for (const int i : grow(cells, own_of_[static_cast<std::size_t>(q)], 2))
      if (part[static_cast<std::size_t>(i)] == rank)
        send_[static_cast<std::size_t>(q)].push_back(i);
  }
  for (int q = 0; q < size; ++q)
    if (!send_[static_cast<std::size_t>(q)].empty() || !recv_[static_cast<std::size_t>(q)].empty())
      peers_.push_back(q);
}

double RankSplit::seconds_since_split() const {
  return omp_get_wtime() - made_;
}

#if FLOTSAM_MPI

namespace {
constexpr int halo_tag = 41;  // the halo's messages
}  // namespace

void RankSplit::exchange(std::span<double* const> arrays) const {
  if (size_ == 1) return;
  const double start = omp_get_wtime();
  const auto A = arrays.size();
  std::vector<std::vector<double>> out(peers_.size()), in(peers_.size());
  std::vector<MPI_Request> requests;
  requests.reserve(2 * peers_.size());
  for (std::size_t p = 0; p < peers_.size(); ++p) {
    const auto q = static_cast<std::size_t>(peers_[p]);
    in[p].resize(A * recv_[q].size());
    requests.emplace_back();
    MPI_Irecv(in[p].data(), static_cast<int>(in[p].size()), MPI_DOUBLE, peers_[p], halo_tag,
              MPI_COMM_WORLD, &requests.back());
  }
  for (std::size_t p = 0; p < peers_.size(); ++p) {
    const auto q = static_cast<std::size_t>(peers_[p]);
    out[p].reserve(A * send_[q].size());
    for (double* a : arrays)
      for (const int i : send_[q]) out[p].push_back(a[i]);
    requests.emplace_back();
    MPI_Isend(out[p].data(), static_cast<int>(out[p].size()), MPI_DOUBLE, peers_[p], halo_tag,
              MPI_COMM_WORLD, &requests.back());
    bytes_ += 8.0 * static_cast<double>(out[p].size());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  for (std::size_t p = 0; p < peers_.size(); ++p) {
    const auto& cells = recv_[static_cast<std::size_t>(peers_[p])];
    std::size_t k = 0;
    for (double* a : arrays)
      for (const int i : cells) a[i] = in[p][k++];
  }
  seconds_ += omp_get_wtime() - start;
}

// Every rank's `mine` (rank q sends counts[q] values) on every rank, in rank order.
std::vector<double> RankSplit::all_of(const std::vector<double>& mine,
                                      const std::vector<int>& counts) const {
  std::vector<int> offsets(counts.size(), 0);
  int total = 0;
  for (std::size_t q = 0; q < counts.size(); ++q) {
    offsets[q] = total;
    total += counts[q];
  }
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(), counts.data(),
                 offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  bytes_ += 8.0 * static_cast<double>(mine.size()) * (size_ - 1);
  return all;
}

void RankSplit::gather(double* data, int per_cell) const {
  if (size_ == 1) return;
  const double start = omp_get_wtime();
  std::vector<int> counts;
  for (const auto& own : own_of_) counts.push_back(per_cell * static_cast<int>(own.size()));
  std::vector<double> mine;
  mine.reserve(static_cast<std::size_t>(per_cell) * own_.size());
  for (const int i : own_)
    for (int k = 0; k < per_cell; ++k) mine.push_back(data[per_cell * i + k]);
  const std::vector<double> all = all_of(mine, counts);
  std::size_t j = 0;
  for (const auto& own : own_of_)
    for (const int i : own)
      for (int k = 0; k < per_cell; ++k) data[per_cell * i + k] = all[j++];
  seconds_ += omp_get_wtime() - start;
}

void RankSplit::gather_boundary(std::vector<double>& values) const {
  if (size_ == 1) return;
  const double start = omp_get_wtime();
  std::vector<int> counts;
  for (const auto& positions : bedges_of_) counts.push_back(static_cast<int>(positions.size()));
  std::vector<double> mine;
  for (const int k : bedges_) mine.push_back(values[static_cast<std::size_t>(k)]);
  const std::vector<double> all = all_of(mine, counts);
  std::size_t j = 0;
  for (const auto& positions : bedges_of_)
    for (const int k : positions) values[static_cast<std::size_t>(k)] = all[j++];
  seconds_ += omp_get_wtime() - start;
}

double RankSplit::min(double x) const {
  if (size_ == 1) return x;
  const double start = omp_get_wtime();
  double result = x;
  MPI_Allreduce(&x, &result, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  seconds_ += omp_get_wtime() - start;
  return result;
}

bool RankSplit::any(bool x) const {
  if (size_ == 1) return x;
  const double start = omp_get_wtime();
  int mine = x ? 1 : 0, result = 0;
  MPI_Allreduce(&mine, &result, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
  seconds_ += omp_get_wtime() - start;
  return result != 0;
}

#else

void RankSplit::exchange(std::span<double* const>) const {}
void RankSplit::gather(double*, int) const {}
void RankSplit::gather_boundary(std::vector<double>&) const {}
std::vector<double> RankSplit::all_of(const std::vector<double>& mine,
                                      const std::vector<int>&) const {
  return mine;
}
double RankSplit::min(double x) const {
  return x;
}
bool RankSplit::any(bool x) const {
  return x;
}

#endif

}  // namespace flotsam
