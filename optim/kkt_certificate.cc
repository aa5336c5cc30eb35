#include "optim/kkt_certificate.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "optim/nnls.h"

namespace tbridge {
namespace {

void Require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("CertifyLocalOptimum: ") + what);
}

void Fail(std::string& failed, const char* what, double value, double limit) {
  char text[96];
  std::snprintf(text, sizeof text, "%s %.1e > %.1e", what, value, limit);
  failed += (failed.empty() ? "" : "; ") + std::string(text);
}

// The tangent space: the null space of the strongly active normals. A weakly active
// constraint (multiplier 0), row or bound, does not restrict it: the directions into its
// feasible side belong to the critical cone, and checking the whole line instead of the
// half is the safer error. The normals are scaled to unit length so that the rank
// tolerance (near sqrt(eps): normals closer to dependent than that give no vertex one can
// trust) does not depend on the rows' units.
// Returns an orthonormal basis of it, of the `n` variables: the identity without such normals.
Eigen::MatrixXd TangentSpace(const Eigen::MatrixXd& A, const Eigen::VectorXd& z,
                             double largest_multiplier, Eigen::Index n) {
  const Eigen::Index k = A.cols();
  const double strong = 1e-10 * std::max(1.0, largest_multiplier);
  std::vector<Eigen::VectorXd> normals;
  for (Eigen::Index j = 0; j < k; ++j) {
    const double norm = A.col(j).norm();
    if (z[j] > strong && norm > 0) normals.push_back(A.col(j) / norm);
  }
  Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(n, n);
  if (!normals.empty()) {
    Eigen::MatrixXd N(n, static_cast<Eigen::Index>(normals.size()));
    for (size_t j = 0; j < normals.size(); ++j) N.col(static_cast<Eigen::Index>(j)) = normals[j];
    Eigen::FullPivHouseholderQR<Eigen::MatrixXd> qr(N);
    qr.setThreshold(1e-8);
    const Eigen::MatrixXd Q = qr.matrixQ();  // its first rank() columns span N's
    Z = Q.rightCols(n - qr.rank());
  }
  return Z;
}

// The second-order condition on the tangent space `Z`, by the Hessian of the Lagrangian
// (central differences of its gradient, from `in.at`) reduced to it.
void SecondOrderByHessian(const KktInput& in, const Eigen::VectorXd& z, const Eigen::MatrixXd& Z,
                          double tolerance, double grad_norm, KktCertificate& c) {
  const Eigen::Index n = in.x.size();
  const int m = static_cast<int>(in.active.size());
  const Eigen::VectorXd lambda = z.head(m);
  const auto grad_lagrangian = [&](const Eigen::VectorXd& y) {
    Eigen::VectorXd g;
    Eigen::MatrixXd J;
    in.at(y, g, J);
    Require(g.size() == n && J.rows() == m && J.cols() == n, "`at` returned wrong sizes");
    Require(g.allFinite() && J.allFinite(), "`at` returned non-finite values");
    return Eigen::VectorXd(g - J.transpose() * lambda);
  };
  // Central differences: truncation O(h^2) (nothing for quadratic f and g), rounding about
  // eps |grad L| / h, 1e-10 of it.
  const double h = 1e-6 * std::max(1.0, in.x.lpNorm<Eigen::Infinity>());
  Eigen::MatrixXd HZ(n, Z.cols());
  for (Eigen::Index j = 0; j < Z.cols(); ++j) {
    HZ.col(j) =
        (grad_lagrangian(in.x + h * Z.col(j)) - grad_lagrangian(in.x - h * Z.col(j))) / (2 * h);
  }
  const Eigen::MatrixXd M = Z.transpose() * HZ;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (M + M.transpose()),
                                                           Eigen::EigenvaluesOnly);
  c.smallest_curvature = eig.eigenvalues()[0];
  const double size = std::max({1.0, eig.eigenvalues().cwiseAbs().maxCoeff(), grad_norm});
  c.second_order = c.smallest_curvature >= -tolerance * size;
  if (c.second_order) c.second_order_by = "reduced Hessian";
}

// What failed, in c.failed ("" when every condition holds).
void RecordFailures(const KktInput& in, double tolerance, KktCertificate& c) {
  // Written as "not <=" so that NaN fails.
  if (!(c.stationarity <= tolerance)) Fail(c.failed, "stationarity", c.stationarity, tolerance);
  if (!(c.feasibility <= tolerance)) Fail(c.failed, "feasibility", c.feasibility, tolerance);
  if (!(c.complementarity <= tolerance)) {
    Fail(c.failed, "complementarity", c.complementarity, tolerance);
  }
  if (!c.second_order) {
    char text[128];
    if (in.at) {
      std::snprintf(text, sizeof text, "second order: reduced Hessian eigenvalue %.1e < 0",
                    c.smallest_curvature);
    } else {
      std::snprintf(text, sizeof text,
                    "second order: not a vertex (%d free directions) and no Hessian",
                    c.null_space_dimension);
    }
    c.failed += (c.failed.empty() ? "" : "; ") + std::string(text);
  }
}

}  // namespace

KktCertificate CertifyLocalOptimum(const KktInput& in, double tolerance) {
  const Eigen::Index n = in.x.size();
  const int m = static_cast<int>(in.active.size());
  Require(in.lo_x.size() == n && in.hi_x.size() == n && in.grad_f.size() == n,
          "x, lo_x, hi_x and grad_f differ in size");
  Require(in.jac_active.rows() == m && in.jac_active.cols() == n,
          "jac_active is not active.size() x n");
  for (const int r : in.active) Require(r >= 0 && r < in.slack.size(), "active row outside slack");
  Require(in.x.allFinite() && in.grad_f.allFinite() && in.jac_active.allFinite(),
          "non-finite x, grad_f or jac_active");
  const double inf = std::numeric_limits<double>::infinity();

  KktCertificate c;
  c.active_rows = m;
  std::vector<Eigen::Index> lower, upper;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double lo = in.lo_x[i], hi = in.hi_x[i];
    const bool at_lo =
        std::isfinite(lo) && in.x[i] - lo <= in.active_tolerance * std::max(1.0, std::abs(lo));
    const bool at_hi =
        std::isfinite(hi) && hi - in.x[i] <= in.active_tolerance * std::max(1.0, std::abs(hi));
    if (at_lo) lower.push_back(i);
    if (at_hi) upper.push_back(i);
    if (!at_lo && !at_hi) ++c.free_variables;
    c.feasibility = std::max({c.feasibility, lo - in.x[i], in.x[i] - hi});
  }
  c.active_bounds = static_cast<int>(lower.size() + upper.size());
  // Every row, not only the active ones: a row the caller missed may be violated. NaN is
  // infinitely violated (std::max would drop it).
  for (Eigen::Index r = 0; r < in.slack.size(); ++r) {
    const double s = in.slack[r];
    c.feasibility = std::isnan(s) ? inf : std::max(c.feasibility, -s);
  }

  // grad f = A z, z >= 0, with the columns of A the active rows' normals and +e_i, -e_i for
  // the active lower and upper bounds.
  const Eigen::Index k = m + static_cast<Eigen::Index>(lower.size() + upper.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, k);
  A.leftCols(m) = in.jac_active.transpose();
  for (size_t j = 0; j < lower.size(); ++j) A(lower[j], m + static_cast<Eigen::Index>(j)) = 1;
  for (size_t j = 0; j < upper.size(); ++j)
    A(upper[j], m + static_cast<Eigen::Index>(lower.size() + j)) = -1;
  const Eigen::VectorXd z = NonNegativeLeastSquares(A, in.grad_f);
  const double grad_norm = in.grad_f.lpNorm<Eigen::Infinity>();
  const double scale = grad_norm > 0 ? grad_norm : 1.0;
  c.stationarity = (in.grad_f - A * z).lpNorm<Eigen::Infinity>() / scale;
  c.multipliers = z.head(m);
  c.bound_multipliers = Eigen::VectorXd::Zero(n);
  c.largest_multiplier = k > 0 ? z.maxCoeff() : 0.0;
  for (int r = 0; r < m; ++r) {
    c.complementarity = std::max(c.complementarity, z[r] * std::abs(in.slack[in.active[r]]));
  }
  for (Eigen::Index j = 0; j < k - m; ++j) {
    const bool is_lower = j < static_cast<Eigen::Index>(lower.size());
    const size_t b = static_cast<size_t>(j);
    const Eigen::Index i = is_lower ? lower[b] : upper[b - lower.size()];
    const double gap = std::abs(in.x[i] - (is_lower ? in.lo_x[i] : in.hi_x[i]));
    c.complementarity = std::max(c.complementarity, z[m + j] * gap);
    c.bound_multipliers[i] += is_lower ? z[m + j] : -z[m + j];
  }
  c.complementarity /= scale;

  // The tangent space: the null space of the strongly active normals.
  const Eigen::MatrixXd Z = TangentSpace(A, z, c.largest_multiplier, n);
  c.null_space_dimension = static_cast<int>(Z.cols());
  c.smallest_curvature = std::numeric_limits<double>::quiet_NaN();
  if (Z.cols() == 0) {
    // As many independent strongly active constraints as variables: every feasible direction
    // leaves some constraint with a positive multiplier, and f rises at first order.
    c.second_order = true;
    c.second_order_by = "vertex";
  } else if (in.at) {
    SecondOrderByHessian(in, z, Z, tolerance, grad_norm, c);
  }

  RecordFailures(in, tolerance, c);
  c.proved_local_optimum = c.failed.empty();
  return c;
}

}  // namespace tbridge
