// Every equilibrium solution of a pin-jointed network, from one sparse QR factorisation.
//
// Equilibrium is A x = -w on the free DOFs (design/equilibrium.h), with x the member forces
// [C_bars; T_strings] in N. Every solution is
//   x = x_p + N alpha,
// x_p a particular solution per load case and N an orthonormal basis of the self-stresses
// (null space of A, n_b + n_s - rank(A) columns). Both come from SuiteSparseQR's rank-revealing
// factorisation of A^T (members x DOFs): A^T E = Q R, rank r. Then
//   A x = -w  <=>  R^T (Q^T x) = -E^T w,
// so x_p = Q [R11^-T (-E^T w)_1..r; 0] and N = the trailing n - r columns of Q. The cost is
// that of one sparse QR of a tree-like matrix: linear in the members for these bridges.
#pragma once

#include <Eigen/Core>
#include <memory>

#include "design/equilibrium.h"

namespace tbridge {

struct EquilibriumBasis {
  int rank = 0;    // numerical rank of A (SuiteSparseQR's default tolerance)
  int states = 0;  // n_b + n_s - rank: the number of self-stresses
  // False when the basis was not formed because members x states exceeded the limit given to
  // FactorEquilibrium (self_stress is then members x 0; `states` still counts them).
  bool basis_formed = true;
  Eigen::MatrixXd particular;   // (n_b + n_s) x n_cases: forces of each load case [N]
  Eigen::MatrixXd self_stress;  // (n_b + n_s) x (n_b + n_s - rank): orthonormal columns
  // Largest |A x_p + w| over every case and free DOF [N]: nonzero when a load has a
  // component the network cannot carry (a mechanism it excites).
  double load_residual = 0;
  // Largest |A N| entry: a check of the rank decision (a few eps for a sound basis).
  double basis_residual = 0;

  int self_stress_states() const { return states; }
};

// One sparse QR of A^T, kept for solving further load cases (influence lines, the self-weight
// fixed point) without refactorising.
class EquilibriumSolver {
 public:
  // Throws ModelError when the factorisation fails.
  explicit EquilibriumSolver(const EquilibriumSystem& eq);
  ~EquilibriumSolver();
  EquilibriumSolver(const EquilibriumSolver&) = delete;
  EquilibriumSolver& operator=(const EquilibriumSolver&) = delete;

  int rank() const;
  int states() const;  // n_b + n_s - rank
  // The particular solution (members x cases) of each column of `free_loads` (n_dof x cases).
  Eigen::MatrixXd Particular(const Eigen::MatrixXd& free_loads) const;
  // The orthonormal self-stress basis (members x states).
  Eigen::MatrixXd SelfStresses() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// `free_loads` is n_dof x n_cases, each column w of one load case on the free DOFs [N]
// (FreeLoads). The basis is dense (members x states): it is formed only while that has at most
// `max_basis_entries` entries. The default, 2^20 (8 MB), admits every planar bridge (one state
// at any n) and the 3D bridge up to n = 6; beyond, its thousands of states would only feed a
// self-stress form that the full sparse problem beats (a whole 3D n = 8 design: 4.1 s and
// 308 MB with the basis formed, 1.6 s and 33 MB without).
EquilibriumBasis FactorEquilibrium(const EquilibriumSystem& eq, const Eigen::MatrixXd& free_loads,
                                   double max_basis_entries = 1048576.0);
// The same from a factorisation already made.
EquilibriumBasis FactorEquilibrium(const EquilibriumSolver& solver, const EquilibriumSystem& eq,
                                   const Eigen::MatrixXd& free_loads,
                                   double max_basis_entries = 1048576.0);

}  // namespace tbridge
