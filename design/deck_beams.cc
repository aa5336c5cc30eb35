#include "design/deck_beams.h"

#include <algorithm>
#include <cmath>

namespace tbridge {

DeckBeamLoad DeckBeamLoadOf(const LoadCase& c, const Config& config, const Deck& deck) {
  const BridgeConfig& b = config.bridge;
  const double own = deck.section_mass * config.design.gravity / deck.section_length;  // rho g w t
  const double q = b.payload / b.span;
  DeckBeamLoad load;
  // A half-span payload loads a beam of the loaded half fully: the worst beam carries q.
  const double payload =
      c.factor[kPayloadFull] + std::max(c.factor[kPayloadLeft], c.factor[kPayloadRight]);
  load.vertical_n_per_m = c.factor[kDeckDead] * (own + config.loads.superimposed_dead_n_per_m) +
                          c.factor[kPaperLoad] * (own + q) + payload * q;
  load.point_n = c.station_load;
  load.lateral_n_per_m = b.planes == 2 ? c.factor[kWind] * config.loads.wind_n_per_m : 0.0;
  return load;
}

CheckStatus DeckBeamCheck::Status() const {
  return utilisation > 1.0 + 1e-9 || SagRatio() > 1.0 + 1e-9 ? CheckStatus::kFailed
                                                             : CheckStatus::kPassed;
}

namespace {

// The elastic section of one deck section across the deck's whole width.
struct DeckSectionProperties {
  double vertical_modulus;  // [m^3]
  double lateral_modulus;   // [m^3], bending in plan under the wind
  double inertia;           // vertical [m^4]
};

DeckSectionProperties PropertiesOf(const Deck& deck, double width) {
  if (deck.girder_depth > 0) {
    // Two girders: vertically each bends alone (modulus 2 I / h); in plan the decking ties them
    // into one section about the deck's centre line, each girder's area at w / 2 from it (their
    // own lateral inertia neglected: small beside it).
    const double h = deck.girder_depth, inertia = 2.0 * GirderInertia(h);
    return {2.0 * inertia / h, GirderArea(h) * width, inertia};
  }
  const double t = deck.thickness, w = width;
  return {w * t * t / 6.0, t * w * w / 6.0, w * t * t * t / 12.0};
}

}  // namespace

DeckBeamCheck CheckDeckBeams(const Config& config, const Deck& deck,
                             const std::vector<LoadCase>& cases) {
  const double l = deck.section_length;
  const double E = config.material.youngs_modulus;
  const auto [vertical_modulus, lateral_modulus, inertia] =
      PropertiesOf(deck, config.bridge.deck_width);
  DeckBeamCheck out;
  out.stress_rd_pa = config.material.yield_stress / config.design.yield_safety_factor;
  out.sag_limit_m = l / config.loads.deck_sag_limit;
  for (const LoadCase& c : cases) {
    const DeckBeamLoad p = DeckBeamLoadOf(c, config, deck);
    if (c.state == LimitState::kUltimate) {
      const double mv = p.vertical_n_per_m * l * l / 8.0 + p.point_n * l / 4.0;
      const double mh = p.lateral_n_per_m * l * l / 8.0;
      const double stress = std::abs(mv) / vertical_modulus + std::abs(mh) / lateral_modulus;
      if (out.governing_case.empty() || stress > out.stress_ed_pa) {
        out.stress_ed_pa = stress;
        out.moment_ed_nm = mv;
        out.lateral_moment_ed_nm = mh;
        out.governing_case = c.name;
      }
    } else {
      const double sag = 5.0 * p.vertical_n_per_m * std::pow(l, 4) / (384.0 * E * inertia) +
                         p.point_n * l * l * l / (48.0 * E * inertia);
      if (out.sag_case.empty() || std::abs(sag) > out.sag_m) {
        out.sag_m = std::abs(sag);
        out.sag_case = c.name;
      }
    }
  }
  out.utilisation = out.stress_ed_pa / out.stress_rd_pa;
  return out;
}

namespace {

// The larger of the stress and sag ratios: both fall as the plate thickens (the weight grows
// with t, the section modulus with t^2, the inertia with t^3) or the girders deepen (the
// weight as A, the modulus as A h, the inertia as A h^2).
double WorstRatio(const DeckBeamCheck& c) { return std::max(c.utilisation, c.SagRatio()); }

}  // namespace

Deck SizeDeckBeams(const Config& config, const Deck& start) {
  if (KeepsPaperSwitches(config)) return start;
  const BridgeConfig& b = config.bridge;
  const Material& m = config.material;
  const DesignConfig& d = config.design;
  std::vector<std::string> notes;
  // The one size that sizes the section: the plate's thickness, or the girders' depth.
  const bool girders = d.deck_section == DeckSection::kGirders;
  const auto deck_of = [&](double size) {
    return girders ? DeckOfGirders(b, m, d, size) : DeckOfThickness(b, m, d, size);
  };
  const double size0 = girders ? start.section_length / 20.0 : start.thickness;
  Deck deck = girders ? deck_of(size0) : start;
  // The paper's travelling load f = F_tot / 2^n carries the beams' own weight: the cases
  // follow the deck, so repeat until the size holds still (a few rounds: f changes by the
  // beams' share of F_tot).
  for (int round = 0; round < 50; ++round) {
    const std::vector<LoadCase> cases = MakeLoadCases(config, deck, notes);
    auto ratio = [&](double size) {
      return WorstRatio(CheckDeckBeams(config, deck_of(size), cases));
    };
    if (!(ratio(size0 * 1e3) > 0)) return start;  // no case loads the beams: eq 7 stays
    // Bracket the smallest passing size from the start's (eq 7's plate, girders l / 20 deep),
    // then bisect in log size to the last bit: both ratios fall as the size grows.
    double lo = size0, hi = size0;
    while (ratio(lo) <= 1.0 && lo > 1e-12 * size0) lo *= 0.5;
    while (ratio(hi) > 1.0) hi *= 2.0;
    for (int k = 0; k < 200 && hi - lo > 4e-16 * hi; ++k) {
      const double mid = std::sqrt(lo * hi);
      (ratio(mid) > 1.0 ? lo : hi) = mid;
    }
    const bool floored = girders && hi < kMinGirderDepth;
    if (floored) hi = kMinGirderDepth;
    const double last = girders ? deck.girder_depth : deck.thickness;
    const bool settled = std::abs(hi - last) <= 1e-14 * hi;
    deck = deck_of(hi);
    const DeckBeamCheck check = CheckDeckBeams(config, deck, cases);
    deck.sized_by = floored ? "the smallest rolled girder (IPE 80)"
                    : check.utilisation >= check.SagRatio()
                        ? "bending (" + check.governing_case + ")"
                        : "sag (" + check.sag_case + ")";
    if (settled) break;
  }
  return deck;
}

}  // namespace tbridge
