#include "design/deck.h"

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {
namespace {

// Eq 9's loads from the beams' mass, then the check that all is computable.
void FillLoads(Deck& deck, const BridgeConfig& b, const Material& m, const DesignConfig& d) {
  const double stations = std::ldexp(1.0, b.n);
  deck.beams_mass = stations * deck.section_mass;
  deck.total_load = b.payload + deck.beams_mass * d.gravity;
  deck.station_load = deck.total_load / stations;
  deck.node_load = deck.station_load / b.planes;
  CheckComputable(deck, b, m, d);
}

}  // namespace

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
  FillLoads(deck, b, m, d);
  return deck;
}

Deck DeckOfThickness(const BridgeConfig& b, const Material& m, const DesignConfig& d,
                     double thickness_m) {
  Deck deck;
  deck.section_length = b.span / std::ldexp(1.0, b.n);
  deck.thickness = thickness_m;
  deck.section_mass = m.density * b.deck_width * deck.section_length * thickness_m;
  FillLoads(deck, b, m, d);
  return deck;
}

double GirderArea(double depth_m) {
  return kGirderAreaAt100mm * std::pow(depth_m / 0.1, kGirderAreaExponent);
}

double GirderInertia(double depth_m) {
  return kGirderInertiaRatio * GirderArea(depth_m) * depth_m * depth_m;
}

Deck DeckOfGirders(const BridgeConfig& b, const Material& m, const DesignConfig& d,
                   double depth_m) {
  Deck deck;
  deck.section_length = b.span / std::ldexp(1.0, b.n);
  deck.girder_depth = depth_m;
  deck.section_mass = 2.0 * m.density * GirderArea(depth_m) * deck.section_length;
  deck.thickness = deck.section_mass / (m.density * b.deck_width * deck.section_length);
  FillLoads(deck, b, m, d);
  return deck;
}

void CheckComputable(const Deck& deck, const BridgeConfig& b, const Material& m,
                     const DesignConfig& d) {
  const std::pair<const char*, double> derived[] = {
      {"deck section length L / 2^n", deck.section_length},
      {"deck beam mass m_d (eq 7)", deck.section_mass},
      {"deck thickness (eq 6)", deck.thickness},
      {"total load F_tot (eq 9)", deck.total_load},
      {"deck node load", deck.node_load}};
  for (const auto& [what, value] : derived) {
    if (std::isfinite(value) && value > 0 && value < kMaxComputable) continue;
    // The input farthest from its default, in orders of magnitude, is the likeliest cause.
    const BridgeConfig b0;
    const Material m0;
    const DesignConfig d0;
    const std::tuple<const char*, double, double> inputs[] = {
        {"bridge.span", b.span, b0.span},
        {"bridge.payload", b.payload, b0.payload},
        {"bridge.deck_width", b.deck_width, b0.deck_width},
        {"material.density", m.density, m0.density},
        {"material.yield_stress", m.yield_stress, m0.yield_stress},
        {"design.yield_safety_factor", d.yield_safety_factor, d0.yield_safety_factor},
        {"design.gravity", d.gravity, d0.gravity}};
    const char* key = "bridge.span";
    double input = b.span, farthest = -1;
    for (const auto& [name, v, v0] : inputs) {
      if (!(v > 0)) continue;  // gravity 0 is a weightless deck, not an extreme
      const double orders = std::abs(std::log10(v / v0));
      if (orders > farthest) {
        farthest = orders;
        key = name;
        input = v;
      }
    }
    throw ConfigError(key, NumberText(input),
                      std::string("gives a ") + what + " of " + NumberText(value) +
                          ", outside what can be computed (finite, > 0 and < " +
                          NumberText(kMaxComputable) +
                          "): bring the inputs nearer to a real bridge (configs/README.md)");
  }
}

}  // namespace tbridge
