// Eigen's sparse module trips GCC's -Wnull-dereference inside its own headers.
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include "flow/fem/linear_system.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace flotsam {

std::array<int, 15> LinearSystem::element_rows(const Mesh& mesh, int e) const {
  const auto& el = mesh.elements[e];
  std::array<int, 15> rows;
  for (int a = 0; a < 6; ++a) {
    rows[local_velocity(a, 0)] = u_row(el[a]);
    rows[local_velocity(a, 1)] = v_row(el[a]);
  }
  for (int j = 0; j < 3; ++j) rows[local_elevation(j)] = eta_row(el[j]);
  return rows;
}

void LinearSystem::setup(const Mesh& mesh, const std::vector<int>& dirichlet_rows,
                         const std::vector<int>& slip_nodes) {
  node_count_ = mesh.node_count();
  const int n = 2 * node_count_ + mesh.vertex_count;
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<size_t>(mesh.element_count()) * 225);
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto rows = element_rows(mesh, e);
    for (int r : rows)
      for (int c : rows) entries.emplace_back(r, c, 0.0);
  }
  A.resize(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  b = Eigen::VectorXd::Zero(n);
  // Per element, the position of the first entry of each of its 9 x 9 node blocks (row node,
  // column node; nodes in the order u of the six P2 nodes, then eta of the three vertices).
  constexpr std::array<int, 9> first_row = {
      local_velocity(0, 0), local_velocity(1, 0), local_velocity(2, 0),
      local_velocity(3, 0), local_velocity(4, 0), local_velocity(5, 0),
      local_elevation(0),   local_elevation(1),   local_elevation(2)};
  block_positions_.resize(static_cast<size_t>(mesh.element_count()) * 81);
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto rows = element_rows(mesh, e);
    int* block = block_positions_.data() + static_cast<size_t>(e) * 81;
    for (int c : first_row)
      for (int r : first_row) *block++ = position(rows[r], rows[c]);
  }

  dirichlet_rows_ = dirichlet_rows;
  slip_nodes_ = slip_nodes;
  // Row lists: one pass over the column-major storage, columns in increasing order, so that the
  // u and v rows of a node list the same columns in the same order.
  std::vector<int> slot(n, -1);
  const int n_d = static_cast<int>(dirichlet_rows.size());
  for (int k = 0; k < n_d; ++k) slot[dirichlet_rows[k]] = k;
  for (int k = 0; k < static_cast<int>(slip_nodes.size()); ++k) {
    slot[u_row(slip_nodes[k])] = n_d + 2 * k;
    slot[v_row(slip_nodes[k])] = n_d + 2 * k + 1;
  }
  std::vector<RowEntries> lists(n_d + 2 * slip_nodes.size());
  for (int c = 0; c < n; ++c)
    for (int p = A.outerIndexPtr()[c]; p < A.outerIndexPtr()[c + 1]; ++p) {
      const int s = slot[A.innerIndexPtr()[p]];
      if (s < 0) continue;
      lists[s].position.push_back(p);
      lists[s].column.push_back(c);
    }
  dirichlet_entries_.assign(lists.begin(), lists.begin() + n_d);
  slip_u_entries_.clear();
  slip_v_entries_.clear();
  for (size_t k = 0; k < slip_nodes.size(); ++k) {
    slip_u_entries_.push_back(lists[n_d + 2 * k]);
    slip_v_entries_.push_back(lists[n_d + 2 * k + 1]);
    if (slip_u_entries_.back().column != slip_v_entries_.back().column)
      throw std::logic_error("LinearSystem: u and v rows of a slip node differ in pattern");
  }
  saved_values_.assign(n_d, {});
  saved_rhs_.assign(n_d, 0.0);
}

void LinearSystem::set_zero() {
  std::fill(A.valuePtr(), A.valuePtr() + A.outerIndexPtr()[A.outerSize()], 0.0);
  b.setZero();
}

int LinearSystem::position(int row, int column) const {
  const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[column];
  const int* end = A.innerIndexPtr() + A.outerIndexPtr()[column + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - A.innerIndexPtr());
}

// The pattern holds full 2x2 node blocks (setup), so one stored position gives up to four
// entries: in column 2n (u of node n) the v row 2m+1 of node m follows its u row 2m, and column
// 2n+1 (v of node n), stored right after column 2n, has the same rows, its entries shifted by the
// length of column 2n. Each entry receives the element's contributions in element order
// (deterministic).
void LinearSystem::add(int element, const std::array<int, 15>& rows, const LocalMatrix& K,
                       const LocalVector& F) {
  double* values = A.valuePtr();
  const int* outer = A.outerIndexPtr();
  const int* block = block_positions_.data() + static_cast<size_t>(element) * 81;
  for (int c = 0; c < 6; ++c, block += 9) {  // columns u and v of node c
    const int column = rows[local_velocity(c, 0)];
    const int shift = outer[column + 1] - outer[column];
    for (int a = 0; a < 6; ++a) {
      const int p = block[a];
      values[p] += K(local_velocity(a, 0), local_velocity(c, 0));
      values[p + 1] += K(local_velocity(a, 1), local_velocity(c, 0));
      values[p + shift] += K(local_velocity(a, 0), local_velocity(c, 1));
      values[p + shift + 1] += K(local_velocity(a, 1), local_velocity(c, 1));
    }
    for (int j = 0; j < 3; ++j) {
      values[block[6 + j]] += K(local_elevation(j), local_velocity(c, 0));
      values[block[6 + j] + shift] += K(local_elevation(j), local_velocity(c, 1));
    }
  }
  for (int k = 0; k < 3; ++k, block += 9) {  // column eta of vertex k
    for (int a = 0; a < 6; ++a) {
      values[block[a]] += K(local_velocity(a, 0), local_elevation(k));
      values[block[a] + 1] += K(local_velocity(a, 1), local_elevation(k));
    }
    for (int j = 0; j < 3; ++j) values[block[6 + j]] += K(local_elevation(j), local_elevation(k));
  }
  for (int i = 0; i < 15; ++i) b[rows[i]] += F(i);
}

void LinearSystem::set_dirichlet(int slot, double value) {
  const int row = dirichlet_rows_[slot];
  const auto& list = dirichlet_entries_[slot];
  for (size_t k = 0; k < list.position.size(); ++k)
    A.valuePtr()[list.position[k]] = list.column[k] == row ? 1.0 : 0.0;
  b[row] = value;
}

void LinearSystem::set_slip(int slot, const Vec2& n) {
  const int node = slip_nodes_[slot];
  const int ru = u_row(node), rv = v_row(node);
  const Vec2 t(-n.y(), n.x());
  const auto& lu = slip_u_entries_[slot];
  const auto& lv = slip_v_entries_[slot];
  double* values = A.valuePtr();
  for (size_t k = 0; k < lu.position.size(); ++k) {
    const double a_u = values[lu.position[k]], a_v = values[lv.position[k]];
    values[lu.position[k]] = t.x() * a_u + t.y() * a_v;  // tangential momentum
    const int c = lv.column[k];
    values[lv.position[k]] = c == ru ? n.x() : c == rv ? n.y() : 0.0;  // n . u = 0
  }
  b[ru] = t.x() * b[ru] + t.y() * b[rv];
  b[rv] = 0.0;
}

void LinearSystem::save_dirichlet_rows() {
  for (size_t k = 0; k < dirichlet_rows_.size(); ++k) {
    const auto& list = dirichlet_entries_[k];
    saved_values_[k].resize(list.position.size());
    for (size_t i = 0; i < list.position.size(); ++i)
      saved_values_[k][i] = A.valuePtr()[list.position[i]];
    saved_rhs_[k] = b[dirichlet_rows_[k]];
  }
}

double LinearSystem::saved_row_residual(int slot, const Eigen::VectorXd& x) const {
  const auto& list = dirichlet_entries_[slot];
  double r = -saved_rhs_[slot];
  for (size_t i = 0; i < list.column.size(); ++i) r += saved_values_[slot][i] * x[list.column[i]];
  return r;
}

}  // namespace flotsam
