// The linear response of a prestressed bar-string structure about its reference state: the
// forces a statically indeterminate bridge really carries under a load, shared by stiffness,
// and how they change with the string areas and the prestress (direct and adjoint sensitivities).
//
// About the reference state (the drawn geometry, member forces x = [C; T]), a load change f
// on the free DOFs moves the nodes by u, with the bars rigid (their length held to first order):
//   [K  C^T] [u ]   [f]      K = sum_strings (k_s e e^T + t_s / l_s (I - e e^T))
//   [C  0  ] [mu] = [0],         - sum_bars c_b / l_b I            (design/stability.h's K_T)
// C the bar-length rows (e^T (u_j - u_i) per bar), mu the bars' multipliers. The member forces
// change by
//   strings: dT_s = k_s e^T (u_j - u_i),  bars: dC_b = -mu_b  (mu is the bar's added tension).
// k_s = E A_s / L0_s = (E A_s + T_s) / l_s, since the rest length makes the string carry T_s
// at its drawn length l_s (L0 = l / (1 + T / (E A))).
//
// Sensitivities: with a parameter p that moves k and x, d[u; mu]/dp = -KKT^-1 [dK/dp u; 0],
// dK/dp = sum_s dk_s/dp (e e^T)_s + sum_j dx_j/dp G_j (G_j the member's geometric block per
// unit force), and the force map adds dk_s/dp e^T (u_j - u_i).
//
// The KKT matrix is (dim n_free + n_b) square and sparse (a node meets a few members), factorised
// once per state by KLU (core/klu_factor.h); the solutions are dense columns. A dense
// partial-pivoting LU took 60 % of the default's verified design at n = 6 (its O(n^3)
// factorisation and O(n^2) solves per column, for every column the sizing asks of every state);
// the sparse one does in O(fill) what the dense one did in O(n^2): BENCHMARKS.md.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/klu_factor.h"
#include "core/structure.h"

namespace tbridge {

class LinearResponse {
 public:
  // `reference_forces`: [C_bars; T_strings] [N] of the reference state; `string_stiffness`:
  // k_s [N/m] per string. Throws ModelError on size mismatches or a singular KKT matrix (a
  // mechanism the prestress does not hold).
  LinearResponse(const Structure& structure, const Eigen::VectorXd& reference_forces,
                 const Eigen::VectorXd& string_stiffness);

  int num_free_dofs() const { return ndof_; }
  int num_members() const { return nb_ + ns_; }
  // The free-DOF vector (dim per free node, node order) of 3 x n_n node loads [N]: the
  // right-hand side Solve takes, for `structure` without a response built.
  static Eigen::VectorXd FreeVector(const Structure& structure, const Eigen::Matrix3Xd& loads);
  Eigen::VectorXd FreeVector(const Eigen::Matrix3Xd& loads) const { return FreeVector(s_, loads); }
  // [u; mu / s] for each column of free-DOF loads [N]: (n_dof + n_b) x columns (s the bar
  // rows' scale, which ForceChanges takes back out).
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& free_loads) const;
  // The member force changes [dC; dT] [N] of solutions from Solve: (n_b + n_s) x columns.
  Eigen::MatrixXd ForceChanges(const Eigen::MatrixXd& solutions) const;
  // The vertical (y) displacement [m] of node `node` in each solution (0 for a pinned node).
  Eigen::RowVectorXd Vertical(const Eigen::MatrixXd& solutions, int node) const;
  // The row of the solutions that holds node `node`'s vertical displacement; -1 for a pinned node.
  int VerticalRow(int node) const { return DisplacementRow(node, 1); }
  // The row that holds its displacement along `axis` (0: x, 1: y, 2: z on a 3D structure); -1
  // for a pinned node or an axis the structure does not have.
  int DisplacementRow(int node, int axis) const {
    return dof_[node] < 0 || axis >= dim_ ? -1 : dof_[node] + axis;
  }

  // How a parameter moves the state: dk_s/dp per string and dx_j/dp per member.
  struct Direction {
    Eigen::VectorXd stiffness;  // n_s [N/m per unit p]
    Eigen::VectorXd forces;     // n_b + n_s [N per unit p]
  };
  // d(solutions)/dp for the direction: (n_dof + n_b) x columns. The direct form: the sizing
  // takes the adjoint one (Adjoint below), and the tests check each against the other.
  Eigen::MatrixXd SolveDerivative(const Eigen::MatrixXd& solutions, const Direction& dp) const;
  // [dK/dp u; 0] for each solution column: the right-hand side of SolveDerivative, nonzero
  // only at the DOFs of the members the direction moves.
  Eigen::MatrixXd StiffnessAction(const Eigen::MatrixXd& solutions, const Direction& dp) const;
  // The adjoint solutions KKT^-T l of the functionals l that read, from a solution, the force
  // change of each of `members` ([bars; strings] index, as ForceChanges) and then the
  // vertical displacement of each of `nodes` (as Vertical): (n_dof + n_b) x (members + nodes).
  // A functional's derivative along a direction is then -(its column)^T StiffnessAction, plus
  // for a string dk_s/dp times its stretch: one solve per functional instead of one per
  // direction and load column.
  Eigen::MatrixXd Adjoint(const std::vector<int>& members, const std::vector<int>& nodes) const;
  // The adjoint solutions KKT^-T l of any functionals, each a column over the solutions' rows.
  Eigen::MatrixXd AdjointOf(Eigen::MatrixXd functionals) const;
  // e^T (u_j - u_i) of every string [m] in each solution: n_s x columns.
  Eigen::MatrixXd StringStretches(const Eigen::MatrixXd& solutions) const;
  // d(force changes)/dp: (n_b + n_s) x columns, from the solutions and their derivative.
  Eigen::MatrixXd ForceChangeDerivative(const Eigen::MatrixXd& solutions,
                                        const Eigen::MatrixXd& d_solutions,
                                        const Direction& dp) const;

 private:
  // Adds g (u_j - u_i) at j and its negative at i, per column: a member block's action.
  void AddBlockAction(const Eigen::Matrix3d& g, int i, int j, const Eigen::MatrixXd& solutions,
                      Eigen::MatrixXd& out) const;

  const Structure& s_;
  int dim_ = 0, nb_ = 0, ns_ = 0, ndof_ = 0;
  std::vector<int> dof_;
  std::vector<Eigen::Vector3d> unit_;  // per member [bars; strings]
  std::vector<double> length_;         // per member [m]
  Eigen::VectorXd k_;                  // per string [N/m]
  double constraint_scale_ = 1;        // the bar rows' scale in the KKT matrix [N/m]
  KluFactor lu_;
  // Row k: e_k^T at string k's end j and -e_k^T at its end i, over the solution's rows, so
  // that the strings' stretches of many columns are one sparse product (strided copies of each
  // node's rows per string were a tenth of the verified design at n = 7).
  Eigen::SparseMatrix<double, Eigen::RowMajor> stretch_;
};

}  // namespace tbridge
