#include "optim/nnls.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tbridge {
namespace {

// The QR factors of the passive columns A_P = Q [R; 0], kept up to date by Givens rotations as
// columns join and leave: O(rows^2) per change, where factorising A_P afresh at every step
// costs O(rows |P|^2) (the sizing's start multipliers at n = 7: 256 rows, a few hundred
// columns, 13 % of the whole design with a fresh factorisation per step).
class PassiveQr {
 public:
  PassiveQr(const Eigen::MatrixXd& A, const Eigen::VectorXd& b)
      : A_(A), Q_(Eigen::MatrixXd::Identity(A.rows(), A.rows())), R_(A.rows(), A.rows()), qtb_(b) {}

  int size() const { return static_cast<int>(cols_.size()); }
  const std::vector<int>& cols() const { return cols_; }

  // Appends column j; false (and nothing changes) where it is dependent on the passive ones.
  bool Add(int j) {
    const int k = size();
    if (k >= A_.rows()) return false;
    v_.noalias() = Q_.transpose() * A_.col(j);
    for (Eigen::Index i = A_.rows() - 1; i > k; --i) {
      if (v_[i] == 0.0) continue;
      Rotation(v_[i - 1], v_[i]);
      v_[i - 1] = h_;
      v_[i] = 0.0;
      RotateFactors(static_cast<int>(i) - 1);
    }
    if (std::abs(v_[k]) <= 1e-12 * A_.col(j).norm()) {
      // Nothing to undo: the rotations only turned the columns k.. of Q, which no passive
      // column uses, among themselves, and Q^T b with them.
      return false;
    }
    R_.col(k).head(k + 1) = v_.head(k + 1);
    cols_.push_back(j);
    return true;
  }

  // Removes the passive column at position l.
  void Remove(int l) {
    const int k = size();
    for (int c = l; c < k - 1; ++c) R_.col(c).head(k) = R_.col(c + 1).head(k);
    cols_.erase(cols_.begin() + l);
    // R is upper Hessenberg from column l: rotate each subdiagonal entry away.
    for (int i = l; i < k - 1; ++i) {
      Rotation(R_(i, i), R_(i + 1, i));
      if (h_ == 0.0) continue;
      for (int c = i; c < k - 1; ++c) {
        const double x = R_(i, c), y = R_(i + 1, c);
        R_(i, c) = c_ * x + s_ * y;
        R_(i + 1, c) = -s_ * x + c_ * y;
      }
      R_(i + 1, i) = 0.0;
      RotateFactors(i);
    }
  }

  // The least squares on the passive columns, by position.
  Eigen::VectorXd Solve() const {
    const int k = size();
    return R_.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(qtb_.head(k));
  }

 private:
  // The rotation that takes (a, b) to (h, 0).
  void Rotation(double a, double b) {
    h_ = std::hypot(a, b);
    c_ = h_ == 0.0 ? 1.0 : a / h_;
    s_ = h_ == 0.0 ? 0.0 : b / h_;
  }
  // Applies the last rotation to rows i, i + 1 of Q^T (columns of Q) and of Q^T b.
  void RotateFactors(int i) {
    for (Eigen::Index r = 0; r < Q_.rows(); ++r) {
      const double x = Q_(r, i), y = Q_(r, i + 1);
      Q_(r, i) = c_ * x + s_ * y;
      Q_(r, i + 1) = -s_ * x + c_ * y;
    }
    const double x = qtb_[i], y = qtb_[i + 1];
    qtb_[i] = c_ * x + s_ * y;
    qtb_[i + 1] = -s_ * x + c_ * y;
  }

  const Eigen::MatrixXd& A_;
  Eigen::MatrixXd Q_, R_;
  Eigen::VectorXd qtb_, v_;
  std::vector<int> cols_;
  double h_ = 0, c_ = 1, s_ = 0;
};

}  // namespace

Eigen::VectorXd NonNegativeLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                        double* residual) {
  const Eigen::Index n = A.cols();
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  std::vector<char> passive(static_cast<size_t>(n), 0), dependent(static_cast<size_t>(n), 0);
  PassiveQr qr(A, b);
  // The gradient's tolerance: rounding in A^T (b - A z) is about eps |A| |b|.
  const double tol = 10 * std::numeric_limits<double>::epsilon() * std::max(A.norm(), 1.0) *
                     std::max(b.norm(), 1.0);
  for (Eigen::Index step = 0; step < 3 * n; ++step) {
    const Eigen::VectorXd w = A.transpose() * (b - A * z);
    Eigen::Index enter = -1;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!passive[j] && !dependent[j] && w[j] > tol && (enter < 0 || w[j] > w[enter])) enter = j;
    }
    if (enter < 0) break;  // Kuhn-Tucker conditions hold
    // A column in the span of the passive ones cannot lower the residual (its w is rounding):
    // it stays out until the passive set changes.
    if (!qr.Add(static_cast<int>(enter))) {
      dependent[enter] = 1;
      continue;
    }
    std::fill(dependent.begin(), dependent.end(), 0);
    passive[enter] = 1;
    for (Eigen::Index inner = 0; inner < n; ++inner) {
      const Eigen::VectorXd sp = qr.Solve();
      Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
      for (int k = 0; k < qr.size(); ++k) s[qr.cols()[k]] = sp[k];
      bool feasible = true;
      for (Eigen::Index j = 0; j < n; ++j) feasible = feasible && (!passive[j] || s[j] > 0);
      if (feasible) {
        z = s;
        break;
      }
      // Step from z towards s as far as every passive entry stays >= 0, then free those at 0.
      double alpha = 1;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[j] && s[j] <= 0) alpha = std::min(alpha, z[j] / (z[j] - s[j]));
      }
      z += alpha * (s - z);
      for (int k = qr.size() - 1; k >= 0; --k) {
        const int j = qr.cols()[k];
        if (z[j] <= tol) passive[j] = 0, z[j] = 0, qr.Remove(k);
      }
    }
  }
  if (residual) *residual = (A * z - b).norm();
  return z;
}

}  // namespace tbridge
