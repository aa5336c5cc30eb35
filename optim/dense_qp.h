// A strictly convex quadratic program with dense rows, solved by the dual active-set method
// of Goldfarb and Idnani (Math. Programming 27, 1983):
//
//   min  1/2 p^T G p + a^T p   s.t.   C p >= b,   lo <= p <= hi,
//
// G symmetric positive definite (n x n), C (m x n). It starts from the unconstrained minimum
// and adds the most violated constraint at each step. In the variables y = L^T p (G = L L^T)
// the objective is 1/2 |y|^2 plus a linear term, and the method needs only the thin QR factors
// Q1 R of the active normals L^-1 N, updated by Gram-Schmidt (twice, so that Q1 stays
// orthonormal to rounding) as a constraint joins and by Givens rotations as one leaves: a step
// costs O(n q) with q active constraints, plus the scan of the rows, O(m n). The original
// keeps the whole n x n basis J = L^-T Q and rotates all of it at every step, O(n^2); the
// sizing's subproblems (n = 512, q about 260) spent most of their time there. The sequential
// quadratic programming of optim/sqp_solver.h solves one per iteration; the bounds are its
// move limits and are scanned without forming their rows.
#pragma once

#include <Eigen/Cholesky>
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

// How a solve ended: each failure is its own, as its lever differs (an infeasible program
// wants its rows relaxed, a step limit more steps or a warm start, a G that is not positive
// definite its curvature floored).
enum class DenseQpStatus {
  kSolved,
  kInfeasible,           // a violated constraint lies in the active normals' span
  kStepLimit,            // 10 (m + 2 n) + 10 steps without a solution
  kNotPositiveDefinite,  // G has a non-positive pivot (or diagonal entry)
};
const char* DenseQpStatusName(DenseQpStatus status);

struct DenseQpSolution {
  bool solved = false;  // status == kSolved
  DenseQpStatus status = DenseQpStatus::kStepLimit;
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
  // `warm` (optional): constraints, numbered as DenseQpSolution::active, taken as the active
  // set at once (StartFrom) before the scans for the most violated begin. The dual method
  // may start from any such set whose multipliers are non-negative, so the minimiser is the
  // same; a warm set near the final one saves the scans of the rows, O(m n) per step, and
  // the drops of constraints the scans' order would add and remove again. `steps` counts
  // the steps after it.
  void Solve(const DenseQp& qp, DenseQpSolution& out, double tolerance = 1e-11,
             const std::vector<int>* warm = nullptr);

 private:
  void Resize(int n, int m);
  // The normal of constraint k (rows of C, then lower, then upper bounds), transformed:
  // L^-1 n_k into nt_.
  void TransformedNormal(const DenseQp& qp, int k);
  // A direction in y into p: L^-T v.
  void ToP(Eigen::VectorXd& v) const;
  double Slack(const DenseQp& qp, int k, const Eigen::VectorXd& p) const;  // >= 0 where it holds
  double Rhs(const DenseQp& qp, int k) const;  // constraint k as n_k^T p >= Rhs: b_k, lo_j, -hi_j
  // The transformed normal nt_ split along the active normals' span: d1_ = Q1^T nt its part
  // there, z_ = nt - Q1 d1 the rest.
  void Split();
  // Takes the warm constraints (independent ones, in order) as the active set at once, and
  // drops those whose multipliers come out negative: the equality minimiser on what is left,
  // with its multipliers, is a start the dual method may take (Goldfarb and Idnani's S-pair).
  // Adding them one at a time from the unconstrained minimum dropped and added them again many
  // times over (n = 8: 1 000 steps for a warm set of 410, a third of a second).
  void StartFrom(const DenseQp& qp, const std::vector<int>& warm, Eigen::VectorXd& p);
  // The most violated constraint at p, -1 where none is.
  int MostViolated(const DenseQp& qp, const Eigen::VectorXd& p, double tolerance);
  void Add(double z_norm, int k);  // constraint k joins: z_ / z_norm to Q1, [d1; z_norm] to R
  void Drop(int l);                // removes active constraint l (0-based in the active list)
  // G's factor (diagonal_, inv_sqrt_ or llt_) and the unconstrained minimiser into p; false
  // where G is not positive definite.
  bool Factor(const DenseQp& qp, Eigen::VectorXd& p);
  // How one step toward the candidate kp ended: kp joined the active set, an active
  // constraint left, kp was left out as met by rounding, or the program is infeasible.
  enum class StepEnd { kJoined, kDropped, kLeftOut, kInfeasible };
  // One step along the primal and dual directions toward candidate kp (nt_ its transformed
  // normal, nt_norm its norm).
  StepEnd Step(const DenseQp& qp, int kp, double nt_norm, Eigen::VectorXd& p);
  // The active set and its multipliers, as rows and bounds, into out.
  void Multipliers(DenseQpSolution& out) const;

  static constexpr int kBlock = 32;  // warm constraints that join StartFrom's active set at once
  int n_ = -1, m_ = -1, q_ = 0;      // sizes; q_: active constraints
  bool diagonal_ = true;             // G diagonal: L = sqrt(G), its inverse inv_sqrt_
  Eigen::VectorXd inv_sqrt_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::MatrixXd Q1_, R_;  // n x n and n x n, of which the first q_ columns are in use
  Eigen::VectorXd nt_, d1_, z_, r_, u_, dp_, y0_, Cp_;
  Eigen::MatrixXd block_, coef_,
      coef2_;  // StartFrom's block of normals and their coefficients on Q1
  Eigen::VectorXd block_norm_;
  std::vector<int> active_;
  // Per constraint, numbered as DenseQpSolution::active: 1 active, 2 left out as met by
  // rounding (until the active set loses a constraint), 0 otherwise.
  std::vector<char> is_active_;
  bool left_out_ = false;
};

}  // namespace tbridge
