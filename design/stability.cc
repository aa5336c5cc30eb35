#include "design/stability.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <string>
#include <tuple>

#include "core/error.h"

namespace tbridge {

StabilityReport CheckStability(const Structure& s, const Eigen::VectorXd& forces,
                               const std::vector<double>& k_string, double relative_tolerance) {
  const int nb = s.num_bars();
  const int ns = s.num_strings();
  if (forces.size() != nb + ns || static_cast<int>(k_string.size()) != ns) {
    throw ModelError("CheckStability: expected " + std::to_string(nb + ns) + " member forces and " +
                     std::to_string(ns) + " string stiffnesses, got " +
                     std::to_string(forces.size()) + " and " + std::to_string(k_string.size()));
  }
  const int dim = s.dim();
  std::vector<int> dof(s.num_nodes(), -1);
  int ndof = 0;
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (!s.fixed[v]) {
      dof[v] = ndof;
      ndof += dim;
    }
  }

  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(ndof, ndof);
  auto add = [&](const Member& m, const Eigen::MatrixXd& G) {
    for (const auto& [a, b, sign] : {std::tuple{m.i, m.i, 1.0}, std::tuple{m.j, m.j, 1.0},
                                     std::tuple{m.i, m.j, -1.0}, std::tuple{m.j, m.i, -1.0}}) {
      if (dof[a] >= 0 && dof[b] >= 0) K.block(dof[a], dof[b], dim, dim) += sign * G;
    }
  };
  auto unit = [&](const Member& m) {
    return Eigen::VectorXd((s.nodes.col(m.j) - s.nodes.col(m.i)).head(dim).normalized());
  };
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(dim, dim);
  for (int k = 0; k < ns; ++k) {
    const Member& m = s.strings[k];
    const Eigen::VectorXd u = unit(m);
    const double q = forces[nb + k] / s.Length(m);
    add(m, q * (I - u * u.transpose()) + k_string[k] * u * u.transpose());
  }
  // Bar length constraints on the free DOFs, one row per bar.
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(nb, ndof);
  for (int b = 0; b < nb; ++b) {
    const Member& m = s.bars[b];
    add(m, -(forces[b] / s.Length(m)) * I);
    const Eigen::VectorXd u = unit(m);
    if (dof[m.i] >= 0) C.block(b, dof[m.i], 1, dim) = -u.transpose();
    if (dof[m.j] >= 0) C.block(b, dof[m.j], 1, dim) = u.transpose();
  }

  StabilityReport r;
  r.free_dofs = ndof;
  // Null space of C from a rank-revealing QR of C^T: the trailing columns of Q.
  Eigen::MatrixXd N;
  if (nb > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(C.transpose());
    qr.setThreshold(1e-12);  // rows of C are unit-norm pairs, so rank decisions are O(1)
    r.bar_constraints = static_cast<int>(qr.rank());
    const Eigen::MatrixXd Q = qr.householderQ();
    N = Q.rightCols(ndof - r.bar_constraints);
  } else {
    N = Eigen::MatrixXd::Identity(ndof, ndof);
  }
  r.reduced_dofs = static_cast<int>(N.cols());
  if (r.reduced_dofs == 0) {
    r.positive_definite = true;  // nothing can move
    return r;
  }
  const Eigen::MatrixXd Kr = N.transpose() * K * N;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (Kr + Kr.transpose()));
  r.eigenvalues = eig.eigenvalues();
  r.min_eigenvalue = r.eigenvalues[0];
  r.max_eigenvalue = r.eigenvalues[r.reduced_dofs - 1];
  const double scale = r.eigenvalues.cwiseAbs().maxCoeff();
  for (int i = 0; i < r.reduced_dofs; ++i) {
    if (r.eigenvalues[i] <= relative_tolerance * scale) ++r.non_positive;
  }
  r.positive_definite = r.non_positive == 0;
  r.softest_mode = (N * eig.eigenvectors().col(0)).normalized();
  return r;
}

StabilityReport CheckStability(const Design& d, double relative_tolerance) {
  std::vector<double> k(d.strings.size());
  for (size_t i = 0; i < d.strings.size(); ++i) k[i] = d.strings[i].stiffness;
  return CheckStability(d.topology.structure, MemberForces(d), k, relative_tolerance);
}

}  // namespace tbridge
