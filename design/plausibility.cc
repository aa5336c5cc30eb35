#include "design/plausibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <utility>

#include "design/abutments.h"

namespace tbridge {

namespace {

std::string Format(const char* format, double a, double b = 0) {
  char buf[96];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

// Which members CountMembers looks at; the deck strings are strings.
enum class Among { kBars, kStrings, kMembers };

// "3 bars ... (worst 1-8: ...)" over every member where `bad` holds; `worst` orders them.
void CountMembers(const Design& d, const std::function<bool(const MemberSizing&)>& bad,
                  const std::function<double(const MemberSizing&)>& score, Among among,
                  const std::string& what,
                  const std::function<std::string(const MemberSizing&)>& show,
                  std::vector<std::string>& out) {
  int count = 0;
  const MemberSizing* worst = nullptr;
  auto visit = [&](const MemberSizing& m) {
    if (!bad(m)) return;
    ++count;
    if (worst == nullptr || score(m) > score(*worst)) worst = &m;
  };
  if (among != Among::kStrings) {
    for (const MemberSizing& m : d.bars) visit(m);
  }
  if (among != Among::kBars) {
    for (const MemberSizing& m : d.strings) visit(m);
  }
  if (count == 0) return;
  const char* noun = among == Among::kBars      ? " bar"
                     : among == Among::kStrings ? " string"
                                                : " member";
  out.push_back(std::to_string(count) + noun + (count == 1 ? " " : "s ") + what + " (worst " +
                worst->name + ": " + show(*worst) + ")");
}

// One abutment's largest horizontal reaction over the ultimate cases, with that case's load.
struct AbutmentThrust {
  Abutment abutment;
  double h = -1;      // [N], the in-plan vector sum of its nodes' horizontal reactions
  double w = 0;       // [N], the case's total vertical load
  double thrust = 0;  // [N], that load's own thrust W L / (8 d)
  std::string label;  // the case
  double Ratio() const { return h / thrust; }
};

// Warns where an abutment's horizontal reaction over the ultimate cases exceeds
// kMaxAbutmentThrustRatio times the thrust the load of that case gives by itself; not where the
// config gives the abutments a capacity, which the static check holds them to.
void CheckAbutmentThrust(const Design& d, std::vector<std::string>& out) {
  if (d.config.supports.horizontal_capacity_n) return;
  const Structure& s = d.topology.structure;
  const double span = d.config.bridge.span;
  const std::array<Abutment, 2> abutments = AbutmentsOf(s, span);
  AbutmentThrust ends[2];
  double deck = 0;
  int supports = 0;
  for (int e = 0; e < 2; ++e) {
    ends[e].abutment = abutments[static_cast<size_t>(e)];
    for (const int v : ends[e].abutment.nodes) deck += s.nodes(1, v), ++supports;
  }
  if (ends[0].abutment.nodes.empty() || ends[1].abutment.nodes.empty()) return;
  // The substructure's depth at mid-span: from the deck level (the supports' height: they are
  // the deck's ends) down to the lowest node within a quarter span of mid-span. There the p = 1
  // bridge has its deepest node, L/2 tan(beta/2) under mid-span; a module of p >= 2 bars has
  // its deepest vertices off the middle (at 3/8 and 5/8 of the span for p = 2), still inside.
  deck /= supports;
  double lowest = deck;
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (std::abs(s.nodes(0, v) - span / 2) <= span / 4) lowest = std::min(lowest, s.nodes(1, v));
  }
  const double depth = deck - lowest;  // [m]
  if (!(depth > 0)) return;
  for (const CaseResponse& c : d.statics.cases) {
    if (!c.converged || c.case_index < 0 || c.case_index >= static_cast<int>(d.cases.size()) ||
        d.cases[c.case_index].state != LimitState::kUltimate ||
        c.reactions.cols() != s.num_nodes()) {
      continue;
    }
    // The reactions balance every applied load: their vertical sum is the load.
    const double w =
        ReactionOf(ends[0].abutment, c.reactions).y + ReactionOf(ends[1].abutment, c.reactions).y;
    if (!(w > 0)) continue;
    for (AbutmentThrust& end : ends) {
      const double h = ReactionOf(end.abutment, c.reactions).Horizontal();
      if (h <= end.h) continue;
      end.h = h;
      end.w = w;
      end.thrust = w * span / (8 * depth);
      end.label = c.label;
    }
  }
  // The worse end named in full, the other's numbers added when it is beyond the ratio too.
  const int worst = ends[1].h > ends[0].h * (1 + 1e-9) ? 1 : 0;  // x = 0 first when alike
  const AbutmentThrust& a = ends[worst];
  const AbutmentThrust& other = ends[1 - worst];
  if (a.label.empty() || !(a.Ratio() > kMaxAbutmentThrustRatio)) return;
  std::string text =
      AbutmentName(a.abutment) +
      " takes a horizontal reaction H = " + Format("%.4g kN", a.h / 1000) + " (" + a.label + "), " +
      Format("%.3g times", a.Ratio()) +
      " the load path's own thrust W L / (8 d) = " + Format("%.4g kN", a.thrust / 1000) +
      " (W = " + Format("%.4g kN", a.w / 1000) +
      ", that case's vertical load; L = " + Format("%g m; d = %.3g m", span, depth) +
      ", the substructure's depth at mid-span), above " +
      Format("%g times", kMaxAbutmentThrustRatio);
  if (!other.label.empty() && other.Ratio() > kMaxAbutmentThrustRatio) {
    text += "; " + AbutmentName(other.abutment) + " takes " +
            Format("%.4g kN, %.3g times", other.h / 1000, other.Ratio());
  }
  out.push_back(
      text +
      ": there prestress, not the load, sets the thrust, so the abutments must be designed for it, "
      "as a stressed ribbon's anchorage is");
}

}  // namespace

std::vector<std::string> ConfigWarnings(const Config& c) {
  std::vector<std::string> out;
  // The bridge's density, and each member kind's own where it gives one.
  const std::pair<const char*, std::optional<double>> densities[] = {
      {"material.density", c.material.density},
      {"material.strings.density", c.material.strings.density},
      {"material.bars.density", c.material.bars.density}};
  for (const auto& [key, density] : densities) {
    if (!density || *density >= kMinPlausibleDensity) continue;
    out.push_back(
        std::string(key) + " = " + Format("%g", *density) + " kg/m^3 is below " +
        Format("%g", kMinPlausibleDensity) +
        " kg/m^3, lighter than water: timber is about 450, steel 7850; a density given in "
        "t/m^3 or g/cm^3 is 1000 times too small");
  }
  // The paper's one case has no partial factors, and its 12 kN on 12 m is its own.
  if (KeepsPaperSwitches(c)) return out;
  if (c.loads.gamma_g_inf == 0) {
    out.push_back(
        "loads.gamma_g_inf = 0 leaves the permanent load out of the favourable cases, which no "
        "code does (EN 1990 A2 set B: 1.0): did you mean 1?");
  }
  const double span = c.bridge.span, width = c.bridge.deck_width;
  const double pressure = c.bridge.payload / (span * width);  // [Pa]
  const std::string payload = "bridge.payload = " + Format("%g N", c.bridge.payload) +
                              " over the " + Format("%g m x %g m deck", span, width) + " is " +
                              Format("%.3g kPa", pressure / 1000);
  // EN 1991-2 5.3.2.1's footbridge crowd, 2.5 to 5 kPa, on this deck.
  const std::string crowd = "2.5 to 5 kPa, EN 1991-2 5.3.2.1: between " +
                            Format("%g N and %g N here", 2500 * span * width, 5000 * span * width);
  if (pressure < kMinPlausiblePayloadPressure) {
    out.push_back(payload + ", below " + Format("%g kPa", kMinPlausiblePayloadPressure / 1000) +
                  ": a footbridge crowd is " + crowd +
                  "; a payload given in kN is 1000 times too small");
  } else if (pressure > kMaxPlausiblePayloadPressure) {
    out.push_back(payload + ", above " + Format("%g kPa", kMaxPlausiblePayloadPressure / 1000) +
                  ", ten times a footbridge crowd (" + crowd +
                  "): is the payload or bridge.deck_width in the wrong unit?");
  }
  if (width > kMaxPlausibleDeckWidth) {
    out.push_back("bridge.deck_width = " + Format("%g m", width) + " is wider than " +
                  Format("%g m", kMaxPlausibleDeckWidth) +
                  ", a motorway of six lanes: a footbridge deck is 2 to 5 m wide; a width given in "
                  "mm is 1000 "
                  "times too large (" +
                  Format("%g mm is %g m)", width, width / 1000));
  }
  return out;
}

std::vector<std::string> PlausibilityWarnings(const Design& d) {
  std::vector<std::string> out = ConfigWarnings(d.config);
  CountMembers(
      d, [](const MemberSizing& m) { return m.length < kMinMemberLength; },
      [](const MemberSizing& m) { return -m.length; }, Among::kMembers, "shorter than 1 mm",
      [](const MemberSizing& m) { return Format("%.3g m", m.length); }, out);
  CountMembers(
      d, [](const MemberSizing& m) { return 2 * m.radius > m.length; },
      [](const MemberSizing& m) { return m.radius / m.length; }, Among::kBars,
      "thicker than long (diameter > length)",
      [](const MemberSizing& m) {
        return Format("diameter %.3g m, length %.3g m", 2 * m.radius, m.length);
      },
      out);
  CountMembers(
      d,
      [](const MemberSizing& m) {
        return m.radius > 0 && m.length / m.radius > kMaxBarSlenderness;
      },
      [](const MemberSizing& m) { return m.length / m.radius; }, Among::kBars,
      "more slender than l/r = " + Format("%g", kMaxBarSlenderness),
      [](const MemberSizing& m) { return Format("l/r = %.4g", m.length / m.radius); }, out);
  const double t = d.deck.thickness, span = d.config.bridge.span;
  if (t < kMinDeckThickness) {
    out.push_back("deck thickness " + Format("%.3g m", t) + " is below 1 mm");
  }
  if (t > kMaxDeckThicknessPerSpan * span) {
    out.push_back("deck thickness " +
                  Format("%.3g m exceeds span / 10 = %.3g m", t, kMaxDeckThicknessPerSpan * span));
  }
  // An engineering design only: the paper's blanket factor of 10 makes its members thick on
  // purpose.
  if (!KeepsPaperSwitches(d.config)) {
    CountMembers(
        d, [](const MemberSizing& m) { return 2 * m.radius > kMaxPlausibleStringDiameter; },
        [](const MemberSizing& m) { return m.radius; }, Among::kStrings,
        "thicker than " + Format("%g mm", kMaxPlausibleStringDiameter * 1000) +
            " in diameter, more than the largest cables made (about 180 mm)",
        [](const MemberSizing& m) { return Format("diameter %.4g mm", 2000 * m.radius); }, out);
    const double per_metre = d.mass.total / span;  // [kg/m]
    if (per_metre > kMaxPlausibleMassPerSpan) {
      out.push_back(
          "mass.total = " + Format("%.6g kg", d.mass.total) + " is " +
          Format("%.3g t per metre of the %g m span", per_metre / 1000, span) + ", above " +
          Format("%g t/m", kMaxPlausibleMassPerSpan / 1000) +
          ": a steel road bridge weighs about 1 to 2 t/m, a footbridge a few hundred kg/m; are "
          "bridge.payload, bridge.deck_width and material.density in SI units?");
    }
    CheckAbutmentThrust(d, out);
    const double per_area =
        d.deck.section_mass / (d.config.bridge.deck_width * d.deck.section_length);
    if (d.deck.girder_depth == 0 && per_area > kMaxPlausiblePlateDeckMass) {
      out.push_back(
          "the deck is a solid plate " +
          Format("%.4g mm thick over its sections of l = %.4g m", t * 1e3, d.deck.section_length) +
          Format(" (%.0f kg/m^2, ", per_area) + "set by " + d.deck.sized_by + ")" +
          Format(", heavier than %g kg/m^2 (40 mm of steel)", kMaxPlausiblePlateDeckMass) +
          ": a deck of such sections is carried by girders (design.deck_section "
          "\"girders\")");
    }
  }
  const std::pair<const char*, double> masses[] = {{"bars", d.mass.bars},
                                                   {"strings", d.mass.strings},
                                                   {"structure", d.mass.structure},
                                                   {"total", d.mass.total}};
  for (const auto& [name, mass] : masses) {
    if (mass < kMinPrintedMass) {
      out.push_back(std::string("mass.") + name + " = " + Format("%.3g kg", mass) +
                    " prints as 0.000 kg (below half a gram)");
    }
  }
  return out;
}

}  // namespace tbridge
