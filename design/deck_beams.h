// The deck beams as members of an engineering design: each is a plate of the deck's width
// spanning one section l_d between two deck stations, simply supported on them (one-way, the
// whole width carrying the load). Checked for bending at the ultimate cases and for its own
// sag between its stations at the serviceability cases; sized to the thinnest plate that
// passes both (docs/verified_sizing.md).
#pragma once

#include <string>
#include <vector>

#include "core/config.h"
#include "design/deck.h"
#include "design/load_cases.h"
#include "design/verification.h"

namespace tbridge {

// What one case puts on one deck beam: line loads along it [N/m] and a point load at its middle
// [N], where the travelling load bends it most.
struct DeckBeamLoad {
  double vertical_n_per_m = 0;  // its own weight, the superimposed dead load, the payload
  double point_n = 0;           // the travelling load
  double lateral_n_per_m = 0;   // wind, bending the plate about its strong axis
};
DeckBeamLoad DeckBeamLoadOf(const LoadCase& c, const Config& config, const Deck& deck);

struct DeckBeamCheck {
  // Ultimate: the largest bending stress over the ultimate cases, at the beam's middle.
  double utilisation = 0;           // stress_ed / stress_rd
  double stress_ed_pa = 0;          // M_v / (w t^2 / 6) + M_h / (t w^2 / 6)
  double stress_rd_pa = 0;          // yield_stress / yield_safety_factor
  double moment_ed_nm = 0;          // M_v = p l^2 / 8 + P l / 4 of the governing case [N m]
  double lateral_moment_ed_nm = 0;  // M_h = p_h l^2 / 8 of the governing case [N m]
  std::string governing_case;       // empty when no ultimate case loads the beams
  // Serviceability: the largest sag at the middle, 5 p l^4 / (384 E I) + P l^3 / (48 E I).
  double sag_m = 0;
  double sag_limit_m = 0;  // l_d / loads.deck_sag_limit
  std::string sag_case;    // empty when no serviceability case is checked
  double SagRatio() const { return sag_limit_m > 0 ? sag_m / sag_limit_m : 0.0; }
  // Failed when the stress or the sag exceeds its limit (1e-9 allows for a beam sized to it).
  CheckStatus Status() const;
};

// The check of `deck`'s beams under `cases`. Changes nothing.
DeckBeamCheck CheckDeckBeams(const Config& config, const Deck& deck,
                             const std::vector<LoadCase>& cases);

// The thinnest deck that passes CheckDeckBeams under the config's load cases, `start` (eq 7)
// when no case loads the beams. The paper's switches keep eq 7's deck (`start`).
Deck SizeDeckBeams(const Config& config, const Deck& start);

}  // namespace tbridge
