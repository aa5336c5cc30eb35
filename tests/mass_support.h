// A bridge's mass recomputed from what it is built of, not from its mass breakdown: each
// member's rho pi r^2 times the distance between its end nodes, and the deck beams' stress
// under their own load (paper eqs 4-6), for tests of the reported masses.
#pragma once

#include <cmath>

#include "design/design.h"

namespace tbridge::test {

// Member masses [kg] of a planar design from its node coordinates and member radii (solid
// circular sections, SPEC §4). The deck strings are the strings with both ends on the deck
// line y = 0, found from the geometry rather than from the members' groups.
struct MemberMasses {
  double bars = 0, strings = 0, deck_strings = 0;
};

inline MemberMasses MassFromMembers(const Design& d) {
  const Eigen::Matrix3Xd& x = d.topology.structure.nodes;
  const double rho = d.config.material.density;
  const auto mass = [&](const MemberSizing& m) {
    return rho * M_PI * m.radius * m.radius * (x.col(m.j) - x.col(m.i)).norm();
  };
  MemberMasses out;
  for (const MemberSizing& b : d.bars) out.bars += mass(b);
  for (const MemberSizing& s : d.strings) {
    const bool on_deck = x(1, s.i) == 0.0 && x(1, s.j) == 0.0;
    (on_deck ? out.deck_strings : out.strings) += mass(s);
  }
  return out;
}

// The largest bending stress [Pa] of one deck beam when 2^n beams of `beams_mass` [kg] in total
// span the design's deck: Navier's sigma = 3/4 f_d l_d^2 / (w_d t_d^2) (eq 5) under the line load
// f_d = F/L + 2^n m_d g / L (eq 4 as SPEC §3 corrects it), with the thickness t_d = m_d /
// (rho w_d l_d) (eq 6) that the mass implies. Eq 7 sizes the beams so that this is sigma_w.
inline double DeckBeamStress(const Design& d, double beams_mass) {
  const BridgeConfig& b = d.config.bridge;
  const double beams = std::ldexp(1.0, b.n), l_d = b.span / beams, m_d = beams_mass / beams;
  const double t_d = m_d / (d.config.material.density * b.deck_width * l_d);
  const double f_d = b.payload / b.span + beams_mass * d.config.design.gravity / b.span;
  return 0.75 * f_d * l_d * l_d / (b.deck_width * t_d * t_d);
}

// The members' working stress sigma_w = sigma_yield / gamma [Pa] (SPEC §1), which the deck
// beams work at too.
inline double WorkingStress(const Design& d) {
  return d.config.material.yield_stress / d.config.design.yield_safety_factor;
}

}  // namespace tbridge::test
