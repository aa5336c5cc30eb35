#include "optim/dense_qp.h"

#include <Eigen/Jacobi>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tbridge {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A constraint is independent of the active ones where the part of its transformed normal off
// their span is above this fraction of it; below, the equality problem on them would take wild
// multipliers, and a primal step's length would read rounding.
constexpr double kIndependent = 1e-8;

// The rotation that takes (a, b) to (hypot(a, b), 0), applied to columns i and j of M as
// M <- M Q^T, so that M^T v becomes Q M^T v for any v. Eigen's plane rotation is vectorised.
void RotateColumns(Eigen::MatrixXd& M, int i, int j, double c, double s) {
  // applyOnTheRight(i, j, G) sets col_i = c' col_i - s' col_j, col_j = s' col_i + c' col_j.
  M.applyOnTheRight(i, j, Eigen::JacobiRotation<double>(c, -s));
}

}  // namespace

void DenseQpSolver::Resize(int n, int m) {
  if (n == n_ && m == m_) return;
  n_ = n;
  m_ = m;
  Q1_.resize(n, n);
  R_.resize(n, n);
  inv_sqrt_.resize(n);
  nt_.resize(n);
  d1_.resize(n);
  z_.resize(n);
  r_.resize(n);
  u_.resize(n + 1);
  dp_.resize(n);
  y0_.resize(n);
  Cp_.resize(m);
  block_.resize(n, kBlock);
  block_norm_.resize(kBlock);
  coef_.resize(n, kBlock);
  coef2_.resize(n, kBlock);
  active_.reserve(static_cast<size_t>(n));
}

void DenseQpSolver::TransformedNormal(const DenseQp& qp, int k) {
  if (k < m_) {
    nt_ = qp.C.row(k).transpose();
  } else {
    nt_.setZero();
    if (k < m_ + n_) {
      nt_[k - m_] = 1.0;  // p_j >= lo_j
    } else {
      nt_[k - m_ - n_] = -1.0;  // -p_j >= -hi_j
    }
  }
  if (diagonal_) {
    nt_.array() *= inv_sqrt_.array();
  } else {
    llt_.matrixL().solveInPlace(nt_);
  }
}

void DenseQpSolver::ToP(Eigen::VectorXd& v) const {
  if (diagonal_) {
    v.array() *= inv_sqrt_.array();
  } else {
    llt_.matrixU().solveInPlace(v);
  }
}

double DenseQpSolver::Slack(const DenseQp& qp, int k, const Eigen::VectorXd& p) const {
  if (k < m_) return qp.C.row(k).dot(p) - qp.b[k];
  if (k < m_ + n_) return p[k - m_] - qp.lo[k - m_];
  return qp.hi[k - m_ - n_] - p[k - m_ - n_];
}

double DenseQpSolver::Rhs(const DenseQp& qp, int k) const {
  if (k < m_) return qp.b[k];
  if (k < m_ + n_) return qp.lo[k - m_];
  return -qp.hi[k - m_ - n_];
}

void DenseQpSolver::StartFrom(const DenseQp& qp, const std::vector<int>& warm, Eigen::VectorXd& p) {
  const int total = m_ + 2 * n_;
  // The warm constraints join block by block (classical Gram-Schmidt applied twice, by blocks:
  // Barlow and Smoktunowicz, Numer. Math. 123, 2013): each block is made orthogonal to the
  // active normals by two products with Q1 as a whole, then its columns one by one to those of
  // the block that joined before them. Q1 is read four times a block, not four times a
  // constraint: one at a time, each constraint's two passes read all of Q1 (n = 8: 390 warm
  // constraints, 1.6 MB of Q1, most of the subproblem's time).
  std::vector<int> block;
  size_t next = 0;
  while (next < warm.size() && q_ < n_) {
    block.clear();
    for (; next < warm.size() && static_cast<int>(block.size()) < kBlock; ++next) {
      const int k = warm[next];
      if (k < 0 || k >= total || is_active_[static_cast<size_t>(k)]) continue;
      if (std::find(block.begin(), block.end(), k) != block.end()) continue;
      TransformedNormal(qp, k);
      block_.col(static_cast<Eigen::Index>(block.size())) = nt_;
      block_norm_[static_cast<Eigen::Index>(block.size())] = nt_.norm();
      block.push_back(k);
    }
    const int b = static_cast<int>(block.size());
    const int q0 = q_;
    auto B = block_.leftCols(b);
    auto C = coef_.topLeftCorner(q0, b);
    if (q0 > 0) {
      const auto Q = Q1_.leftCols(q0);
      C.noalias() = Q.transpose() * B;
      B.noalias() -= Q * C;
      // The second pass only where a column lost more than 1 - 1/sqrt(2) of its norm in the
      // first: one that kept more is orthogonal to Q1 to rounding already (Daniel, Gragg,
      // Kaufman and Stewart, Math. Comp. 30, 1976). At n = 8, 72 % of the blocks need none.
      bool again = false;
      for (int i = 0; i < b && !again; ++i)
        again = B.col(i).norm() < std::sqrt(0.5) * block_norm_[i];
      if (again) {
        auto C2 = coef2_.topLeftCorner(q0, b);
        C2.noalias() = Q.transpose() * B;
        B.noalias() -= Q * C2;
        C += C2;
      }
    }
    for (int i = 0; i < b && q_ < n_; ++i) {
      z_ = B.col(i);
      // Against the block's columns that joined before it, twice.
      const int joined = q_ - q0;
      if (joined > 0) {
        const auto Qb = Q1_.middleCols(q0, joined);
        d1_.head(joined).noalias() = Qb.transpose() * z_;
        z_.noalias() -= Qb * d1_.head(joined);
        r_.head(joined).noalias() = Qb.transpose() * z_;
        z_.noalias() -= Qb * r_.head(joined);
        d1_.head(joined) += r_.head(joined);
      }
      // A nearly dependent normal is left to the scans, which add it where it is violated.
      const double z_norm = z_.norm();
      if (!(z_norm > kIndependent * block_norm_[i])) continue;
      Q1_.col(q_) = z_ / z_norm;
      R_.col(q_).head(q0) = C.col(i);
      R_.col(q_).segment(q0, joined) = d1_.head(joined);
      R_(q_, q_) = z_norm;
      ++q_;
      active_.push_back(block[static_cast<size_t>(i)]);
      is_active_[static_cast<size_t>(block[static_cast<size_t>(i)])] = 1;
    }
  }
  // In y = L^T p the minimiser on the active normals N~ = Q1 R as equalities is
  // y = y0 + Q1 (c - Q1^T y0), R^T c = b, with multipliers u = R^-1 (c - Q1^T y0), y0 the
  // unconstrained minimiser. A negative multiplier: that constraint leaves, until none is.
  y0_ = p;
  if (diagonal_) {
    y0_.array() /= inv_sqrt_.array();
  } else {
    y0_ = llt_.matrixU() * y0_;
  }
  while (q_ > 0) {
    for (int k = 0; k < q_; ++k) r_[k] = Rhs(qp, active_[static_cast<size_t>(k)]);
    const auto R = R_.topLeftCorner(q_, q_).triangularView<Eigen::Upper>();
    R.transpose().solveInPlace(r_.head(q_));  // c
    d1_.head(q_).noalias() = Q1_.leftCols(q_).transpose() * y0_;
    d1_.head(q_) = r_.head(q_) - d1_.head(q_);  // c - Q1^T y0
    u_.head(q_) = R.solve(d1_.head(q_));
    int worst = -1;
    for (int k = 0; k < q_; ++k) {
      if (u_[k] < 0 && (worst < 0 || u_[k] < u_[worst])) worst = k;
    }
    if (worst < 0) {
      dp_.noalias() = Q1_.leftCols(q_) * d1_.head(q_);
      ToP(dp_);
      p += dp_;
      return;
    }
    Drop(worst);
  }
}

int DenseQpSolver::MostViolated(const DenseQp& qp, const Eigen::VectorXd& p, double tolerance) {
  Cp_.noalias() = qp.C * p;
  int kp = -1;
  double worst = 0.0;
  // An active constraint holds as an equality; rounding in p may read it a hair below its bound,
  // and adding it again would drop it and add it back.
  for (int i = 0; i < m_; ++i) {
    if (is_active_[static_cast<size_t>(i)]) continue;
    const double s = Cp_[i] - qp.b[i];
    if (s < -tolerance * (1 + std::abs(qp.b[i])) && s < worst) worst = s, kp = i;
  }
  for (int j = 0; j < n_; ++j) {
    if (std::isfinite(qp.lo[j]) && !is_active_[static_cast<size_t>(m_ + j)]) {
      const double s = p[j] - qp.lo[j];
      if (s < -tolerance * (1 + std::abs(qp.lo[j])) && s < worst) worst = s, kp = m_ + j;
    }
    if (std::isfinite(qp.hi[j]) && !is_active_[static_cast<size_t>(m_ + n_ + j)]) {
      const double s = qp.hi[j] - p[j];
      if (s < -tolerance * (1 + std::abs(qp.hi[j])) && s < worst) worst = s, kp = m_ + n_ + j;
    }
  }
  return kp;
}

void DenseQpSolver::Split() {
  z_ = nt_;
  if (q_ == 0) return;
  const auto Q = Q1_.leftCols(q_);
  d1_.head(q_).noalias() = Q.transpose() * nt_;
  z_.noalias() -= Q * d1_.head(q_);
}

void DenseQpSolver::Add(double z_norm, int k) {
  // z_ = nt - Q1 d1 is orthogonal to Q1 in exact arithmetic; a second pass takes what rounding
  // left along Q1 (Gram-Schmidt twice is enough: Giraud et al., Numer. Math. 101, 2005), and
  // that part joins R's column, so that Q1 R still equals the active normals.
  if (q_ > 0) {
    const auto Q = Q1_.leftCols(q_);
    r_.head(q_).noalias() = Q.transpose() * z_;
    z_.noalias() -= Q * r_.head(q_);
    d1_.head(q_) += r_.head(q_);
    z_norm = z_.norm();
  }
  Q1_.col(q_) = z_ / z_norm;
  R_.col(q_).head(q_) = d1_.head(q_);
  R_(q_, q_) = z_norm;
  ++q_;
  active_.push_back(k);
  is_active_[static_cast<size_t>(k)] = 1;
}

void DenseQpSolver::Drop(int l) {
  for (int k = l; k < q_ - 1; ++k) R_.col(k).head(q_) = R_.col(k + 1).head(q_);
  for (int k = l; k < q_; ++k) u_[k] = u_[k + 1];  // the candidate's multiplier moves with them
  is_active_[static_cast<size_t>(active_[static_cast<size_t>(l)])] = 0;
  // A constraint left out as met by rounding was so for the active set that leaves now.
  if (left_out_) {
    for (char& a : is_active_) a = a == 2 ? 0 : a;
    left_out_ = false;
  }
  active_.erase(active_.begin() + l);
  // R is upper Hessenberg from column l: rotate each subdiagonal entry away, and Q1's columns
  // with it; Q1's last column then spans nothing active and leaves.
  for (int k = l; k < q_ - 1; ++k) {
    const double a = R_(k, k), b = R_(k + 1, k);
    const double h = std::hypot(a, b);
    if (h == 0.0) continue;
    const double c = a / h, s = b / h;
    for (int col = k; col < q_ - 1; ++col) {
      const double x = R_(k, col), y = R_(k + 1, col);
      R_(k, col) = c * x + s * y;
      R_(k + 1, col) = -s * x + c * y;
    }
    R_(k + 1, k) = 0.0;
    RotateColumns(Q1_, k, k + 1, c, s);
  }
  --q_;
}

const char* DenseQpStatusName(DenseQpStatus status) {
  switch (status) {
    case DenseQpStatus::kSolved:
      return "solved";
    case DenseQpStatus::kInfeasible:
      return "infeasible";
    case DenseQpStatus::kStepLimit:
      return "step limit";
    case DenseQpStatus::kNotPositiveDefinite:
      return "not positive definite";
  }
  return "unknown";
}

bool DenseQpSolver::Factor(const DenseQp& qp, Eigen::VectorXd& p) {
  diagonal_ = qp.G.isDiagonal(0.0);
  if (diagonal_) {
    // The sequential QP's G is diagonal: L = sqrt(G), with no dense factorisation.
    if (!(qp.G.diagonal().array() > 0).all()) return false;
    inv_sqrt_ = qp.G.diagonal().cwiseSqrt().cwiseInverse();
    p = -qp.a.cwiseQuotient(qp.G.diagonal());
  } else {
    llt_.compute(qp.G);
    if (llt_.info() != Eigen::Success) return false;
    p = -llt_.solve(qp.a);
  }
  return true;
}

DenseQpSolver::StepEnd DenseQpSolver::Step(const DenseQp& qp, int kp, double nt_norm,
                                           Eigen::VectorXd& p) {
  // z, the rest of the candidate's normal, is the step in y; r = R^-1 d1 how the active
  // multipliers must change.
  Split();
  if (q_ > 0) {
    r_.head(q_) = R_.topLeftCorner(q_, q_).triangularView<Eigen::Upper>().solve(d1_.head(q_));
  }
  double t1 = kInf;
  int l = -1;
  for (int k = 0; k < q_; ++k) {
    if (r_[k] > 0.0 && u_[k] / r_[k] < t1) t1 = u_[k] / r_[k], l = k;
  }
  // The candidate is independent of the active normals as StartFrom judges (kIndependent).
  // The primal step length is -slack / (z . nt), and z . nt = |z|^2 exactly (z is orthogonal
  // to Q1), where the product itself is |z|^2 plus rounding of order 1e-14 |z| |nt|: below
  // z/nt = 1e-7 that sign could flip, and a step of -1e6 left the active rows violated by
  // 3e-4 in a program "solved" (n = 7).
  const double z_norm = z_.norm();
  const bool primal = z_norm > kIndependent * nt_norm;
  const double t2 = primal ? -Slack(qp, kp, p) / (z_norm * z_norm) : kInf;
  if (!std::isfinite(t1) && !std::isfinite(t2)) {
    // kp lies in the active normals' span, and no active multiplier can give way: in exact
    // arithmetic the program is infeasible. Violated by rounding alone (the active
    // constraints imply it to within 1e-8 of its bound), it is met, and left out.
    if (Slack(qp, kp, p) >= -1e-8 * (1 + std::abs(Rhs(qp, kp)))) {
      is_active_[static_cast<size_t>(kp)] = 2;
      left_out_ = true;
      return StepEnd::kLeftOut;
    }
    return StepEnd::kInfeasible;
  }
  const double t = std::min(t1, t2);
  if (primal) {
    dp_ = z_;
    ToP(dp_);
    p += t * dp_;
  }
  if (q_ > 0) u_.head(q_) -= t * r_.head(q_);
  u_[q_] += t;
  if (t2 <= t1) {
    Add(z_norm, kp);  // a primal step: kp is independent of the active normals
    return StepEnd::kJoined;
  }
  Drop(l);
  return StepEnd::kDropped;
}

void DenseQpSolver::Multipliers(DenseQpSolution& out) const {
  out.active = active_;
  for (int k = 0; k < q_; ++k) {
    const int c = active_[static_cast<size_t>(k)];
    if (c < m_) {
      out.row_multiplier[c] = u_[k];
    } else if (c < m_ + n_) {
      out.bound_multiplier[c - m_] += u_[k];
    } else {
      out.bound_multiplier[c - m_ - n_] -= u_[k];
    }
  }
}

void DenseQpSolver::Solve(const DenseQp& qp, DenseQpSolution& out, double tolerance,
                          const std::vector<int>* warm) {
  const int n = static_cast<int>(qp.G.rows());
  const int m = static_cast<int>(qp.C.rows());
  Resize(n, m);
  out.solved = false;
  out.status = DenseQpStatus::kStepLimit;
  out.steps = 0;
  out.active.clear();
  out.row_multiplier.setZero(m);
  out.bound_multiplier.setZero(n);

  Eigen::VectorXd& p = out.p;
  if (!Factor(qp, p)) {
    out.status = DenseQpStatus::kNotPositiveDefinite;
    return;
  }
  q_ = 0;
  active_.clear();
  is_active_.assign(static_cast<size_t>(m + 2 * n), 0);
  left_out_ = false;

  if (warm != nullptr) StartFrom(qp, *warm, p);

  const int total = m + 2 * n;
  const int max_steps = 10 * total + 10;
  while (out.steps < max_steps) {
    const int kp = MostViolated(qp, p, tolerance);
    if (kp < 0) {
      out.solved = true;
      out.status = DenseQpStatus::kSolved;
      break;
    }
    TransformedNormal(qp, kp);
    const double nt_norm = nt_.norm();
    u_[q_] = 0.0;
    // Move along the primal and dual directions until kp holds (then it joins the active
    // set) or an active constraint's multiplier reaches zero (then it leaves).
    for (;;) {
      ++out.steps;
      if (out.steps > max_steps) break;
      const StepEnd end = Step(qp, kp, nt_norm, p);
      if (end == StepEnd::kInfeasible) {
        out.status = DenseQpStatus::kInfeasible;
        return;
      }
      if (end != StepEnd::kDropped) break;
    }
  }
  if (!out.solved) return;
  Multipliers(out);
}

}  // namespace tbridge
