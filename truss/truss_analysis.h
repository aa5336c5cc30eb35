// The linear analysis of a pin-jointed structure (truss/truss_model.h) at given group areas: each
// load case's displacements and member forces, the lowest natural frequencies, and their
// derivatives in the group areas, which the sizing's rows need.
//
// Stiffness: each member E A / L along its direction, K = sum k_e (d d^T) in its end blocks.
// Mass: each member's consistent mass, (rho A L / 6) [[2 I, I], [I, 2 I]] on its ends'
// translations (the rod's exact shape functions, as MSC Nastran's coupled mass and the published
// frequency-constrained 10-bar problem take it), plus the node masses. Derivatives: direct
// differentiation of K u = f (f holds the self-weight, itself linear in the areas), one solve per
// group with the case's factor; the eigenvalues' by d(lambda) = phi^T (dK - lambda dM) phi with
// phi^T M phi = 1, exact for a simple eigenvalue (a repeated one has no derivative: the sizing
// then reads a one-sided one).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <memory>

#include "truss/truss_model.h"

namespace tbridge {

struct TrussCaseResponse {
  Eigen::VectorXd u;        // free degrees of freedom [m]
  Eigen::VectorXd forces;   // per member [N], tension > 0
  Eigen::MatrixXd du;       // num_free x groups: du / dA_g [m/m^2] (when asked)
  Eigen::MatrixXd dforces;  // members x groups: dN / dA_g [N/m^2] (when asked)
};

struct TrussModes {
  Eigen::VectorXd eigenvalues;   // omega^2 [rad^2/s^2], lowest first
  Eigen::MatrixXd shapes;        // num_free x count, M-orthonormal
  Eigen::MatrixXd deigenvalues;  // count x groups: d(omega^2) / dA_g (when asked)
};

// The most free degrees of freedom the modal analysis takes (a dense generalised eigenproblem,
// O(n^3): 4000 take about a minute here).
inline constexpr int kTrussMaxModalDofs = 4000;

class TrussAnalysis {
 public:
  // Assembles and factorises K at each member's area (`member_areas`: its group's in a sizing,
  // its own in the check of an edited design). Throws ModelError naming the structure's
  // mechanism where K is singular (a node held by no member in some direction).
  TrussAnalysis(const TrussModel& model, const Eigen::VectorXd& member_areas);

  // Case `c`'s response; with `sensitivities`, its derivatives in the group areas.
  TrussCaseResponse Solve(int c, bool sensitivities) const;
  // The `count` lowest modes; with `sensitivities`, the eigenvalues' derivatives. Throws
  // ModelError beyond kTrussMaxModalDofs free degrees of freedom.
  TrussModes Modes(int count, bool sensitivities) const;
  // Per group g, phi_a^T (dK/dA_g - omega_a^2 dM/dA_g) phi_b: for a == b the eigenvalue's
  // derivative, for a pair of modes that meet the off-diagonal entry of the derivative of the
  // pair's 2 x 2 eigenvalue problem (a repeated eigenvalue's directional derivatives are the
  // eigenvalues of that matrix).
  Eigen::VectorXd ModeCoupling(const TrussModes& modes, int a, int b) const;
  // Member e's axial force from the displacements u: (E A / L) d . (u_j - u_i).
  double Force(int e, const Eigen::VectorXd& u) const;

 private:
  // The elongation of member e under u, d . (u_j - u_i) [m].
  double Elongation(int e, const Eigen::VectorXd& u) const;
  // Adds `same` into member e's blocks (i, i) and (j, j) of `out` (free dofs, dense) and
  // `across` into (i, j) and (j, i).
  void AddEnds(int e, const Eigen::Matrix3d& same, const Eigen::Matrix3d& across,
               Eigen::MatrixXd& out) const;
  // dK / dA_g and dM / dA_g, dense.
  Eigen::MatrixXd StiffnessPerArea(int g) const;
  Eigen::MatrixXd MassPerArea(int g) const;
  Eigen::MatrixXd Mass() const;

  const TrussModel& model_;
  Eigen::VectorXd areas_;  // per member
  Eigen::SparseMatrix<double> stiffness_;
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> factor_;
};

}  // namespace tbridge
