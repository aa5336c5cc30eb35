#include "design/linear_response.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/tangent_blocks.h"

namespace tbridge {

LinearResponse::LinearResponse(const Structure& structure, const Eigen::VectorXd& reference_forces,
                               const Eigen::VectorXd& string_stiffness)
    : s_(structure),
      dim_(structure.dim()),
      nb_(structure.num_bars()),
      ns_(structure.num_strings()) {
  if (reference_forces.size() != nb_ + ns_ || string_stiffness.size() != ns_) {
    throw ModelError("linear response: expected " + std::to_string(nb_ + ns_) +
                     " member forces and " + std::to_string(ns_) + " string stiffnesses");
  }
  dof_ = FreeDofs(s_.fixed, dim_, ndof_);
  k_ = string_stiffness;
  for (int j = 0; j < nb_ + ns_; ++j) {
    const Member& m = s_.MemberAt(j);
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e.head(dim_) = (s_.nodes.col(m.j) - s_.nodes.col(m.i)).head(dim_);
    length_.push_back(e.norm());
    unit_.push_back(e / e.norm());
  }
  TangentTriplets t;
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  I.topLeftCorner(dim_, dim_).setIdentity();
  for (int j = 0; j < nb_ + ns_; ++j) {
    const bool bar = j < nb_;
    const Member& m = s_.MemberAt(j);
    const double q = reference_forces[j] / length_[j];
    const Eigen::Matrix3d g =
        bar ? Eigen::Matrix3d(-q * I) : StringTangentBlock(unit_[j], k_[j - nb_], q, dim_);
    AddPairBlock(g, m.i, m.j, dof_, dim_, t);
    if (bar) AddBarRow(ndof_ + j, m.i, m.j, unit_[j], dof_, dim_, t);
  }
  // The constraint rows are direction cosines (O(1)) beside stiffnesses of O(1e8) N/m: scaled
  // to the stiffness, the matrix is balanced and its condition says what the structure's is.
  // The multipliers come out divided by the scale.
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(ndof_);
  for (const auto& e : t) {
    if (e.row() < ndof_ && e.row() == e.col()) diagonal[e.row()] += e.value();
  }
  constraint_scale_ = std::max(ndof_ > 0 ? diagonal.cwiseAbs().maxCoeff() : 0.0, 1.0);
  TangentTriplets scaled;
  scaled.reserve(t.size() + 4 * static_cast<size_t>(nb_) * dim_);
  for (const auto& e : t) {
    if (e.row() < ndof_) {
      scaled.push_back(e);
    } else {
      scaled.emplace_back(e.row(), e.col(), constraint_scale_ * e.value());
      scaled.emplace_back(e.col(), e.row(), constraint_scale_ * e.value());  // C^T beside C
    }
  }
  std::vector<Eigen::Triplet<double>> st;
  for (int k = 0; k < ns_; ++k) {
    const Member& m = s_.strings[k];
    for (int a = 0; a < dim_; ++a) {
      if (dof_[m.j] >= 0) st.emplace_back(k, dof_[m.j] + a, unit_[nb_ + k][a]);
      if (dof_[m.i] >= 0) st.emplace_back(k, dof_[m.i] + a, -unit_[nb_ + k][a]);
    }
  }
  stretch_.resize(ns_, ndof_ + nb_);
  stretch_.setFromTriplets(st.begin(), st.end());
  Eigen::SparseMatrix<double> kkt(ndof_ + nb_, ndof_ + nb_);
  kkt.setFromTriplets(scaled.begin(), scaled.end());
  // A singular KKT matrix shows as a failed factorisation or a reciprocal condition far below
  // rounding.
  const double rcond = lu_.Analyse(kkt) && lu_.Factorise(kkt) ? lu_.ReciprocalCondition(kkt) : 0.0;
  if (!(rcond > 1e-13)) {
    throw ModelError(
        "linear response: the stiffness about the reference state is singular (reciprocal "
        "condition " +
        std::to_string(rcond) + "): a mechanism that the prestress does not hold");
  }
}

Eigen::VectorXd LinearResponse::FreeVector(const Structure& s, const Eigen::Matrix3Xd& loads) {
  const int dim = s.dim();
  int ndof = 0;
  const std::vector<int> dof = FreeDofs(s.fixed, dim, ndof);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(ndof);
  for (int a = 0; a < s.num_nodes(); ++a) {
    if (dof[a] >= 0) f.segment(dof[a], dim) = loads.col(a).head(dim);
  }
  return f;
}

Eigen::MatrixXd LinearResponse::Solve(const Eigen::MatrixXd& free_loads) const {
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ndof_ + nb_, free_loads.cols());
  rhs.topRows(ndof_) = free_loads;
  lu_.Solve(rhs);
  return rhs;
}

Eigen::MatrixXd LinearResponse::ForceChanges(const Eigen::MatrixXd& u) const {
  Eigen::MatrixXd x(nb_ + ns_, u.cols());
  x.topRows(nb_) = -constraint_scale_ * u.bottomRows(nb_);
  x.bottomRows(ns_).noalias() = stretch_ * u;
  x.bottomRows(ns_) = k_.asDiagonal() * x.bottomRows(ns_);
  return x;
}

Eigen::RowVectorXd LinearResponse::Vertical(const Eigen::MatrixXd& u, int node) const {
  if (dof_[node] < 0) return Eigen::RowVectorXd::Zero(u.cols());
  return u.row(dof_[node] + 1);
}

void LinearResponse::AddBlockAction(const Eigen::Matrix3d& g, int i, int j,
                                    const Eigen::MatrixXd& u, Eigen::MatrixXd& out) const {
  // Column by column in fixed-size vectors: the sizing's Jacobian calls this for every member
  // and self-stress, and dense temporaries per call were a tenth of its time.
  const int fi = dof_[i], fj = dof_[j];
  Eigen::Vector3d d, w;
  for (Eigen::Index c = 0; c < u.cols(); ++c) {
    d.setZero();
    for (int a = 0; a < dim_; ++a)
      d[a] = (fj >= 0 ? u(fj + a, c) : 0.0) - (fi >= 0 ? u(fi + a, c) : 0.0);
    w.noalias() = g * d;
    for (int a = 0; a < dim_; ++a) {
      if (fj >= 0) out(fj + a, c) += w[a];
      if (fi >= 0) out(fi + a, c) -= w[a];
    }
  }
}

Eigen::MatrixXd LinearResponse::SolveDerivative(const Eigen::MatrixXd& u,
                                                const Direction& dp) const {
  Eigen::MatrixXd d = -StiffnessAction(u, dp);
  lu_.Solve(d);
  return d;
}

Eigen::MatrixXd LinearResponse::Adjoint(const std::vector<int>& members,
                                        const std::vector<int>& nodes) const {
  const int nm = static_cast<int>(members.size());
  Eigen::MatrixXd l =
      Eigen::MatrixXd::Zero(ndof_ + nb_, nm + static_cast<Eigen::Index>(nodes.size()));
  for (int f = 0; f < nm; ++f) {
    const int j = members[f];
    if (j < nb_) {
      l(ndof_ + j, f) = -constraint_scale_;  // dC_b = -mu_b, mu scaled as Solve returns it
      continue;
    }
    const Member& m = s_.strings[j - nb_];
    const Eigen::VectorXd e = k_[j - nb_] * unit_[j].head(dim_);
    if (dof_[m.j] >= 0) l.col(f).segment(dof_[m.j], dim_) += e;
    if (dof_[m.i] >= 0) l.col(f).segment(dof_[m.i], dim_) -= e;
  }
  for (size_t v = 0; v < nodes.size(); ++v) {
    if (dof_[nodes[v]] >= 0) l(dof_[nodes[v]] + 1, nm + static_cast<Eigen::Index>(v)) = 1.0;
  }
  lu_.SolveTransposed(l);
  return l;
}

Eigen::MatrixXd LinearResponse::AdjointOf(Eigen::MatrixXd functionals) const {
  lu_.SolveTransposed(functionals);
  return functionals;
}

Eigen::MatrixXd LinearResponse::StringStretches(const Eigen::MatrixXd& u) const {
  Eigen::MatrixXd out(ns_, u.cols());
  out.noalias() = stretch_ * u;
  return out;
}

Eigen::MatrixXd LinearResponse::StiffnessAction(const Eigen::MatrixXd& u,
                                                const Direction& dp) const {
  Eigen::MatrixXd dKu = Eigen::MatrixXd::Zero(ndof_ + nb_, u.cols());
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  I.topLeftCorner(dim_, dim_).setIdentity();
  for (int j = 0; j < nb_ + ns_; ++j) {
    const bool bar = j < nb_;
    const double dk = bar ? 0.0 : dp.stiffness[j - nb_];
    const double dq = dp.forces[j] / length_[j];
    if (dk == 0 && dq == 0) continue;
    const Member& m = s_.MemberAt(j);
    // The string block is linear in (k, q): at (dk, dq) it is its own derivative.
    const Eigen::Matrix3d g =
        bar ? Eigen::Matrix3d(-dq * I) : StringTangentBlock(unit_[j], dk, dq, dim_);
    AddBlockAction(g, m.i, m.j, u, dKu);
  }
  return dKu;
}

Eigen::MatrixXd LinearResponse::ForceChangeDerivative(const Eigen::MatrixXd& u,
                                                      const Eigen::MatrixXd& du,
                                                      const Direction& dp) const {
  Eigen::MatrixXd dx = ForceChanges(du);
  dx.bottomRows(ns_) += dp.stiffness.asDiagonal() * StringStretches(u);
  return dx;
}

}  // namespace tbridge
