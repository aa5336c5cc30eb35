// The pieces of a tensegrity's linearisation about a state that the static solve
// (statics/static_solve.h), the modal analysis (dynamics/modal.h), the stability check
// (design/stability.h), the linear response (design/linear_response.h) and the truss analysis
// assemble: the free degrees of freedom, a string's tangent block, a member's 3x3 block placed at
// its two ends, and a bar's constraint row.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace tbridge {

using TangentTriplets = std::vector<Eigen::Triplet<double>>;

// The first DOF of each node (dim per free node, in node order), -1 for a pinned node; their
// count into `n_dof`.
inline std::vector<int> FreeDofs(const std::vector<bool>& fixed, int dim, int& n_dof) {
  std::vector<int> first(fixed.size(), -1);
  n_dof = 0;
  for (std::size_t a = 0; a < fixed.size(); ++a) {
    if (fixed[a]) continue;
    first[a] = n_dof;
    n_dof += dim;
  }
  return first;
}

// u u^T, `u` a unit vector: the projector onto u, evaluated (so that k u u^T rounds as
// k (u_a u_b) wherever it is formed).
inline Eigen::Matrix3d AlongProjector(const Eigen::Vector3d& u) { return u * u.transpose(); }

// I - u u^T on the top-left dim x dim (zero elsewhere), `u` a unit vector: the projector normal
// to u, which turns a member's force into the stiffness of its direction's turning.
inline Eigen::Matrix3d NormalProjector(const Eigen::Vector3d& u, int dim = 3) {
  Eigen::Matrix3d p = Eigen::Matrix3d::Zero();
  p.topLeftCorner(dim, dim).setIdentity();
  return p - AlongProjector(u);
}

// A string's material stiffness k u u^T [N/m]: `k` its axial stiffness E A / L0, `u` its unit
// vector.
inline Eigen::Matrix3d StringMaterialBlock(const Eigen::Vector3d& u, double k) {
  return k * AlongProjector(u);
}

// A string's geometric stiffness q (I - u u^T) [N/m], `q` its force density t / L [N/m]; with a
// bar's (-q I) it is what prestress adds to the tangent.
inline Eigen::Matrix3d StringGeometricBlock(const Eigen::Vector3d& u, double q, int dim = 3) {
  return q * NormalProjector(u, dim);
}

// The tangent stiffness d(t u)/d(x_j - x_i) of a taut string [N/m]: k u u^T + q (I - u u^T),
// with `k` its axial stiffness and `q` its force density t / L. It is linear in (k, q), so the
// same block at (dk, dq) is its derivative along a change of stiffness and force.
inline Eigen::Matrix3d StringTangentBlock(const Eigen::Vector3d& u, double k, double q,
                                          int dim = 3) {
  return StringMaterialBlock(u, k) + StringGeometricBlock(u, q, dim);
}

// Adds the member block `g` as [g -g; -g g] on the free DOFs of its end nodes i and j (the
// top-left dim x dim of g; zero entries are left out of the pattern).
inline void AddPairBlock(const Eigen::Matrix3d& g, int i, int j, const std::vector<int>& first_dof,
                         int dim, TangentTriplets& out) {
  const int ends[2] = {i, j};
  for (int a = 0; a < 2; ++a) {
    for (int c = 0; c < 2; ++c) {
      const int ra = first_dof[ends[a]], rc = first_dof[ends[c]];
      if (ra < 0 || rc < 0) continue;
      const double sign = a == c ? 1.0 : -1.0;
      for (int r = 0; r < dim; ++r) {
        for (int q = 0; q < dim; ++q) {
          if (g(r, q) != 0) out.emplace_back(ra + r, rc + q, sign * g(r, q));
        }
      }
    }
  }
}

// Row `row` of the bar-length constraints: -d on node i's free DOFs, +d on node j's, with d
// the bar's direction (b = n_j - n_i, or its unit vector).
inline void AddBarRow(int row, int i, int j, const Eigen::Vector3d& d,
                      const std::vector<int>& first_dof, int dim, TangentTriplets& out) {
  for (int r = 0; r < dim; ++r) {
    if (first_dof[i] >= 0) out.emplace_back(row, first_dof[i] + r, -d[r]);
    if (first_dof[j] >= 0) out.emplace_back(row, first_dof[j] + r, d[r]);
  }
}

}  // namespace tbridge
