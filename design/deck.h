// Deck beams and node loads (paper eqs 3-9, corrected per SPEC.md §3).
#pragma once

#include <string>

#include "core/config.h"

namespace tbridge {

struct Deck {
  double section_length = 0;  // l_d = L / 2^n [m]
  double section_mass = 0;    // m_d, one deck beam [kg] (eq 7)
  double thickness = 0;       // t_d = m_d / (rho w_d l_d) [m] (eq 6); girders: the same ratio
  double girder_depth = 0;    // h of each of the two girders [m]; 0: a plate deck
  double beams_mass = 0;      // 2^n m_d [kg]
  double total_load = 0;      // F_tot = F + 2^n m_d g [N] (eq 9)
  double node_load = 0;       // load on each loaded deck node: F_tot / (2^n planes) [N]
  double station_load = 0;    // F_tot / 2^n, the paper's f for a planar bridge [N]
  // What set the thickness: "eq 7" (the paper's deck: the payload and its own weight at
  // sigma_d), or the deck-beam check that governs an engineering design (design/deck_beams.h).
  std::string sized_by = "eq 7";
};

// Largest magnitude a derived load, length or mass may have: the solver forms products and
// squares of the loads, which must stay finite in double precision (about 1e308).
inline constexpr double kMaxComputable = 1e100;

// sigma_d = yield_stress / yield_safety_factor. Throws ConfigError (CheckComputable) when the
// inputs give a deck quantity that cannot be computed.
Deck ComputeDeck(const BridgeConfig& bridge, const Material& material, const DesignConfig& design);
// The deck of beams `thickness_m` thick, with the loads that follow (eqs 6 and 9). Throws
// ConfigError (CheckComputable) as ComputeDeck does.
Deck DeckOfThickness(const BridgeConfig& bridge, const Material& material,
                     const DesignConfig& design, double thickness_m);

// A deck girder of depth h (design.deck_section "girders") has a rolled I-section's
// proportions: its area A = kGirderAreaAt100mm (h / 0.1 m)^kGirderAreaExponent and its second
// moment I = kGirderInertiaRatio A h^2, a fit to the IPE 100-600 series (EN 10365's tables:
// A within 3 %, I within 4.1 %; tests/design/deck_beams_test.cc). Beyond IPE 600 it stands for
// a welded girder of the same proportions.
inline constexpr double kGirderAreaAt100mm = 10.0e-4;  // [m^2]
inline constexpr double kGirderAreaExponent = 1.53;
inline constexpr double kGirderInertiaRatio = 0.17;
// The shallowest girder the deck gets [m]: IPE 80, the smallest rolled I-section. Shorter
// sections need less, but a shallower one is no girder: the decking's own stiffeners.
inline constexpr double kMinGirderDepth = 0.08;
double GirderArea(double depth_m);     // [m^2]
double GirderInertia(double depth_m);  // [m^4]

// The deck of two girders `depth_m` deep, one under each edge of the deck, with the loads that
// follow (eq 9); its thickness is the plate's of the same mass. Throws ConfigError
// (CheckComputable) as ComputeDeck does.
Deck DeckOfGirders(const BridgeConfig& bridge, const Material& material, const DesignConfig& design,
                   double depth_m);

// Throws ConfigError when a quantity of `deck` is not finite, not positive (underflow) or not
// below kMaxComputable. It names the input farthest from its default in orders of magnitude
// (span, payload, deck width, density, yield stress, safety factor, gravity), its value, and
// the quantity.
void CheckComputable(const Deck& deck, const BridgeConfig& bridge, const Material& material,
                     const DesignConfig& design);

}  // namespace tbridge
