// Which motion of the deck a mode shape is: the shape's deck-node displacements projected on
// the deck's rigid section motions. The deck nodes (DynamicModel::deck_nodes) are grouped into
// stations by their x (a planar bridge has one node per station, the 3D bridge one per plane);
// at each station the section's motions are
//   longitudinal  the mean x displacement,
//   vertical      the mean y displacement,
//   lateral       the mean z displacement,
//   torsional     the rotation about x, the least-squares slope of y against z across the
//                 station (stations of two or more nodes at different z only),
// and each motion's share is the sum of its squares over the stations (times the nodes, or the
// squared lever arms for torsion) over the sum of squares of every deck-node displacement. The
// four shares add up to at most 1; the rest deforms the sections. A mode is named after its
// largest share, or "local" when the deck hardly takes part (its deck displacements hold under
// kLocalDeckShare of the shape's squares: a string or bar mode) or mostly deforms its sections
// (the four shares add up to less than kSectionShare: the planes moving against each other).
#pragma once

#include <Eigen/Core>
#include <array>

#include "core/deck_motion_kind.h"
#include "dynamics/model.h"

namespace tbridge {

inline constexpr double kLocalDeckShare = 1e-3;
inline constexpr double kSectionShare = 0.5;

struct DeckMotionReport {
  DeckMotion motion = DeckMotion::kLocal;
  // Share of each motion, in the order vertical, lateral, longitudinal, torsional.
  std::array<double, 4> share{0, 0, 0, 0};
  // The coordinate a crowd loads this motion along, and its acceleration is measured on:
  // 1 (y) for vertical and torsional, 2 (z) lateral, 0 (x) longitudinal.
  int axis = 1;
  int peak_node = -1;  // the deck node (0-based) of the largest |displacement| along `axis`
  double peak_displacement = 0;  // that |displacement|, in the shape's unit
};

// Projects `shape` (3 x n_n node displacements) on the deck motions of `model`'s deck nodes.
// O(deck nodes log deck nodes). Throws ModelError when the model has no deck nodes or the
// shape's size differs from the model's.
DeckMotionReport ProjectOnDeckMotions(const DynamicModel& model, const Eigen::Matrix3Xd& shape);

}  // namespace tbridge
