// The deck's inertia in the dynamic model against the one-degree-of-freedom closed form of the
// n = 1 bridge.

#include <catch2/catch.hpp>
#include <cmath>

#include "bridge/design_model.h"
#include "design/design.h"
#include "dynamics/modal.h"
#include "dynamics/model.h"

namespace tbridge {
namespace {

// The n = 1 bridge's symmetric mode: its one vertical bar (deck node on top, the cable node
// below) translates vertically. Horizontal translation and rotation are antisymmetric.
double SymmetricOmega(const DynamicModel& model) {
  for (const Mode& m : ComputeModes(model).modes) {
    if (ClassifySymmetry(model.positions, m.shape).symmetry == ModeSymmetry::kSymmetric)
      return m.omega_rad_s;
  }
  FAIL("no symmetric mode");
  return 0;
}

TEST_CASE(
    "n = 1 with deck inertia: the vertical mode against its one-degree-of-freedom closed form",
    "[dynamics][modal][inertia]") {
  Config config;  // the engineering defaults: the run carries the permanent load and the payload
  config.bridge.n = 1;
  const Design d = RunDesign(config);
  REQUIRE(d.bars.size() == 1);
  const Material& mat = d.config.material;
  ModelOptions with;
  with.deck_inertia = true;
  const DynamicModel model = BuildDynamicModel(d, with);
  const ModelOptions without;
  const DynamicModel bare = BuildDynamicModel(d, without);

  // Stiffness of a vertical translation u of both bar ends at the run's start (the static
  // equilibrium under the design loads, symmetric, so the bar stays vertical): each string
  // gives its axial stiffness times sin^2 of its slope plus its tension over its length times
  // cos^2 (the geometric stiffness across it). The bar, rigid, adds nothing.
  double stiffness = 0, string_mass_on_bar = 0;
  for (size_t k = 0; k < d.strings.size(); ++k) {
    const MemberSizing& m = d.strings[k];
    const Eigen::Vector3d chord = model.positions.col(m.j) - model.positions.col(m.i);
    const double length = chord.norm();
    const double sin2 = chord.y() * chord.y() / (length * length);
    const double tension = m.stiffness * (length - m.rest_length);
    REQUIRE(tension > 0);
    stiffness += m.stiffness * sin2 + tension / length * (1.0 - sin2);
    // Each string's half at its free end rides on the bar (dynamics.string_mass "bars").
    string_mass_on_bar += 0.5 * mat.density * m.area * m.rest_length;
  }
  const double bare_mass = d.bars[0].mass + string_mass_on_bar;
  // At the deck node: the deck beam m_d and the payload over its section, F l_d / (L g).
  const double deck_mass = d.deck.section_mass + d.config.bridge.payload / d.config.bridge.span *
                                                     d.deck.section_length /
                                                     d.config.design.gravity;

  // 1e-9: the modal solve linearises the same model exactly; the residue is the eigensolver's
  // and the rounding of the stiffness sums.
  CHECK(SymmetricOmega(model) ==
        Approx(std::sqrt(stiffness / (bare_mass + deck_mass))).epsilon(1e-9));
  CHECK(SymmetricOmega(bare) == Approx(std::sqrt(stiffness / bare_mass)).epsilon(1e-9));
  // The deck and payload are the heavier part by far (600 kg against tens of kg of members).
  CHECK(deck_mass > 3 * bare_mass);
}

}  // namespace
}  // namespace tbridge
