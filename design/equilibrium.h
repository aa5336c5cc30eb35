// Node equilibrium of a pin-jointed bar-string network (SPEC.md §4: full equilibrium at every
// free node, 2 equations per node for planar structures, 3 otherwise).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/structure.h"

namespace tbridge {

// Maps member forces to net node forces on the free degrees of freedom.
//
// Unknowns x (size n_b + n_s): bar compressions first (bar order), then string tensions
// (string order); both positive in their working sense. Rows: for each free node in node
// order, its dim() coordinates. Equilibrium is A x + w_free = 0.
struct EquilibriumSystem {
  Eigen::SparseMatrix<double> A;  // (dim * n_free) x (n_b + n_s)
  std::vector<int> row_node;      // node of each row
  std::vector<int> row_axis;      // axis (0 = x, 1 = y, 2 = z) of each row
  std::vector<int> node_row;      // first row of each node, -1 for fixed nodes
};

EquilibriumSystem BuildEquilibrium(const Structure& structure);

// Free-DOF load vector from a 3 x n_n node load matrix [N].
Eigen::VectorXd FreeLoads(const EquilibriumSystem& eq, const Eigen::Matrix3Xd& loads);

// Residual A x + w on the free DOFs, for given member forces [N].
Eigen::VectorXd EquilibriumResidual(const EquilibriumSystem& eq, const Eigen::VectorXd& forces,
                                    const Eigen::Matrix3Xd& loads);

// Support reactions (3 x n_n, zero at free nodes): minus the member forces acting on each
// fixed node, so that reactions + applied loads balance the whole structure.
Eigen::Matrix3Xd SupportReactions(const Structure& structure, const Eigen::VectorXd& forces,
                                  const Eigen::Matrix3Xd& loads);

// Number of independent self-stress states: n_b + n_s - rank(A). Dense rank; for small
// structures and tests.
int CountSelfStresses(const EquilibriumSystem& eq);

}  // namespace tbridge
