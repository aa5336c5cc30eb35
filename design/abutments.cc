#include "design/abutments.h"

#include <cmath>
#include <cstdio>

namespace tbridge {

std::array<Abutment, 2> AbutmentsOf(const Structure& s, double span) {
  std::array<Abutment, 2> ends;
  ends[1].x_m = span;
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (s.fixed[v]) ends[s.nodes(0, v) < span / 2 ? 0 : 1].nodes.push_back(v);
  }
  return ends;
}

double AbutmentReaction::Horizontal() const { return std::hypot(x, z); }
double AbutmentReaction::Vertical() const { return std::abs(y); }

AbutmentReaction ReactionOf(const Abutment& a, const Eigen::Matrix3Xd& reactions) {
  AbutmentReaction r;
  for (const int v : a.nodes) {
    r.x += reactions(0, v);
    r.y += reactions(1, v);
    r.z += reactions(2, v);
  }
  return r;
}

std::string AbutmentName(const Abutment& a) {
  std::string nodes;
  for (const int v : a.nodes) {
    nodes += nodes.empty() ? "" : " and ";
    nodes += std::to_string(v + 1);
  }
  char x[32];
  std::snprintf(x, sizeof x, "%g m", a.x_m);
  return std::string("the abutment at x = ") + x + (a.nodes.size() == 1 ? " (node " : " (nodes ") +
         nodes + ")";
}

}  // namespace tbridge
