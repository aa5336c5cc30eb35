#include "sweep/sweep_config.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/json_reader.h"
#include "sweep/sweep_fields.h"

namespace tbridge {

namespace {

// Non-empty, no value twice (a repeated value would evaluate one candidate twice).
template <typename T>
void CheckGridList(const std::vector<T>& values, const std::string& path) {
  if (values.empty()) throw ConfigError(path, "[]", "must list at least one value");
  for (size_t a = 0; a < values.size(); ++a) {
    for (size_t b = 0; b < a; ++b) {
      if (values[a] == values[b]) {
        std::ostringstream v;
        v << values[a];
        throw ConfigError(path + "[" + std::to_string(a) + "]", v.str(),
                          "each value may appear only once");
      }
    }
  }
}

// The keys of the sweep's own travelling-load run, which gave way to the design's dynamic check:
// each with the key that replaced it, or (`by` null) why nothing does.
struct Replaced {
  const char* key;
  const char* by;
  const char* why = nullptr;
};
constexpr Replaced kReplacedRunKeys[] = {
    {"duration",
     "loads.travelling_speed_m_s (the walking load crosses the span at it; the paper's travelling "
     "load, "
     "loads.cases \"paper_travelling\", stands 0.25 s on each station, eqs 50-51)"},
    {"dt", "loads.dynamic_dt_s"},
    {"integrator",
     "loads.dynamic_method (the check runs RK4 or the modal run, never SDIRK3, which reads peaks "
     "low)"},
    {"load_factor", "loads.travelling_load_n (the walking load) and loads.gamma_q (its factor)"},
    {"string_mass", nullptr,
     "the check's model shares each string's mass among the bars it meets (eq 27), "
     "dynamics.string_mass's default "
     "\"bars\""},
    {"damping_c", nullptr, "the check's runs are undamped, which reads the peaks high"},
    {"deck_inertia", nullptr,
     "the check carries the deck's and payload's mass at the deck nodes, except under the paper's "
     "switches "
     "(loads.cases [\"paper\"]), whose model has none"},
};

// Refuses the sweep's travelling-load run of earlier versions, naming what replaced each key.
void RefuseReplacedKeys(const nlohmann::json& sweep) {
  if (!sweep.is_object()) return;
  if (sweep.contains("travelling_load")) {
    const nlohmann::json& run = sweep["travelling_load"];
    if (run.is_object()) {
      for (const Replaced& r : kReplacedRunKeys) {
        if (run.contains(r.key)) {
          throw ConfigError(
              std::string("sweep.travelling_load.") + r.key, Show(run[r.key]),
              std::string("the sweep's own run was replaced by the design's dynamic check; ") +
                  (r.by != nullptr ? std::string("set ") + r.by
                                   : std::string("nothing replaces it: ") + r.why));
        }
      }
    }
    throw ConfigError(
        "sweep.travelling_load", Show(run),
        "the sweep's own run was replaced by the design's dynamic check, whose runs the loads "
        "section sets (loads.cases, loads.travelling_load_n, loads.travelling_speed_m_s, "
        "loads.dynamic_dt_s, loads.dynamic_method)");
  }
  if (sweep.contains("report") && sweep["report"].is_object() &&
      sweep["report"].contains("travelling_load")) {
    throw ConfigError("sweep.report.travelling_load", Show(sweep["report"]["travelling_load"]),
                      "replaced by sweep.report.dynamic_check (the design's dynamic check)");
  }
}

}  // namespace

void CheckSweepRules(const SweepConfig& s, const BridgeConfig& bridge) {
  CheckGridList(s.n, "sweep.n");
  CheckGridList(s.p, "sweep.p");
  CheckGridList(s.beta_deg, "sweep.beta_deg");
  CheckGridList(s.deck_prestrain, "sweep.deck_prestrain");
  for (size_t k = 0; k < s.p.size() && bridge.planes == 2; ++k) {
    if (s.p[k] != 1) {
      throw ConfigError("sweep.p[" + std::to_string(k) + "]", std::to_string(s.p[k]),
                        "must be 1 when bridge.planes = 2");
    }
  }
}

std::string SweepSectionText() {
  return SectionHeading(kSweepSection) + "\n" +
         SectionBody(kSweepSection, KeyTableOf(SweepConfig{}));
}

SweepSpec ParseSweepSpec(const nlohmann::json& root) {
  if (!root.is_object()) throw ConfigError("(root)", Show(root), "must be a JSON object");
  if (!root.contains("sweep"))
    throw ConfigError("sweep", "(missing)", "required section of a sweep config");
  if (root.contains("dynamics")) {
    throw ConfigError(
        "dynamics", "(section)",
        "not allowed in a sweep config: the design's dynamic check runs the loads section's "
        "dynamic loads (loads.cases)");
  }
  const nlohmann::json& bridge = root.contains("bridge") ? root["bridge"] : nlohmann::json();
  SweepSpec spec;
  // beta_deg's default is the bridge's.
  spec.sweep.beta_deg = {bridge.is_object() && bridge.contains("beta_deg") &&
                                 bridge["beta_deg"].is_number()
                             ? bridge["beta_deg"].get<double>()
                             : BridgeConfig{}.beta_deg};
  RefuseReplacedKeys(root["sweep"]);
  ParseFields(JsonSection(root["sweep"], "sweep"), spec.sweep);
  // The base config: bridge.n (and p, beta_deg) are set per candidate, so n may be left out.
  nlohmann::json base = root;
  base.erase("sweep");
  if (base.contains("bridge") && base["bridge"].is_object() && !base["bridge"].contains("n")) {
    base["bridge"]["n"] = spec.sweep.n.empty() ? 1 : spec.sweep.n.front();
  }
  spec.base = ParseConfig(base);
  if (spec.base.structure) {
    throw ConfigError("structure", "(custom scene)",
                      "a sweep designs bridges: give a \"bridge\" section instead");
  }
  CheckSweepRules(spec.sweep, spec.base.bridge);
  // With "auto" each candidate searches its own angle (sizing/angle_search.h): a list of angles
  // would design the same bridges again.
  if (spec.base.bridge.beta_auto && root["sweep"].is_object() &&
      root["sweep"].contains("beta_deg")) {
    throw ConfigError(
        "sweep.beta_deg", Show(root["sweep"]["beta_deg"]),
        "not allowed with bridge.beta_deg \"auto\": each candidate searches its own angle in "
        "design.beta_range_deg; give the angles here and a number there to sweep them instead");
  }
  return spec;
}

SweepSpec LoadSweepSpec(const std::string& path) { return ParseSweepSpec(ReadJsonFile(path)); }

void Validate(const SweepSpec& spec) {
  Validate(spec.base);
  ValidateFields(spec.sweep, kSweepSection.name);
  CheckSweepRules(spec.sweep, spec.base.bridge);
}

nlohmann::json ToJson(const SweepSpec& spec) {
  nlohmann::json j = ToJson(spec.base);
  j["sweep"] = EchoFields(spec.sweep);
  return j;
}

}  // namespace tbridge
