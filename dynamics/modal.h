// Linearised vibration modes about the static equilibrium of a DynamicModel, with the bar
// lengths held (the bars are rigid in the dynamics, paper eqs 20-27).
//
// Stiffness (tangent, on the free DOFs: `dim` per free node, pinned nodes removed):
//   taut string (s >= L0):  q (I - u u^T) + k u u^T  with q = T/s, T = k (s - L0), u = s/|s|
//   slack string:           nothing
//   bar:                   -lambda I (geometric term of the held length), lambda = C/l > 0 in
//                           compression, taken from the equilibrium of the model (see below)
// Each term enters as [K -K; -K K] at the member's two end nodes.
// Mass: eq. (21) per bar, m [1/3 1/6; 1/6 1/3] (x) I_dim at its two nodes, plus node_mass.
// The linearised constraints b . (dn_j - dn_i) = 0 are eliminated with an orthonormal basis Z
// of their null space, and (Z^T K Z) y = omega^2 (Z^T M Z) y is solved densely: memory
// O(n_dof^2) and time O(n_dof^3), fine up to a few thousand DOFs (planar n = 9, 2044 DOFs:
// about 7 s).
//
// Bar forces. The model's string tensions follow from its positions and rest lengths; the bar
// force densities are the least-squares solution of node equilibrium under those tensions and
// the model's loads (for class 1 this is eq. 23 at rest). The remaining force imbalance is
// reported. A designed bridge is in equilibrium (imbalance ~ solver tolerance), and so is a
// planar one with prestrained deck strings: a uniform deck-chain tension is its self-stress.
// Damping is ignored: the modes are those of the undamped system.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/model.h"

namespace tbridge {

struct ModalOptions {
  // Relative size of the constraint pivots below which a bar constraint counts as dependent.
  double rank_tolerance = 1e-10;
};

struct Mode {
  double omega_squared = 0;  // eigenvalue [rad^2/s^2]; negative for an unstable mode
  double omega_rad_s = 0;    // sqrt(omega^2); -sqrt(-omega^2) marks an unstable mode
  double frequency_hz = 0;   // omega / (2 pi)
  double period_s = 0;       // 2 pi / |omega|; 0 for a zero-frequency (mechanism) mode
  // Node displacements (3 x n_n, zero at pinned nodes and out of plane when dim = 2), scaled
  // so that shape^T M shape = 1 [m sqrt(kg)^-1], signed so that its largest component is
  // positive.
  Eigen::Matrix3Xd shape;
};

struct ModalResult {
  std::vector<Mode> modes;        // all modes, ascending omega^2
  int free_dofs = 0;              // dim x free nodes
  int constraints = 0;            // independent bar-length constraints removed
  Eigen::VectorXd bar_force_density;  // lambda per bar, > 0 in compression [N/m]
  Eigen::VectorXd string_tension;     // T = k (s - L0), 0 when slack [N]
  int slack_strings = 0;              // strings with s < L0 at the model's positions
  double equilibrium_residual = 0;    // max |force imbalance| over free DOFs after bars [N]
};

// Tangent stiffness and mass on the free DOFs (before the bar constraints are eliminated),
// exposed for checks. DOF order: free nodes in index order, dim components each.
struct LinearisedSystem {
  Eigen::MatrixXd stiffness;    // n_dof x n_dof [N/m]
  Eigen::MatrixXd mass;         // n_dof x n_dof [kg]
  Eigen::MatrixXd constraints;  // n_b x n_dof, row k = d(b_k . b_k / 2)/dx [m]
  std::vector<int> dof_node;    // node index of each DOF
  std::vector<int> dof_axis;    // coordinate (0 x, 1 y, 2 z) of each DOF
  Eigen::VectorXd bar_force_density;
  Eigen::VectorXd string_tension;
  int slack_strings = 0;
  double equilibrium_residual = 0;
};

// Assembles K, M and the constraint Jacobian at the model's positions. Throws ModelError for
// an inconsistent model (sizes, node indices, dim not 2 or 3, negative masses).
LinearisedSystem Linearise(const DynamicModel& model);

// All linearised modes. Throws ModelError when the model is inconsistent or when the reduced
// mass matrix is not positive definite (a free direction without mass, e.g. massless strings
// at a node without bars).
ModalResult ComputeModes(const DynamicModel& model, const ModalOptions& options = {});

// Largest step for which fixed-step RK4 is stable on the linearised system:
// dt < 2 sqrt(2) / omega_max (the RK4 stability region reaches 2 sqrt(2) on the imaginary
// axis) [s]. Throws ModelError when there are no modes.
double Rk4StableStep(const ModalResult& result);

enum class ModeSymmetry { kSymmetric, kAntisymmetric, kMixed };
const char* SymmetryName(ModeSymmetry symmetry);  // "symmetric" | "antisymmetric" | "mixed"

// Symmetry of a mode shape about the mid-span plane x = (x_min + x_max) / 2 of `positions`
// (3 x n_n). The mirror image of a displacement field moves node a to the node at the mirrored
// position and flips the x component. correlation = <shape, mirror> / <shape, shape> is +1 for
// a symmetric and -1 for an antisymmetric shape; |correlation| >= 1 - tolerance classifies.
// Degenerate mode pairs may come out mixed. Throws ModelError when a node has no mirror node
// within 1e-6 of the span.
struct SymmetryReport {
  ModeSymmetry symmetry = ModeSymmetry::kMixed;
  double correlation = 0;
};
SymmetryReport ClassifySymmetry(const Eigen::Matrix3Xd& positions, const Eigen::Matrix3Xd& shape,
                                double tolerance = 1e-3);

}  // namespace tbridge
