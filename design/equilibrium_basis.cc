#include "design/equilibrium_basis.h"

#include <Eigen/SparseCore>
#include <SuiteSparseQR.hpp>
#include <memory>

#include "core/error.h"

namespace tbridge {

namespace {

// One cholmod_common per call: factorisations on several threads never share state.
class Common {
 public:
  Common() { cholmod_l_start(&cc_); }
  ~Common() { cholmod_l_finish(&cc_); }
  Common(const Common&) = delete;
  Common& operator=(const Common&) = delete;
  cholmod_common* get() { return &cc_; }

 private:
  cholmod_common cc_;
};

using LongSparse = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;

// A non-owning cholmod view of a compressed Eigen matrix or of dense column-major storage.
cholmod_sparse SparseView(LongSparse& m) {
  cholmod_sparse v{};
  v.nrow = static_cast<size_t>(m.rows());
  v.ncol = static_cast<size_t>(m.cols());
  v.nzmax = static_cast<size_t>(m.nonZeros());
  v.p = m.outerIndexPtr();
  v.i = m.innerIndexPtr();
  v.x = m.valuePtr();
  v.stype = 0;
  v.itype = CHOLMOD_LONG;
  v.xtype = CHOLMOD_REAL;
  v.dtype = CHOLMOD_DOUBLE;
  v.sorted = 1;
  v.packed = 1;
  return v;
}

cholmod_dense DenseView(Eigen::MatrixXd& m) {
  cholmod_dense v{};
  v.nrow = static_cast<size_t>(m.rows());
  v.ncol = static_cast<size_t>(m.cols());
  v.nzmax = v.nrow * v.ncol;
  v.d = v.nrow;
  v.x = m.data();
  v.xtype = CHOLMOD_REAL;
  v.dtype = CHOLMOD_DOUBLE;
  return v;
}

// Copies a cholmod result into Eigen and frees it.
Eigen::MatrixXd TakeDense(cholmod_dense* d, cholmod_common* cc, const char* what) {
  if (d == nullptr) throw ModelError(std::string("equilibrium factorisation: ") + what + " failed");
  Eigen::MatrixXd out =
      Eigen::Map<Eigen::MatrixXd>(static_cast<double*>(d->x), static_cast<Eigen::Index>(d->nrow),
                                  static_cast<Eigen::Index>(d->ncol));
  cholmod_l_free_dense(&d, cc);
  return out;
}

}  // namespace

struct EquilibriumSolver::Impl {
  using Factor = SuiteSparseQR_factorization<double>;
  Common common;
  LongSparse at;
  Factor* qr = nullptr;
  Eigen::Index members = 0, dofs = 0;
  int rank = 0;
  ~Impl() {
    if (qr) SuiteSparseQR_free<double>(&qr, common.get());
  }
};

EquilibriumSolver::EquilibriumSolver(const EquilibriumSystem& eq)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.members = eq.A.cols();
  d.dofs = eq.A.rows();
  if (d.dofs == 0) return;  // nothing free: every member force is a self-stress
  cholmod_common* cc = d.common.get();
  d.at = eq.A.transpose();
  d.at.makeCompressed();
  cholmod_sparse at_view = SparseView(d.at);
  d.qr = SuiteSparseQR_factorize<double>(SPQR_ORDERING_DEFAULT, SPQR_DEFAULT_TOL, &at_view, cc);
  if (!d.qr)
    throw ModelError("equilibrium factorisation: sparse QR failed (status " +
                     std::to_string(cc->status) + ")");
  d.rank = static_cast<int>(d.qr->rank);
}

EquilibriumSolver::~EquilibriumSolver() = default;

int EquilibriumSolver::rank() const { return impl_->rank; }
int EquilibriumSolver::states() const { return static_cast<int>(impl_->members) - impl_->rank; }

Eigen::MatrixXd EquilibriumSolver::Particular(const Eigen::MatrixXd& free_loads) const {
  Impl& d = *impl_;
  if (free_loads.rows() != d.dofs)
    throw ModelError("equilibrium factorisation: load rows differ from the DOFs");
  if (d.dofs == 0 || free_loads.cols() == 0)
    return Eigen::MatrixXd::Zero(d.members, free_loads.cols());
  cholmod_common* cc = d.common.get();
  // y = R^-T (E^T (-w)), zero past the rank; x_p = Q y.
  Eigen::MatrixXd rhs = -free_loads;
  cholmod_dense rhs_view = DenseView(rhs);
  Eigen::MatrixXd y =
      TakeDense(SuiteSparseQR_solve<double>(SPQR_RTX_EQUALS_ETB, d.qr, &rhs_view, cc), cc,
                "the triangular solve");
  y.bottomRows(d.members - d.rank).setZero();
  cholmod_dense y_view = DenseView(y);
  return TakeDense(SuiteSparseQR_qmult<double>(SPQR_QX, d.qr, &y_view, cc), cc, "Q x");
}

Eigen::MatrixXd EquilibriumSolver::SelfStresses() const {
  Impl& d = *impl_;
  const Eigen::Index s = d.members - d.rank;
  if (d.dofs == 0) return Eigen::MatrixXd::Identity(d.members, d.members);
  if (s == 0) return Eigen::MatrixXd(d.members, 0);
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(d.members, s);
  for (Eigen::Index k = 0; k < s; ++k) unit(d.rank + k, k) = 1.0;
  cholmod_dense unit_view = DenseView(unit);
  return TakeDense(SuiteSparseQR_qmult<double>(SPQR_QX, d.qr, &unit_view, d.common.get()),
                   d.common.get(), "Q e");
}

EquilibriumBasis FactorEquilibrium(const EquilibriumSolver& solver, const EquilibriumSystem& eq,
                                   const Eigen::MatrixXd& free_loads, double max_basis_entries) {
  EquilibriumBasis out;
  out.rank = solver.rank();
  out.states = solver.states();
  out.particular = solver.Particular(free_loads);
  const Eigen::MatrixXd residual = eq.A * out.particular + free_loads;
  out.load_residual = residual.size() ? residual.cwiseAbs().maxCoeff() : 0.0;
  const Eigen::Index n = eq.A.cols();
  if (static_cast<double>(n) * static_cast<double>(out.states) > max_basis_entries) {
    out.basis_formed = false;
    out.self_stress = Eigen::MatrixXd(n, 0);
    return out;
  }
  out.self_stress = solver.SelfStresses();
  const Eigen::MatrixXd an = eq.A * out.self_stress;
  out.basis_residual = an.size() ? an.cwiseAbs().maxCoeff() : 0.0;
  return out;
}

EquilibriumBasis FactorEquilibrium(const EquilibriumSystem& eq, const Eigen::MatrixXd& free_loads,
                                   double max_basis_entries) {
  const EquilibriumSolver solver(eq);
  return FactorEquilibrium(solver, eq, free_loads, max_basis_entries);
}

}  // namespace tbridge
