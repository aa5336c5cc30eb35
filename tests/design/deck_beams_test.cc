// The deck beams against their statics worked by hand: a plate of the deck's width w and
// thickness t, simply supported over one section l, with its weight, the superimposed dead
// load and the payload per metre along it and the travelling load at its middle.

#include "design/deck_beams.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "design/design.h"
#include "io/design_reader.h"
#include "io/design_report.h"

namespace tbridge {
namespace {

struct HandBeam {
  double utilisation = 0;  // the largest bending stress over the ultimate cases / f_y / gamma_M
  double sag_m = 0;        // the largest sag at midspan over the serviceability cases
};

// The default cases of a planar bridge: permanent, payload (full, left, right) and the
// travelling load, each with unfavourable and favourable G at the ultimate limit state.
HandBeam SolveByHand(const Config& c, double t) {
  const double l = c.bridge.span / std::pow(2.0, c.bridge.n), w = c.bridge.deck_width;
  const double own = c.material.density * c.design.gravity * w * t;  // [N/m]
  const double g = own + c.loads.superimposed_dead_n_per_m;          // G on the beam [N/m]
  const double q = c.bridge.payload / c.bridge.span;                 // [N/m]
  const double Q = c.loads.travelling_load_n;
  const double gs = c.loads.gamma_g_sup, gq = c.loads.gamma_q;
  // Ultimate: the unfavourable-G cases govern (gamma_g_inf < gamma_g_sup).
  const double m_payload = (gs * g + gq * q) * l * l / 8.0;
  const double m_travelling = gs * g * l * l / 8.0 + gq * Q * l / 4.0;
  const double section_modulus = w * t * t / 6.0;
  HandBeam h;
  h.utilisation = std::max(m_payload, m_travelling) / section_modulus /
                  (c.material.yield_stress / c.design.yield_safety_factor);
  // Serviceability: G + Q_full, or G + Q_t at the middle.
  const double ei = c.material.youngs_modulus * w * t * t * t / 12.0;
  const double sag_payload = 5.0 * (g + q) * std::pow(l, 4) / (384.0 * ei);
  const double sag_travelling =
      5.0 * g * std::pow(l, 4) / (384.0 * ei) + Q * l * l * l / (48.0 * ei);
  h.sag_m = std::max(sag_payload, sag_travelling);
  return h;
}

TEST_CASE("deck beams: utilisation and sag of one section against the hand calculation",
          "[design][deck]") {
  for (const double dead : {0.0, 2000.0}) {
    Config c;  // the engineering defaults: n = 2, 12 m, steel
    c.loads.superimposed_dead_n_per_m = dead;
    const DesignInputs in = PrepareDesign(c);
    std::vector<std::string> notes;
    const DeckBeamCheck check = CheckDeckBeams(c, in.deck, MakeLoadCases(c, in.deck, notes));
    const HandBeam hand = SolveByHand(c, in.deck.thickness);
    INFO("superimposed dead load " << dead << " N/m: t = " << in.deck.thickness << " m, sized by "
                                   << in.deck.sized_by);
    // The same closed forms summed in another order: 1e-9 leaves room for a few roundings.
    CHECK(check.utilisation == Approx(hand.utilisation).epsilon(1e-9));
    CHECK(check.sag_m == Approx(hand.sag_m).epsilon(1e-9));
    CHECK(check.sag_limit_m == Approx(c.bridge.span / 4 / c.loads.deck_sag_limit).epsilon(1e-15));
    // Sized to the thinnest plate that passes: the governing ratio is 1 to the bisection's last
    // bits (t to 4e-16, the sag going as 1 / t^2 to 1 / t^3).
    CHECK(std::max(check.utilisation, check.SagRatio()) == Approx(1.0).epsilon(1e-12));
    CHECK(check.Status() == CheckStatus::kPassed);
    // 0.1 % thinner fails by the hand calculation's own numbers.
    const HandBeam thinner = SolveByHand(c, 0.999 * in.deck.thickness);
    CHECK(std::max(thinner.utilisation, thinner.sag_m / check.sag_limit_m) > 1.0);
  }
}

TEST_CASE("deck beams: the paper's eq 7 deck is fully stressed under the paper's load",
          "[design][deck]") {
  // Eq 7 solves sigma_d = 3/4 f_d l^2 / (w t^2) for the paper's f_d (payload and the beams'
  // own weight) in closed form; the check's bending stress M / (w t^2 / 6) is the same law
  // reached through M = f_d l^2 / 8. Agreement to 1e-12 (the quadratic's rounding).
  Config c;
  ApplyPaperSwitches(c);
  for (const int n : {1, 3, 5}) {
    c.bridge.n = n;
    const Deck deck = ComputeDeck(c.bridge, c.material, c.design);
    std::vector<std::string> notes;
    const DeckBeamCheck check = CheckDeckBeams(c, deck, MakeLoadCases(c, deck, notes));
    INFO("n = " << n);
    CHECK(PrepareDesign(c).deck.thickness == deck.thickness);  // the paper keeps eq 7
    CHECK(check.utilisation == Approx(1.0).epsilon(1e-12));
    CHECK(check.sag_case.empty());  // the paper's one case is ultimate: no sag is checked
  }
}

TEST_CASE("deck beams: a design file with another deck is refused, naming the thickness",
          "[design][deck]") {
  // The members' reference forces carry the deck's weight: a deck of another thickness is
  // another design, which tbridge check cannot take as written.
  Config c;
  const Design designed = RunDesign(c);
  std::ostringstream os;
  WriteDesignJson(designed, os);
  nlohmann::json file = nlohmann::json::parse(os.str());
  const Deck thinner =
      DeckOfThickness(c.bridge, c.material, c.design, 0.9 * designed.deck.thickness);
  file["deck"]["thickness"] = thinner.thickness;
  file["deck"]["section_mass"] = thinner.section_mass;
  file["deck"]["beams_mass"] = thinner.beams_mass;
  file["deck"]["total_load"] = thinner.total_load;
  file["deck"]["node_load"] = thinner.node_load;
  try {
    ReadDesign(file);
    FAIL("a thinner deck was read");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("deck.thickness") && Catch::Contains("tbridge design"));
  }
}

}  // namespace
}  // namespace tbridge
