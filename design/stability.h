// Static stability of a prestressed bar-string structure about its equilibrium state.
//
// The tangent stiffness on the free degrees of freedom (dim() per free node, in node order:
// x, y for planar structures, x, y, z otherwise) is assembled member by member; each member
// from node i to node j with unit vector u and length l adds G to the (i, i) and (j, j)
// blocks and -G to the (i, j) and (j, i) blocks, with
//   string: G = q (I - u u^T) + k u u^T,   q = T / l,  k = E A / L0   (geometric + material)
//   bar:    G = -lambda I,                 lambda = C / l               (geometric only)
// Bars are rigid: the stiffness is restricted to the null space Z of the linearised bar
// length constraints u_b^T (d_j - d_i) = 0, K_r = Z^T K_T Z. That is the Hessian of the
// potential energy on the constraint manifold (the bar geometric term is the constraint
// curvature weighted by its multiplier). The structure is stable when K_r is positive
// definite.
//
// Two implementations:
// - AssessStability (the product's): sparse, roughly linear in the number of members. Z is
//   block diagonal, one dense block per cluster of bars joined at nodes (a single bar for
//   class 1), so K_r keeps the sparsity of K_T; an unpivoted sparse LDL^T of K_r counts its
//   negative pivots, which by Sylvester's law of inertia is its number of negative
//   eigenvalues.
// - CheckStability: dense eigenvalues of K_r, for structures up to a few hundred nodes; the
//   cross-check in the tests.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/structure.h"

namespace tbridge {

struct Design;

// The product's verdict (the design JSON's `stability` object).
struct StabilityVerdict {
  bool stable = false;  // K_r positive definite: no negative and no zero pivot
  int negative_pivots =
      0;                // pivots < -relative_tolerance * max diag(K_r): negative eigenvalues of K_r
  int zero_pivots = 0;  // |pivot| <= relative_tolerance * max diag(K_r): mechanisms (to rounding)
  int free_dofs = 0;    // dim() x free nodes
  int reduced_dofs = 0;  // columns of Z: motions that keep every bar length
  double min_pivot = 0;  // smallest pivot of the LDL^T [N/m]
  std::string method = "nullspace-ldlt";
  // Smallest factor c > 0 on every member force (the design load and the prestress together,
  // member areas and stiffnesses held) at which K_m + c K_g turns singular on the motions that
  // keep bar lengths; > 1 for a stable design whose material stiffness is positive definite.
  // Empty when not computed, or when no positive factor exists (the geometric stiffness never
  // softens the structure).
  std::optional<double> critical_load_factor;
  bool critical_load_factor_computed = false;
};

// `member_forces`: size n_b + n_s, [C_bars; T_strings] in N, compression and tension
// positive (the order of EquilibriumSystem and MemberForces(design)).
// `string_axial_stiffness`: size n_s, E A / L0 per string [N/m] (0 for a string of zero area).
// `relative_tolerance`: a pivot counts as zero when |pivot| is at most this times the largest
// diagonal entry of K_r; well above rounding (~1e-16 relative) and well below the smallest
// prestress stiffness of a sensible design (~1e-6 relative).
// `critical_load_factor`: also solve the dense generalised eigenproblem (K_m, -K_g) on the
// reduced motions for critical_load_factor; O(reduced_dofs^3), meant for n <= 6.
// Throws ModelError on size mismatches.
StabilityVerdict AssessStability(const Structure& structure, const Eigen::VectorXd& member_forces,
                                 const std::vector<double>& string_axial_stiffness,
                                 bool critical_load_factor, double relative_tolerance = 1e-10);

struct StabilityReport {
  int free_dofs = 0;          // dim() x free nodes
  int bar_constraints = 0;    // rank of the bar-length constraints on the free DOFs
  int reduced_dofs = 0;       // free_dofs - bar_constraints: size of K_r
  double min_eigenvalue = 0;  // smallest eigenvalue of K_r [N/m]
  double max_eigenvalue = 0;  // largest eigenvalue of K_r [N/m]
  int non_positive = 0;       // eigenvalues <= relative_tolerance * max |eigenvalue|
  bool positive_definite = false;
  Eigen::VectorXd eigenvalues;   // of K_r, ascending [N/m]
  Eigen::VectorXd softest_mode;  // free-DOF displacement of min_eigenvalue, unit norm
};

// Dense: eigenvalues of K_r with Z from a rank-revealing QR of all bar constraints at once.
// Arguments as for AssessStability; an eigenvalue counts as non-positive when it is at most
// relative_tolerance times the largest |eigenvalue|. Throws ModelError on size mismatches.
StabilityReport CheckStability(const Structure& structure, const Eigen::VectorXd& member_forces,
                               const std::vector<double>& string_axial_stiffness,
                               double relative_tolerance = 1e-10);

// Same, at a design's equilibrium: forces from MemberForces(design), stiffness from each
// string's sizing (E A / L0).
StabilityReport CheckStability(const Design& design, double relative_tolerance = 1e-10);

}  // namespace tbridge
