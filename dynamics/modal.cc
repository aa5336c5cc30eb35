#include "dynamics/modal.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace tbridge {
namespace {

void CheckModel(const DynamicModel& model) {
  const int n_n = model.num_nodes();
  if (model.dim != 2 && model.dim != 3) {
    throw ModelError("modal analysis: dim must be 2 or 3, got " + std::to_string(model.dim));
  }
  if (static_cast<int>(model.fixed.size()) != n_n) {
    throw ModelError("modal analysis: fixed has " + std::to_string(model.fixed.size()) +
                     " entries for " + std::to_string(n_n) + " nodes");
  }
  if (model.node_mass.size() != 0 && model.node_mass.size() != n_n) {
    throw ModelError("modal analysis: node_mass has " + std::to_string(model.node_mass.size()) +
                     " entries for " + std::to_string(n_n) + " nodes");
  }
  if (model.loads.size() != 0 && model.loads.cols() != n_n) {
    throw ModelError("modal analysis: loads has " + std::to_string(model.loads.cols()) +
                     " columns for " + std::to_string(n_n) + " nodes");
  }
  auto check_pair = [&](int i, int j, const std::string& what) {
    if (i < 0 || j < 0 || i >= n_n || j >= n_n || i == j) {
      throw ModelError("modal analysis: " + what + " joins nodes " + std::to_string(i) + " and " +
                       std::to_string(j) + " of " + std::to_string(n_n));
    }
  };
  for (size_t k = 0; k < model.bars.size(); ++k) {
    const DynamicBar& b = model.bars[k];
    check_pair(b.i, b.j, "bar " + std::to_string(k));
    if (b.mass < 0) throw ModelError("modal analysis: bar " + std::to_string(k) + " has negative mass");
  }
  for (size_t k = 0; k < model.strings.size(); ++k) {
    const DynamicString& s = model.strings[k];
    check_pair(s.i, s.j, "string " + std::to_string(k));
    if (s.stiffness < 0 || s.rest_length <= 0) {
      throw ModelError("modal analysis: string " + s.name + " needs stiffness >= 0 and rest length > 0");
    }
  }
  if (model.node_mass.size() != 0 && model.node_mass.minCoeff() < 0) {
    throw ModelError("modal analysis: negative node mass");
  }
}

// Adds the 3x3 block `k` as [k -k; -k k] at nodes i, j (only their free DOFs).
void AddPairBlock(const Eigen::Matrix3d& k, int i, int j, const std::vector<int>& first_dof, int dim,
                  Eigen::MatrixXd& target) {
  const int ends[2] = {i, j};
  for (int a = 0; a < 2; ++a) {
    for (int c = 0; c < 2; ++c) {
      const int ra = first_dof[ends[a]], rc = first_dof[ends[c]];
      if (ra < 0 || rc < 0) continue;
      const double sign = (a == c) ? 1.0 : -1.0;
      target.block(ra, rc, dim, dim) += sign * k.topLeftCorner(dim, dim);
    }
  }
}

}  // namespace

LinearisedSystem Linearise(const DynamicModel& model) {
  CheckModel(model);
  const int dim = model.dim;
  const int n_n = model.num_nodes();
  LinearisedSystem sys;

  std::vector<int> first_dof(n_n, -1);
  int n_dof = 0;
  for (int a = 0; a < n_n; ++a) {
    if (model.fixed[a]) continue;
    first_dof[a] = n_dof;
    for (int c = 0; c < dim; ++c) {
      sys.dof_node.push_back(a);
      sys.dof_axis.push_back(c);
    }
    n_dof += dim;
  }
  const int n_b = static_cast<int>(model.bars.size());
  const int n_s = static_cast<int>(model.strings.size());
  sys.stiffness = Eigen::MatrixXd::Zero(n_dof, n_dof);
  sys.mass = Eigen::MatrixXd::Zero(n_dof, n_dof);
  sys.constraints = Eigen::MatrixXd::Zero(n_b, n_dof);

  // Net non-bar force per node: loads minus string pulls. The planar case keeps only x, y.
  Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, n_n);
  if (model.loads.size() != 0) force = model.loads;
  sys.string_tension = Eigen::VectorXd::Zero(n_s);
  const Eigen::Matrix3d eye = Eigen::Matrix3d::Identity();
  for (int k = 0; k < n_s; ++k) {
    const DynamicString& st = model.strings[k];
    const Eigen::Vector3d s = model.positions.col(st.j) - model.positions.col(st.i);
    const double length = s.norm();
    if (length < st.rest_length) {
      ++sys.slack_strings;
      continue;
    }
    const double tension = st.stiffness * (length - st.rest_length);
    sys.string_tension(k) = tension;
    const Eigen::Vector3d u = s / length;
    force.col(st.i) += tension * u;
    force.col(st.j) -= tension * u;
    const Eigen::Matrix3d uu = u * u.transpose();
    const Eigen::Matrix3d block = (tension / length) * (eye - uu) + st.stiffness * uu;
    AddPairBlock(block, st.i, st.j, first_dof, dim, sys.stiffness);
  }

  // Bar force directions on the free DOFs: a compression lambda pushes node j along +b and
  // node i along -b. The same columns, transposed, are the constraint rows d(b.b/2)/dx.
  for (int k = 0; k < n_b; ++k) {
    const DynamicBar& bar = model.bars[k];
    const Eigen::Vector3d b = model.positions.col(bar.j) - model.positions.col(bar.i);
    if (first_dof[bar.i] >= 0) sys.constraints.block(k, first_dof[bar.i], 1, dim) = -b.head(dim).transpose();
    if (first_dof[bar.j] >= 0) sys.constraints.block(k, first_dof[bar.j], 1, dim) = b.head(dim).transpose();
  }
  Eigen::VectorXd f(n_dof);
  for (int r = 0; r < n_dof; ++r) f(r) = force(sys.dof_axis[r], sys.dof_node[r]);
  // Least squares: G^T lambda = -f. Rank-revealing so dependent bars (class k) get the minimum
  // norm split instead of a breakdown.
  sys.bar_force_density = Eigen::VectorXd::Zero(n_b);
  if (n_b > 0 && n_dof > 0) {
    const Eigen::MatrixXd gt = sys.constraints.transpose();
    sys.bar_force_density = gt.completeOrthogonalDecomposition().solve(-f);
    sys.equilibrium_residual = (f + gt * sys.bar_force_density).cwiseAbs().maxCoeff();
  } else if (n_dof > 0) {
    sys.equilibrium_residual = f.cwiseAbs().maxCoeff();
  }

  for (int k = 0; k < n_b; ++k) {
    const DynamicBar& bar = model.bars[k];
    AddPairBlock(-sys.bar_force_density(k) * eye, bar.i, bar.j, first_dof, dim, sys.stiffness);
    // Eq. (21): the uniform rigid bar's kinetic energy in its end velocities.
    const double third = bar.mass / 3.0, sixth = bar.mass / 6.0;
    const int ends[2] = {bar.i, bar.j};
    for (int a = 0; a < 2; ++a) {
      for (int c = 0; c < 2; ++c) {
        const int ra = first_dof[ends[a]], rc = first_dof[ends[c]];
        if (ra < 0 || rc < 0) continue;
        const double m = (a == c) ? third : sixth;
        for (int d = 0; d < dim; ++d) sys.mass(ra + d, rc + d) += m;
      }
    }
  }
  if (model.node_mass.size() != 0) {
    for (int a = 0; a < n_n; ++a) {
      if (first_dof[a] < 0) continue;
      for (int d = 0; d < dim; ++d) sys.mass(first_dof[a] + d, first_dof[a] + d) += model.node_mass(a);
    }
  }
  return sys;
}

ModalResult ComputeModes(const DynamicModel& model, const ModalOptions& options) {
  const LinearisedSystem sys = Linearise(model);
  const int n_dof = static_cast<int>(sys.mass.rows());
  ModalResult result;
  result.free_dofs = n_dof;
  result.bar_force_density = sys.bar_force_density;
  result.string_tension = sys.string_tension;
  result.slack_strings = sys.slack_strings;
  result.equilibrium_residual = sys.equilibrium_residual;
  if (n_dof == 0) return result;

  // Orthonormal null-space basis of the constraint rows: the trailing columns of Q in
  // G^T P = Q R, past the numerical rank.
  Eigen::MatrixXd z;
  if (sys.constraints.rows() > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(sys.constraints.transpose());
    qr.setThreshold(options.rank_tolerance);
    const int rank = static_cast<int>(qr.rank());
    const Eigen::MatrixXd q = qr.householderQ();
    z = q.rightCols(n_dof - rank);
    result.constraints = rank;
  } else {
    z = Eigen::MatrixXd::Identity(n_dof, n_dof);
  }
  const int n_red = static_cast<int>(z.cols());
  if (n_red == 0) return result;

  Eigen::MatrixXd k_red = z.transpose() * sys.stiffness * z;
  Eigen::MatrixXd m_red = z.transpose() * sys.mass * z;
  // Symmetrise away round-off so the solver sees exactly symmetric input.
  k_red = 0.5 * (k_red + k_red.transpose()).eval();
  m_red = 0.5 * (m_red + m_red.transpose()).eval();
  Eigen::LLT<Eigen::MatrixXd> llt(m_red);
  const double m_scale = std::max(m_red.diagonal().cwiseAbs().maxCoeff(), 1e-300);
  if (llt.info() != Eigen::Success ||
      llt.matrixL().toDenseMatrix().diagonal().minCoeff() <= 1e-12 * std::sqrt(m_scale)) {
    throw ModelError(
        "modal analysis: the mass matrix is singular on the free motions; a free node moves "
        "without mass (give the strings mass or add node masses)");
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(k_red, m_red);
  if (eig.info() != Eigen::Success) throw ModelError("modal analysis: the eigensolver did not converge");

  const int n_n = model.num_nodes();
  result.modes.resize(n_red);
  for (int r = 0; r < n_red; ++r) {
    Mode& mode = result.modes[r];
    const double w2 = eig.eigenvalues()(r);
    mode.omega_squared = w2;
    mode.omega_rad_s = (w2 >= 0 ? 1.0 : -1.0) * std::sqrt(std::abs(w2));
    mode.frequency_hz = mode.omega_rad_s / (2 * std::numbers::pi);
    mode.period_s = mode.omega_rad_s != 0 ? 2 * std::numbers::pi / std::abs(mode.omega_rad_s) : 0.0;
    // The solver normalises y^T M_red y = 1; Z is orthonormal so x = Z y keeps x^T M x = 1.
    Eigen::VectorXd x = z * eig.eigenvectors().col(r);
    // Fix the arbitrary sign so that outputs are reproducible: largest component positive.
    Eigen::Index largest = 0;
    x.cwiseAbs().maxCoeff(&largest);
    if (x(largest) < 0) x = -x;
    mode.shape = Eigen::Matrix3Xd::Zero(3, n_n);
    for (int d = 0; d < n_dof; ++d) mode.shape(sys.dof_axis[d], sys.dof_node[d]) = x(d);
  }
  return result;
}

double Rk4StableStep(const ModalResult& result) {
  if (result.modes.empty()) throw ModelError("RK4 step limit: the model has no modes");
  const double omega_max = std::abs(result.modes.back().omega_rad_s);
  if (omega_max <= 0) throw ModelError("RK4 step limit: every mode has zero frequency");
  return 2 * std::sqrt(2.0) / omega_max;
}

const char* SymmetryName(ModeSymmetry symmetry) {
  switch (symmetry) {
    case ModeSymmetry::kSymmetric: return "symmetric";
    case ModeSymmetry::kAntisymmetric: return "antisymmetric";
    case ModeSymmetry::kMixed: return "mixed";
  }
  return "mixed";
}

SymmetryReport ClassifySymmetry(const Eigen::Matrix3Xd& positions, const Eigen::Matrix3Xd& shape,
                                double tolerance) {
  const int n_n = static_cast<int>(positions.cols());
  if (shape.cols() != n_n) throw ModelError("mode symmetry: shape and positions differ in node count");
  SymmetryReport report;
  if (n_n == 0) return report;
  const double x_min = positions.row(0).minCoeff(), x_max = positions.row(0).maxCoeff();
  const double mid = 0.5 * (x_min + x_max);
  const double tol = 1e-6 * std::max(x_max - x_min, 1.0);
  double dot = 0, norm = 0;
  for (int a = 0; a < n_n; ++a) {
    Eigen::Vector3d mirrored = positions.col(a);
    mirrored.x() = 2 * mid - mirrored.x();
    int partner = -1;
    for (int b = 0; b < n_n && partner < 0; ++b) {
      if ((positions.col(b) - mirrored).cwiseAbs().maxCoeff() <= tol) partner = b;
    }
    if (partner < 0) {
      throw ModelError("mode symmetry: node " + std::to_string(a + 1) + " has no mirror node about x = " +
                       std::to_string(mid));
    }
    Eigen::Vector3d image = shape.col(partner);
    image.x() = -image.x();
    dot += shape.col(a).dot(image);
    norm += shape.col(a).squaredNorm();
  }
  if (norm == 0) return report;
  report.correlation = dot / norm;
  if (report.correlation >= 1 - tolerance) report.symmetry = ModeSymmetry::kSymmetric;
  if (report.correlation <= -1 + tolerance) report.symmetry = ModeSymmetry::kAntisymmetric;
  return report;
}

}  // namespace tbridge
