// A strictly convex quadratic program with dense rows, solved by the dual active-set method
// of Goldfarb and Idnani (Math. Programming 27, 1983):
//
//   min  1/2 p^T G p + a^T p   s.t.   C p >= b,   lo <= p <= hi,
//
// G symmetric positive definite (n x n), C (m x n). It starts from the unconstrained minimum
// and adds the most violated constraint at each step, keeping the factors J = L^-T Q and R of
// the active normals (G = L L^T, L^-1 N = Q [R; 0]) up to date by Givens rotations: a step costs
// O(n^2) plus the scan of the rows, O(m n). The sequential quadratic programming of
// design/sqp_solver.h solves one per iteration; the bounds are its move limits and are
// scanned without forming their rows.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace tbridge {

struct DenseQp {
  Eigen::MatrixXd G;   // n x n, symmetric positive definite
  Eigen::VectorXd a;   // n
  Eigen::MatrixXd C;   // m x n
  Eigen::VectorXd b;   // m
  Eigen::VectorXd lo;  // n, may be -inf
  Eigen::VectorXd hi;  // n, may be +inf
};

struct DenseQpSolution {
  bool solved = false;               // false: infeasible, or the step limit was reached
  Eigen::VectorXd p;                 // the minimiser
  Eigen::VectorXd row_multiplier;    // m, >= 0: the multipliers of C p >= b
  Eigen::VectorXd bound_multiplier;  // n: > 0 where p sits on lo, < 0 where on hi
  int steps = 0;                     // constraints added or dropped
  // The active constraints at the minimiser, in the order they joined: rows of C (0..m-1),
  // lower bounds (m + j), upper bounds (m + n + j). A warm start for the next solve.
  std::vector<int> active;
};

// The solver keeps its factors and scratch between solves of one size (no allocation after
// the first solve of that size).
class DenseQpSolver {
 public:
  // `tolerance`: a row counts as violated when C_i p - b_i < -tolerance (1 + |b_i|).
  // `warm` (optional): constraints, numbered as DenseQpSolution::active, tried first and in
  // that order, each added where it is violated, before the scans for the most violated
  // begin. The dual method may add any violated constraint at any step, so the minimiser is
  // the same; a warm set near the final one saves the scans of the rows, O(m n) per step, and
  // the drops of constraints the scans' order would add and remove again.
  void Solve(const DenseQp& qp, DenseQpSolution& out, double tolerance = 1e-11,
             const std::vector<int>* warm = nullptr);

 private:
  void Resize(int n, int m);
  // The normal of constraint k (rows of C, then lower, then upper bounds) into `np`.
  void Normal(const DenseQp& qp, int k, Eigen::VectorXd& np) const;
  double Slack(const DenseQp& qp, int k, const Eigen::VectorXd& p) const;  // >= 0 where it holds
  double Bound(const DenseQp& qp, int k) const;                            // b_k, lo_j or hi_j
  // The most violated constraint at p, -1 where none is.
  int MostViolated(const DenseQp& qp, const Eigen::VectorXd& p, double tolerance);
  bool Add();        // appends d's new column to R (false: dependent on the active normals)
  void Drop(int l);  // removes active constraint l (0-based in the active list)

  int n_ = -1, m_ = -1, q_ = 0;  // sizes; q_: active constraints
  Eigen::MatrixXd J_, R_;
  Eigen::VectorXd d_, z_, r_, u_, np_, Cp_;
  std::vector<int> active_;
};

}  // namespace tbridge
