#include "dynamics/modal.h"

#include <Spectra/MatOp/SparseCholesky.h>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <Spectra/SymGEigsSolver.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/string_law.h"
#include "core/structure.h"
#include "core/tangent_blocks.h"

namespace tbridge {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

constexpr const char* kMasslessMessage =
    "modal analysis: the mass matrix is singular on the free motions; a free node moves "
    "without mass (give the strings mass or add node masses)";

// Bars joined at nodes, with the free DOFs (ascending) they touch. Different groups touch
// different DOFs, so their constraint rows, their least-squares bar forces and their null
// spaces are independent. A bar with both ends pinned touches no DOF and is in no group.
struct BarGroup {
  std::vector<int> bars;
  std::vector<int> dofs;
};

std::vector<BarGroup> GroupBars(const DynamicModel& model, const std::vector<int>& first_dof) {
  // The bar-connected clusters of core/structure.h, as the stability check finds them (bars
  // meeting at a pinned node share a group: their rows touch different DOFs, so the group's
  // null space is still the product of theirs).
  const int n_b = static_cast<int>(model.bars.size());
  const std::vector<int> component = ComponentOf(model.num_nodes(), model.bars);
  std::vector<BarGroup> groups;
  std::vector<int> group_of_root(model.num_nodes(), -1);
  for (int k = 0; k < n_b; ++k) {
    const DynamicBar& bar = model.bars[k];
    if (first_dof[bar.i] < 0 && first_dof[bar.j] < 0) continue;
    int& g = group_of_root[component[bar.i]];
    if (g < 0) {
      g = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[g].bars.push_back(k);
    for (const int end : {bar.i, bar.j}) {
      if (first_dof[end] >= 0) groups[g].dofs.push_back(first_dof[end]);
    }
  }
  for (BarGroup& g : groups) {
    std::sort(g.dofs.begin(), g.dofs.end());
    g.dofs.erase(std::unique(g.dofs.begin(), g.dofs.end()), g.dofs.end());
    std::vector<int> expanded;
    for (const int d : g.dofs) {
      for (int c = 0; c < model.dim; ++c) expanded.push_back(d + c);
    }
    g.dofs = std::move(expanded);
  }
  return groups;
}

// The group's bar force directions on its DOFs: column c is bar c's constraint row transposed
// (G^T restricted to the group). `local` is scratch of n_dof entries, -1 on entry and exit.
Eigen::MatrixXd GroupJacobianT(const DynamicModel& model, const BarGroup& group,
                               const std::vector<int>& first_dof, std::vector<int>& local) {
  const int dim = model.dim;
  for (size_t r = 0; r < group.dofs.size(); ++r) local[group.dofs[r]] = static_cast<int>(r);
  Eigen::MatrixXd gt = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(group.dofs.size()),
                                             static_cast<Eigen::Index>(group.bars.size()));
  for (size_t c = 0; c < group.bars.size(); ++c) {
    const DynamicBar& bar = model.bars[group.bars[c]];
    const Eigen::Vector3d b = model.positions.col(bar.j) - model.positions.col(bar.i);
    if (first_dof[bar.i] >= 0) gt.block(local[first_dof[bar.i]], c, dim, 1) = -b.head(dim);
    if (first_dof[bar.j] >= 0) gt.block(local[first_dof[bar.j]], c, dim, 1) = b.head(dim);
  }
  for (const int d : group.dofs) local[d] = -1;
  return gt;
}

std::vector<int> FirstDofs(const LinearisedSystem& sys, int n_n) {
  std::vector<int> first_dof(n_n, -1);
  for (int r = static_cast<int>(sys.dof_node.size()) - 1; r >= 0; --r)
    first_dof[sys.dof_node[r]] = r;
  return first_dof;
}

void SetOmega(double w2, Mode& mode) {
  mode.omega_squared = w2;
  mode.omega_rad_s = (w2 >= 0 ? 1.0 : -1.0) * std::sqrt(std::abs(w2));
  mode.frequency_hz = mode.omega_rad_s / (2 * std::numbers::pi);
  mode.period_s = mode.omega_rad_s != 0 ? 2 * std::numbers::pi / std::abs(mode.omega_rad_s) : 0.0;
}

// One mode from omega^2 and its M-normalised full-DOF vector x.
Mode MakeMode(double w2, Eigen::VectorXd x, const LinearisedSystem& sys, int n_n) {
  Mode mode;
  SetOmega(w2, mode);
  // Fix the arbitrary sign so that outputs are reproducible: largest component positive.
  Eigen::Index largest = 0;
  x.cwiseAbs().maxCoeff(&largest);
  if (x(largest) < 0) x = -x;
  mode.shape = Eigen::Matrix3Xd::Zero(3, n_n);
  for (Eigen::Index d = 0; d < x.size(); ++d) mode.shape(sys.dof_axis[d], sys.dof_node[d]) = x(d);
  return mode;
}

// Every mode by a dense generalised eigen-decomposition on the null space of the whole
// constraint Jacobian; keeps the lowest options.count when count > 0.
void DenseModes(const DynamicModel& model, const LinearisedSystem& sys, const ModalOptions& options,
                ModalResult& result) {
  const int n_dof = static_cast<int>(sys.mass.rows());
  const Eigen::MatrixXd stiffness = sys.stiffness, mass = sys.mass, constraints = sys.constraints;
  // Orthonormal null-space basis of the constraint rows: the trailing columns of Q in
  // G^T P = Q R, past the numerical rank.
  Eigen::MatrixXd z;
  result.constraints = 0;
  if (constraints.rows() > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(constraints.transpose());
    qr.setThreshold(options.rank_tolerance);
    const int rank = static_cast<int>(qr.rank());
    const Eigen::MatrixXd q = qr.householderQ();
    z = q.rightCols(n_dof - rank);
    result.constraints = rank;
  } else {
    z = Eigen::MatrixXd::Identity(n_dof, n_dof);
  }
  const int n_red = static_cast<int>(z.cols());
  result.solver = "dense";
  result.total_modes = n_red;
  if (n_red == 0) return;

  Eigen::MatrixXd k_red = z.transpose() * stiffness * z;
  Eigen::MatrixXd m_red = z.transpose() * mass * z;
  // Symmetrise away round-off so the solver sees exactly symmetric input.
  k_red = 0.5 * (k_red + k_red.transpose()).eval();
  m_red = 0.5 * (m_red + m_red.transpose()).eval();
  Eigen::LLT<Eigen::MatrixXd> llt(m_red);
  const double m_scale = std::max(m_red.diagonal().cwiseAbs().maxCoeff(), 1e-300);
  if (llt.info() != Eigen::Success ||
      llt.matrixL().toDenseMatrix().diagonal().minCoeff() <= 1e-12 * std::sqrt(m_scale)) {
    throw ModelError(kMasslessMessage);
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(k_red, m_red);
  if (eig.info() != Eigen::Success)
    throw ModelError("modal analysis: the eigensolver did not converge");

  const int kept = options.count > 0 ? std::min(options.count, n_red) : n_red;
  result.all_modes = kept == n_red;
  result.modes.reserve(kept);
  // The solver normalises y^T M_red y = 1; Z is orthonormal so x = Z y keeps x^T M x = 1.
  for (int r = 0; r < kept; ++r) {
    result.modes.push_back(
        MakeMode(eig.eigenvalues()(r), z * eig.eigenvectors().col(r), sys, model.num_nodes()));
  }
  Mode top;
  SetOmega(eig.eigenvalues()(n_red - 1), top);
  result.highest_omega_rad_s = top.omega_rad_s;
}

// Z: per group the trailing columns of Q in its G^T P = Q R, identity on DOFs of no group.
// Columns follow the DOFs: a group's block is emitted where its first DOF comes. Returns Z's
// entries; `columns` takes its number of columns, `rank_sum` the groups' ranks.
Triplets BlockNullSpace(const DynamicModel& model, const LinearisedSystem& sys,
                        const ModalOptions& options, int& columns, int& rank_sum) {
  const int n_dof = static_cast<int>(sys.mass.rows());
  const std::vector<int> first_dof = FirstDofs(sys, model.num_nodes());
  const std::vector<BarGroup> groups = GroupBars(model, first_dof);
  std::vector<int> group_of(n_dof, -1);
  for (size_t g = 0; g < groups.size(); ++g) {
    for (const int d : groups[g].dofs) group_of[d] = static_cast<int>(g);
  }
  std::vector<int> local(n_dof, -1);
  Triplets zt;
  columns = 0;
  rank_sum = 0;
  for (int d = 0; d < n_dof; ++d) {
    const int g = group_of[d];
    if (g < 0) {
      zt.emplace_back(d, columns++, 1.0);
      continue;
    }
    const BarGroup& group = groups[g];
    if (group.dofs.front() != d) continue;  // emitted at its first DOF
    const Eigen::MatrixXd gt = GroupJacobianT(model, group, first_dof, local);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(gt);
    qr.setThreshold(options.rank_tolerance);
    const int rank = static_cast<int>(qr.rank());
    rank_sum += rank;
    const Eigen::MatrixXd q = qr.householderQ();
    for (Eigen::Index c = rank; c < q.cols(); ++c) {
      for (Eigen::Index r = 0; r < q.rows(); ++r) {
        if (q(r, c) != 0.0) zt.emplace_back(group.dofs[r], columns, q(r, c));
      }
      ++columns;
    }
  }
  return zt;
}

// The highest mode's omega, into result.highest_omega_rad_s.
void HighestMode(const SparseMatrix& k_red, const SparseMatrix& m_red, int n_red,
                 const ModalOptions& options, ModalResult& result) {
  using StiffnessOp = Spectra::SparseSymMatProd<double>;
  using CholeskyOp = Spectra::SparseCholesky<double>;
  StiffnessOp stiffness_op(k_red);
  CholeskyOp cholesky_op(m_red);
  Spectra::SymGEigsSolver<StiffnessOp, CholeskyOp, Spectra::GEigsMode::Cholesky> top(
      stiffness_op, cholesky_op, 1, std::min(n_red, 20));
  top.init();
  top.compute(Spectra::SortRule::LargestAlge, 1000, options.highest_tolerance);
  if (top.info() != Spectra::CompInfo::Successful) {
    throw ModelError("modal analysis: the sparse eigensolver did not converge to the highest mode");
  }
  Mode highest;
  SetOmega(top.eigenvalues()(0), highest);
  result.highest_omega_rad_s = highest.omega_rad_s;
}

// The lowest options.count modes by Spectra on the block-wise null space of the bar groups
// (see the header for why). Falls back to DenseModes when the count is too close to the
// number of modes for a Lanczos basis.
void SparseModes(const DynamicModel& model, const LinearisedSystem& sys,
                 const ModalOptions& options, ModalResult& result) {
  const int n_dof = static_cast<int>(sys.mass.rows());
  int columns = 0, rank_sum = 0;
  const Triplets zt = BlockNullSpace(model, sys, options, columns, rank_sum);
  const int n_red = columns;
  result.constraints = rank_sum;
  result.total_modes = n_red;
  if (n_red == 0) {
    result.solver = "sparse";
    return;
  }
  // Spectra needs a Lanczos basis larger than the count and at most the problem size.
  if (options.count >= n_red - 1) {
    DenseModes(model, sys, options, result);
    return;
  }
  SparseMatrix z(n_dof, n_red);
  z.setFromTriplets(zt.begin(), zt.end());
  const SparseMatrix k_red = z.transpose() * sys.stiffness * z;
  const SparseMatrix m_red = z.transpose() * sys.mass * z;

  Eigen::SimplicialLLT<SparseMatrix> llt(m_red);
  const double m_scale = std::max(m_red.diagonal().cwiseAbs().maxCoeff(), 1e-300);
  if (llt.info() != Eigen::Success) throw ModelError(kMasslessMessage);
  const SparseMatrix l = llt.matrixL();
  if (l.diagonal().minCoeff() <= 1e-12 * std::sqrt(m_scale)) throw ModelError(kMasslessMessage);

  // A small negative shift keeps K - sigma M regular when K has a zero mode on the constraint
  // manifold; 1e-6 of the mean stiffness-to-mass ratio leaves the nearest modes' order alone.
  const double sigma = -1e-6 * k_red.diagonal().cwiseAbs().sum() / m_red.diagonal().sum();
  using ShiftOp = Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse>;
  using MassOp = Spectra::SparseSymMatProd<double>;
  ShiftOp shift_op(k_red, m_red);
  MassOp mass_op(m_red);
  const int count = options.count;
  // Basis size: Spectra's advice of at least 2 count + 1, and 20 so that few-mode runs restart
  // rarely.
  const int ncv = std::min(n_red, std::max(2 * count + 1, count + 20));
  Eigen::VectorXd w2;
  Eigen::MatrixXd y;
  try {
    Spectra::SymGEigsShiftSolver<ShiftOp, MassOp, Spectra::GEigsMode::ShiftInvert> eigs(
        shift_op, mass_op, count, ncv, sigma);
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestMagn, 1000, options.tolerance,
                 Spectra::SortRule::SmallestAlge);
    if (eigs.info() != Spectra::CompInfo::Successful) {
      throw ModelError("modal analysis: the sparse eigensolver did not converge to " +
                       std::to_string(count) + " modes");
    }
    w2 = eigs.eigenvalues();
    y = eigs.eigenvectors();
    result.iterations = static_cast<int>(eigs.num_iterations());
  } catch (const std::invalid_argument& e) {
    throw ModelError(
        std::string("modal analysis: the shifted stiffness is singular (a mechanism): ") +
        e.what());
  }
  std::vector<int> order(w2.size());
  for (size_t r = 0; r < order.size(); ++r) order[r] = static_cast<int>(r);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return w2(a) < w2(b); });
  result.modes.reserve(order.size());
  for (const int r : order) {
    // Spectra's vectors are M_red-orthonormal up to its tolerance; normalise exactly.
    const Eigen::VectorXd yr = y.col(r) / std::sqrt(y.col(r).dot(m_red * y.col(r)));
    result.modes.push_back(MakeMode(w2(r), z * yr, sys, model.num_nodes()));
  }
  result.all_modes = false;
  result.solver = "sparse";

  if (options.highest) {
    HighestMode(k_red, m_red, n_red, options, result);
  }
}

}  // namespace

LinearisedSystem Linearise(const DynamicModel& model) {
  CheckModel(model, "modal analysis");
  const int dim = model.dim;
  const int n_n = model.num_nodes();
  LinearisedSystem sys;

  int n_dof = 0;
  const std::vector<int> first_dof = FreeDofs(model.fixed, dim, n_dof);
  for (int a = 0; a < n_n; ++a) {
    for (int c = 0; c < dim && first_dof[a] >= 0; ++c) {
      sys.dof_node.push_back(a);
      sys.dof_axis.push_back(c);
    }
  }
  const int n_b = static_cast<int>(model.bars.size());
  const int n_s = static_cast<int>(model.strings.size());
  Triplets stiffness, mass, constraints;

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
    const double tension = StringTension(st.stiffness, st.rest_length, length);
    sys.string_tension(k) = tension;
    const Eigen::Vector3d u = s / length;
    force.col(st.i) += tension * u;
    force.col(st.j) -= tension * u;
    AddPairBlock(StringTangentBlock(u, st.stiffness, tension / length), st.i, st.j, first_dof, dim,
                 stiffness);
  }

  // Bar force directions on the free DOFs: a compression lambda pushes node j along +b and
  // node i along -b. The same columns, transposed, are the constraint rows d(b.b/2)/dx.
  for (int k = 0; k < n_b; ++k) {
    const DynamicBar& bar = model.bars[k];
    AddBarRow(k, bar.i, bar.j, model.positions.col(bar.j) - model.positions.col(bar.i), first_dof,
              dim, constraints);
  }
  sys.constraints.resize(n_b, n_dof);
  sys.constraints.setFromTriplets(constraints.begin(), constraints.end());
  Eigen::VectorXd f(n_dof);
  for (int r = 0; r < n_dof; ++r) f(r) = force(sys.dof_axis[r], sys.dof_node[r]);
  // Least squares G^T lambda = -f, group by group. Rank-revealing so dependent bars (class k)
  // get the minimum-norm split instead of a breakdown; one bar is a closed-form projection.
  sys.bar_force_density = Eigen::VectorXd::Zero(n_b);
  if (n_b > 0 && n_dof > 0) {
    std::vector<int> local(n_dof, -1);
    for (const BarGroup& group : GroupBars(model, first_dof)) {
      const Eigen::MatrixXd gt = GroupJacobianT(model, group, first_dof, local);
      Eigen::VectorXd f_group(gt.rows());
      for (Eigen::Index r = 0; r < gt.rows(); ++r) f_group(r) = f(group.dofs[r]);
      const Eigen::VectorXd lambda = gt.completeOrthogonalDecomposition().solve(-f_group);
      for (size_t c = 0; c < group.bars.size(); ++c)
        sys.bar_force_density(group.bars[c]) = lambda(c);
    }
    sys.equilibrium_residual =
        (f + sys.constraints.transpose() * sys.bar_force_density).cwiseAbs().maxCoeff();
  } else if (n_dof > 0) {
    sys.equilibrium_residual = f.cwiseAbs().maxCoeff();
  }

  for (int k = 0; k < n_b; ++k) {
    const DynamicBar& bar = model.bars[k];
    AddPairBlock(-sys.bar_force_density(k) * eye, bar.i, bar.j, first_dof, dim, stiffness);
    // Eq. (21): the uniform rigid bar's kinetic energy in its end velocities.
    const double third = bar.mass / 3.0, sixth = bar.mass / 6.0;
    const int ends[2] = {bar.i, bar.j};
    for (int a = 0; a < 2; ++a) {
      for (int c = 0; c < 2; ++c) {
        const int ra = first_dof[ends[a]], rc = first_dof[ends[c]];
        if (ra < 0 || rc < 0) continue;
        const double m = (a == c) ? third : sixth;
        for (int d = 0; d < dim; ++d) mass.emplace_back(ra + d, rc + d, m);
      }
    }
  }
  if (model.node_mass.size() != 0) {
    for (int a = 0; a < n_n; ++a) {
      if (first_dof[a] < 0) continue;
      for (int d = 0; d < dim; ++d)
        mass.emplace_back(first_dof[a] + d, first_dof[a] + d, model.node_mass(a));
    }
  }
  sys.stiffness.resize(n_dof, n_dof);
  sys.stiffness.setFromTriplets(stiffness.begin(), stiffness.end());
  sys.mass.resize(n_dof, n_dof);
  sys.mass.setFromTriplets(mass.begin(), mass.end());
  return sys;
}

ModalResult ComputeModes(const DynamicModel& model, const ModalOptions& options) {
  if (options.count < 0) throw ModelError("modal analysis: the mode count must be >= 0");
  const LinearisedSystem sys = Linearise(model);
  const int n_dof = static_cast<int>(sys.mass.rows());
  ModalResult result;
  result.free_dofs = n_dof;
  result.bar_force_density = sys.bar_force_density;
  result.string_tension = sys.string_tension;
  result.slack_strings = sys.slack_strings;
  result.equilibrium_residual = sys.equilibrium_residual;
  if (n_dof == 0) return result;
  const bool dense = options.count == 0 || options.solver == ModalSolver::kDense ||
                     (options.solver == ModalSolver::kAuto && n_dof <= options.dense_max_dofs);
  if (dense) {
    DenseModes(model, sys, options, result);
  } else {
    SparseModes(model, sys, options, result);
  }
  return result;
}

double Rk4StableStep(const ModalResult& result) {
  if (result.modes.empty()) throw ModelError("RK4 step limit: the model has no modes");
  const double omega_max = std::abs(result.highest_omega_rad_s);
  if (omega_max <= 0) {
    throw ModelError("RK4 step limit: the highest mode was not computed or has zero frequency");
  }
  return 2 * std::sqrt(2.0) / omega_max;
}

const char* SymmetryName(ModeSymmetry symmetry) {
  switch (symmetry) {
    case ModeSymmetry::kSymmetric:
      return "symmetric";
    case ModeSymmetry::kAntisymmetric:
      return "antisymmetric";
    case ModeSymmetry::kMixed:
      return "mixed";
  }
  return "mixed";
}

std::vector<int> MirrorNodes(const Eigen::Matrix3Xd& positions) {
  const int n_n = static_cast<int>(positions.cols());
  std::vector<int> mirror(n_n, -1);
  if (n_n == 0) return mirror;
  const double x_min = positions.row(0).minCoeff(), x_max = positions.row(0).maxCoeff();
  const double mid = 0.5 * (x_min + x_max);
  const double tol = 1e-6 * std::max(x_max - x_min, 1.0);
  // Nodes by x: a node's mirror lies among those within tol of its mirrored x.
  std::vector<int> by_x(n_n);
  for (int a = 0; a < n_n; ++a) by_x[a] = a;
  std::sort(by_x.begin(), by_x.end(),
            [&](int a, int b) { return positions(0, a) < positions(0, b); });
  for (int a = 0; a < n_n; ++a) {
    Eigen::Vector3d mirrored = positions.col(a);
    mirrored.x() = 2 * mid - mirrored.x();
    auto it = std::lower_bound(by_x.begin(), by_x.end(), mirrored.x() - tol,
                               [&](int b, double x) { return positions(0, b) < x; });
    for (; it != by_x.end() && positions(0, *it) <= mirrored.x() + tol; ++it) {
      if ((positions.col(*it) - mirrored).cwiseAbs().maxCoeff() <= tol &&
          (mirror[a] < 0 || *it < mirror[a])) {
        mirror[a] = *it;
      }
    }
    if (mirror[a] < 0) {
      throw ModelError("mode symmetry: node " + std::to_string(a + 1) +
                       " has no mirror node about x = " + std::to_string(mid));
    }
  }
  return mirror;
}

SymmetryReport ClassifySymmetry(const std::vector<int>& mirror, const Eigen::Matrix3Xd& shape,
                                double tolerance) {
  const int n_n = static_cast<int>(mirror.size());
  if (shape.cols() != n_n)
    throw ModelError("mode symmetry: shape and mirror map differ in node count");
  SymmetryReport report;
  double dot = 0, norm = 0;
  for (int a = 0; a < n_n; ++a) {
    if (mirror[a] < 0 || mirror[a] >= n_n)
      throw ModelError("mode symmetry: the mirror map names no node");
    Eigen::Vector3d image = shape.col(mirror[a]);
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

SymmetryReport ClassifySymmetry(const Eigen::Matrix3Xd& positions, const Eigen::Matrix3Xd& shape,
                                double tolerance) {
  if (shape.cols() != positions.cols())
    throw ModelError("mode symmetry: shape and positions differ in node count");
  return ClassifySymmetry(MirrorNodes(positions), shape, tolerance);
}

}  // namespace tbridge
