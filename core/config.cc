#include "core/config.h"

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

namespace {

BridgeConfig ParseBridge(JsonSection s) {
  BridgeConfig b;
  b.n = s.Integer("n", std::nullopt, 1, kMaxComplexity);  // required: no sensible default
  b.p = s.Integer("p", b.p, 1, kMaxBarsPerModule);
  b.beta_deg = s.Number("beta_deg", b.beta_deg, Range::Open(0.0, 90.0));
  b.span = s.Number("span", b.span, Range::Positive());
  b.payload = s.Number("payload", b.payload, Range::Positive());
  b.deck_width = s.Number("deck_width", b.deck_width, Range::Positive());
  b.planes = s.Integer("planes", b.planes, 1, 2);
  s.Finish();
  return b;
}

Material ParseMaterial(JsonSection s) {
  Material m;
  m.density = s.Number("density", m.density, Range::Positive());
  m.yield_stress = s.Number("yield_stress", m.yield_stress, Range::Positive());
  m.youngs_modulus = s.Number("youngs_modulus", m.youngs_modulus, Range::Positive());
  s.Finish();
  return m;
}

DesignConfig ParseDesign(JsonSection s) {
  DesignConfig d;
  d.yield_safety_factor = s.Number("yield_safety_factor", d.yield_safety_factor, Range::Closed(1, 1000));
  d.buckling_safety_factor =
      s.Number("buckling_safety_factor", d.buckling_safety_factor, Range::Closed(1, 1000));
  d.deck_string_min_radius =
      s.Number("deck_string_min_radius", d.deck_string_min_radius, Range::Closed(0.0, 1.0));
  d.transverse_string_min_radius = s.Number(
      "transverse_string_min_radius", d.transverse_string_min_radius, Range::Closed(0.0, 1.0));
  d.bar_min_radius = s.Number("bar_min_radius", d.bar_min_radius, Range::Closed(0.0, 1.0));
  d.gravity = s.Number("gravity", d.gravity, Range::Closed(0.0, 100.0));
  d.solver = s.Choice("solver", d.solver, {"auto", "direct", "ipopt", "nlopt"});
  d.tolerance = s.Number("tolerance", d.tolerance, Range::Closed(1e-14, 1e-3));
  d.max_iterations = s.Integer("max_iterations", d.max_iterations, 1, 1000000);
  s.Finish();
  return d;
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
    c.bridge = ParseBridge(top.Section("bridge"));
    c.material = ParseMaterial(top.Section("material"));
    c.design = ParseDesign(top.Section("design"));
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
  j["bridge"] = {{"n", c.bridge.n},           {"p", c.bridge.p},
                 {"beta_deg", c.bridge.beta_deg}, {"span", c.bridge.span},
                 {"payload", c.bridge.payload},   {"deck_width", c.bridge.deck_width},
                 {"planes", c.bridge.planes}};
  j["material"] = {{"density", c.material.density},
                   {"yield_stress", c.material.yield_stress},
                   {"youngs_modulus", c.material.youngs_modulus}};
  j["design"] = {{"yield_safety_factor", c.design.yield_safety_factor},
                 {"buckling_safety_factor", c.design.buckling_safety_factor},
                 {"deck_string_min_radius", c.design.deck_string_min_radius},
                 {"transverse_string_min_radius", c.design.transverse_string_min_radius},
                 {"bar_min_radius", c.design.bar_min_radius},
                 {"gravity", c.design.gravity},
                 {"solver", c.design.solver},
                 {"tolerance", c.design.tolerance},
                 {"max_iterations", c.design.max_iterations}};
  if (c.dynamics) j["dynamics"] = ToJson(*c.dynamics);
  return j;
}

}  // namespace tbridge
