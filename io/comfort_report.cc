#include "io/comfort_report.h"

#include <algorithm>
#include <cstdio>

#include "design/pedestrian_loads.h"

namespace tbridge {

namespace {

int LevelRank(const std::string& name) {
  for (const int level : {1, 2, 3}) {
    if (name == ComfortLevelName(level)) return level;
  }
  return 4;
}

}  // namespace

std::string ComfortClassReached(const ComfortCheck& check) {
  int worst = 1;
  for (const ComfortMode& m : check.modes) worst = std::max(worst, LevelRank(m.comfort_class));
  return ComfortLevelName(worst);
}

nlohmann::json ComfortJson(const Design& d) {
  const ComfortCheck& c = d.comfort;
  nlohmann::json modes = nlohmann::json::array();
  for (const ComfortMode& m : c.modes) {
    modes.push_back({{"index", m.index},
                     {"direction", NameOf(m.direction)},
                     {"share", m.share},
                     {"frequency_hz", m.frequency_hz},
                     {"frequency_empty_hz", m.frequency_empty_hz},
                     {"modal_mass_kg", m.modal_mass_kg},
                     {"range", m.range},
                     {"load_model", m.load_model},
                     {"psi", m.psi},
                     {"equivalent_pedestrians", m.equivalent_pedestrians},
                     {"modal_force_n", m.modal_force_n},
                     {"acceleration_m_s2", m.acceleration_m_s2},
                     {"limit_m_s2", m.limit_m_s2},
                     {"node", m.node + 1},
                     {"comfort_class", m.comfort_class},
                     {"lock_in_pedestrians", m.lock_in_pedestrians},
                     {"pass", m.pass}});
  }
  const CheckStatus status = c.Status();
  return {{"status", CheckStatusName(status)},
          {"done", c.done},
          {"required", c.required},
          {"note", c.note},
          {"traffic_class", NameOf(c.traffic_class)},
          {"comfort_level", NameOf(c.comfort_level)},
          {"damping_ratio", c.damping_ratio},
          {"density_per_m2", c.density_per_m2},
          {"pedestrians", c.pedestrians},
          {"crowd_mass_kg", c.crowd_mass_kg},
          {"comfort_class", ComfortClassReached(c)},
          {"modes", modes},
          {"pass", status == CheckStatus::kPassed || status == CheckStatus::kNotRequired}};
}

nlohmann::json ComfortUnits() {
  return {{"damping_ratio", "1"},
          {"density_per_m2", "pedestrians/m^2"},
          {"pedestrians", "1"},
          {"crowd_mass_kg", "kg"},
          {"modes",
           {{"index", "1 (1-based mode number)"},
            {"share", "1"},
            {"frequency_hz", "Hz"},
            {"frequency_empty_hz", "Hz"},
            {"modal_mass_kg", "kg (shape scaled to a largest deck displacement of 1)"},
            {"range", "1 (Setra frequency range 1-4)"},
            {"psi", "1"},
            {"equivalent_pedestrians", "1"},
            {"modal_force_n", "N"},
            {"acceleration_m_s2", "m/s^2"},
            {"limit_m_s2", "m/s^2"},
            {"node", "1 (1-based node number)"},
            {"lock_in_pedestrians", "1"}}}};
}

std::vector<std::string> ComfortSummaryLines(const Design& d) {
  const ComfortCheck& c = d.comfort;
  std::vector<std::string> out;
  char text[1024];
  if (!c.done) {
    out.push_back("comfort: not checked (" + c.note + ")");
    return out;
  }
  std::snprintf(text, sizeof text,
                "comfort: %s; traffic class %s (%.3g pedestrians/m^2, %.4g on the deck, %.4g kg), "
                "comfort level %s, "
                "damping ratio %.3g; comfort class reached: %s%s%s",
                CheckStatusName(c.Status()), NameOf(c.traffic_class), c.density_per_m2,
                c.pedestrians, c.crowd_mass_kg, NameOf(c.comfort_level), c.damping_ratio,
                ComfortClassReached(c).c_str(), c.note.empty() ? "" : "; ", c.note.c_str());
  out.push_back(text);
  if (!c.required)
    out.push_back("  no deck mode below EN 1990 A2.4.3.2's triggers: comfort not required");
  for (const ComfortMode& m : c.modes) {
    std::snprintf(text, sizeof text,
                  "  mode %d %s: f = %.4g Hz (empty %.4g Hz), modal mass %.5g kg, range %d; %s; "
                  "peak acceleration "
                  "%.4g m/s^2 at node %d, limit %.3g m/s^2: %s (%s)",
                  m.index, NameOf(m.direction), m.frequency_hz, m.frequency_empty_hz,
                  m.modal_mass_kg, m.range, m.load_model.c_str(), m.acceleration_m_s2, m.node + 1,
                  m.limit_m_s2, m.pass ? "passes" : "FAILS", m.comfort_class.c_str());
    out.push_back(text);
  }
  return out;
}

}  // namespace tbridge
