// Which nodes' positions and velocities each node's acceleration depends on: the sparsity of
// the Jacobian that the implicit integrator (dynamics/sdirk.h) estimates by finite differences.
#pragma once

#include <vector>

#include "dynamics/model.h"

namespace tbridge {

// depends_on[a]: the nodes (0-based, sorted, a included) whose state can change node a's
// acceleration. Bars tie the accelerations of every node of a bar-connected component
// together (the bar forces are solved jointly; in class 1 a component is one bar), and each
// node of the component feels the strings at it, so
//   depends_on[a] = C(a) + { string neighbours of every node of C(a) },
// C(a) = the bar-connected component of a. Pinned nodes keep the same rows (their
// acceleration is zero; the extra entries are harmless). Covers class 1 and class k.
struct AccelerationCoupling {
  int dim = 2;
  std::vector<std::vector<int>> depends_on;  // one list per node
  long entries() const;                      // sum of the list sizes
};

// Throws nothing; node indices of the model are assumed valid (the engines check them).
AccelerationCoupling CouplingOf(const DynamicModel& model);

// A greedy distance-2 colouring of the columns: nodes q and r share a colour only if no node
// depends on both, so one right-hand-side evaluation per colour and direction recovers all
// their columns. Returns a colour per node (0-based); the number of colours is max + 1.
std::vector<int> ColourColumns(const AccelerationCoupling& coupling);

}  // namespace tbridge
