#include "core/config.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/config_fields.h"
#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

namespace {

// bridge: the rule across keys (kBridgeSection.rules).
void CheckBridgeRules(const BridgeConfig& b) {
  if (b.planes == 2 && b.p != 1) {
    throw ConfigError("bridge.p", std::to_string(b.p), "must be 1 when bridge.planes = 2");
  }
}

// material: the rule across keys (kMaterialSection.rules).
void CheckMaterialRules(const Material& m) {
  auto modulus_above_yield = [](const std::string& section, double E, double f) {
    if (E > f) return;
    throw ConfigError(section + "youngs_modulus", NumberText(E),
                      "must exceed " + section + "yield_stress = " + NumberText(f) +
                          " Pa: a strain at yield of " + NumberText(f / E) +
                          " is no structural material (steel: 0.0017); are both in Pa?");
  };
  modulus_above_yield("material.", m.youngs_modulus, m.yield_stress);
  const MemberMaterial strings = StringMaterial(m, 1.0), bars = BarMaterial(m, 1.0);
  modulus_above_yield("material.strings.", strings.youngs_modulus, strings.yield_stress);
  modulus_above_yield("material.bars.", bars.youngs_modulus, bars.yield_stress);
  if (m.strings.breaking_stress && !(*m.strings.breaking_stress > strings.yield_stress)) {
    throw ConfigError("material.strings.breaking_stress", NumberText(*m.strings.breaking_stress),
                      "must exceed the strings' proof strength yield_stress = " +
                          NumberText(strings.yield_stress) +
                          " Pa: a cable breaks above its 0.2 % proof stress");
  }
  if (m.strings.end_efficiency && !m.strings.breaking_stress) {
    throw ConfigError(
        "material.strings.end_efficiency", NumberText(*m.strings.end_efficiency),
        "applies to a cable's breaking strength: give material.strings.breaking_stress with it");
  }
}

// loads: the rules across keys (kLoadsSection.rules).
void CheckLoadsRules(const LoadsConfig& l) {
  const auto& c = l.cases;
  if (c.size() > 1 && l.Asks(LoadFamily::kPaper)) {
    throw ConfigError(
        "loads.cases", "[\"paper\", ...]",
        "\"paper\" stands alone: it is the paper's one unfactored case, which replaces the others");
  }
  if (c.empty()) throw ConfigError("loads.cases", "[]", "must list at least one case");
  const bool temperature = l.Asks(LoadFamily::kTemperature);
  if (temperature && !(l.temperature_delta_k > 0)) {
    throw ConfigError("loads.temperature_delta_k", NumberText(l.temperature_delta_k),
                      "must be > 0 with \"temperature\" in loads.cases: the change either way [K]");
  }
  if (!temperature && l.temperature_delta_k > 0) {
    throw ConfigError("loads.temperature_delta_k", NumberText(l.temperature_delta_k),
                      "needs \"temperature\" in loads.cases, or 0 (no temperature case)");
  }
  if (temperature && c.size() == 1) {
    throw ConfigError(
        "loads.cases", "[\"temperature\"]",
        "the temperature accompanies the other cases: list it with one of \"permanent\", "
        "\"payload\", \"travelling\", \"paper_travelling\", \"wind\"");
  }
  if (l.gamma_g_inf > l.gamma_g_sup) {
    throw ConfigError("loads.gamma_g_inf", NumberText(l.gamma_g_inf),
                      "must not exceed loads.gamma_g_sup = " + NumberText(l.gamma_g_sup));
  }
}

// bridge and loads together: the cases asked for must leave one this bridge carries ("wind"
// is dropped on a planar bridge, design/load_cases.h).
// design: the rules across keys (kDesignSection.rules).
void CheckDesignRules(const DesignConfig& d) {
  const std::vector<double>& r = d.beta_range_deg;
  if (r.size() != 2 || !(r[0] < r[1])) {
    throw ConfigError("design.beta_range_deg", nlohmann::json(r).dump(),
                      "must be two angles [low, high] with low < high, each in [1, 90) deg");
  }
}

// loads.cases is the paper's one case: its switches hold (KeepsPaperSwitches).
bool PaperCasesOnly(const LoadsConfig& l) {
  return l.cases == std::vector<LoadFamily>{LoadFamily::kPaper};
}

void CheckAngleForCases(const BridgeConfig& b, const LoadsConfig& l) {
  if (b.beta_auto && PaperCasesOnly(l)) {
    throw ConfigError(
        "bridge.beta_deg", "\"auto\"",
        "must be a number with loads.cases [\"paper\"]: the paper's design is checked, not "
        "resized, at its own angle; \"auto\" chooses the angle by the verified design");
  }
}

void CheckDeckForCases(const DesignConfig& d, const LoadsConfig& l) {
  if (d.deck_section == DeckSection::kGirders && PaperCasesOnly(l)) {
    throw ConfigError("design.deck_section", "\"girders\"",
                      "must be \"plate\" with loads.cases [\"paper\"]: the paper's deck is eq "
                      "7's plate, and its design keeps it");
  }
}

void CheckCasesForBridge(const BridgeConfig& b, const LoadsConfig& l) {
  // The temperature only accompanies: it leaves no case of its own.
  const auto wind = [](LoadFamily c) {
    return c == LoadFamily::kWind || c == LoadFamily::kTemperature;
  };
  if (b.planes == 1 && std::all_of(l.cases.begin(), l.cases.end(), wind)) {
    throw ConfigError("loads.cases", nlohmann::json(NamesIn(kLoadFamilyNames, l.cases)).dump(),
                      "leaves no load case to design for: a planar bridge (bridge.planes = 1) "
                      "carries no transverse load, so \"wind\" is left out; list at least one of "
                      "\"paper\", \"permanent\", \"payload\", \"travelling\", "
                      "\"paper_travelling\" (or set bridge.planes = 2 for wind)");
  }
}

// The keys of `material` and `design` a structure to design reads (truss/); the others are
// the bridge's, refused there rather than ignored.
const std::vector<std::string> kStructureMaterialKeys{"density", "youngs_modulus"};
const std::vector<std::string> kStructureDesignKeys{
    "self_weight", "gravity", "buckling_safety_factor", "solver", "tolerance", "max_iterations"};

void RequireKeysOf(const nlohmann::json& root, const char* section,
                   const std::vector<std::string>& keys) {
  if (!root.contains(section) || !root.at(section).is_object()) return;
  for (const auto& [key, value] : root.at(section).items()) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      std::string list;
      for (const std::string& k : keys) list += (list.empty() ? "" : ", ") + k;
      throw ConfigError(
          std::string(section) + "." + key, Show(value),
          "not read for a structure to design: " + std::string(section) + " takes " + list);
    }
  }
}

}  // namespace

void ApplyPaperSwitches(Config& c) {
  c.design.self_weight = false;
  c.design.yield_safety_factor = 10.0;
  c.design.buckling_safety_factor = 1.0;
  c.design.bar_resistance = BarResistanceRule::kEuler;
  c.design.deck_section = DeckSection::kPlate;
  c.loads.cases = {LoadFamily::kPaper};
  if (c.dynamics) {
    c.dynamics->deck_inertia = false;
    c.dynamics->gravity_on_structure = false;
  }
}

bool KeepsPaperSwitches(const Config& c) { return PaperCasesOnly(c.loads); }

Config ParseConfig(const nlohmann::json& root) {
  JsonSection top(root, "");
  Config c;
  if (top.Has("structure")) {
    if (top.Has("bridge")) {
      throw ConfigError(
          "structure", "(given with 'bridge')",
          "a config has either \"bridge\" (a designed bridge) or \"structure\" (a custom scene), "
          "not both");
    }
    c.structure = ParseStructureConfig(top.Section("structure"));
    const bool designable = c.structure->Designable();
    for (const char* section : {"material", "design", "loads", "comfort", "supports"}) {
      const bool beside_members =
          designable && (std::string(section) == "material" || std::string(section) == "design");
      if (top.Has(section) && !beside_members) {
        throw ConfigError(section, "(section)",
                          designable
                              ? "not allowed with \"structure\": a structure to design takes "
                                "\"material\" and \"design\" beside it, its loads in "
                                "structure.load_cases"
                              : "not allowed with \"structure\": a custom scene gives its masses, "
                                "stiffnesses and rest lengths directly");
      }
    }
    if (designable) {
      RequireKeysOf(root, "material", kStructureMaterialKeys);
      RequireKeysOf(root, "design", kStructureDesignKeys);
      c.material = ParseSection<Material>(top.Section("material"), CheckMaterialRules);
      c.design = ParseSection<DesignConfig>(top.Section("design"), CheckDesignRules);
    }
  } else {
    if (!top.Has("bridge")) {
      throw ConfigError("bridge", "(missing)",
                        "required section (or \"structure\" for a custom scene)");
    }
    c.bridge = ParseSection<BridgeConfig>(top.Section("bridge"), CheckBridgeRules);
    c.material = ParseSection<Material>(top.Section("material"), CheckMaterialRules);
    c.design = ParseSection<DesignConfig>(top.Section("design"), CheckDesignRules);
    c.loads = ParseSection<LoadsConfig>(top.Section("loads"), CheckLoadsRules);
    CheckCasesForBridge(c.bridge, c.loads);
    CheckAngleForCases(c.bridge, c.loads);
    CheckDeckForCases(c.design, c.loads);
    c.comfort = ParseSection<ComfortConfig>(top.Section("comfort"));
    c.supports = ParseSection<SupportsConfig>(top.Section("supports"));
  }
  if (top.Has("dynamics")) {
    c.dynamics = ParseDynamicsConfig(top.Section("dynamics"));
    // For a designed bridge the structure's weight in a run follows the design's, unless set.
    const nlohmann::json& dynamics = root.at("dynamics");
    if (!c.structure && dynamics.is_object() && !dynamics.contains("gravity_on_structure")) {
      c.dynamics->gravity_on_structure = c.design.self_weight;
    }
  }
  top.Finish();
  return c;
}

Config LoadConfig(const std::string& path) { return ParseConfig(ReadJsonFile(path)); }

nlohmann::json ToJson(const Config& c) {
  nlohmann::json j;
  if (c.structure) {
    j["structure"] = ToJson(*c.structure);
    if (c.structure->Designable()) {  // only the keys a structure to design reads
      const nlohmann::json material = EchoFields(c.material), design = EchoFields(c.design);
      for (const std::string& k : kStructureMaterialKeys) j["material"][k] = material.at(k);
      for (const std::string& k : kStructureDesignKeys) j["design"][k] = design.at(k);
    }
    if (c.dynamics) j["dynamics"] = ToJson(*c.dynamics);
    return j;
  }
  j["bridge"] = EchoFields(c.bridge);
  j["material"] = EchoFields(c.material);
  j["design"] = EchoFields(c.design);
  j["loads"] = EchoFields(c.loads);
  j["comfort"] = EchoFields(c.comfort);
  j["supports"] = EchoFields(c.supports);
  if (c.dynamics) j["dynamics"] = ToJson(*c.dynamics);
  return j;
}

void Validate(const Config& c) {
  if (c.structure) {  // a custom scene: bridge, material and design are not used
    ValidateFields(*c.structure, kStructureSection.name);
    CheckStructureRules(*c.structure);
    if (c.structure->Designable()) {
      ValidateFields(c.material, kMaterialSection.name);
      CheckMaterialRules(c.material);
      ValidateFields(c.design, kDesignSection.name);
      CheckDesignRules(c.design);
    }
  } else {
    ValidateFields(c.bridge, kBridgeSection.name);
    CheckBridgeRules(c.bridge);
    ValidateFields(c.material, kMaterialSection.name);
    CheckMaterialRules(c.material);
    ValidateFields(c.design, kDesignSection.name);
    CheckDesignRules(c.design);
    ValidateFields(c.loads, kLoadsSection.name);
    CheckLoadsRules(c.loads);
    CheckCasesForBridge(c.bridge, c.loads);
    CheckAngleForCases(c.bridge, c.loads);
    CheckDeckForCases(c.design, c.loads);
    ValidateFields(c.comfort, kComfortSection.name);
    ValidateFields(c.supports, kSupportsSection.name);
  }
  if (c.dynamics) {
    ValidateFields(*c.dynamics, kDynamicsSection.name);
    CheckDynamicsRules(*c.dynamics);
  }
}

std::string ConfigSectionText(const SectionInfo& section) {
  return SectionHeading(section) + "\n" + SectionBody(section, ConfigKeyTable(section.name));
}

std::string ConfigKeyTable(const std::string& section) {
  if (section == kBridgeSection.name) return KeyTableOf(BridgeConfig{});
  if (section == kMaterialSection.name) return KeyTableOf(Material{});
  if (section == kDesignSection.name) return KeyTableOf(DesignConfig{});
  if (section == kLoadsSection.name) return KeyTableOf(LoadsConfig{});
  if (section == kComfortSection.name) return KeyTableOf(ComfortConfig{});
  if (section == kSupportsSection.name) return KeyTableOf(SupportsConfig{});
  if (section == kDynamicsSection.name) return KeyTableOf(DynamicsConfig{});
  if (section == kStructureSection.name) return KeyTableOf(StructureConfig{});
  throw std::invalid_argument("ConfigKeyTable: no described section '" + section + "'");
}

}  // namespace tbridge
