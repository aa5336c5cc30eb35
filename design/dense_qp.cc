#include "design/dense_qp.h"

#include <Eigen/Cholesky>
#include <Eigen/Jacobi>
#include <cmath>
#include <limits>

namespace tbridge {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The rotation that takes (a, b) to (hypot(a, b), 0), applied to columns i and j of M as
// M <- M Q^T, so that M^T v becomes Q M^T v for any v. Eigen's plane rotation is vectorised
// (a third of the subproblem's time at n = 8 was these rotations).
void RotateColumns(Eigen::MatrixXd& M, int i, int j, double c, double s) {
  // applyOnTheRight(i, j, G) sets col_i = c' col_i - s' col_j, col_j = s' col_i + c' col_j.
  M.applyOnTheRight(i, j, Eigen::JacobiRotation<double>(c, -s));
}

}  // namespace

void DenseQpSolver::Resize(int n, int m) {
  if (n == n_ && m == m_) return;
  n_ = n;
  m_ = m;
  J_.resize(n, n);
  R_.resize(n, n);
  d_.resize(n);
  z_.resize(n);
  r_.resize(n);
  u_.resize(n + 1);
  np_.resize(n);
  Cp_.resize(m);
  active_.reserve(static_cast<size_t>(n));
}

void DenseQpSolver::Normal(const DenseQp& qp, int k, Eigen::VectorXd& np) const {
  if (k < m_) {
    np = qp.C.row(k).transpose();
    return;
  }
  np.setZero();
  if (k < m_ + n_) {
    np[k - m_] = 1.0;  // p_j >= lo_j
  } else {
    np[k - m_ - n_] = -1.0;  // -p_j >= -hi_j
  }
}

double DenseQpSolver::Slack(const DenseQp& qp, int k, const Eigen::VectorXd& p) const {
  if (k < m_) return qp.C.row(k).dot(p) - qp.b[k];
  if (k < m_ + n_) return p[k - m_] - qp.lo[k - m_];
  return qp.hi[k - m_ - n_] - p[k - m_ - n_];
}

double DenseQpSolver::Bound(const DenseQp& qp, int k) const {
  if (k < m_) return qp.b[k];
  if (k < m_ + n_) return qp.lo[k - m_];
  return qp.hi[k - m_ - n_];
}

int DenseQpSolver::MostViolated(const DenseQp& qp, const Eigen::VectorXd& p, double tolerance) {
  Cp_.noalias() = qp.C * p;
  int kp = -1;
  double worst = 0.0;
  for (int i = 0; i < m_; ++i) {
    const double s = Cp_[i] - qp.b[i];
    if (s < -tolerance * (1 + std::abs(qp.b[i])) && s < worst) worst = s, kp = i;
  }
  for (int j = 0; j < n_; ++j) {
    if (std::isfinite(qp.lo[j])) {
      const double s = p[j] - qp.lo[j];
      if (s < -tolerance * (1 + std::abs(qp.lo[j])) && s < worst) worst = s, kp = m_ + j;
    }
    if (std::isfinite(qp.hi[j])) {
      const double s = qp.hi[j] - p[j];
      if (s < -tolerance * (1 + std::abs(qp.hi[j])) && s < worst) worst = s, kp = m_ + n_ + j;
    }
  }
  return kp;
}

bool DenseQpSolver::Add() {
  // Rotate d's tail into its entry q_, so that J's first q_ + 1 columns span the active normals.
  for (int j = n_ - 1; j > q_; --j) {
    if (d_[j] == 0.0) continue;
    const double h = std::hypot(d_[j - 1], d_[j]);
    const double c = d_[j - 1] / h, s = d_[j] / h;
    d_[j - 1] = h;
    d_[j] = 0.0;
    RotateColumns(J_, j - 1, j, c, s);
  }
  if (std::abs(d_[q_]) <= 1e-12 * d_.head(q_ + 1).norm()) return false;
  R_.col(q_).head(q_ + 1) = d_.head(q_ + 1);
  ++q_;
  return true;
}

void DenseQpSolver::Drop(int l) {
  for (int k = l; k < q_ - 1; ++k) R_.col(k).head(q_) = R_.col(k + 1).head(q_);
  for (int k = l; k < q_; ++k) u_[k] = u_[k + 1];  // the candidate's multiplier moves with them
  active_.erase(active_.begin() + l);
  // R is upper Hessenberg from column l: rotate each subdiagonal entry away.
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
    RotateColumns(J_, k, k + 1, c, s);
  }
  --q_;
}

void DenseQpSolver::Solve(const DenseQp& qp, DenseQpSolution& out, double tolerance,
                          const std::vector<int>* warm) {
  const int n = static_cast<int>(qp.G.rows());
  const int m = static_cast<int>(qp.C.rows());
  Resize(n, m);
  out.solved = false;
  out.steps = 0;
  out.active.clear();
  out.row_multiplier.setZero(m);
  out.bound_multiplier.setZero(n);

  Eigen::VectorXd& p = out.p;
  if (qp.G.isDiagonal(0.0)) {
    // The sequential QP's G is diagonal: L = sqrt(G), and J = L^-T is its inverse, where the
    // dense Cholesky factor and its inverse cost n^3 / 3 + n^3 / 2 per solve (n = 7: 0.3 s
    // of the verified design's sizing).
    if (!(qp.G.diagonal().array() > 0).all()) return;
    J_.setZero();
    J_.diagonal() = qp.G.diagonal().cwiseSqrt().cwiseInverse();
    p = -qp.a.cwiseQuotient(qp.G.diagonal());
  } else {
    const Eigen::LLT<Eigen::MatrixXd> llt(qp.G);
    if (llt.info() != Eigen::Success) return;
    J_.setIdentity();
    llt.matrixU().solveInPlace(J_);  // J = L^-T
    p = -llt.solve(qp.a);
  }
  R_.setZero();
  q_ = 0;
  active_.clear();

  const int total = m + 2 * n;
  const int max_steps = 10 * total + 10;
  size_t next_warm = 0;
  while (out.steps < max_steps) {
    int kp = -1;
    while (warm != nullptr && next_warm < warm->size() && kp < 0) {
      const int k = (*warm)[next_warm++];
      if (k >= 0 && k < total && Slack(qp, k, p) < -tolerance * (1 + std::abs(Bound(qp, k))))
        kp = k;
    }
    if (kp < 0) kp = MostViolated(qp, p, tolerance);
    if (kp < 0) {
      out.solved = true;
      break;
    }
    Normal(qp, kp, np_);
    // A bound's normal is +-e_j: J^T n is J's row j, O(n) where a row's product is O(n^2).
    const int bound_var = kp < m ? -1 : kp < m + n ? kp - m : kp - m - n;
    const double bound_sign = kp < m + n ? 1.0 : -1.0;
    u_[q_] = 0.0;
    // Move along the primal and dual directions until kp holds (then it joins the active
    // set) or an active constraint's multiplier reaches zero (then it leaves).
    for (;;) {
      ++out.steps;
      if (out.steps > max_steps) break;
      if (bound_var >= 0) {
        d_ = bound_sign * J_.row(bound_var).transpose();
      } else {
        d_.noalias() = J_.transpose() * np_;
      }
      z_.noalias() = J_.rightCols(n - q_) * d_.tail(n - q_);
      if (q_ > 0) {
        r_.head(q_) = R_.topLeftCorner(q_, q_).triangularView<Eigen::Upper>().solve(d_.head(q_));
      }
      double t1 = kInf;
      int l = -1;
      for (int k = 0; k < q_; ++k) {
        if (r_[k] > 0.0 && u_[k] / r_[k] < t1) t1 = u_[k] / r_[k], l = k;
      }
      const double zn = z_.dot(np_);
      const bool primal = d_.tail(n - q_).norm() > 1e-12 * d_.norm();
      const double t2 = primal ? -Slack(qp, kp, p) / zn : kInf;
      if (!std::isfinite(t1) && !std::isfinite(t2)) return;  // infeasible
      const double t = std::min(t1, t2);
      if (primal) p += t * z_;
      if (q_ > 0) u_.head(q_) -= t * r_.head(q_);
      u_[q_] += t;
      if (t2 <= t1) {
        if (!Add()) return;  // not reached: a primal step means kp is independent
        active_.push_back(kp);
        break;
      }
      Drop(l);
    }
  }
  if (!out.solved) return;
  out.active = active_;
  for (int k = 0; k < q_; ++k) {
    const int c = active_[static_cast<size_t>(k)];
    if (c < m) {
      out.row_multiplier[c] = u_[k];
    } else if (c < m + n) {
      out.bound_multiplier[c - m] += u_[k];
    } else {
      out.bound_multiplier[c - m - n] -= u_[k];
    }
  }
}

}  // namespace tbridge
