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
// K, M and the constraint Jacobian are assembled as sparse matrices from triplets, O(members).
//
// The linearised constraints b . (dn_j - dn_i) = 0 are eliminated with an orthonormal basis Z
// of their null space, and (Z^T K Z) y = omega^2 (Z^T M Z) y is solved by one of two solvers:
// - dense: Z from a QR of the whole constraint Jacobian, every mode by a dense generalised
//   eigen-decomposition; memory O(n_dof^2), time O(n_dof^3) (planar n = 8, 1020 DOFs: about
//   1 s; n = 9, 2044 DOFs: about 7 s). Kept for small models and as the tests' cross-check.
// - sparse: Z block by block, one block per group of bars joined at free nodes (a single bar
//   for class 1), so Z, Z^T K Z and Z^T M Z stay sparse; the lowest modes by Spectra's
//   shift-invert Lanczos (SymGEigsShiftSolver, one sparse LU of Z^T (K - sigma M) Z) and the
//   highest by its Cholesky-mode Lanczos (one sparse Cholesky of Z^T M Z). Memory O(n_dof)
//   when the bar groups stay small, time a little above linear (the restarts grow slowly with
//   n): the lowest six modes of planar n = 10 / 11 / 12 in about 35 / 85 / 230 ms and 5 / 10 /
//   18 MB (bench/bench_modal.cc).
//   Why a null-space basis rather than the saddle-point operator [K - sigma M, C^T; C, 0]:
//   the reduced pencil is symmetric with a positive definite mass, so Spectra's stock
//   operators apply unchanged (including the Cholesky mode for the highest mode, which the
//   saddle point would need a projected operator for), the factorised system is n_dof - n_b
//   instead of n_dof + n_b, and the basis is orthonormal as in the dense path, so both paths
//   normalise shapes alike. Measured at planar n = 12 (16380 DOFs, 4095 bars; Eigen's
//   SparseLU, COLAMD): the reduced LU (12285 rows) takes 35-45 ms, fills 0.29 M entries and
//   solves 100 times in 45-50 ms; the saddle point's (20475 rows) 75-145 ms, 0.51 M entries
//   and 80-130 ms. The basis per bar group is a small dense QR; bridges have groups of one bar
//   (class 1), p bars (planar p) or two (the 3D bridge), where it costs O(members). A
//   structure whose bars all hang together would make it one dense QR, O(n_dof^3).
//
// Bar forces. The model's string tensions follow from its positions and rest lengths; the bar
// force densities are the minimum-norm least-squares solution of node equilibrium under those
// tensions and the model's loads (for class 1 this is eq. 23 at rest). Bar groups touch
// disjoint DOFs, so the least-squares problem splits into one small rank-revealing solve per
// group (a closed form per bar for class 1). The remaining force imbalance is reported. A
// designed bridge is in equilibrium (imbalance ~ solver tolerance), and so is a planar one with
// prestrained deck strings: a uniform deck-chain tension is its self-stress.
// Damping is ignored: the modes are those of the undamped system.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "dynamics/model.h"

namespace tbridge {

enum class ModalSolver {
  kAuto,    // dense for every mode (count = 0) or at most dense_max_dofs free DOFs, else sparse
  kDense,   // every mode, densely; the lowest `count` of them are kept when count > 0
  kSparse,  // the lowest `count` modes (count > 0) by sparse shift-invert Lanczos
};

struct ModalOptions {
  // Relative size of the constraint pivots below which a bar constraint counts as dependent.
  double rank_tolerance = 1e-10;
  // Lowest modes wanted; 0 = every mode. A count of at least (number of modes - 1) is served
  // densely whatever `solver` says (the Lanczos basis must be larger than the count).
  int count = 0;
  ModalSolver solver = ModalSolver::kAuto;
  int dense_max_dofs = 300;  // kAuto: dense at or below this many free DOFs
  // Sparse solver: relative tolerance of the Lanczos Ritz residuals (Spectra's criterion) of
  // the lowest modes, and whether to find the highest mode as well (needed by Rk4StableStep).
  double tolerance = 1e-10;
  bool highest = true;
  // Ritz residual tolerance of the highest mode. The top of a large bridge's spectrum is a
  // cluster of nearly equal string-bar modes that Lanczos separates only slowly (planar
  // n = 12: no convergence to 1e-10 in 1000 restarts, 24 restarts to 1e-6). The eigenvalue
  // error is at most the residual and in practice its square (1e-9 of omega at n = 12), far
  // below what a step-size limit needs.
  double highest_tolerance = 1e-6;
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
  std::vector<Mode> modes;  // ascending omega^2: every mode, or the lowest options.count
  bool all_modes = true;    // modes holds every mode of the constrained system
  int total_modes = 0;      // free_dofs - constraints
  // The highest mode's omega [rad/s] (modes.back() when all_modes); 0 when the sparse solver
  // was not asked for it (ModalOptions::highest = false) or there are no modes.
  double highest_omega_rad_s = 0;
  std::string solver;   // "dense" | "sparse" ("" when there is no mode)
  int iterations = 0;   // Lanczos restarts of the sparse solver (lowest modes); 0 dense
  int free_dofs = 0;    // dim x free nodes
  int constraints = 0;  // independent bar-length constraints removed
  Eigen::VectorXd bar_force_density;  // lambda per bar, > 0 in compression [N/m]
  Eigen::VectorXd string_tension;     // T = k (s - L0), 0 when slack [N]
  int slack_strings = 0;              // strings with s < L0 at the model's positions
  double equilibrium_residual = 0;    // max |force imbalance| over free DOFs after bars [N]
};

// Tangent stiffness and mass on the free DOFs (before the bar constraints are eliminated),
// exposed for checks. DOF order: free nodes in index order, dim components each. The
// matrices are sparse (column-major, both triangles stored).
struct LinearisedSystem {
  Eigen::SparseMatrix<double> stiffness;    // n_dof x n_dof [N/m]
  Eigen::SparseMatrix<double> mass;         // n_dof x n_dof [kg]
  Eigen::SparseMatrix<double> constraints;  // n_b x n_dof, row k = d(b_k . b_k / 2)/dx [m]
  std::vector<int> dof_node;                // node index of each DOF
  std::vector<int> dof_axis;                // coordinate (0 x, 1 y, 2 z) of each DOF
  Eigen::VectorXd bar_force_density;
  Eigen::VectorXd string_tension;
  int slack_strings = 0;
  double equilibrium_residual = 0;
};

// Assembles K, M and the constraint Jacobian at the model's positions. Throws ModelError for
// an inconsistent model (sizes, node indices, dim not 2 or 3, negative masses).
LinearisedSystem Linearise(const DynamicModel& model);

// The linearised modes: all of them (options.count = 0) or the lowest options.count, by the
// solver options.solver picks. The sparse solver finds the modes nearest a small negative
// shift, which are the lowest when the structure is stable; of an unstable structure it finds
// the unstable modes nearest zero first. Throws ModelError when the model is inconsistent,
// when the reduced mass matrix is not positive definite (a free direction without mass, e.g.
// massless strings at a node without bars), when the shifted stiffness is singular (sparse)
// or when an eigensolver does not converge.
ModalResult ComputeModes(const DynamicModel& model, const ModalOptions& options = {});

// Largest step for which fixed-step RK4 is stable on the linearised system:
// dt < 2 sqrt(2) / omega_max (the RK4 stability region reaches 2 sqrt(2) on the imaginary
// axis) [s], omega_max = result.highest_omega_rad_s. Throws ModelError when there are no modes
// or the highest was not computed.
double Rk4StableStep(const ModalResult& result);

enum class ModeSymmetry { kSymmetric, kAntisymmetric, kMixed };
const char* SymmetryName(ModeSymmetry symmetry);  // "symmetric" | "antisymmetric" | "mixed"

// The mirror node of every node about the mid-span plane x = (x_min + x_max) / 2 of
// `positions` (3 x n_n): entry a is the node within 1e-6 of the span of a's mirrored position
// in every coordinate (the lowest index if several). O(n_n log n_n) by sorting on x (plus the
// nodes that share one x within that tolerance). Throws ModelError when a node has none.
std::vector<int> MirrorNodes(const Eigen::Matrix3Xd& positions);

// Symmetry of a mode shape about mid-span. The mirror image of a displacement field moves node
// a to node mirror[a] and flips the x component. correlation = <shape, mirror> / <shape, shape>
// is +1 for a symmetric and -1 for an antisymmetric shape; |correlation| >= 1 - tolerance
// classifies. Degenerate mode pairs may come out mixed. O(n_n) given the mirror map, which is
// found once for all modes. Throws ModelError when the sizes of mirror and shape differ.
struct SymmetryReport {
  ModeSymmetry symmetry = ModeSymmetry::kMixed;
  double correlation = 0;
};
SymmetryReport ClassifySymmetry(const std::vector<int>& mirror, const Eigen::Matrix3Xd& shape,
                                double tolerance = 1e-3);
// The same for one shape, finding the mirror map of `positions` first (MirrorNodes, which
// throws when a node has no mirror node).
SymmetryReport ClassifySymmetry(const Eigen::Matrix3Xd& positions, const Eigen::Matrix3Xd& shape,
                                double tolerance = 1e-3);

}  // namespace tbridge
