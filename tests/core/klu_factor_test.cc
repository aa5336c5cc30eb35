// The sparse LU on a fixed pattern (core/klu_factor.h) against a second algorithm: Eigen's
// dense partial-pivoting LU of the same matrix.
#include "core/klu_factor.h"

#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <random>
#include <vector>

namespace tbridge {
namespace {

// A saddle-point matrix shaped like the static solve's: a banded, diagonally weighted block
// beside zero-diagonal constraint rows, its values drawn from `seed`.
Eigen::SparseMatrix<double> SaddlePoint(int n, int m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4.0 + u(rng));
    if (i + 1 < n) t.emplace_back(i, i + 1, u(rng)), t.emplace_back(i + 1, i, u(rng));
  }
  for (int r = 0; r < m; ++r) {
    for (int c : {2 * r, 2 * r + 3}) {
      const double v = u(rng);
      t.emplace_back(n + r, c, v);
      t.emplace_back(c, n + r, v);
    }
  }
  Eigen::SparseMatrix<double> a(n + m, n + m);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST_CASE("the KLU factor solves as the dense LU does: plain and transposed and refactorised",
          "[klu]") {
  const int n = 40, m = 12;
  KluFactor lu;
  const Eigen::SparseMatrix<double> first = SaddlePoint(n, m, 1);
  REQUIRE(lu.Analyse(first));
  // Two matrices on one pattern: the second is refactorised with the first's pivots.
  for (unsigned seed : {1u, 2u}) {
    const Eigen::SparseMatrix<double> a = SaddlePoint(n, m, seed);
    REQUIRE(lu.Factorise(a));
    const Eigen::MatrixXd dense(a);
    const Eigen::PartialPivLU<Eigen::MatrixXd> reference(dense);
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(n + m, 3);
    Eigen::MatrixXd x = b, xt = b;
    lu.Solve(x);
    lu.SolveTransposed(xt);
    const Eigen::MatrixXd x_ref = reference.solve(b), xt_ref = reference.transpose().solve(b);
    // Both are backward stable on a matrix of condition about 8e2 (measured below): their
    // solutions agree to a few hundred roundings of the largest entry. 1e-12 relative.
    CHECK((x - x_ref).cwiseAbs().maxCoeff() <= 1e-12 * x_ref.cwiseAbs().maxCoeff());
    CHECK((xt - xt_ref).cwiseAbs().maxCoeff() <= 1e-12 * xt_ref.cwiseAbs().maxCoeff());
    Eigen::VectorXd v = b.col(0);
    lu.Solve(v);
    CHECK((v - x_ref.col(0)).cwiseAbs().maxCoeff() <= 1e-12 * x_ref.cwiseAbs().maxCoeff());
    // The condition estimate is the 1-norm one, as the dense LU's: both are Hager's lower
    // bound, within a factor of a few of the true value (measured equal, 1.3e-3); a factor 2.
    const double rcond = lu.ReciprocalCondition(a), rcond_ref = reference.rcond();
    INFO("rcond " << rcond << ", dense " << rcond_ref);
    CHECK(rcond >= 0.5 * rcond_ref);
    CHECK(rcond <= 2 * rcond_ref);
  }
}

TEST_CASE("the KLU factor refactorises a matrix whose rows differ in scale by 1e13 to rounding",
          "[klu]") {
  // The static solve's Newton matrix: stiffness rows of ~1e13 beside constraint rows of ~1,
  // whose pivot ratio reads about 1e-13 with any pivots. The later factorisations keep the
  // first's pivots (the ratio stays within a thousandth of what fresh pivots gave); each must
  // still solve to rounding. Backward error |A x - b|_i / (|A| |x| + |b|)_i: a stable LU gives
  // a modest multiple of 1e-16 in every row; 1e-13 allows a thousand, and the dense LU's own is
  // the yardstick printed beside it.
  const int n = 40, m = 12;
  const auto scaled = [&](unsigned seed) {
    Eigen::SparseMatrix<double> a = SaddlePoint(n, m, seed);
    for (int k = 0; k < a.outerSize(); ++k) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it) {
        if (it.row() < n && it.col() < n) it.valueRef() *= 1e13;
      }
    }
    return a;
  };
  KluFactor lu;
  REQUIRE(lu.Analyse(scaled(1)));
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::SparseMatrix<double> a = scaled(seed);
    REQUIRE(lu.Factorise(a));
    const Eigen::MatrixXd dense(a);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n + m);
    Eigen::VectorXd x = b;
    lu.Solve(x);
    const Eigen::VectorXd x_ref = Eigen::PartialPivLU<Eigen::MatrixXd>(dense).solve(b);
    // Row by row (Oettli and Prager's componentwise measure), so that the rows of 1e13 do
    // not hide the constraint rows' error.
    const auto backward = [&](const Eigen::VectorXd& y) {
      const Eigen::ArrayXd scale = (dense.cwiseAbs() * y.cwiseAbs() + b.cwiseAbs()).array();
      return ((dense * y - b).cwiseAbs().array() / scale).maxCoeff();
    };
    INFO("seed " << seed << ": KLU " << backward(x) << ", dense LU " << backward(x_ref));
    CHECK(backward(x) <= 1e-13);
  }
}

TEST_CASE("the KLU factor reports a singular matrix", "[klu]") {
  // A constraint row that repeats another: the matrix is singular.
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 2.0}, {1, 1, 3.0}, {2, 0, 1.0},
                                           {0, 2, 1.0}, {3, 0, 1.0}, {0, 3, 1.0}};
  Eigen::SparseMatrix<double> a(4, 4);
  a.setFromTriplets(t.begin(), t.end());
  KluFactor lu;
  REQUIRE(lu.Analyse(a));
  CHECK(!lu.Factorise(a));
}

}  // namespace
}  // namespace tbridge
