#include "design/stability.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include "core/error.h"
#include "core/tangent_blocks.h"
#include "design/design.h"

namespace tbridge {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// The tangent stiffness split into its material part K_m (string axial terms) and geometric
// part K_g (string q (I - u u^T), bar -lambda I), and the bar-length constraint rows C, all
// on the free DOFs. K = K_m + K_g at the given member forces; K_m and K_g are kept apart only
// when `split` asks (the critical load factor needs them), else both go straight into K.
struct Tangent {
  std::vector<int> dof;  // first free DOF of each node, -1 when fixed
  int ndof = 0;
  SparseMatrix K, Km, Kg, C;
};

Tangent AssembleTangent(const Structure& s, const Eigen::VectorXd& forces,
                        const std::vector<double>& k_string, bool split) {
  const int nb = s.num_bars();
  const int ns = s.num_strings();
  if (forces.size() != nb + ns || static_cast<int>(k_string.size()) != ns) {
    throw ModelError("stability: expected " + std::to_string(nb + ns) + " member forces and " +
                     std::to_string(ns) + " string stiffnesses, got " +
                     std::to_string(forces.size()) + " and " + std::to_string(k_string.size()));
  }
  const int dim = s.dim();
  Tangent t;
  t.dof = FreeDofs(s.fixed, dim, t.ndof);
  Triplets km, kg, c;
  const size_t block = static_cast<size_t>(4 * dim * dim);  // four dim x dim blocks per member
  Triplets& material = split ? km : kg;  // one list when K_m is not wanted on its own
  if (split) km.reserve(block * ns);
  kg.reserve(block * ((split ? ns : 2 * ns) + nb));
  c.reserve(static_cast<size_t>(2 * dim * nb));
  auto add = [&](Triplets& out, const Member& m, const Eigen::Matrix3d& G) {
    AddPairBlock(G, m.i, m.j, t.dof, dim, out);
  };
  auto unit = [&](const Member& m) {
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    u.head(dim) = (s.nodes.col(m.j) - s.nodes.col(m.i)).head(dim).normalized();
    return u;
  };
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  I.topLeftCorner(dim, dim).setIdentity();
  for (int k = 0; k < ns; ++k) {
    const Member& m = s.strings[k];
    const Eigen::Vector3d u = unit(m);
    add(kg, m, StringGeometricBlock(u, forces[nb + k] / s.Length(m), dim));
    add(material, m, StringMaterialBlock(u, k_string[k]));
  }
  for (int b = 0; b < nb; ++b) {
    const Member& m = s.bars[b];
    add(kg, m, -(forces[b] / s.Length(m)) * I);
    AddBarRow(b, m.i, m.j, unit(m), t.dof, dim, c);
  }
  auto build = [](int rows, int cols, const Triplets& triplets) {
    SparseMatrix m(rows, cols);
    m.setFromTriplets(triplets.begin(), triplets.end());
    return m;
  };
  if (split) {
    t.Km = build(t.ndof, t.ndof, km);
    t.Kg = build(t.ndof, t.ndof, kg);
    t.K = t.Km + t.Kg;
  } else {
    t.K = build(t.ndof, t.ndof, kg);  // duplicate entries are summed
  }
  t.C = build(nb, t.ndof, c);
  return t;
}

// Orthonormal basis of the rank-revealing QR's null space of C^T (columns), C with unit-norm
// row pairs, so rank decisions are O(1) and 1e-12 sits far from both rounding and any real
// constraint. Returns the rank through `rank`.
Eigen::MatrixXd NullSpace(const Eigen::MatrixXd& C, int& rank) {
  if (C.rows() == 0) {
    rank = 0;
    return Eigen::MatrixXd::Identity(C.cols(), C.cols());
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(C.transpose());
  qr.setThreshold(1e-12);
  rank = static_cast<int>(qr.rank());
  const Eigen::MatrixXd Q = qr.householderQ();
  return Q.rightCols(C.cols() - rank);
}

// Sparse Z: the free DOFs are split into clusters, the nodes joined by bars (one bar and its
// two nodes for class 1; a node on no bar is a cluster of its own with Z = I). Each cluster's
// constraints touch only its own DOFs, so a null-space basis of each cluster's few rows,
// placed block by block, spans the null space of all of C. Cost: one dense QR per cluster of
// (dim x its free nodes) columns, linear in the structure for bounded clusters.
SparseMatrix SparseNullSpace(const Structure& s, const Tangent& t) {
  const int nn = s.num_nodes();
  const int dim = s.dim();
  const std::vector<int> component = ComponentOf(nn, s.bars);
  std::vector<std::vector<int>> nodes_of(nn), bars_of(nn);
  for (int v = 0; v < nn; ++v) {
    if (t.dof[v] >= 0) nodes_of[component[v]].push_back(v);
  }
  for (int b = 0; b < s.num_bars(); ++b) bars_of[component[s.bars[b].i]].push_back(b);

  const SparseMatrix Ct = t.C.transpose();  // column b: bar b's constraint over the free DOFs
  Triplets z;
  int col = 0;
  for (int root = 0; root < nn; ++root) {
    const std::vector<int>& nodes = nodes_of[root];
    if (nodes.empty()) continue;
    std::vector<int> local(nodes.size() * dim);
    for (size_t a = 0; a < nodes.size(); ++a) {
      for (int r = 0; r < dim; ++r) local[a * dim + r] = t.dof[nodes[a]] + r;
    }
    // The cluster's constraint rows restricted to its DOFs (dense: a handful of bars).
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(bars_of[root].size()),
                                              static_cast<Eigen::Index>(local.size()));
    for (size_t row = 0; row < bars_of[root].size(); ++row) {
      for (SparseMatrix::InnerIterator it(Ct, bars_of[root][row]); it; ++it) {
        const auto at = std::lower_bound(local.begin(), local.end(), static_cast<int>(it.row()));
        C(static_cast<Eigen::Index>(row), at - local.begin()) = it.value();
      }
    }
    int rank = 0;
    const Eigen::MatrixXd N = NullSpace(C, rank);
    for (Eigen::Index j = 0; j < N.cols(); ++j, ++col) {
      for (Eigen::Index i = 0; i < N.rows(); ++i) {
        if (N(i, j) != 0) z.emplace_back(local[i], col, N(i, j));
      }
    }
  }
  SparseMatrix Z(t.ndof, col);
  Z.setFromTriplets(z.begin(), z.end());
  return Z;
}

// Smallest c > 0 with (Km + c Kg) v = 0, v != 0: the generalised eigenvalues of (Km, -Kg).
// Roots below 1e-6 are a singular Km (a mechanism that only the prestress holds: singular at
// c = 0 alone) seen through rounding, not a load factor; complex or infinite ones are no root.
std::optional<double> CriticalFactor(const Eigen::MatrixXd& Km, const Eigen::MatrixXd& Kg) {
  if (Km.rows() == 0) return std::nullopt;
  // Km positive definite (the usual case): the symmetric form -Kg v = s Km v, ten times
  // cheaper than QZ; c = 1/s for the largest s > 0.
  const Eigen::MatrixXd Ks = 0.5 * (Km + Km.transpose());
  if (Eigen::LLT<Eigen::MatrixXd>(Ks).info() == Eigen::Success) {
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> gsa(-0.5 * (Kg + Kg.transpose()), Ks,
                                                                  Eigen::EigenvaluesOnly);
    if (gsa.info() == Eigen::Success) {
      const double s = gsa.eigenvalues().maxCoeff();
      if (s > 0) return 1.0 / s;
      return std::nullopt;
    }
  }
  Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> ges(Km, -Kg, false);
  std::optional<double> best;
  for (Eigen::Index i = 0; i < ges.alphas().size(); ++i) {
    const std::complex<double> alpha = ges.alphas()[i];
    const double beta = ges.betas()[i];
    if (beta == 0 || std::abs(alpha.imag()) > 1e-8 * std::abs(alpha)) continue;
    const double c = alpha.real() / beta;
    if (std::isfinite(c) && c > 1e-6 && (!best || c < *best)) best = c;
  }
  return best;
}

}  // namespace

StabilityVerdict AssessStability(const Structure& s, const Eigen::VectorXd& forces,
                                 const std::vector<double>& k_string, bool critical_load_factor,
                                 double relative_tolerance) {
  const Tangent t = AssembleTangent(s, forces, k_string, critical_load_factor);
  const SparseMatrix Z = SparseNullSpace(s, t);
  StabilityVerdict v;
  v.free_dofs = t.ndof;
  v.reduced_dofs = static_cast<int>(Z.cols());
  if (v.reduced_dofs == 0) {
    v.stable = true;  // nothing can move
    return v;
  }
  const SparseMatrix Kr = SparseMatrix(Z.transpose() * t.K * Z);
  // Why this and not the saddle point [K C^T; C 0]: its inertia needs a pivoting symmetric
  // indefinite factorisation (Bunch-Kaufman), which neither Eigen's sparse module nor
  // CHOLMOD's LDL^T offers (neither pivots, and the zero block stalls them). Z^T K Z is
  // congruent to a diagonal through any unpivoted LDL^T that completes, so the signs of its
  // pivots are its inertia. Measured (bench/bench_stability, two shared cores): the paper's
  // planar bridge at n = 14 (65532 free DOFs, 49149 reduced) takes 45 ms against 370 ms for
  // the rest of the design, doubling per level up to n = 14 (n = 13: 22 ms); at n = 15 and
  // 16 it takes 0.37 s and 1.1 s, where assembling the member blocks (0.6 s at n = 16) and
  // the product Z^T K Z (0.4 s) leave the caches, against 0.2 s for the LDL^T. Assembling
  // K_r member by member in the cluster coordinates instead was 4x slower (small
  // dynamic-size products per member).
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(Kr);
  const double scale = Kr.diagonal().cwiseAbs().maxCoeff();
  if (ldlt.info() != Eigen::Success) {
    v.zero_pivots = 1;  // an exact zero pivot: a mechanism
  } else {
    const Eigen::VectorXd D = ldlt.vectorD();
    v.min_pivot = D.minCoeff();
    for (Eigen::Index i = 0; i < D.size(); ++i) {
      if (D[i] < -relative_tolerance * scale) {
        ++v.negative_pivots;
      } else if (D[i] <= relative_tolerance * scale) {
        ++v.zero_pivots;
      }
    }
  }
  v.stable = v.negative_pivots == 0 && v.zero_pivots == 0;
  if (critical_load_factor) {
    const Eigen::MatrixXd Zd(Z);
    v.critical_load_factor = CriticalFactor(Zd.transpose() * t.Km * Zd, Zd.transpose() * t.Kg * Zd);
    v.critical_load_factor_computed = true;
  }
  return v;
}

StabilityReport CheckStability(const Structure& s, const Eigen::VectorXd& forces,
                               const std::vector<double>& k_string, double relative_tolerance) {
  const Tangent t = AssembleTangent(s, forces, k_string, false);
  StabilityReport r;
  r.free_dofs = t.ndof;
  // Null space of all of C at once (no clusters): the dense cross-check of SparseNullSpace.
  const Eigen::MatrixXd N = NullSpace(Eigen::MatrixXd(t.C), r.bar_constraints);
  r.reduced_dofs = static_cast<int>(N.cols());
  if (r.reduced_dofs == 0) {
    r.positive_definite = true;  // nothing can move
    return r;
  }
  const Eigen::MatrixXd Kr = N.transpose() * Eigen::MatrixXd(t.K) * N;
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
