// The nonlinear static solve on structures small enough to solve by hand: large deflections,
// a string going slack and a rigid bar that rotates, each against its closed form.

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "statics/static_solve.h"

namespace tbridge {
namespace {

// A planar structure of the given nodes (columns x, y) with no bars yet.
StaticModel Planar(const Eigen::Matrix2Xd& xy, const std::vector<bool>& fixed) {
  StaticModel m;
  m.structure.nodes = Eigen::Matrix3Xd::Zero(3, xy.cols());
  m.structure.nodes.topRows<2>() = xy;
  m.structure.fixed = fixed;
  m.structure.planar = true;
  return m;
}

void AddString(StaticModel& m, int i, int j, double k, double rest_length) {
  m.structure.strings.push_back({i, j, MemberGroup::kString});
  m.string_stiffness.push_back(k);
  m.string_rest_length.push_back(rest_length);
}

// A vertical load on node v [N] (positive down).
Eigen::Matrix3Xd Down(const StaticModel& m, int v, double p) {
  Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.structure.num_nodes());
  f(1, v) = -p;
  return f;
}

// The solver converges when the forces balance to 1e-10 of the largest load or member force;
// divided by the tangent stiffness at the solution that bounds the position error. The
// tolerances below are that bound with a factor of 100 of room.

TEST_CASE("a prestressed string pair sags to its large-deflection closed form", "[statics]") {
  // Node 2 between fixed nodes at x = -a and +a on two strings of rest length L0 < a. Sagging
  // by d, each string has length s = sqrt(a^2 + d^2) and tension T = k (s - L0), and vertical
  // balance gives the load P = 2 T d / s. Solved here the other way: P for d = 0.3 m (over a
  // quarter of the span, far outside a linear theory), then d from the solve.
  const double a = 1.0, rest = 0.99, k = 1e5, d = 0.3;
  Eigen::Matrix2Xd xy(2, 3);
  xy << -a, a, 0, 0, 0, 0;
  StaticModel m = Planar(xy, {true, true, false});
  AddString(m, 0, 2, k, rest);
  AddString(m, 1, 2, k, rest);
  const double s = std::hypot(a, d), tension = k * (s - rest), p = 2 * tension * d / s;
  // Start: straight, each string at k (a - L0) = 1000 N, no load: in equilibrium.
  const StaticState start = StateAt(m, m.structure.nodes, Eigen::VectorXd(0), Down(m, 2, 0));
  const StaticResult r = SolveStatic(m, start, Down(m, 2, 0), Down(m, 2, p));
  INFO(r.message << "; node 2 at (" << r.state.nodes(0, 2) << ", " << r.state.nodes(1, 2) << ")");
  REQUIRE(r.converged);
  // Force tolerance 1e-10 x 5.4e3 N over a vertical stiffness of about 2.9e4 N/m: 2e-11 m.
  CHECK(std::abs(r.state.nodes(1, 2) + d) <= 2e-9);
  CHECK(std::abs(r.state.nodes(0, 2)) <= 2e-9);  // symmetry
  for (int j = 0; j < 2; ++j) CHECK(r.state.string_tension[j] == Approx(tension).epsilon(1e-8));
  // Each support takes the string's pull: T (direction to the node), so their sum is P up.
  CHECK(r.state.reactions(1, 0) + r.state.reactions(1, 1) == Approx(p).epsilon(1e-10));
  CHECK(r.state.reactions(0, 0) == Approx(-tension * a / s).epsilon(1e-8));
  CHECK(r.slack_strings == 0);
}

TEST_CASE("a string in line with the load goes slack where its closed form says", "[statics]") {
  // Node 2 between a fixed node 1 m above and one 1 m below, on an upper string (k1, L1) and a
  // lower one (k2, L2), both at 2000 N to start. Moving down by d: T1 = k1 (1 + d - L1) and
  // T2 = k2 (1 - d - L2) while taut; P = T1 - T2. Both stay taut up to d = 1 - L2 = 0.02 m,
  // i.e. P = k1 (0.03) = 6000 N; beyond it the lower string is slack and P = T1 alone.
  const double k1 = 2e5, rest1 = 0.99, k2 = 1e5, rest2 = 0.98;
  Eigen::Matrix2Xd xy(2, 3);
  xy << 0, 0, 0, 1, -1, 0;
  StaticModel m = Planar(xy, {true, true, false});
  AddString(m, 0, 2, k1, rest1);
  AddString(m, 1, 2, k2, rest2);
  const StaticState start = StateAt(m, m.structure.nodes, Eigen::VectorXd(0), Down(m, 2, 0));
  REQUIRE(start.string_tension[0] == Approx(start.string_tension[1]).epsilon(1e-12));
  struct Case {
    double p, d;  // load [N], deflection by the closed form [m]
    int slack;
  };
  for (const Case& c :
       {Case{3000, 3000 / (k1 + k2), 0}, Case{10000, 10000 / k1 - (1 - rest1), 1}}) {
    const StaticResult r = SolveStatic(m, start, Down(m, 2, 0), Down(m, 2, c.p));
    INFO("P = " << c.p << " N: " << r.message << "; node 2 at y = " << r.state.nodes(1, 2));
    REQUIRE(r.converged);
    // Force tolerance 1e-10 x 1e4 N over the stiffness k1 (or k1 + k2), 2e5 N/m: 5e-12 m.
    CHECK(std::abs(r.state.nodes(1, 2) + c.d) <= 5e-10);
    CHECK(r.slack_strings == c.slack);
    CHECK(r.state.string_tension[0] == Approx(k1 * (1 + c.d - rest1)).epsilon(1e-9));
    CHECK(r.state.string_tension[1] == Approx(c.slack ? 0.0 : k2 * (1 - c.d - rest2)).margin(1e-6));
  }
}

TEST_CASE("a boom held by a string rotates to its moment balance", "[statics]") {
  // A rigid bar of length 1 m pinned at A = (0, 0) with its free end B at angle theta above
  // the horizontal, held by a string from B to C = (0, 1.5) and loaded by P down at B. Moments
  // about A: P B_x = T (B_x u_y - B_y u_x), u = (C - B) / |C - B|; along the bar the
  // compression is N = -(T u + (0, -P)) . B / |B|. For theta = 30 deg and 20 deg these give
  // the start (in equilibrium) and the load of the end state; the solve must find the angle.
  const double k = 1e5, rest = 1.3;
  const Eigen::Vector2d c(0, 1.5);
  struct Balance {
    Eigen::Vector2d b;
    double tension, load, compression;
  };
  const auto balance = [&](double theta) {
    Balance out;
    out.b = Eigen::Vector2d(std::cos(theta), std::sin(theta));
    const Eigen::Vector2d u = (c - out.b).normalized();
    out.tension = k * ((c - out.b).norm() - rest);
    out.load = out.tension * (out.b.x() * u.y() - out.b.y() * u.x()) / out.b.x();
    out.compression = -(out.tension * u + Eigen::Vector2d(0, -out.load)).dot(out.b);
    return out;
  };
  const Balance b0 = balance(M_PI / 6), b1 = balance(M_PI / 9);
  REQUIRE(b0.tension > 0);
  Eigen::Matrix2Xd xy(2, 3);
  xy << 0, b0.b.x(), c.x(), 0, b0.b.y(), c.y();
  StaticModel m = Planar(xy, {true, false, true});
  m.structure.bars.push_back({0, 1, MemberGroup::kNone});
  AddString(m, 1, 2, k, rest);
  const StaticState start = StateAt(
      m, m.structure.nodes, Eigen::VectorXd::Constant(1, b0.compression), Down(m, 1, b0.load));
  const StaticResult r = SolveStatic(m, start, Down(m, 1, b0.load), Down(m, 1, b1.load));
  INFO(r.message << "; B at (" << r.state.nodes(0, 1) << ", " << r.state.nodes(1, 1) << ")");
  REQUIRE(r.converged);
  // Force tolerance 1e-10 x 2e4 N over the rotational stiffness at B (of order k, 1e5 N/m):
  // 2e-11 m; the bar length to 1e-12.
  CHECK((r.state.nodes.col(1).head<2>() - b1.b).norm() <= 2e-9);
  CHECK(r.state.bar_compression[0] == Approx(b1.compression).epsilon(1e-8));
  CHECK(r.state.string_tension[0] == Approx(b1.tension).epsilon(1e-8));
  // The pin takes the bar's push along the bar, the anchor the string's pull.
  const Eigen::Vector2d reaction_a = b1.compression * b1.b,
                        reaction_c = b1.tension * (c - b1.b).normalized();
  CHECK((r.state.reactions.col(0).head<2>() - reaction_a).norm() <= 1e-8 * b1.compression);
  CHECK((r.state.reactions.col(2).head<2>() - reaction_c).norm() <= 1e-8 * b1.tension);
}

}  // namespace
}  // namespace tbridge
