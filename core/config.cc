#include "core/config.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/config_fields.h"
#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

namespace {

// Reads every described key of a section from JSON, strictly; a key's current value (the
// struct's default) is its fallback unless the key is required.
struct ParseVisitor {
  JsonSection& section;
  void Number(const KeyInfo& key, double& field, Range range) {
    field = section.Number(key.name, key.required ? std::nullopt : std::optional<double>(field), range);
  }
  void Integer(const KeyInfo& key, int& field, int lo, int hi) {
    field = section.Integer(key.name, key.required ? std::nullopt : std::optional<int>(field), lo, hi);
  }
  void Choice(const KeyInfo& key, std::string& field, const std::vector<std::string>& allowed) {
    field = section.Choice(key.name, key.required ? std::nullopt : std::optional<std::string>(field), allowed);
  }
};

// Writes every described key of a section into a JSON object: the echo.
struct EchoVisitor {
  nlohmann::json& out;
  template <class T>
  void Value(const KeyInfo& key, const T& field) {
    out[key.name] = field;
  }
  void Number(const KeyInfo& key, double field, Range) { Value(key, field); }
  void Integer(const KeyInfo& key, int field, int, int) { Value(key, field); }
  void Choice(const KeyInfo& key, const std::string& field, const std::vector<std::string>&) { Value(key, field); }
};

// Checks every described key of a section built in code against its range, with the messages
// the parse gives for the same value.
struct ValidateVisitor {
  std::string section;
  std::string Path(const KeyInfo& key) const { return section + "." + key.name; }
  void Number(const KeyInfo& key, double field, Range range) const {
    if (!std::isfinite(field) || !range.Contains(field)) {
      throw ConfigError(Path(key), NumberText(field), "must be " + range.Describe());
    }
  }
  void Integer(const KeyInfo& key, int field, int lo, int hi) const {
    if (field < lo || field > hi) throw ConfigError(Path(key), std::to_string(field), "must be " + IntegerRangeText(lo, hi));
  }
  void Choice(const KeyInfo& key, const std::string& field, const std::vector<std::string>& allowed) const {
    if (std::find(allowed.begin(), allowed.end(), field) == allowed.end()) {
      throw ConfigError(Path(key), "\"" + Printable(field) + "\"", "must be one of " + ChoiceText(allowed));
    }
  }
};

// One Markdown row per key: | `key` | unit | default | allowed | what it controls |.
struct TableVisitor {
  std::string rows;
  void Row(const KeyInfo& key, const std::string& fallback, const std::string& allowed) {
    rows += std::string("| `") + key.name + "` | " + key.unit + " | " + (key.required ? "required" : fallback) +
            " | " + allowed + " | " + key.what + " |\n";
  }
  void Number(const KeyInfo& key, double field, Range range) { Row(key, NumberText(field), range.Interval()); }
  void Integer(const KeyInfo& key, int field, int lo, int hi) {
    Row(key, std::to_string(field), "integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  void Choice(const KeyInfo& key, const std::string& field, const std::vector<std::string>& allowed) {
    std::string list;
    for (size_t k = 0; k < allowed.size(); ++k) {
      list += (k == 0 ? "" : k + 1 == allowed.size() ? " or " : ", ") + ("`\"" + allowed[k] + "\"`");
    }
    Row(key, "`\"" + field + "\"`", list);
  }
};

template <class T>
T ParseSection(JsonSection s) {
  T config;
  ParseVisitor visitor{s};
  DescribeFields(config, visitor);
  s.Finish();
  return config;
}

template <class T>
nlohmann::json EchoSection(const T& config) {
  nlohmann::json out = nlohmann::json::object();
  EchoVisitor visitor{out};
  DescribeFields(config, visitor);
  return out;
}

template <class T>
void ValidateSection(const T& config, const SectionInfo& info) {
  ValidateVisitor visitor{info.name};
  DescribeFields(config, visitor);
}

template <class T>
std::string TableOf() {
  T config;
  TableVisitor visitor;
  DescribeFields(config, visitor);
  return "| key | unit | default | allowed | what it controls |\n|---|---|---|---|---|\n" + visitor.rows;
}

// bridge: the rule across keys (kBridgeSection.rules).
void CheckBridgeRules(const BridgeConfig& b) {
  if (b.planes == 2 && b.p != 1) {
    throw ConfigError("bridge.p", std::to_string(b.p), "must be 1 when bridge.planes = 2");
  }
}

}  // namespace

Config ParseConfig(const nlohmann::json& root) {
  JsonSection top(root, "");
  Config c;
  if (top.Has("structure")) {
    if (top.Has("bridge")) {
      throw ConfigError("structure", "(given with 'bridge')",
                        "a config has either \"bridge\" (a designed bridge) or \"structure\" (a custom scene), "
                        "not both");
    }
    for (const char* section : {"material", "design"}) {
      if (top.Has(section)) {
        throw ConfigError(section, "(section)",
                          "not allowed with \"structure\": a custom scene gives its masses, stiffnesses and rest "
                          "lengths directly");
      }
    }
    c.structure = ParseStructureConfig(top.Section("structure"));
  } else {
    if (!top.Has("bridge")) {
      throw ConfigError("bridge", "(missing)", "required section (or \"structure\" for a custom scene)");
    }
    c.bridge = ParseSection<BridgeConfig>(top.Section("bridge"));
    CheckBridgeRules(c.bridge);
    c.material = ParseSection<Material>(top.Section("material"));
    c.design = ParseSection<DesignConfig>(top.Section("design"));
  }
  if (top.Has("dynamics")) c.dynamics = ParseDynamicsConfig(top.Section("dynamics"));
  top.Finish();
  return c;
}

Config LoadConfig(const std::string& path) { return ParseConfig(ReadJsonFile(path)); }

nlohmann::json ToJson(const Config& c) {
  nlohmann::json j;
  if (c.structure) {
    j["structure"] = ToJson(*c.structure);
    if (c.dynamics) j["dynamics"] = ToJson(*c.dynamics);
    return j;
  }
  j["bridge"] = EchoSection(c.bridge);
  j["material"] = EchoSection(c.material);
  j["design"] = EchoSection(c.design);
  if (c.dynamics) j["dynamics"] = ToJson(*c.dynamics);
  return j;
}

void Validate(const Config& c) {
  if (c.structure) return;  // a custom scene: bridge, material and design are not used
  ValidateSection(c.bridge, kBridgeSection);
  CheckBridgeRules(c.bridge);
  ValidateSection(c.material, kMaterialSection);
  ValidateSection(c.design, kDesignSection);
}

std::string ConfigSectionText(const SectionInfo& section) {
  std::string text = std::string("## `") + section.name + "`: " + section.title + "\n\n";
  if (*section.rules) text += std::string("Rules across keys: ") + section.rules + "\n\n";
  return text + ConfigKeyTable(section.name);
}

std::string ConfigKeyTable(const std::string& section) {
  if (section == kBridgeSection.name) return TableOf<BridgeConfig>();
  if (section == kMaterialSection.name) return TableOf<Material>();
  if (section == kDesignSection.name) return TableOf<DesignConfig>();
  throw std::invalid_argument("ConfigKeyTable: no described section '" + section + "'");
}

}  // namespace tbridge
