// The dense quadratic program (Goldfarb-Idnani) against closed forms and against a second
// algorithm: every active set enumerated, each solved as a linear KKT system.

#include "optim/dense_qp.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <limits>
#include <random>
#include <string>

namespace tbridge {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

DenseQp Unbounded(int n, int m) {
  DenseQp qp;
  qp.G = Eigen::MatrixXd::Identity(n, n);
  qp.a = Eigen::VectorXd::Zero(n);
  qp.C = Eigen::MatrixXd::Zero(m, n);
  qp.b = Eigen::VectorXd::Zero(m);
  qp.lo = Eigen::VectorXd::Constant(n, -kInf);
  qp.hi = Eigen::VectorXd::Constant(n, kInf);
  return qp;
}

// The constraints as rows C_all p >= b_all: C's rows, then the finite bounds.
void AllRows(const DenseQp& qp, Eigen::MatrixXd& C, Eigen::VectorXd& b) {
  const int n = static_cast<int>(qp.G.rows()), m = static_cast<int>(qp.C.rows());
  C = Eigen::MatrixXd::Zero(m + 2 * n, n);
  b = Eigen::VectorXd::Zero(m + 2 * n);
  C.topRows(m) = qp.C;
  b.head(m) = qp.b;
  int r = m;
  for (int j = 0; j < n; ++j) {
    if (std::isfinite(qp.lo[j])) C(r, j) = 1, b[r++] = qp.lo[j];
    if (std::isfinite(qp.hi[j])) C(r, j) = -1, b[r++] = -qp.hi[j];
  }
  C.conservativeResize(r, n);
  b.conservativeResize(r);
}

// The second algorithm: every subset of the rows as the active set, its KKT system solved
// directly; the feasible one with non-negative multipliers is the optimum (strictly convex:
// unique). Returns the least objective among feasible points as a check of that too.
Eigen::VectorXd Enumerated(const DenseQp& qp, double* best_objective) {
  Eigen::MatrixXd C;
  Eigen::VectorXd b;
  AllRows(qp, C, b);
  const int n = static_cast<int>(qp.G.rows()), rows = static_cast<int>(C.rows());
  Eigen::VectorXd best;
  *best_objective = kInf;
  for (int mask = 0; mask < (1 << rows); ++mask) {
    std::vector<int> act;
    for (int r = 0; r < rows; ++r) {
      if (mask & (1 << r)) act.push_back(r);
    }
    const int k = static_cast<int>(act.size());
    if (k > n) continue;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + k, n + k);
    Eigen::VectorXd rhs(n + k);
    K.topLeftCorner(n, n) = qp.G;
    rhs.head(n) = -qp.a;
    for (int i = 0; i < k; ++i) {
      K.block(0, n + i, n, 1) = -C.row(act[i]).transpose();
      K.block(n + i, 0, 1, n) = C.row(act[i]);
      rhs[n + i] = b[act[i]];
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
    if (lu.rank() < n + k) continue;
    const Eigen::VectorXd sol = lu.solve(rhs);
    const Eigen::VectorXd p = sol.head(n);
    if ((C * p - b).minCoeff() < -1e-10 || (k > 0 && sol.tail(k).minCoeff() < -1e-10)) continue;
    const double f = 0.5 * p.dot(qp.G * p) + qp.a.dot(p);
    if (f < *best_objective) *best_objective = f, best = p;
  }
  return best;
}

TEST_CASE("dense QP: the projection onto a half-space and a box has its closed form", "[qp]") {
  // min 1/2 |p - c|^2 s.t. w^T p >= 1: p = c + (1 - w^T c) / |w|^2 w where c violates it, the
  // multiplier (1 - w^T c) / |w|^2. 1e-12: a few rotations of O(1) numbers.
  DenseQp qp = Unbounded(3, 1);
  const Eigen::Vector3d c(0.2, -0.1, 0.3), w(1.0, 2.0, -0.5);
  qp.a = -c;
  qp.C.row(0) = w.transpose();
  qp.b[0] = 1.0;
  DenseQpSolver solver;
  DenseQpSolution sol;
  solver.Solve(qp, sol);
  REQUIRE(sol.solved);
  const double lambda = (1 - w.dot(c)) / w.squaredNorm();
  CHECK((sol.p - (c + lambda * w)).norm() <= 1e-12);
  CHECK(sol.row_multiplier[0] == Approx(lambda).epsilon(1e-12));
  // A box alone: the projection is the clamp, the bound multipliers the gradient's parts.
  DenseQp box = Unbounded(3, 0);
  box.a = -c;
  box.lo = Eigen::Vector3d(0.25, -1, -1);
  box.hi = Eigen::Vector3d(1, 1, 0.1);
  solver.Solve(box, sol);
  REQUIRE(sol.solved);
  CHECK((sol.p - Eigen::Vector3d(0.25, -0.1, 0.1)).norm() <= 1e-14);
  CHECK(sol.bound_multiplier[0] == Approx(0.05).epsilon(1e-12));  // on lo: G p + a = 0.05
  CHECK(sol.bound_multiplier[2] == Approx(-0.2).epsilon(1e-12));  // on hi: -(0.1 - 0.3)
  CHECK(sol.bound_multiplier[1] == 0.0);
}

TEST_CASE("dense QP: random programs agree with every active set enumerated", "[qp]") {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  int solved = 0, infeasible = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 2 + trial % 3, m = 2 + trial % 4;
    DenseQp qp = Unbounded(n, m);
    Eigen::MatrixXd A(n, n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) A(i, j) = normal(rng);
    }
    qp.G = A * A.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
    for (int i = 0; i < n; ++i) qp.a[i] = normal(rng);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < n; ++j) qp.C(i, j) = normal(rng);
      qp.b[i] = normal(rng);
    }
    if (trial % 2) {  // move limits on half of them, as the sequential QP poses them
      qp.lo = Eigen::VectorXd::Constant(n, -0.8);
      qp.hi = Eigen::VectorXd::Constant(n, 0.8);
    }
    double best = 0;
    const Eigen::VectorXd expected = Enumerated(qp, &best);
    DenseQpSolver solver;
    DenseQpSolution sol;
    solver.Solve(qp, sol);
    INFO("trial " << trial);
    if (expected.size() == 0) {
      // No active set gives a feasible KKT point: the program is infeasible.
      CHECK_FALSE(sol.solved);
      ++infeasible;
      continue;
    }
    REQUIRE(sol.solved);
    ++solved;
    // 1e-9: the enumeration's LU and the rotations both work to rounding on O(1) data whose
    // matrices have condition up to ~1e4 (G's smallest eigenvalue 0.1).
    CHECK((sol.p - expected).norm() <= 1e-9 * (1 + expected.norm()));
    // The multipliers satisfy stationarity G p + a = C^T lambda + mu (bounds), themselves.
    const Eigen::VectorXd residual =
        qp.G * sol.p + qp.a - qp.C.transpose() * sol.row_multiplier - sol.bound_multiplier;
    CHECK(residual.norm() <= 1e-9 * (1 + qp.a.norm()));
    CHECK(sol.row_multiplier.minCoeff() >= 0.0);
  }
  // Both outcomes occur, so neither branch passes vacuously.
  CHECK(solved >= 20);
  CHECK(infeasible >= 1);
}

TEST_CASE("dense QP: a warm start, right or wrong, reaches the minimiser of a cold one", "[qp]") {
  // The warm set is taken as the active set at once and its negative multipliers dropped
  // (DenseQpSolver::StartFrom): whatever it holds, the dual method then reaches the program's
  // one minimiser. The second algorithm: every active set enumerated.
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<int> pick(0, 1);
  int compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 3 + trial % 3, m = 3 + trial % 4;
    DenseQp qp = Unbounded(n, m);
    qp.G = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) qp.G(i, i) = 0.1 + std::abs(normal(rng));  // diagonal, as the SQP's
    for (int i = 0; i < n; ++i) qp.a[i] = normal(rng);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < n; ++j) qp.C(i, j) = normal(rng);
      qp.b[i] = normal(rng);
    }
    qp.lo = Eigen::VectorXd::Constant(n, -0.8);
    qp.hi = Eigen::VectorXd::Constant(n, 0.8);
    double best = 0;
    const Eigen::VectorXd expected = Enumerated(qp, &best);
    if (expected.size() == 0) continue;  // infeasible: the first test covers it
    DenseQpSolver solver;
    DenseQpSolution cold;
    solver.Solve(qp, cold);
    REQUIRE(cold.solved);
    // The right set, the right set with wrong constraints before it, a random set, and every
    // constraint (rows, both bounds of each variable: dependent pairs among them).
    std::vector<std::vector<int>> warms{cold.active, {}, {}, {}};
    for (int k = 0; k < m + 2 * n; ++k) {
      if (pick(rng)) warms[1].push_back(k);
      if (pick(rng)) warms[2].push_back(k);
      warms[3].push_back(k);
    }
    warms[1].insert(warms[1].end(), cold.active.begin(), cold.active.end());
    for (const std::vector<int>& warm : warms) {
      DenseQpSolution sol;
      solver.Solve(qp, sol, 1e-11, &warm);
      INFO("trial " << trial << ", warm set of " << warm.size());
      REQUIRE(sol.solved);
      // 1e-9, as the cold solve against the enumeration: rounding on O(1) data.
      CHECK((sol.p - expected).norm() <= 1e-9 * (1 + expected.norm()));
      CHECK((sol.row_multiplier - cold.row_multiplier).norm() <=
            1e-8 * (1 + cold.row_multiplier.norm()));
      ++compared;
    }
  }
  CHECK(compared >= 100);
}

TEST_CASE("dense QP: a constraint its active ones imply is met within 1e-8, and not beyond",
          "[qp]") {
  // p_0 >= 1 (a row) and p_0 <= 1 - delta (the upper bound): the bound lies in the row's span,
  // and no multiplier can give way. Violated by rounding's order (delta = 1e-10) it is met and
  // left out; by 1e-3 the program is infeasible and says so.
  DenseQp qp = Unbounded(2, 1);
  qp.a = Eigen::Vector2d(1.0, 0.5);
  qp.C(0, 0) = 1.0;
  qp.b[0] = 1.0;
  DenseQpSolver solver;
  DenseQpSolution sol;
  qp.hi[0] = 1.0 - 1e-10;
  solver.Solve(qp, sol);
  REQUIRE(sol.solved);
  CHECK(sol.p[0] == Approx(1.0).margin(1e-9));
  CHECK(sol.p[1] == Approx(-0.5).margin(1e-12));  // G = I: the free variable at -a_1
  qp.hi[0] = 1.0 - 1e-3;
  solver.Solve(qp, sol);
  CHECK_FALSE(sol.solved);
  CHECK(sol.status == DenseQpStatus::kInfeasible);
}

TEST_CASE("dense QP: each failure has its own status", "[qp]") {
  DenseQpSolver solver;
  DenseQpSolution sol;
  // A solvable program: solved.
  DenseQp qp = Unbounded(2, 1);
  qp.C(0, 0) = 1.0;
  qp.b[0] = 1.0;
  solver.Solve(qp, sol);
  REQUIRE(sol.solved);
  CHECK(sol.status == DenseQpStatus::kSolved);
  // A G with a zero pivot, diagonal or not: not positive definite, before any step.
  qp.G(1, 1) = 0.0;
  solver.Solve(qp, sol);
  CHECK_FALSE(sol.solved);
  CHECK(sol.status == DenseQpStatus::kNotPositiveDefinite);
  qp.G << 1.0, 1.0, 1.0, 1.0;  // singular, not diagonal: its Cholesky factorisation fails
  solver.Solve(qp, sol);
  CHECK(sol.status == DenseQpStatus::kNotPositiveDefinite);
  // p_0 >= 1 and -p_0 >= 0: infeasible.
  qp = Unbounded(2, 2);
  qp.C(0, 0) = 1.0;
  qp.b[0] = 1.0;
  qp.C(1, 0) = -1.0;
  solver.Solve(qp, sol);
  CHECK(sol.status == DenseQpStatus::kInfeasible);
  CHECK(std::string(DenseQpStatusName(sol.status)) == "infeasible");
}

TEST_CASE("dense QP: rows nearly parallel to active ones hold at the minimiser to rounding",
          "[qp]") {
  // Rows in pairs 1e-9 apart, as the sizing's rows of one member at neighbouring stations: a
  // candidate's part off the active span is then of order 1e-9 of it, and the primal step
  // length -slack / (z . nt) read that product's rounding (1e-14 |z| |nt|) as its value,
  // stepping the wrong way by 1e6 and leaving active rows violated in a program reported
  // solved. The checks are the optimality conditions themselves: every row met, every
  // multiplier non-negative, and G p + a = C^T lambda + mu (the bounds' multipliers).
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  int solved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 12, m = 24;
    DenseQp qp = Unbounded(n, m);
    for (int i = 0; i < n; ++i) qp.G(i, i) = 0.1 + std::abs(normal(rng));
    for (int i = 0; i < n; ++i) qp.a[i] = normal(rng);
    for (int i = 0; i < m; i += 2) {
      for (int j = 0; j < n; ++j) qp.C(i, j) = normal(rng);
      for (int j = 0; j < n; ++j) qp.C(i + 1, j) = qp.C(i, j) + 1e-9 * normal(rng);
      qp.b[i] = std::abs(normal(rng));
      qp.b[i + 1] = qp.b[i] + 1e-9 * normal(rng);
    }
    qp.lo = Eigen::VectorXd::Constant(n, -2.0);
    qp.hi = Eigen::VectorXd::Constant(n, 2.0);
    DenseQpSolver solver;
    DenseQpSolution sol;
    solver.Solve(qp, sol);
    if (!sol.solved) continue;  // a pair 1e-9 apart may leave no feasible point within rounding
    ++solved;
    INFO("trial " << trial);
    // Every row met to 1e-9 (1 + |b|): the pairs' own spread, far above rounding's 1e-14.
    const Eigen::VectorXd slack = (qp.C * sol.p - qp.b).array() / (1 + qp.b.array().abs());
    CHECK(slack.minCoeff() >= -1e-9);
    CHECK(sol.row_multiplier.minCoeff() >= 0.0);
    // Stationarity to 1e-6 of the terms' scale: a pair's multipliers may be large and of
    // opposite trend (their difference carries 1e-9 of the normal), their sum is what counts.
    const Eigen::VectorXd residual =
        qp.G * sol.p + qp.a - qp.C.transpose() * sol.row_multiplier - sol.bound_multiplier;
    const double scale = 1 + qp.a.norm() + (qp.C.transpose() * sol.row_multiplier).norm();
    CHECK(residual.norm() <= 1e-6 * scale);
  }
  CHECK(solved >= 100);
}

}  // namespace
}  // namespace tbridge
