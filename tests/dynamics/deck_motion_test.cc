// The projection of mode shapes on the deck's motions (dynamics/deck_motion.h) on a hand-built
// symmetric structure whose modes are known in closed form.
#include "dynamics/deck_motion.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <string>

#include "dynamics/modal.h"

namespace tbridge {

namespace {

// Two deck nodes P1 (1, 0, -0.75) and P2 (1, 0, 0.75) of mass m, each on a taut span string
// pair to supports at x = 0 and 2 (tension T, stiffness k each), joined by a transverse string
// (T_t, k_t) and each held outwards by a stay to a support 2 m away in z (T_t, k_s), so that both
// are in equilibrium with no load. A string of tension T and length s stiffens its
// perpendicular directions by T/s and its own by its k: the six modes are the mirror-symmetric
// and -antisymmetric motions along x, y and z, with the stiffnesses per node
//   vertical (y1 = y2):     2T/a + T_t/L_s
//   torsional (y1 = -y2):   2T/a + T_t/L_s + 2 T_t/L_t
//   lateral (z1 = z2):      2T/a + k_s
//   z1 = -z2 (local):       2T/a + k_s + 2 k_t
//   longitudinal (x1 = x2): 2k + T_t/L_s
//   x1 = -x2 (local):       2k + T_t/L_s + 2 T_t/L_t
// with a = 1 m, L_s = 2 m, L_t = 1.5 m.
constexpr double kMass = 100, kT = 1000, kK = 1e5, kTt = 500, kKs = 2e4, kKt = 3e4;

DynamicModel TwoPlaneDeck() {
  DynamicModel m;
  m.dim = 3;
  m.positions.resize(3, 8);
  m.positions << 1, 1, 0, 2, 0, 2, 1, 1,  //
      0, 0, 0, 0, 0, 0, 0, 0,             //
      -0.75, 0.75, -0.75, -0.75, 0.75, 0.75, -2.75, 2.75;
  m.fixed = {false, false, true, true, true, true, true, true};
  m.node_mass = Eigen::VectorXd::Zero(8);
  m.node_mass(0) = m.node_mass(1) = kMass;
  m.loads = Eigen::Matrix3Xd::Zero(3, 8);
  m.deck_nodes = {0, 1};
  const auto add = [&m](int i, int j, double tension, double k) {
    const double s = (m.positions.col(j) - m.positions.col(i)).norm();
    DynamicString d;
    d.i = i;
    d.j = j;
    d.stiffness = k;
    d.rest_length = s - tension / k;
    m.AddString(d, std::to_string(i + 1) + "-" + std::to_string(j + 1), MemberGroup::kString);
  };
  add(2, 0, kT, kK), add(0, 3, kT, kK), add(4, 1, kT, kK), add(1, 5, kT, kK);
  add(0, 1, kTt, kKt);
  add(0, 6, kTt, kKs), add(1, 7, kTt, kKs);
  return m;
}

}  // namespace

TEST_CASE("deck motions of a hand-built two-plane deck: names, frequencies and modal masses",
          "[comfort][modal]") {
  const DynamicModel model = TwoPlaneDeck();
  const ModalResult modes = ComputeModes(model);
  REQUIRE(modes.modes.size() == 6);
  const double a = 1.0, ls = 2.0, lt = 1.5;
  const std::map<std::string, double> expected_omega2 = {
      {"vertical", (2 * kT / a + kTt / ls) / kMass},
      {"torsional", (2 * kT / a + kTt / ls + 2 * kTt / lt) / kMass},
      {"lateral", (2 * kT / a + kKs) / kMass},
      {"longitudinal", (2 * kK + kTt / ls) / kMass}};
  std::map<std::string, int> found;
  int local = 0;
  for (const Mode& mode : modes.modes) {
    const DeckMotionReport r = ProjectOnDeckMotions(model, mode.shape);
    const std::string name = NameOf(r.motion);
    if (r.motion == DeckMotion::kLocal) {
      ++local;
      continue;
    }
    ++found[name];
    INFO(name << " at omega^2 = " << mode.omega_squared);
    // The eigensolver's relative accuracy on a 6 x 6 problem: 1e-9 leaves room for rounding.
    CHECK(mode.omega_squared == Approx(expected_omega2.at(name)).epsilon(1e-9));
    // A pure section motion: its share is all of the deck's motion.
    CHECK(r.share[static_cast<int>(r.motion)] == Approx(1.0).epsilon(1e-9));
    // Both nodes move alike (or opposite) with the mass-normalised amplitude 1 / sqrt(2 m):
    // scaled to a largest displacement of 1 the modal mass is the two nodes' 2 m.
    CHECK(1.0 / (r.peak_displacement * r.peak_displacement) == Approx(2 * kMass).epsilon(1e-9));
  }
  CHECK(found == std::map<std::string, int>{
                     {"vertical", 1}, {"torsional", 1}, {"lateral", 1}, {"longitudinal", 1}});
  CHECK(local == 2);  // the planes moving against each other along x and along z
}

TEST_CASE("deck motions: a planar deck has vertical and longitudinal modes only",
          "[comfort][modal]") {
  // The same deck cut to its first plane, in 2D: one node on a taut string pair (vertical:
  // 2T/a per node, longitudinal: 2k), held by nothing across.
  DynamicModel m;
  m.dim = 2;
  m.positions.resize(3, 3);
  m.positions << 1, 0, 2, 0, 0, 0, 0, 0, 0;
  m.fixed = {false, true, true};
  m.node_mass = Eigen::Vector3d(kMass, 0, 0);
  m.loads = Eigen::Matrix3Xd::Zero(3, 3);
  m.deck_nodes = {0};
  for (const int support : {1, 2}) {
    DynamicString d;
    d.i = support;
    d.j = 0;
    d.stiffness = kK;
    d.rest_length = 1.0 - kT / kK;
    m.AddString(d, "s", MemberGroup::kString);
  }
  const ModalResult modes = ComputeModes(m);
  REQUIRE(modes.modes.size() == 2);
  CHECK(std::string(NameOf(ProjectOnDeckMotions(m, modes.modes[0].shape).motion)) == "vertical");
  CHECK(std::string(NameOf(ProjectOnDeckMotions(m, modes.modes[1].shape).motion)) ==
        "longitudinal");
  // 2T/a / m and 2k / m, to the eigensolver's accuracy.
  CHECK(modes.modes[0].omega_squared == Approx(2 * kT / kMass).epsilon(1e-9));
  CHECK(modes.modes[1].omega_squared == Approx(2 * kK / kMass).epsilon(1e-9));
}

}  // namespace tbridge
