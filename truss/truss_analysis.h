// The linear analysis of a pin-jointed structure (truss/truss_model.h) at given group areas: each
// load case's displacements and member forces, the lowest natural frequencies, and their
// derivatives in the group areas, which the sizing's rows need.
//
// Stiffness: each member E A / L along its direction and, where it is prestressed by N0, the
// geometric stiffness of that force across it: K = sum k_e d d^T + (N0_e / L_e) (I - d d^T) in
// its end blocks (the tangent of the prestressed state; the displacements are small against it).
// A member's force is N0 + k_e d . (u_j - u_i).
// Mass: each member's consistent mass, (rho A L / 6) [[2 I, I], [I, 2 I]] on its ends'
// translations (the rod's exact shape functions, as MSC Nastran's coupled mass and the published
// frequency-constrained 10-bar problem take it), plus the node masses. Derivatives: direct
// differentiation of K u = f (f holds the self-weight, itself linear in the areas), one solve per
// variable (each group's area, then each self-stress state's amplitude, which moves N0 and the
// geometric stiffness) with the case's factor; the eigenvalues' by d(lambda) = phi^T (dK - lambda
// dM) phi with phi^T M phi = 1, exact for a simple eigenvalue (a repeated one has no derivative:
// the sizing then reads a one-sided one).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "truss/truss_model.h"

namespace tbridge {

struct TrussCaseResponse {
  Eigen::VectorXd u;       // free degrees of freedom [m]
  Eigen::VectorXd forces;  // per member [N], tension > 0
  // Derivatives in the sizing's variables (TrussModel::num_variables: the group areas, then the
  // self-stress amplitudes), when asked:
  Eigen::MatrixXd du;       // num_free x variables: du / dA_g [m/m^2], du / ds [m/N]
  Eigen::MatrixXd dforces;  // members x variables: dN / dA_g [N/m^2], dN / ds [-]
};

struct TrussModes {
  Eigen::VectorXd eigenvalues;   // omega^2 [rad^2/s^2], lowest first
  Eigen::MatrixXd shapes;        // num_free x count, M-orthonormal
  Eigen::MatrixXd deigenvalues;  // count x variables: d(omega^2) / d(variable) (when asked)
};

using TrussFactor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;

// A member's tangent block along unit direction d at length l with axial stiffness k and force
// n: k d d^T + (n / l)(I - d d^T); +block in its end blocks (i, i) and (j, j), -block across.
Eigen::Matrix3d MemberBlock(const Eigen::Vector3d& d, double l, double k, double n);
// The stiffness matrix on the free degrees of freedom from each member's block.
Eigen::SparseMatrix<double> AssembleStiffness(const TrussModel& model,
                                              const std::vector<Eigen::Matrix3d>& blocks);
// Its LDL^T factor. Throws ModelError naming the mechanism where it is singular or not positive
// definite.
std::unique_ptr<TrussFactor> FactoriseStiffness(const TrussModel& model,
                                                const Eigen::SparseMatrix<double>& stiffness);
// u_j - u_i of member e, zero along a support's axes.
Eigen::Vector3d RelativeDisplacement(const TrussModel& model, int e, const Eigen::VectorXd& u);
// Adds to row e of `dforces` (members x variables) member e's force derivatives at fixed
// displacements: E (l - L) / L for its group's area (`stretch` = l - L), and its share of each
// self-stress state for that state's amplitude.
void AddForcePartials(const TrussModel& model, int e, double stretch, Eigen::MatrixXd& dforces);
// Adds `pull` to member e's node i and -pull to its node j, on their free degrees of freedom.
void ScatterPull(const TrussModel& model, int e, const Eigen::Vector3d& pull, Eigen::VectorXd& out);

// The most free degrees of freedom the modal analysis takes (a dense generalised eigenproblem,
// O(n^3): 4000 take about a minute here).
inline constexpr int kTrussMaxModalDofs = 4000;

class TrussAnalysis {
 public:
  // Assembles and factorises K at each member's area (`member_areas`: its group's in a sizing,
  // its own in the check of an edited design) and prestress force (`prestress` [N], one per
  // member, a self-stress; empty: none). Throws ModelError naming the structure's mechanism
  // where K is singular or not positive definite (a node held by no member in some direction, or
  // an infinitesimal mechanism that no prestress stiffens).
  TrussAnalysis(const TrussModel& model, const Eigen::VectorXd& member_areas,
                const Eigen::VectorXd& prestress = Eigen::VectorXd());

  // Case `c`'s response; with `sensitivities`, its derivatives in the group areas.
  TrussCaseResponse Solve(int c, bool sensitivities) const;
  // The `count` lowest modes; with `sensitivities`, the eigenvalues' derivatives. Throws
  // ModelError beyond kTrussMaxModalDofs free degrees of freedom.
  TrussModes Modes(int count, bool sensitivities) const;
  // Per variable v, phi_a^T (dK/dv - omega_a^2 dM/dv) phi_b: for a == b the eigenvalue's
  // derivative, for a pair of modes that meet the off-diagonal entry of the derivative of the
  // pair's 2 x 2 eigenvalue problem (a repeated eigenvalue's directional derivatives are the
  // eigenvalues of that matrix).
  Eigen::VectorXd ModeCoupling(const TrussModes& modes, int a, int b) const;
  // Member e's axial force at the displacements u: N0 + (E A / L) d . (u_j - u_i).
  double Force(int e, const Eigen::VectorXd& u) const;
  // The force member e exerts on its node i at the displacements u (on node j the opposite):
  // its axial force along d and its prestress turned with it, N d + (N0 / L) (I - d d^T) w,
  // w = u_j - u_i; what K u balances, so the reactions balance the loads to round-off.
  Eigen::Vector3d Pull(int e, const Eigen::VectorXd& u) const;

 private:
  // The elongation of member e under u, d . (u_j - u_i) [m].
  double Elongation(int e, const Eigen::VectorXd& u) const;
  // Adds `same` into member e's blocks (i, i) and (j, j) of `out` (free dofs, dense) and
  // `across` into (i, j) and (j, i).
  void AddEnds(int e, const Eigen::Matrix3d& same, const Eigen::Matrix3d& across,
               Eigen::MatrixXd& out) const;
  // Member e's stiffness block at area `area` and prestress force `n0` [N].
  Eigen::Matrix3d Block(int e, double area, double n0) const;
  // (dK/dv) u for variable v: a group's area, or a self-stress amplitude (its geometric
  // stiffness).
  Eigen::VectorXd StiffnessTimes(int v, const Eigen::VectorXd& u) const;
  // dK / dv and dM / dv, dense.
  Eigen::MatrixXd StiffnessPerVariable(int v) const;
  Eigen::MatrixXd MassPerVariable(int v) const;
  Eigen::MatrixXd Mass() const;

  const TrussModel& model_;
  Eigen::VectorXd areas_;      // per member
  Eigen::VectorXd prestress_;  // per member [N]
  Eigen::SparseMatrix<double> stiffness_;
  std::unique_ptr<TrussFactor> factor_;
};

}  // namespace tbridge
