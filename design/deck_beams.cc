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

DeckBeamCheck CheckDeckBeams(const Config& config, const Deck& deck,
                             const std::vector<LoadCase>& cases) {
  const double l = deck.section_length, w = config.bridge.deck_width, t = deck.thickness;
  const double E = config.material.youngs_modulus;
  const double vertical_modulus = w * t * t / 6.0,
               lateral_modulus = t * w * w / 6.0;  // elastic, [m^3]
  const double inertia = w * t * t * t / 12.0;     // [m^4]
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
// with t, the section modulus with t^2, the inertia with t^3).
double WorstRatio(const DeckBeamCheck& c) { return std::max(c.utilisation, c.SagRatio()); }

}  // namespace

Deck SizeDeckBeams(const Config& config, const Deck& start) {
  if (KeepsPaperSwitches(config)) return start;
  const BridgeConfig& b = config.bridge;
  const Material& m = config.material;
  const DesignConfig& d = config.design;
  std::vector<std::string> notes;
  Deck deck = start;
  // The paper's travelling load f = F_tot / 2^n carries the beams' own weight: the cases
  // follow the deck, so repeat until the thickness holds still (a few rounds: f changes by
  // the beams' share of F_tot).
  for (int round = 0; round < 50; ++round) {
    const std::vector<LoadCase> cases = MakeLoadCases(config, deck, notes);
    auto ratio = [&](double t) {
      return WorstRatio(CheckDeckBeams(config, DeckOfThickness(b, m, d, t), cases));
    };
    if (!(ratio(start.thickness * 1e3) > 0)) return start;  // no case loads the beams: eq 7 stays
    // Bracket the thinnest passing plate from eq 7's, then bisect in log t to the last bit.
    double lo = start.thickness, hi = start.thickness;
    while (ratio(lo) <= 1.0 && lo > 1e-12 * start.thickness) lo *= 0.5;
    while (ratio(hi) > 1.0) hi *= 2.0;
    for (int k = 0; k < 200 && hi - lo > 4e-16 * hi; ++k) {
      const double mid = std::sqrt(lo * hi);
      (ratio(mid) > 1.0 ? lo : hi) = mid;
    }
    const bool settled = std::abs(hi - deck.thickness) <= 1e-14 * hi;
    deck = DeckOfThickness(b, m, d, hi);
    const DeckBeamCheck check = CheckDeckBeams(config, deck, cases);
    deck.sized_by = check.utilisation >= check.SagRatio() ? "bending (" + check.governing_case + ")"
                                                          : "sag (" + check.sag_case + ")";
    if (settled) break;
  }
  return deck;
}

}  // namespace tbridge
