// Cable pieces of a planar or spatial substructure: straight cable runs split at the nodes
// that lie on them, with coinciding pieces merged (SPEC.md §2).
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace tbridge {

// Splits every straight cable run (u, v) (0-based node indices into `nodes`, 3 x n_n [m]) at
// each node lying strictly inside it, and merges pieces that join the same two nodes.
//
// A node lies on a run when its distance from the segment is at most `tolerance` [m] and it
// is not one of the run's ends. Returns the pieces as (min, max) node pairs in ascending
// lexicographic order, so that the result does not depend on the order of `runs`.
// Cost: O(sum over runs of the nodes whose x lies within the run's x range), which stays
// near O(n p n_n) for the dyadic bridges because wide runs are few.
// Throws ModelError if a run has an index out of range or joins a node to itself.
std::vector<std::pair<int, int>> SplitAndMergeCables(const Eigen::Matrix3Xd& nodes,
                                                     const std::vector<std::pair<int, int>>& runs,
                                                     double tolerance);

}  // namespace tbridge
