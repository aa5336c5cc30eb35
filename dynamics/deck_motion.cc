#include "dynamics/deck_motion.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"

namespace tbridge {

DeckMotionReport ProjectOnDeckMotions(const DynamicModel& model, const Eigen::Matrix3Xd& shape) {
  if (model.deck_nodes.empty()) throw ModelError("deck motions: the model has no deck nodes");
  if (shape.cols() != model.num_nodes())
    throw ModelError("deck motions: the shape's size differs from the model's");
  std::vector<int> deck = model.deck_nodes;
  const Eigen::Matrix3Xd& p = model.positions;
  std::sort(deck.begin(), deck.end(), [&p](int a, int b) { return p(0, a) < p(0, b); });
  const double extent = std::max(p.row(0).maxCoeff() - p.row(0).minCoeff(), 1.0);
  // Squares of the vertical, lateral, longitudinal and torsional section motions.
  std::array<double, 4> squares{0, 0, 0, 0};
  for (size_t first = 0; first < deck.size();) {
    size_t last = first + 1;  // the station: deck nodes at the same x (to 1e-9 of the span)
    while (last < deck.size() && p(0, deck[last]) - p(0, deck[first]) <= 1e-9 * extent) ++last;
    const double m = static_cast<double>(last - first);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    double z_mean = 0;
    for (size_t k = first; k < last; ++k) {
      mean += shape.col(deck[k]);
      z_mean += p(2, deck[k]);
    }
    mean /= m;
    z_mean /= m;
    squares[0] += m * mean.y() * mean.y();
    squares[1] += m * mean.z() * mean.z();
    squares[2] += m * mean.x() * mean.x();
    double lever2 = 0, moment = 0;
    for (size_t k = first; k < last; ++k) {
      const double arm = p(2, deck[k]) - z_mean;
      lever2 += arm * arm;
      moment += arm * shape(1, deck[k]);
    }
    if (lever2 > 0)
      squares[3] += moment * moment / lever2;  // theta^2 sum(arm^2), theta = moment / lever2
    first = last;
  }
  double deck_total = 0;
  for (const int a : deck) deck_total += shape.col(a).squaredNorm();
  DeckMotionReport r;
  const double whole = shape.squaredNorm();
  if (!(deck_total > kLocalDeckShare * whole)) return r;
  for (int k = 0; k < 4; ++k) r.share[k] = squares[k] / deck_total;
  if (r.share[0] + r.share[1] + r.share[2] + r.share[3] < kSectionShare) return r;
  const int best =
      static_cast<int>(std::max_element(r.share.begin(), r.share.end()) - r.share.begin());
  r.motion = static_cast<DeckMotion>(best);
  r.axis = r.motion == DeckMotion::kLateral ? 2 : r.motion == DeckMotion::kLongitudinal ? 0 : 1;
  for (const int a : deck) {
    const double u = std::abs(shape(r.axis, a));
    if (u > r.peak_displacement) r.peak_displacement = u, r.peak_node = a;
  }
  return r;
}

}  // namespace tbridge
