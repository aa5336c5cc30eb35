#include "design/plausibility.h"

#include <cstdio>
#include <functional>
#include <optional>
#include <utility>

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
    out.push_back(std::string(key) + " = " + Format("%g", *density) + " kg/m^3 is below " +
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
  if (pressure < kMinPlausiblePayloadPressure) {
    out.push_back(payload + ", below " + Format("%g kPa", kMinPlausiblePayloadPressure / 1000) +
                  ": a footbridge crowd is 2.5 to 5 kPa (EN 1991-2 5.3.2.1), so between " +
                  Format("%g N and %g N here", 2500 * span * width, 5000 * span * width) +
                  "; a payload given in kN is 1000 times too small");
  } else if (pressure > kMaxPlausiblePayloadPressure) {
    out.push_back(payload + ", above " + Format("%g kPa", kMaxPlausiblePayloadPressure / 1000) +
                  ", ten times a footbridge crowd (2.5 to 5 kPa, EN 1991-2 5.3.2.1: between " +
                  Format("%g N and %g N here", 2500 * span * width, 5000 * span * width) +
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
    out.push_back("deck thickness " + Format("%.3g m exceeds span / 10 = %.3g m", t, kMaxDeckThicknessPerSpan * span));
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
  }
  const std::pair<const char*, double> masses[] = {
      {"bars", d.mass.bars}, {"strings", d.mass.strings}, {"structure", d.mass.structure}, {"total", d.mass.total}};
  for (const auto& [name, mass] : masses) {
    if (mass < kMinPrintedMass) {
      out.push_back(std::string("mass.") + name + " = " + Format("%.3g kg", mass) +
                    " prints as 0.000 kg (below half a gram)");
    }
  }
  return out;
}

}  // namespace tbridge
