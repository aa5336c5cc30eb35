// The one description of each core config section (core/config_fields.h, dynamics_fields.h,
// structure_fields.h) against what the parse accepts, what the echo writes, what Validate()
// refuses and what configs/README.md documents.
#include "core/config_fields.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "config_fields_support.h"
#include "core/config.h"
#include "core/error.h"

namespace tbridge {
namespace {

using nlohmann::json;
using test::CheckDescribedSection;
using test::DescribedSection;

// A dynamics section with every key and one element in each list.
json FullDynamics() {
  return json::parse(
      R"({"duration": 0.5, "dt": 1e-4, "integrator": "rk4", "engine": "classk", "rtol": 1e-6,
    "atol": 1e-9, "string_mass": "nodes", "damping_c": 2, "stabilisation": {"enabled": true, "omega_rad_s": 50,
    "zeta": 0.5}, "prestrain": [{"group": "deck", "ratio": 0.95}], "perturbation": {"bar_class": 1, "delta": 0.01},
    "initial": [{"node": 2, "displacement": [0, 0.01, 0], "velocity": [0, 0, 0.1]}],
    "loads": [{"t_start": 0, "t_end": 0.1, "node": 3, "force": [0, -10, 0], "rise_s": 0.02, "fall_s": 0.05}],
    "record": {"nodes": [2, 3], "every": 5, "csv": false, "bar_forces": true},
    "frequency": {"enabled": false, "every": 20}, "guard": {"max_bar_length_error": 0.01, "max_energy_growth": 2},
    "gravity_on_structure": true, "limits": {"max_steps": 300000000, "max_output_bytes": 1e9}})");
}

// A planar scene with every key; strings[0] gives rest_length_m and area_m2, strings[1]
// rest_ratio.
json FullScene() {
  return json::parse(
      R"({"dim": 2, "nodes": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], "pinned": [1],
    "node_masses": [{"node": 3, "mass_kg": 0.5}], "bars": [{"nodes": [1, 3], "mass_kg": 1}],
    "strings": [{"nodes": [1, 2], "stiffness_n_m": 100, "damping_n_s_m": 1, "rest_length_m": 0.9,
                 "mass_kg": 0.1, "area_m2": 1e-4},
                {"nodes": [2, 3], "stiffness_n_m": 50, "rest_ratio": 0.95}],
    "loads": [{"node": 3, "force_n": [0, -10, 0]}], "deck_nodes": [2, 3], "allowed_stress_pa": 1e8,
    "gravity_m_s2": 9.80665})");
}

// The scene with a structure to design's keys as well: every key of the section.
json FullStructure() {
  json s = FullScene();
  s.update(json::parse(R"({"members": [{"nodes": [1, 2], "group": "g"}],
    "groups": [{"name": "g", "kind": "truss", "min_area_m2": 1e-4, "max_area_m2": 1e-2,
                "allowed_tension_pa": 1e8, "allowed_compression_pa": 1e8, "buckling": "euler"}],
    "load_cases": [{"name": "c", "factor": 1.5, "loads": [{"node": 3, "force_n": [0, -10, 0]}]}],
    "limits": {"displacements": [{"node": 3, "axis": "y", "max_m": 0.01}], "min_frequencies_hz": [5]}})"));
  return s;
}

// The structure section's keys one by one, without its rules across keys: a section with every
// key given has both a scene's bars and a design's members, which the rules forbid together
// (tests/core/structure_config_test.cc and structure_design_config_test.cc hold those rules).
StructureConfig StructureFieldsOf(const json& j) {
  StructureConfig s;
  ParseFields(JsonSection(j, "structure"), s);
  return s;
}

// A config of bridge n = 3 with `section` set to `j`.
json WithSection(const std::string& section, const json& j) {
  json root = {{"bridge", {{"n", 3}}}};
  root[section] = j;
  return root;
}

template <class S>
DescribedSection<S> CoreSection(const SectionInfo& info, S Config::*member, S full) {
  const std::string name = info.name;
  return {info, ConfigSectionText(info), full,
          [name, member](const json& j) { return ParseConfig(WithSection(name, j)).*member; },
          [member](const S& s) {
            Config c;
            c.bridge.n = 3;
            c.*member = s;
            Validate(c);
          }};
}

TEST_CASE("parse, echo, Validate and the README agree on every described key", "[config][fields]") {
  const std::string readme = test::ReadmeText();
  BridgeConfig bridge;
  bridge.n = 3;
  CheckDescribedSection(CoreSection(kBridgeSection, &Config::bridge, bridge), readme);
  // Every optional key of the member kinds given (a cable for the strings, a tube for the bars),
  // so that each is echoed and probed.
  Material material;
  material.strings = {{7850.0, 1.37e9, 1.6e11, 0.9, 1.2e-5}, 1.57e9, 0.9};
  material.bars = {7850.0, 3.55e8, 2.1e11, 1.0, 2.4e-5};
  CheckDescribedSection(CoreSection(kMaterialSection, &Config::material, material), readme);
  CheckDescribedSection(CoreSection(kDesignSection, &Config::design, DesignConfig{}), readme);
  CheckDescribedSection(CoreSection(kLoadsSection, &Config::loads, LoadsConfig{}), readme);
  CheckDescribedSection(CoreSection(kComfortSection, &Config::comfort, ComfortConfig{}), readme);
  // Both capacities given, so that each is echoed and probed.
  SupportsConfig supports;
  supports.horizontal_capacity_n = 1e6;
  supports.vertical_capacity_n = 5e5;
  CheckDescribedSection(CoreSection(kSupportsSection, &Config::supports, supports), readme);
  CheckDescribedSection(
      DescribedSection<DynamicsConfig>{
          kDynamicsSection, ConfigSectionText(kDynamicsSection),
          *ParseConfig(WithSection("dynamics", FullDynamics())).dynamics,
          [](const json& j) { return *ParseConfig(WithSection("dynamics", j)).dynamics; },
          [](const DynamicsConfig& d) {
            Config c;
            c.bridge.n = 3;
            c.dynamics = d;
            Validate(c);
          }},
      readme);
  CheckDescribedSection(
      DescribedSection<StructureConfig>{
          kStructureSection, ConfigSectionText(kStructureSection),
          StructureFieldsOf(FullStructure()), StructureFieldsOf,
          [](const StructureConfig& s) { ValidateFields(s, kStructureSection.name); }},
      readme);
}

TEST_CASE("Validate: a default config passes, the rules across keys hold in code too",
          "[config][fields]") {
  Config c;
  CHECK_NOTHROW(Validate(c));
  c.bridge.planes = 2;
  c.bridge.p = 2;
  try {
    Validate(c);
    FAIL("p = 2 with planes = 2 accepted");
  } catch (const ConfigError& e) {
    CHECK(e.key() == "bridge.p");
    CHECK_THAT(e.what(), Catch::Contains("planes = 2"));
  }

  // Each rule of dynamics and structure: the parse and Validate give the same message.
  struct Rule {
    json root;
    std::function<void(Config&)> break_it;
  };
  const json dynamics = WithSection("dynamics", FullDynamics());
  const json scene = {{"structure", FullScene()}};
  auto with = [](json root, const std::string& where, const json& value) {
    root[json::json_pointer(where)] = value;
    return root;
  };
  const std::vector<Rule> rules = {
      {with(dynamics, "/dynamics/dt", 1.0), [](Config& k) { k.dynamics->dt = 1.0; }},
      {with(dynamics, "/dynamics/loads/0/t_end", 0),
       [](Config& k) { k.dynamics->loads[0].t_end = 0; }},
      {with(dynamics, "/dynamics/loads/0/rise_s", 0.08),  // with fall_s 0.05: 0.13 s in 0.1 s
       [](Config& k) { k.dynamics->loads[0].rise_s = 0.08; }},
      {with(dynamics, "/dynamics/prestrain/1", json{{"group", "deck"}, {"ratio", 0.9}}),
       [](Config& k) {
         k.dynamics->prestrain.push_back({MemberGroup::kDeck, 0.9});
       }},
      {with(scene, "/structure/nodes/2", json{0, 0, 0}),
       [](Config& k) {
         k.structure->nodes[2] = {0, 0, 0};
       }},
      {with(scene, "/structure/nodes/3/2", 0.5), [](Config& k) { k.structure->nodes[3][2] = 0.5; }},
      {with(scene, "/structure/strings/1/nodes", json{2, 1}),
       [](Config& k) {
         k.structure->strings[1].nodes = {2, 1};
       }},
      {with(scene, "/structure/strings/1/rest_length_m", 1),
       [](Config& k) { k.structure->strings[1].rest_length_m = 1; }},
      {with(scene, "/structure/deck_nodes", json{1}),
       [](Config& k) { k.structure->deck_nodes = {1}; }},
      {with(scene, "/structure/pinned", json{1, 1}),
       [](Config& k) {
         k.structure->pinned = {1, 1};
       }},
  };
  for (const Rule& rule : rules) {
    const std::string parsed = test::ErrorOf([&] { ParseConfig(rule.root); }).what();
    INFO("parse: " << parsed);
    Config k = ParseConfig(rule.root.contains("structure") ? scene : dynamics);
    rule.break_it(k);
    CHECK(std::string(test::ErrorOf([&] { Validate(k); }).what()) == parsed);
  }
}

}  // namespace
}  // namespace tbridge
