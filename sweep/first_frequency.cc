#include "sweep/first_frequency.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "dynamics/modal.h"

namespace tbridge {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// [K - sigma M, C^T; C, 0] from the dense blocks; entries below 1e-300 in magnitude are zeros.
SparseMatrix SaddlePoint(const LinearisedSystem& sys, double sigma) {
  const Eigen::Index n = sys.stiffness.rows(), m = sys.constraints.rows();
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index c = 0; c < n; ++c) {
    for (Eigen::Index r = 0; r < n; ++r) {
      const double v = sys.stiffness(r, c) - sigma * sys.mass(r, c);
      if (v != 0.0) t.emplace_back(r, c, v);
    }
  }
  for (Eigen::Index r = 0; r < m; ++r) {
    for (Eigen::Index c = 0; c < n; ++c) {
      const double v = sys.constraints(r, c);
      if (v == 0.0) continue;
      t.emplace_back(n + r, c, v);
      t.emplace_back(c, n + r, v);
    }
  }
  SparseMatrix a(n + m, n + m);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

}  // namespace

FirstFrequency LowestFrequency(const DynamicModel& model, const FirstFrequencyOptions& options) {
  FirstFrequency out;
  const int free_dofs = [&] {
    int free_nodes = 0;
    for (const bool f : model.fixed) free_nodes += f ? 0 : 1;
    return free_nodes * model.dim;
  }();
  if (free_dofs <= options.dense_max_dofs) {
    const ModalResult modes = ComputeModes(model);
    if (modes.modes.empty()) throw ModelError("first frequency: the model has no free degree of freedom");
    out.omega_rad_s = modes.modes.front().omega_rad_s;
    out.method = "dense";
    return out;
  }

  const LinearisedSystem sys = Linearise(model);
  const Eigen::Index n = sys.stiffness.rows(), m = sys.constraints.rows();
  // A small negative shift keeps the factorisation regular when K has a zero mode on the
  // constraint manifold; 1e-6 of the mean stiffness-to-mass ratio leaves omega^2 unaffected.
  const double sigma = -1e-6 * sys.stiffness.diagonal().cwiseAbs().sum() / sys.mass.diagonal().sum();
  const SparseMatrix a = SaddlePoint(sys, sigma);
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(a);
  if (lu.info() != Eigen::Success) {
    throw ModelError("first frequency: the constrained stiffness is singular (a mechanism): " + lu.lastErrorMessage());
  }
  const SparseMatrix mass = sys.mass.sparseView();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
  auto apply = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    rhs.head(n) = mass * v;
    rhs.tail(m).setZero();
    return lu.solve(rhs).head(n);
  };
  auto m_dot = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& y) { return x.dot(mass * y); };

  // Deterministic start: a smooth field, mapped into the constrained subspace by one solve.
  Eigen::VectorXd v = Eigen::VectorXd::Ones(n);
  for (Eigen::Index k = 0; k < n; ++k) v(k) += 0.5 * std::sin(0.37 * static_cast<double>(k));
  v = apply(v);
  const int max_steps = static_cast<int>(std::min<Eigen::Index>(options.max_lanczos_steps, n - m));
  std::vector<Eigen::VectorXd> basis;
  std::vector<double> alpha, beta;
  double norm = std::sqrt(m_dot(v, v));
  if (!(norm > 0)) throw ModelError("first frequency: the start vector has no mass (massless free DOFs)");
  basis.push_back(v / norm);
  for (int step = 1; step <= max_steps; ++step) {
    Eigen::VectorXd w = apply(basis.back());
    alpha.push_back(m_dot(basis.back(), w));
    // Full re-orthogonalisation, twice ("twice is enough"), against the whole basis.
    for (int pass = 0; pass < 2; ++pass) {
      for (const Eigen::VectorXd& q : basis) w -= m_dot(q, w) * q;
    }
    const double b = std::sqrt(std::max(m_dot(w, w), 0.0));
    const int size = static_cast<int>(alpha.size());
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(size, size);
    for (int k = 0; k < size; ++k) {
      t(k, k) = alpha[k];
      if (k + 1 < size) t(k, k + 1) = t(k + 1, k) = beta[k];
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(t);
    // Lowest omega^2 is the largest theta = 1/(omega^2 - sigma) when the system is stable; an
    // unstable mode (omega^2 < sigma) shows as the most negative theta.
    const Eigen::Index top = size - 1;
    const double theta_max = eig.eigenvalues()(top);
    const double theta_min = eig.eigenvalues()(0);
    const bool unstable = theta_min < 0 && (sigma + 1.0 / theta_min) < 0;
    const Eigen::Index pick = unstable ? 0 : top;
    const double theta = unstable ? theta_min : theta_max;
    // Ritz residual |A x - theta x|_M = b |last component of the Ritz vector|.
    const double residual = b * std::abs(eig.eigenvectors()(top, pick));
    const bool invariant = b <= 1e-14 * std::abs(theta);  // the Krylov space is exact
    if (residual <= options.tolerance * std::abs(theta) || invariant) {
      const double omega2 = sigma + 1.0 / theta;
      out.omega_rad_s = omega2 >= 0 ? std::sqrt(omega2) : -std::sqrt(-omega2);
      out.method = "lanczos";
      out.lanczos_steps = step;
      return out;
    }
    if (step == max_steps) {
      throw ModelError("first frequency: Lanczos did not converge in " + std::to_string(max_steps) +
                       " steps (relative residual " + std::to_string(residual / std::abs(theta)) + ")");
    }
    beta.push_back(b);
    basis.push_back(w / b);
  }
  throw ModelError("first frequency: Lanczos found no Ritz value");
}

}  // namespace tbridge
