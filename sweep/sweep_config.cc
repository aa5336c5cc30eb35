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
        throw ConfigError(path + "[" + std::to_string(a) + "]", v.str(), "each value may appear only once");
      }
    }
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
  if (s.travelling_load.dt > s.travelling_load.duration) {
    throw ConfigError("sweep.travelling_load.dt", std::to_string(s.travelling_load.dt),
                      "must be at most sweep.travelling_load.duration");
  }
}

std::string SweepSectionText() {
  return SectionHeading(kSweepSection) + "\n" +
         SectionBody(kSweepSection, KeyTableOf(SweepConfig{}));
}

bool SweepConfig::NeedsRun() const {
  const SweepConstraints& c = constraints;
  return report.travelling_load || c.max_deck_displacement || c.span_over_displacement ||
         c.no_slack_under_service || c.max_dynamic_stress_ratio || c.bar_capacity_during_motion;
}

SweepSpec ParseSweepSpec(const nlohmann::json& root) {
  if (!root.is_object()) throw ConfigError("(root)", Show(root), "must be a JSON object");
  if (!root.contains("sweep")) throw ConfigError("sweep", "(missing)", "required section of a sweep config");
  if (root.contains("dynamics")) {
    throw ConfigError("dynamics", "(section)",
                      "not allowed in a sweep config: the sweep's run is set in sweep.travelling_load");
  }
  const nlohmann::json& bridge = root.contains("bridge") ? root["bridge"] : nlohmann::json();
  SweepSpec spec;
  // beta_deg's default is the bridge's.
  spec.sweep.beta_deg = {bridge.is_object() && bridge.contains("beta_deg") &&
                                 bridge["beta_deg"].is_number()
                             ? bridge["beta_deg"].get<double>()
                             : BridgeConfig{}.beta_deg};
  ParseFields(JsonSection(root["sweep"], "sweep"), spec.sweep);
  // The base config: bridge.n (and p, beta_deg) are set per candidate, so n may be left out.
  nlohmann::json base = root;
  base.erase("sweep");
  if (base.contains("bridge") && base["bridge"].is_object() && !base["bridge"].contains("n")) {
    base["bridge"]["n"] = spec.sweep.n.empty() ? 1 : spec.sweep.n.front();
  }
  spec.base = ParseConfig(base);
  if (spec.base.structure) {
    throw ConfigError("structure", "(custom scene)", "a sweep designs bridges: give a \"bridge\" section instead");
  }
  CheckSweepRules(spec.sweep, spec.base.bridge);
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
