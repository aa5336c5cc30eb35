#include "sweep/sweep_config.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/json_reader.h"

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

std::optional<double> OptionalNumber(JsonSection& s, const std::string& key, Range range) {
  if (!s.Has(key)) return std::nullopt;
  // null = off, so that the echoed resolved config reads back as it was.
  const nlohmann::json* raw = s.Raw(key);
  if (raw->is_null()) return std::nullopt;
  return s.Number(key, std::nullopt, range);
}

SweepConstraints ParseConstraints(JsonSection s) {
  SweepConstraints c;
  c.min_first_frequency_rad_s = OptionalNumber(s, "min_first_frequency_rad_s", Range::Positive());
  c.max_deck_displacement = OptionalNumber(s, "max_deck_displacement", Range::Positive());
  c.span_over_displacement = OptionalNumber(s, "span_over_displacement", Range::Positive());
  c.no_slack_under_service = s.Bool("no_slack_under_service", false);
  c.max_dynamic_stress_ratio = OptionalNumber(s, "max_dynamic_stress_ratio", Range::Positive());
  c.bar_capacity_during_motion = s.Bool("bar_capacity_during_motion", false);
  c.prestress_within_allowed = s.Bool("prestress_within_allowed", false);
  s.Finish();
  return c;
}

TravellingLoadConfig ParseTravellingLoad(JsonSection s) {
  TravellingLoadConfig t;
  t.duration = s.Number("duration", t.duration, Range::Closed(1e-6, 100.0));
  t.dt = s.Number("dt", t.dt, Range::Closed(1e-9, 1e-2));
  if (t.dt > t.duration) {
    throw ConfigError(s.PathOf("dt"), std::to_string(t.dt), "must be at most sweep.travelling_load.duration");
  }
  t.integrator = s.Choice("integrator", t.integrator, {"auto", "rk4", "sdirk3"});
  t.load_factor = s.Number("load_factor", t.load_factor, Range{0.0, 100.0, true, false});
  t.string_mass = s.Choice("string_mass", t.string_mass, {"bars", "nodes", "off"});
  t.damping_c = s.Number("damping_c", t.damping_c, Range::Closed(0.0, 1e9));
  s.Finish();
  return t;
}

SweepConfig ParseSweep(JsonSection s, const nlohmann::json& bridge) {
  SweepConfig c;
  c.n = s.Integers("n", std::nullopt, 1, kMaxComplexity);
  CheckGridList(c.n, s.PathOf("n"));
  c.p = s.Integers("p", std::vector<int>{1}, 1, kMaxBarsPerModule);
  CheckGridList(c.p, s.PathOf("p"));
  const double beta = bridge.is_object() && bridge.contains("beta_deg") && bridge["beta_deg"].is_number()
                          ? bridge["beta_deg"].get<double>()
                          : BridgeConfig{}.beta_deg;
  c.beta_deg = s.Numbers("beta_deg", std::vector<double>{beta}, Range::Open(0.0, 90.0));
  CheckGridList(c.beta_deg, s.PathOf("beta_deg"));
  c.deck_prestrain = s.Numbers("deck_prestrain", std::vector<double>{1.0}, Range{0.0, 1.0, true, false});
  CheckGridList(c.deck_prestrain, s.PathOf("deck_prestrain"));
  c.prestrain_sizing = s.Choice("prestrain_sizing", c.prestrain_sizing, {"grow_area", "keep_area"});
  {
    JsonSection j = s.Section("joint_mass");
    c.joint_mass.per_node_kg = j.Number("per_node_kg", 0.0, Range::Closed(0.0, 1e6));
    c.joint_mass.per_force_kg_per_N = j.Number("per_force_kg_per_N", 0.0, Range::Closed(0.0, 1.0));
    j.Finish();
  }
  c.constraints = ParseConstraints(s.Section("constraints"));
  c.travelling_load = ParseTravellingLoad(s.Section("travelling_load"));
  {
    JsonSection r = s.Section("report");
    c.report_first_frequency = r.Bool("first_frequency", false);
    c.report_travelling_load = r.Bool("travelling_load", false);
    r.Finish();
  }
  s.Finish();
  return c;
}

}  // namespace

bool SweepConfig::NeedsRun() const {
  const SweepConstraints& c = constraints;
  return report_travelling_load || c.max_deck_displacement || c.span_over_displacement ||
         c.no_slack_under_service || c.max_dynamic_stress_ratio || c.bar_capacity_during_motion;
}

SweepSpec ParseSweepSpec(const nlohmann::json& root) {
  if (!root.is_object()) throw ConfigError("(root)", Show(root), "must be a JSON object");
  if (!root.contains("sweep")) throw ConfigError("sweep", "(missing)", "required section of a sweep config");
  if (root.contains("dynamics")) {
    throw ConfigError("dynamics", "(section)",
                      "not allowed in a sweep config: the sweep's run is set in sweep.travelling_load");
  }
  const nlohmann::json bridge = root.contains("bridge") ? root["bridge"] : nlohmann::json();
  SweepSpec spec;
  spec.sweep = ParseSweep(JsonSection(root["sweep"], "sweep"), bridge);
  // The base config: bridge.n (and p, beta_deg) are set per candidate, so n may be left out.
  nlohmann::json base = root;
  base.erase("sweep");
  if (base.contains("bridge") && base["bridge"].is_object() && !base["bridge"].contains("n")) {
    base["bridge"]["n"] = spec.sweep.n.front();
  }
  spec.base = ParseConfig(base);
  if (spec.base.bridge.planes == 2) {
    for (size_t k = 0; k < spec.sweep.p.size(); ++k) {
      if (spec.sweep.p[k] != 1) {
        throw ConfigError("sweep.p[" + std::to_string(k) + "]", std::to_string(spec.sweep.p[k]),
                          "must be 1 when bridge.planes = 2");
      }
    }
  }
  return spec;
}

SweepSpec LoadSweepSpec(const std::string& path) { return ParseSweepSpec(ReadJsonFile(path)); }

nlohmann::json ToJson(const SweepSpec& spec) {
  const SweepConfig& s = spec.sweep;
  const SweepConstraints& c = s.constraints;
  auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  nlohmann::json j = ToJson(spec.base);
  j["sweep"] = {
      {"n", s.n},
      {"p", s.p},
      {"beta_deg", s.beta_deg},
      {"deck_prestrain", s.deck_prestrain},
      {"prestrain_sizing", s.prestrain_sizing},
      {"joint_mass", {{"per_node_kg", s.joint_mass.per_node_kg}, {"per_force_kg_per_N", s.joint_mass.per_force_kg_per_N}}},
      {"constraints",
       {{"min_first_frequency_rad_s", opt(c.min_first_frequency_rad_s)},
        {"max_deck_displacement", opt(c.max_deck_displacement)},
        {"span_over_displacement", opt(c.span_over_displacement)},
        {"no_slack_under_service", c.no_slack_under_service},
        {"max_dynamic_stress_ratio", opt(c.max_dynamic_stress_ratio)},
        {"bar_capacity_during_motion", c.bar_capacity_during_motion},
        {"prestress_within_allowed", c.prestress_within_allowed}}},
      {"travelling_load",
       {{"duration", s.travelling_load.duration},
        {"dt", s.travelling_load.dt},
        {"integrator", s.travelling_load.integrator},
        {"load_factor", s.travelling_load.load_factor},
        {"string_mass", s.travelling_load.string_mass},
        {"damping_c", s.travelling_load.damping_c}}},
      {"report", {{"first_frequency", s.report_first_frequency}, {"travelling_load", s.report_travelling_load}}}};
  return j;
}

}  // namespace tbridge
