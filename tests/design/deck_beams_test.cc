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
#include "design/load_cases.h"
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

// EN 10365's IPE 100-600: depth h [mm], area A [cm^2], second moment I_y [cm^4].
struct Ipe {
  double h_mm, area_cm2, inertia_cm4;
};
constexpr Ipe kIpe[] = {{100, 10.3, 171},    {120, 13.2, 318},   {140, 16.4, 541},
                        {160, 20.1, 869},    {180, 23.9, 1317},  {200, 28.5, 1943},
                        {220, 33.4, 2772},   {240, 39.1, 3892},  {270, 45.9, 5790},
                        {300, 53.8, 8356},   {330, 62.6, 11770}, {360, 72.7, 16270},
                        {400, 84.5, 23130},  {450, 98.8, 33740}, {500, 116.0, 48200},
                        {550, 134.0, 67120}, {600, 156.0, 92080}};

TEST_CASE("deck girders: the rolled-I proportions against the IPE series' tables",
          "[design][deck]") {
  // The fit's stated accuracy (design/deck.h): A within 3 %, I within 4.1 % of every IPE from
  // 100 to 600, the tables being an independent truth; a fit off by 1 % in its exponent fails.
  for (const Ipe& s : kIpe) {
    const double h = s.h_mm / 1e3;
    INFO("IPE " << s.h_mm);
    CHECK(std::abs(GirderArea(h) / (s.area_cm2 * 1e-4) - 1) < 0.03);
    CHECK(std::abs(GirderInertia(h) / (s.inertia_cm4 * 1e-8) - 1) < 0.041);
  }
}

// The girders' deck by hand: two girders of depth h, each of area A = 10 cm^2 (h / 0.1 m)^1.53
// and I = 0.17 A h^2, each carrying half of the deck's load.
HandBeam GirdersByHand(const Config& c, double h) {
  const double l = c.bridge.span / std::pow(2.0, c.bridge.n);
  const double area = 10e-4 * std::pow(h / 0.1, 1.53), inertia = 0.17 * area * h * h;
  const double g = c.material.density * c.design.gravity * 2 * area +
                   c.loads.superimposed_dead_n_per_m;  // G on the deck [N/m]
  const double q = c.bridge.payload / c.bridge.span, Q = c.loads.travelling_load_n;
  const double gs = c.loads.gamma_g_sup, gq = c.loads.gamma_q;
  const double m = std::max((gs * g + gq * q) * l * l / 8.0, gs * g * l * l / 8.0 + gq * Q * l / 4);
  HandBeam out;
  // Each girder: half the moment over its modulus I / (h / 2).
  out.utilisation =
      0.5 * m / (inertia / (0.5 * h)) / (c.material.yield_stress / c.design.yield_safety_factor);
  const double ei = c.material.youngs_modulus * 2 * inertia;  // the pair
  out.sag_m = std::max(5.0 * (g + q) * std::pow(l, 4) / (384.0 * ei),
                       5.0 * g * std::pow(l, 4) / (384.0 * ei) + Q * l * l * l / (48.0 * ei));
  return out;
}

TEST_CASE("deck girders: utilisation and sag against the hand calculation, sized to the limit",
          "[design][deck]") {
  for (const int n : {1, 2}) {  // sections of 6 and 3 m on the 12 m default
    Config c;
    c.bridge.n = n;
    c.bridge.payload = 72000;  // 4 kPa on the 1.5 m deck
    c.loads.superimposed_dead_n_per_m = 2000;
    c.design.deck_section = DeckSection::kGirders;
    const DesignInputs in = PrepareDesign(c);
    std::vector<std::string> notes;
    const DeckBeamCheck check = CheckDeckBeams(c, in.deck, MakeLoadCases(c, in.deck, notes));
    const double h = in.deck.girder_depth;
    INFO("n = " << n << ": h = " << h << " m, sized by " << in.deck.sized_by);
    REQUIRE(h > 0);
    const HandBeam hand = GirdersByHand(c, h);
    // The same closed forms summed in another order: 1e-9 leaves room for a few roundings.
    CHECK(check.utilisation == Approx(hand.utilisation).epsilon(1e-9));
    CHECK(check.sag_m == Approx(hand.sag_m).epsilon(1e-9));
    // The mass is the two girders' steel; the thickness the plate's of that mass.
    CHECK(in.deck.section_mass ==
          Approx(2 * c.material.density * 10e-4 * std::pow(h / 0.1, 1.53) * in.deck.section_length)
              .epsilon(1e-12));
    CHECK(in.deck.thickness * c.bridge.deck_width * in.deck.section_length * c.material.density ==
          Approx(in.deck.section_mass).epsilon(1e-12));
    // Sized to the shallowest that passes (depth bisected to 4e-16); 0.1 % shallower fails.
    CHECK(std::max(check.utilisation, check.SagRatio()) == Approx(1.0).epsilon(1e-12));
    const HandBeam shallower = GirdersByHand(c, 0.999 * h);
    CHECK(std::max(shallower.utilisation, shallower.sag_m / check.sag_limit_m) > 1.0);
  }
}

TEST_CASE("deck girders: a design file reads back with its girders, and another depth is refused",
          "[design][deck]") {
  Config c;
  c.bridge.payload = 72000;  // 4 kPa on the 1.5 m deck: girders deeper than IPE 80
  c.design.deck_section = DeckSection::kGirders;
  const Design designed = RunDesign(c);
  REQUIRE(designed.deck.girder_depth > kMinGirderDepth);
  std::ostringstream os;
  WriteDesignJson(designed, os);
  nlohmann::json file = nlohmann::json::parse(os.str());
  CHECK(file["deck"]["section"] == "girders");
  CHECK(ReadDesign(file).deck.girder_depth == designed.deck.girder_depth);
  file["deck"]["girder_depth"] = 1.1 * designed.deck.girder_depth;
  try {
    ReadDesign(file);
    FAIL("a deeper girder was read");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("deck.girder_depth") && Catch::Contains("tbridge design"));
  }
}

TEST_CASE("deck girders: no shallower than the smallest rolled girder", "[design][deck]") {
  // Sections of 0.75 m under the default's 12 kN need far less than IPE 80: the girders stay
  // 80 mm deep, and pass with room.
  Config c;
  c.bridge.n = 4;
  c.design.deck_section = DeckSection::kGirders;
  const DesignInputs in = PrepareDesign(c);
  std::vector<std::string> notes;
  const DeckBeamCheck check = CheckDeckBeams(c, in.deck, MakeLoadCases(c, in.deck, notes));
  CHECK(in.deck.girder_depth == kMinGirderDepth);
  CHECK_THAT(in.deck.sized_by, Catch::Contains("IPE 80"));
  CHECK(std::max(check.utilisation, check.SagRatio()) < 0.5);
}

TEST_CASE("deck girders: in plan the pair bends as one section under the wind", "[design][deck]") {
  // One ultimate case of wind alone on a weightless deck: the lateral moment W l^2 / 8 over
  // the pair's modulus A w (each girder's area at w / 2 from the centre line), nothing vertical.
  Config c;
  c.bridge.planes = 2;
  c.design.deck_section = DeckSection::kGirders;
  const Deck deck = DeckOfGirders(c.bridge, c.material, c.design, 0.2);
  LoadCase wind;
  wind.name = "uls_wind";
  wind.factor[kWind] = 1.5;
  const DeckBeamCheck check = CheckDeckBeams(c, deck, {wind});
  const double l = deck.section_length;
  const double moment = 1.5 * c.loads.wind_n_per_m * l * l / 8;
  CHECK(check.lateral_moment_ed_nm == Approx(moment).epsilon(1e-15));
  CHECK(check.moment_ed_nm == 0);
  CHECK(check.stress_ed_pa ==
        Approx(moment / (10e-4 * std::pow(2.0, 1.53) * c.bridge.deck_width)).epsilon(1e-12));
}

TEST_CASE("deck girders: refused with the paper's switches, naming the key", "[design][deck]") {
  Config c;
  ApplyPaperSwitches(c);
  c.design.deck_section = DeckSection::kGirders;
  try {
    Validate(c);
    FAIL("girders were taken with the paper's switches");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("design.deck_section") && Catch::Contains("paper"));
  }
}

}  // namespace
}  // namespace tbridge
