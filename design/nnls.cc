#include "design/nnls.h"

#include <Eigen/QR>
#include <algorithm>
#include <limits>
#include <vector>

namespace tbridge {
namespace {

// The least-squares solution on the columns in `passive` (others zero).
Eigen::VectorXd SolveOn(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const std::vector<char>& passive) {
  std::vector<int> cols;
  for (int j = 0; j < static_cast<int>(passive.size()); ++j) {
    if (passive[j]) cols.push_back(j);
  }
  Eigen::MatrixXd sub(A.rows(), static_cast<Eigen::Index>(cols.size()));
  for (size_t k = 0; k < cols.size(); ++k) sub.col(static_cast<Eigen::Index>(k)) = A.col(cols[k]);
  const Eigen::VectorXd s = sub.completeOrthogonalDecomposition().solve(b);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(A.cols());
  for (size_t k = 0; k < cols.size(); ++k) out[cols[k]] = s[static_cast<Eigen::Index>(k)];
  return out;
}

}  // namespace

Eigen::VectorXd NonNegativeLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double* residual) {
  const Eigen::Index n = A.cols();
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  std::vector<char> passive(static_cast<size_t>(n), 0);
  // The gradient's tolerance: rounding in A^T (b - A z) is about eps |A| |b|.
  const double tol = 10 * std::numeric_limits<double>::epsilon() * std::max(A.norm(), 1.0) * std::max(b.norm(), 1.0);
  for (Eigen::Index step = 0; step < 3 * n; ++step) {
    const Eigen::VectorXd w = A.transpose() * (b - A * z);
    Eigen::Index enter = -1;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!passive[j] && w[j] > tol && (enter < 0 || w[j] > w[enter])) enter = j;
    }
    if (enter < 0) break;  // Kuhn-Tucker conditions hold
    passive[enter] = 1;
    for (Eigen::Index inner = 0; inner < n; ++inner) {
      const Eigen::VectorXd s = SolveOn(A, b, passive);
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
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[j] && z[j] <= tol) passive[j] = 0, z[j] = 0;
      }
    }
  }
  if (residual) *residual = (A * z - b).norm();
  return z;
}

}  // namespace tbridge
