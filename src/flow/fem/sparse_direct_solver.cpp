// Eigen's sparse module trips GCC's -Wnull-dereference inside its own headers.
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include "flow/fem/sparse_direct_solver.hpp"

#include <fmt/format.h>

#include <Eigen/KLUSupport>
#include <Eigen/UmfPackSupport>
#include <vector>

#include "flow/fem/serial_blas.hpp"

namespace flotsam {

namespace {

using LongIndex = SuiteSparse_long;
using LongSparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, LongIndex>;
using LongSparseMap = Eigen::Map<const LongSparseMatrix>;

/// Eigen's UmfPackLU keeps UMFPACK's Info array to itself; the sizes of the LU are in it.
class UmfPackWithInfo : public Eigen::UmfPackLU<LongSparseMatrix> {
 public:
  double info(int entry) const { return m_umfpackInfo[entry]; }
};

const char* umfpack_status_name(long status) {
  switch (status) {
    case UMFPACK_WARNING_singular_matrix:
      return "singular matrix";
    case UMFPACK_ERROR_out_of_memory:
      return "out of memory";
    case UMFPACK_ERROR_invalid_matrix:
      return "invalid matrix";
    case UMFPACK_ERROR_different_pattern:
      return "pattern changed since the analysis";
    case UMFPACK_ERROR_ordering_failed:
      return "ordering failed";
    case UMFPACK_ERROR_internal_error:
      return "internal error";
    default:
      return "error";
  }
}

const char* klu_status_name(int status) {
  switch (status) {
    case KLU_SINGULAR:
      return "singular matrix";
    case KLU_OUT_OF_MEMORY:
      return "out of memory";
    case KLU_INVALID:
      return "invalid input";
    case KLU_TOO_LARGE:
      return "integer overflow (matrix too large)";
    default:
      return "error";
  }
}

FactorizationFailure failure_kind(bool singular, bool out_of_memory) {
  if (singular) return FactorizationFailure::singular;
  return out_of_memory ? FactorizationFailure::out_of_memory : FactorizationFailure::other;
}

constexpr double gib = 1024.0 * 1024.0 * 1024.0;  // [bytes]

}  // namespace

struct SparseDirectSolver::Impl {
  LinearSolverKind kind;
  bool analysed = false;
  UmfPackWithInfo umfpack;
  std::vector<LongIndex> outer, inner;  // A's pattern in 64-bit indices (UMFPACK)
  Eigen::KLU<SparseMatrix> klu;

  LongSparseMap long_view(const SparseMatrix& A) const {
    return LongSparseMap(A.rows(), A.cols(), A.nonZeros(), outer.data(), inner.data(),
                         A.valuePtr());
  }
};

SparseDirectSolver::SparseDirectSolver(LinearSolverKind kind) : impl_(std::make_unique<Impl>()) {
  impl_->kind = kind;
  // No iterative refinement: LU with partial pivoting already leaves a residual at round-off
  // on these systems (the water balance closes to 1e-15), and each refinement step costs a solve
  // and a product with A.
  impl_->umfpack.umfpackControl()(UMFPACK_IRSTEP) = 0;
}
SparseDirectSolver::~SparseDirectSolver() = default;
SparseDirectSolver::SparseDirectSolver(SparseDirectSolver&&) noexcept = default;
SparseDirectSolver& SparseDirectSolver::operator=(SparseDirectSolver&&) noexcept = default;

bool SparseDirectSolver::factorize(const SparseMatrix& A) {
  const SerialBlas serial;
  Impl& s = *impl_;
  failure_ = FactorizationFailure::none;
  failure_message_.clear();
  const auto describe = [&](const char* solver, const char* status_name, long status) {
    return fmt::format("{}: {} (status {}) factorising the {} x {} matrix with {} entries", solver,
                       status_name, status, A.rows(), A.cols(), A.nonZeros());
  };
  if (s.kind == LinearSolverKind::klu) {
    if (!s.analysed) s.klu.analyzePattern(A);
    s.analysed = true;
    s.klu.factorize(A);
    if (s.klu.info() == Eigen::Success) return true;
    const int status = s.klu.kluCommon().status;
    failure_ = failure_kind(status == KLU_SINGULAR, status == KLU_OUT_OF_MEMORY);
    failure_message_ = describe("KLU", klu_status_name(status), status);
    return false;
  }

  if (!s.analysed) {
    s.outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
    s.inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
    s.umfpack.analyzePattern(s.long_view(A));
    s.analysed = true;
  }
  s.umfpack.factorize(s.long_view(A));
  // The determinant warnings (2, 3) leave a valid factorisation.
  const long status = s.umfpack.umfpackFactorizeReturncode();
  if (status == UMFPACK_OK || status == UMFPACK_WARNING_determinant_underflow ||
      status == UMFPACK_WARNING_determinant_overflow)
    return true;
  failure_ = failure_kind(status == UMFPACK_WARNING_singular_matrix,
                          status == UMFPACK_ERROR_out_of_memory);
  failure_message_ = describe("UMFPACK", umfpack_status_name(status), status);
  if (failure_ == FactorizationFailure::out_of_memory) {
    // Upper bounds from the symbolic analysis, in UMFPACK's units (Info[UMFPACK_SIZE_OF_UNIT]
    // bytes); the LU is often far smaller (on the paper's channel about 80 times).
    const double unit = s.umfpack.info(UMFPACK_SIZE_OF_UNIT);
    failure_message_ += fmt::format(
        ": the analysis bounds the LU by {:.1f} GiB ({:.3g} entries) and the factorisation's "
        "peak by {:.1f} GiB",
        s.umfpack.info(UMFPACK_NUMERIC_SIZE_ESTIMATE) * unit / gib,
        s.umfpack.info(UMFPACK_LNZ_ESTIMATE) + s.umfpack.info(UMFPACK_UNZ_ESTIMATE),
        s.umfpack.info(UMFPACK_PEAK_MEMORY_ESTIMATE) * unit / gib);
  }
  return false;
}

Eigen::VectorXd SparseDirectSolver::solve(const Eigen::VectorXd& b) const {
  const SerialBlas serial;
  if (impl_->kind == LinearSolverKind::umfpack) return impl_->umfpack.solve(b);
  return impl_->klu.solve(b);
}

}  // namespace flotsam
