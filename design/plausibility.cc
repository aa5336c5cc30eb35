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

// "3 bars ... (worst 1-8: ...)" over every member where `bad` holds; `worst` orders them.
void CountMembers(const Design& d, const std::function<bool(const MemberSizing&)>& bad,
                  const std::function<double(const MemberSizing&)>& score, bool bars_only, const std::string& what,
                  const std::function<std::string(const MemberSizing&)>& show, std::vector<std::string>& out) {
  int count = 0;
  const MemberSizing* worst = nullptr;
  auto visit = [&](const MemberSizing& m) {
    if (!bad(m)) return;
    ++count;
    if (worst == nullptr || score(m) > score(*worst)) worst = &m;
  };
  for (const MemberSizing& m : d.bars) visit(m);
  if (!bars_only) {
    for (const MemberSizing& m : d.strings) visit(m);
  }
  if (count == 0) return;
  out.push_back(std::to_string(count) + (bars_only ? " bar" : " member") + (count == 1 ? " " : "s ") + what +
                " (worst " + worst->name + ": " + show(*worst) + ")");
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
  // The paper's one case has no partial factors.
  if (c.loads.gamma_g_inf == 0 && !KeepsPaperSwitches(c)) {
    out.push_back(
        "loads.gamma_g_inf = 0 leaves the permanent load out of the favourable cases, which no "
        "code does (EN 1990 A2 set B: 1.0): did you mean 1?");
  }
  return out;
}

std::vector<std::string> PlausibilityWarnings(const Design& d) {
  std::vector<std::string> out = ConfigWarnings(d.config);
  CountMembers(
      d, [](const MemberSizing& m) { return m.length < kMinMemberLength; },
      [](const MemberSizing& m) { return -m.length; }, false, "shorter than 1 mm",
      [](const MemberSizing& m) { return Format("%.3g m", m.length); }, out);
  CountMembers(
      d, [](const MemberSizing& m) { return 2 * m.radius > m.length; },
      [](const MemberSizing& m) { return m.radius / m.length; }, true, "thicker than long (diameter > length)",
      [](const MemberSizing& m) { return Format("diameter %.3g m, length %.3g m", 2 * m.radius, m.length); }, out);
  CountMembers(
      d, [](const MemberSizing& m) { return m.radius > 0 && m.length / m.radius > kMaxBarSlenderness; },
      [](const MemberSizing& m) { return m.length / m.radius; }, true,
      "more slender than l/r = " + Format("%g", kMaxBarSlenderness),
      [](const MemberSizing& m) { return Format("l/r = %.4g", m.length / m.radius); }, out);
  const double t = d.deck.thickness, span = d.config.bridge.span;
  if (t < kMinDeckThickness) {
    out.push_back("deck thickness " + Format("%.3g m", t) + " is below 1 mm");
  }
  if (t > kMaxDeckThicknessPerSpan * span) {
    out.push_back("deck thickness " + Format("%.3g m exceeds span / 10 = %.3g m", t, kMaxDeckThicknessPerSpan * span));
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
