// Static stability of a prestressed bar-string structure about its equilibrium state.
//
// The tangent stiffness on the free degrees of freedom (dim() per free node, in node order:
// x, y for planar structures, x, y, z otherwise) is assembled member by member; each member
// from node i to node j with unit vector u and length l adds G to the (i, i) and (j, j)
// blocks and -G to the (i, j) and (j, i) blocks, with
//   string: G = q (I - u u^T) + k u u^T,   q = T / l,  k = E A / L0   (material + geometric)
//   bar:    G = -lambda I,                 lambda = C / l               (geometric only)
// Bars are rigid: the stiffness is projected onto the null space N of the linearised bar
// length constraints u_b^T (d_j - d_i) = 0, K_r = N^T K_T N. That is the Hessian of the
// potential energy on the constraint manifold (the bar geometric term is the constraint
// curvature weighted by its multiplier). The structure is stable when K_r is positive
// definite. Dense: for structures up to a few hundred nodes.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/structure.h"
#include "design/design.h"

namespace tbridge {

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

// `member_forces`: size n_b + n_s, [C_bars; T_strings] in N, compression and tension
// positive (the order of EquilibriumSystem and MemberForces(design)).
// `string_axial_stiffness`: size n_s, E A / L0 per string [N/m] (0 for a string of zero area).
// `relative_tolerance`: an eigenvalue counts as non-positive when it is at most this times
// the largest |eigenvalue|; the default sits well above rounding (~1e-16 relative) and well
// below the smallest prestress stiffness of a sensible design (~1e-6 relative).
// Throws ModelError on size mismatches.
StabilityReport CheckStability(const Structure& structure, const Eigen::VectorXd& member_forces,
                               const std::vector<double>& string_axial_stiffness,
                               double relative_tolerance = 1e-10);

// Same, at a design's equilibrium: forces from MemberForces(design), stiffness from each
// string's sizing (E A / L0).
StabilityReport CheckStability(const Design& design, double relative_tolerance = 1e-10);

}  // namespace tbridge
