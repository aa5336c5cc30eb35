#include "design/equilibrium_basis.h"

#include <SuiteSparseQR.hpp>
#include <Eigen/SparseCore>
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
  Eigen::MatrixXd out = Eigen::Map<Eigen::MatrixXd>(static_cast<double*>(d->x),
                                                    static_cast<Eigen::Index>(d->nrow),
                                                    static_cast<Eigen::Index>(d->ncol));
  cholmod_l_free_dense(&d, cc);
  return out;
}

}  // namespace

EquilibriumBasis FactorEquilibrium(const EquilibriumSystem& eq, const Eigen::MatrixXd& free_loads,
                                   double max_basis_entries) {
  const Eigen::Index n = eq.A.cols(), m = eq.A.rows(), cases = free_loads.cols();
  if (free_loads.rows() != m) throw ModelError("equilibrium factorisation: load rows differ from the DOFs");
  EquilibriumBasis out;
  if (m == 0) {  // nothing free: every member force is a self-stress
    out.particular = Eigen::MatrixXd::Zero(n, cases);
    out.self_stress = Eigen::MatrixXd::Identity(n, n);
    out.states = static_cast<int>(n);
    return out;
  }
  Common common;
  cholmod_common* cc = common.get();
  LongSparse at = eq.A.transpose();
  at.makeCompressed();
  cholmod_sparse at_view = SparseView(at);
  using Factor = SuiteSparseQR_factorization<double>;
  auto release = [cc](Factor* f) { SuiteSparseQR_free<double>(&f, cc); };
  std::unique_ptr<Factor, decltype(release)> qr(
      SuiteSparseQR_factorize<double>(SPQR_ORDERING_DEFAULT, SPQR_DEFAULT_TOL, &at_view, cc), release);
  if (!qr) throw ModelError("equilibrium factorisation: sparse QR failed (status " + std::to_string(cc->status) + ")");
  out.rank = static_cast<int>(qr->rank);

  // y = R^-T (E^T (-w)), zero past the rank; x_p = Q y.
  Eigen::MatrixXd rhs = -free_loads;
  cholmod_dense rhs_view = DenseView(rhs);
  Eigen::MatrixXd y = TakeDense(SuiteSparseQR_solve<double>(SPQR_RTX_EQUALS_ETB, qr.get(), &rhs_view, cc), cc,
                                "the triangular solve");
  y.bottomRows(n - out.rank).setZero();
  cholmod_dense y_view = DenseView(y);
  out.particular = TakeDense(SuiteSparseQR_qmult<double>(SPQR_QX, qr.get(), &y_view, cc), cc, "Q x");

  const Eigen::Index s = n - out.rank;
  out.states = static_cast<int>(s);
  const Eigen::MatrixXd residual = eq.A * out.particular + free_loads;
  out.load_residual = residual.size() ? residual.cwiseAbs().maxCoeff() : 0.0;
  if (static_cast<double>(n) * static_cast<double>(s) > max_basis_entries) {
    out.basis_formed = false;
    out.self_stress = Eigen::MatrixXd(n, 0);
    return out;
  }
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(n, s);
  for (Eigen::Index k = 0; k < s; ++k) unit(out.rank + k, k) = 1.0;
  cholmod_dense unit_view = DenseView(unit);
  out.self_stress = s > 0 ? TakeDense(SuiteSparseQR_qmult<double>(SPQR_QX, qr.get(), &unit_view, cc), cc, "Q e")
                          : Eigen::MatrixXd(n, 0);

  const Eigen::MatrixXd an = eq.A * out.self_stress;
  out.basis_residual = an.size() ? an.cwiseAbs().maxCoeff() : 0.0;
  return out;
}

}  // namespace tbridge
