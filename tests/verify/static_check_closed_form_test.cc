// The static check's member findings on the paper's n = 1 bridge, a statically determinate V,
// against hand statics: the bar carries the deck node's load f = F_tot / 2, each V string
// f / (2 sin(beta / 2)) (SPEC §2: the V slopes at beta / 2), the deck strings their prestress
// sigma_w pi r_min^2; resistances from the members' radii by yield, Euler and the EN 1993-1-1
// column curve written out here.

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "checks/static_check.h"
#include "design/design.h"
#include "test_support.h"

namespace tbridge {
namespace {

// The check of `config`'s n = 1 design against the closed forms; `governs` names the bar's
// resistance that must govern ("yield" or "buckling").
void CheckAgainstHandStatics(const Config& config, const std::string& governs) {
  const Design d = RunDesign(config);
  REQUIRE(d.bars.size() == 1u);
  const StaticCheck check = CheckStatics(d);
  REQUIRE(check.all_converged);
  const double E = config.material.youngs_modulus, fy = config.material.yield_stress;
  const double sigma_w = fy / config.design.yield_safety_factor;
  const double half_slope = 0.5 * config.bridge.beta_deg * M_PI / 180;
  // Eq. 9: F_tot = F + 2^n m_d g over the 2^n stations; the one free deck node carries f.
  const double f = (config.bridge.payload + d.mass.deck_beams * config.design.gravity) / 2;
  // The nonlinear solve of the design load from the design's own state moves nothing: the
  // demands are the reference forces, balanced to the solver's 1e-10 of the largest force.
  const double tol = 1e-9;

  const MemberSizing& bar = d.bars[0];
  const MemberFinding& found = check.members[0];
  const double area = M_PI * bar.radius * bar.radius;
  const double l = config.bridge.span / 2 * std::tan(half_slope);  // the V's depth (SPEC §2)
  const double n_cr = M_PI * M_PI * E * (M_PI * std::pow(bar.radius, 4) / 4) / (l * l);
  double buckling = n_cr / config.design.buckling_safety_factor;
  if (config.design.bar_resistance == BarResistanceRule::kColumnCurve) {
    const double lambda = std::sqrt(area * fy / n_cr), alpha = 0.49;  // curve c: solid sections
    const double phi = 0.5 * (1 + alpha * (lambda - 0.2) + lambda * lambda);
    const double chi = std::min(1.0, 1 / (phi + std::sqrt(phi * phi - lambda * lambda)));
    buckling = chi * area * fy / config.design.buckling_safety_factor;
  }
  const double yield = area * sigma_w;
  INFO("bar: demand " << found.demand << " N (f = " << f << "), resistance " << found.resistance
                      << " N (" << NameOf(found.mode) << "); yield " << yield << ", buckling "
                      << buckling << " N");
  CHECK(bar.length == Approx(l).epsilon(1e-12));  // the drawn geometry, to round-off
  CHECK(found.demand == Approx(f).epsilon(tol));
  CHECK(NameOf(found.mode) == governs);
  CHECK(found.resistance == Approx(governs == "yield" ? yield : buckling).epsilon(tol));
  // Sized to its governing resistance under this one load: utilisation 1.
  CHECK(found.utilisation == Approx(1.0).epsilon(tol));

  for (size_t k = 0; k < d.strings.size(); ++k) {
    const MemberSizing& s = d.strings[k];
    const MemberFinding& sf = check.members[1 + k];
    const bool deck = StringKind(d.topology.structure.strings[k]) == MemberKind::kDeckString;
    const double tension = deck ? sigma_w * M_PI * 0.01 * 0.01 : f / (2 * std::sin(half_slope));
    INFO("string " << s.name << ": demand " << sf.demand << " N, closed form " << tension << " N");
    CHECK(sf.demand == Approx(tension).epsilon(tol));
    CHECK(sf.resistance == Approx(M_PI * s.radius * s.radius * sigma_w).epsilon(1e-12));
    CHECK(sf.utilisation == Approx(1.0).epsilon(tol));  // sized at sigma_w, or prestressed to it
  }
}

TEST_CASE("the static check finds the n = 1 bridge's member forces and resistances by hand statics",
          "[verify][statics]") {
  SECTION("the paper's bridge: the short bar yields") {
    CheckAgainstHandStatics(test::PaperConfig(1), "yield");
  }
  SECTION("steep and light, Euler: the 3.5 m bar buckles") {
    Config c = test::PaperConfig(1);
    c.bridge.beta_deg = 60;
    c.bridge.payload = 1000;
    CheckAgainstHandStatics(c, "buckling");
  }
  SECTION("steep and light, column curve: the bar buckles at chi A f_y") {
    Config c = test::PaperConfig(1);
    c.bridge.beta_deg = 60;
    c.bridge.payload = 1000;
    c.design.bar_resistance = BarResistanceRule::kColumnCurve;
    c.design.buckling_safety_factor = 1.1;
    CheckAgainstHandStatics(c, "buckling");
  }
}

}  // namespace
}  // namespace tbridge
