// The pieces of a tensegrity's linearisation about a state that the modal analysis
// (dynamics/modal.h) and the stability check (design/stability.h) both assemble: the free
// degrees of freedom, a member's 3x3 block placed at its two ends, and a bar's constraint row.
// What goes into the blocks (tangent, geometric, material) stays with each caller.
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
