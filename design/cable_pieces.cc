#include "design/cable_pieces.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <string>

#include "core/error.h"

namespace tbridge {

std::vector<std::pair<int, int>> SplitAndMergeCables(const Eigen::Matrix3Xd& nodes,
                                                     const std::vector<std::pair<int, int>>& runs,
                                                     double tolerance) {
  const int nn = static_cast<int>(nodes.cols());
  // Nodes sorted by x so each run only visits the nodes inside its x range.
  std::vector<int> by_x(nn);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return nodes(0, a) < nodes(0, b); });
  std::vector<double> xs(nn);
  for (int r = 0; r < nn; ++r) xs[r] = nodes(0, by_x[r]);

  std::set<std::pair<int, int>> pieces;  // a set merges pieces that several runs share
  std::vector<std::pair<double, int>> inner;
  for (const auto& [u, v] : runs) {
    if (u < 0 || v < 0 || u >= nn || v >= nn || u == v) {
      throw ModelError("cable run " + std::to_string(u + 1) + "-" + std::to_string(v + 1) +
                       " is not a pair of distinct nodes of the structure");
    }
    const Eigen::Vector3d p = nodes.col(u);
    const Eigen::Vector3d d = nodes.col(v) - p;
    const double len2 = d.squaredNorm();
    const double x_lo = std::min(p.x(), p.x() + d.x()) - tolerance;
    const double x_hi = std::max(p.x(), p.x() + d.x()) + tolerance;
    inner.clear();
    for (auto it = std::lower_bound(xs.begin(), xs.end(), x_lo); it != xs.end() && *it <= x_hi;
         ++it) {
      const int w = by_x[it - xs.begin()];
      if (w == u || w == v) continue;
      const double s = (nodes.col(w) - p).dot(d) / len2;
      if (s <= 0.0 || s >= 1.0) continue;
      if ((nodes.col(w) - p - s * d).norm() <= tolerance) inner.emplace_back(s, w);
    }
    std::sort(inner.begin(), inner.end());
    int prev = u;
    for (const auto& [s, w] : inner) {
      pieces.insert(std::minmax(prev, w));
      prev = w;
    }
    pieces.insert(std::minmax(prev, v));
  }
  return {pieces.begin(), pieces.end()};
}

}  // namespace tbridge
