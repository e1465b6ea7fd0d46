#pragma once
// Preconditioned conjugate gradients for one symmetric positive definite A x = b with some entries
// of x fixed (Dirichlet values): the reference that the segregated step's solve of u and v at once
// (flow/fem/pair_conjugate_gradients.hpp) is checked against, component by component.
#include <Eigen/Dense>
#include <algorithm>
#include <vector>

namespace flotsam {

// Conjugate gradients for A x = b on the free entries (fixed ones keep their value in x):
// apply(p, Ap) computes A p, precondition(r, z) z = P^-1 r; both see zero at fixed entries.
template <class Apply, class Precondition>
int conjugate_gradients(const Apply& apply, const Precondition& precondition,
                        const std::vector<char>& fixed, const Eigen::VectorXd& b,
                        Eigen::VectorXd& x, double tolerance, int max_iterations) {
  const auto mask = [&](Eigen::VectorXd& w) {
    for (Eigen::Index i = 0; i < w.size(); ++i)
      if (fixed[i]) w[i] = 0.0;
  };
  Eigen::VectorXd Ap(x.size());
  apply(x, Ap);
  Eigen::VectorXd r = b - Ap;
  mask(r);
  const double b_norm = [&] {
    Eigen::VectorXd bf = b;
    mask(bf);
    return bf.norm();
  }();
  const double stop = tolerance * std::max(b_norm, 1e-300);
  if (r.norm() <= stop) return 0;
  Eigen::VectorXd z(x.size());
  precondition(r, z);
  mask(z);
  Eigen::VectorXd p = z;
  double rz = r.dot(z);
  for (int k = 1; k <= max_iterations; ++k) {
    apply(p, Ap);
    mask(Ap);
    const double alpha = rz / p.dot(Ap);
    x += alpha * p;
    r -= alpha * Ap;
    if (r.norm() <= stop) return k;
    precondition(r, z);
    mask(z);
    const double rz_new = r.dot(z);
    p = z + (rz_new / rz) * p;
    rz = rz_new;
  }
  return max_iterations + 1;  // not converged
}

}  // namespace flotsam
