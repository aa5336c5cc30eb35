#include "design/deck.h"

#include <cmath>

namespace tbridge {

Deck ComputeDeck(const BridgeConfig& b, const Material& m, const DesignConfig& d) {
  const double sigma_d = m.yield_stress / d.yield_safety_factor;
  const double g = d.gravity;
  const double L = b.span, w = b.deck_width, rho = m.density;
  const double stations = std::ldexp(1.0, b.n);  // 2^n deck beams
  Deck deck;
  deck.section_length = L / stations;
  // Eq (7)-(8) with eq (4) read as f_d = F/L + m_d g 2^n / L (SPEC.md §3): the beam's own
  // weight is part of its load, so m_d solves a quadratic whose positive root is eq (7).
  if (g > 0.0) {
    const double c1 = 3.0 * w * g * rho * rho * L * L * L / (8.0 * sigma_d);
    const double c2 = 16.0 * sigma_d * b.payload / (3.0 * w * g * g * L * L * L * rho * rho);
    const double inv4 = 1.0 / (stations * stations);
    deck.section_mass = c1 / (stations * stations * stations) + c1 * inv4 * std::sqrt(c2 + inv4);
  } else {
    // Weightless deck: sigma_d = 3/4 f_d l^2 / (w t^2) with f_d = F/L and t = m/(rho w l).
    const double l = deck.section_length;
    const double t = std::sqrt(0.75 * (b.payload / L) * l * l / (w * sigma_d));
    deck.section_mass = rho * w * l * t;
  }
  deck.thickness = deck.section_mass / (rho * w * deck.section_length);
  deck.beams_mass = stations * deck.section_mass;
  deck.total_load = b.payload + deck.beams_mass * g;
  deck.station_load = deck.total_load / stations;
  deck.node_load = deck.station_load / b.planes;
  return deck;
}

}  // namespace tbridge
