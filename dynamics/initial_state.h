// The state a run starts from (SPEC.md §9): the model at rest, the paper's perturbation of a
// bar length class, then the config's per-node displacements and velocities, checked against
// the model with errors naming the config key.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/dynamics_config.h"
#include "dynamics/model.h"

namespace tbridge {

// Bars grouped by length, longest first (the paper's Table 5 numbering: class 1 is the
// longest, central bar). Lengths equal within 1e-9 relative share a class. Entries are
// 0-based bar indices.
std::vector<std::vector<int>> BarLengthClasses(const DynamicModel& model);

// Initial state (2 x dim x n_n, see dynamics/class1.h): the model's positions, then the
// perturbation (both end nodes of every bar of the class move down, -y, by delta), then the
// per-node displacements and velocities. Throws ConfigError naming the key for a class or
// node out of range, a pinned node, a z component in a planar model, or an initial condition
// that changes a bar's length (> 1e-9 relative) or its length rate.
Eigen::VectorXd InitialState(const DynamicModel& model, const DynamicsConfig& config);

}  // namespace tbridge
