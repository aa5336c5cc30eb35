// The bridge's two abutments: its support nodes at each end of the span (one per end on a
// planar bridge, one per plane on the 3D bridge), and what one abutment takes of the support
// reactions. The static check's findings (checks/static_check.h), the sizing's support rows
// (sizing/sizing_problem.h) and the thrust warning (design/plausibility.h) read them here.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/structure.h"

namespace tbridge {

struct Abutment {
  std::vector<int> nodes;  // 0-based support nodes at this end of the span
  double x_m = 0;          // where the end is [m]
};

// The supports at x < span / 2 (the first) and beyond (the second).
std::array<Abutment, 2> AbutmentsOf(const Structure& structure, double span);

// One abutment's share of the support reactions (3 x n_n [N]): the sums over its nodes. The
// horizontal reaction is the in-plan vector (x along the span, z across it); y is vertical.
struct AbutmentReaction {
  double x = 0, y = 0, z = 0;  // [N]
  double Horizontal() const;   // |(x, z)| [N]
  double Vertical() const;     // |y| [N]: bearing or uplift
};
AbutmentReaction ReactionOf(const Abutment& abutment, const Eigen::Matrix3Xd& reactions);

// "the abutment at x = 0 m (node 15)", "(nodes 1 and 9)".
std::string AbutmentName(const Abutment& abutment);

}  // namespace tbridge
