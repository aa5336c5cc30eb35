// The "structure" section of a config (a custom scene): strict parsing, every bad input a
// ConfigError naming the key, and the resolved config echoing back to itself.

#include "core/structure_config.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "config_expect.h"
#include "core/config.h"
#include "core/json_reader.h"

namespace tbridge {
namespace {

using nlohmann::json;
using test::ExpectRejected;

// A planar scene with every key of the section; tests break one key at a time.
json GoodScene() {
  return json::parse(R"({
    "structure": {
      "dim": 2,
      "nodes": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
      "pinned": [1],
      "node_masses": [{"node": 3, "mass_kg": 0.5}],
      "bars": [{"nodes": [1, 3], "mass_kg": 1}, {"nodes": [2, 4], "mass_kg": 2}],
      "strings": [
        {"nodes": [1, 2], "stiffness_n_m": 100, "rest_length_m": 0.9, "damping_n_s_m": 1,
         "mass_kg": 0.1, "area_m2": 1e-4},
        {"nodes": [2, 3], "stiffness_n_m": 50, "rest_ratio": 0.95}
      ],
      "loads": [{"node": 3, "force_n": [0, -10, 0]}],
      "deck_nodes": [2, 3],
      "allowed_stress_pa": 1e8,
      "gravity_m_s2": 9.80665
    },
    "dynamics": {"duration": 0.1, "dt": 1e-3}
  })");
}

// GoodScene with the value at JSON pointer `where` set to `value` (or removed: Without).
json With(const std::string& where, const json& value) {
  json c = GoodScene();
  c[json::json_pointer(where)] = value;
  return c;
}

json Without(const std::string& where) {
  json c = GoodScene();
  const json::json_pointer p(where);
  c[p.parent_pointer()].erase(p.back());
  return c;
}

TEST_CASE("structure: a full section is read as written") {
  const Config c = ParseConfig(GoodScene());
  REQUIRE(c.structure);
  const StructureConfig& s = *c.structure;
  CHECK(s.dim == 2);
  CHECK(s.nodes.size() == 4);
  CHECK(s.pinned == std::vector<int>{1});
  CHECK(s.bars[1].nodes == std::array<int, 2>{2, 4});
  CHECK(s.bars[1].mass_kg == 2.0);  // exact: copied from JSON
  CHECK(s.strings[0].rest_length_m == 0.9);
  CHECK(!s.strings[0].rest_ratio);
  CHECK(s.strings[1].rest_ratio == 0.95);
  CHECK(s.strings[1].damping_n_s_m == 0.0);  // default
  CHECK(!s.strings[1].area_m2);
  // rest_ratio x length of the unit string 2-3: one multiplication, so to the last bit.
  CHECK(s.RestLength(1) == 0.95);
  CHECK(s.loads[0].force_n == std::array<double, 3>{0, -10, 0});
  CHECK(s.allowed_stress_pa == 1e8);
  CHECK(c.dynamics);
}

TEST_CASE("structure: defaults of a minimal section") {
  const Config c = ParseConfig(json::parse(R"({"structure": {"nodes": [[0, 0, 0], [0, 0, 1]],
    "bars": [{"nodes": [1, 2], "mass_kg": 1}]}})"));
  REQUIRE(c.structure);
  CHECK(c.structure->dim == 3);
  CHECK(c.structure->pinned.empty());
  CHECK(c.structure->strings.empty());
  CHECK(!c.structure->allowed_stress_pa);
  CHECK(c.structure->gravity_m_s2 == 9.81);
  CHECK(!c.dynamics);
}

TEST_CASE("structure: the resolved config parses back to itself") {
  for (const std::string name : {"motes_prism", "motes_dbar"}) {
    INFO(name);
    const json echoed = ToJson(LoadConfig(TBRIDGE_SOURCE_DIR "/configs/" + name + ".json"));
    // Exact: doubles are written with round-trip precision.
    CHECK(ToJson(ParseConfig(echoed)) == echoed);
    // Only the scene and its run are echoed: no bridge, material or design of defaults.
    CHECK(echoed.size() == 2);
    CHECK(echoed.contains("structure"));
    CHECK(echoed.contains("dynamics"));
  }
  const json echoed = ToJson(ParseConfig(GoodScene()));
  CHECK(ToJson(ParseConfig(echoed)) == echoed);
  CHECK(echoed["structure"]["strings"][0]["area_m2"] == 1e-4);
  CHECK(!echoed["structure"]["strings"][1].contains("rest_length_m"));
}

TEST_CASE("structure: bridge and structure together, and the design sections, are rejected") {
  ExpectRejected(With("/bridge", json{{"n", 2}}), "structure", "bridge", "either \"bridge\"");
  for (const std::string section : {"material", "design"}) {
    ExpectRejected(With("/" + section, json::object()), section, "(section)",
                   "not allowed with \"structure\"");
  }
  ExpectRejected(json::object(), "bridge", "(missing)", "or \"structure\"");
}

TEST_CASE("structure: unknown keys at every level") {
  ExpectRejected(With("/structure/spam", 1), "structure.spam", "1", "unknown key");
  ExpectRejected(With("/structure/bars/1/length", 2), "structure.bars[1].length", "2",
                 "unknown key");
  ExpectRejected(With("/structure/strings/0/k", 2), "structure.strings[0].k", "2", "unknown key");
}

TEST_CASE("structure: node numbers out of range or repeated") {
  ExpectRejected(With("/structure/bars/0/nodes", json{1, 5}), "structure.bars[0].nodes[1]", "5",
                 "an integer in [1, 4]");
  ExpectRejected(With("/structure/strings/1/nodes", json{0, 2}), "structure.strings[1].nodes[0]",
                 "0", "an integer in [1, 4]");
  ExpectRejected(With("/structure/bars/0/nodes", json{1, 2, 3}), "structure.bars[0].nodes",
                 "3 numbers", "two node numbers");
  ExpectRejected(With("/structure/bars/0/nodes", json{3, 3}), "structure.bars[0].nodes", "[3, 3]",
                 "two different nodes");
  ExpectRejected(With("/structure/strings/1/nodes", json{2, 1}), "structure.strings[1].nodes",
                 "[2, 1]", "the same nodes as structure.strings[0]");
  ExpectRejected(With("/structure/pinned", json{1, 1}), "structure.pinned[1]", "1", "at most once");
  ExpectRejected(With("/structure/loads/0/node", 7), "structure.loads[0].node", "7",
                 "an integer in [1, 4]");
  ExpectRejected(With("/structure/node_masses/1", json{{"node", 3}, {"mass_kg", 1}}),
                 "structure.node_masses[1].node", "3", "at most once");
  ExpectRejected(With("/structure/deck_nodes", json{1, 2}), "structure.deck_nodes[0]", "1",
                 "is pinned");
}

TEST_CASE("structure: geometry and member values out of range") {
  ExpectRejected(With("/structure/nodes/2", json{0, 0, 0}), "structure.bars[0].nodes", "[1, 3]",
                 "same position");
  ExpectRejected(With("/structure/nodes/3", json{0, 1, 0.25}), "structure.nodes[3][2]", "0.25",
                 "must be 0: structure.dim is 2");
  ExpectRejected(With("/structure/nodes/0", json{0, 0}), "structure.nodes[0]", "[0,0]",
                 "3 finite numbers");
  ExpectRejected(With("/structure/nodes", json::array()), "structure.nodes", "[]",
                 "a list of 1 to");
  ExpectRejected(With("/structure/loads/0/force_n", json{0, 0, 1}), "structure.loads[0].force_n[2]",
                 "1", "must be 0: structure.dim is 2");
  ExpectRejected(With("/structure/strings/0/rest_length_m", 0),
                 "structure.strings[0].rest_length_m", "0", "> 0");
  ExpectRejected(With("/structure/strings/0/rest_ratio", 0.9), "structure.strings[0].rest_ratio",
                 "rest_length_m", "not both");
  ExpectRejected(Without("/structure/strings/1/rest_ratio"), "structure.strings[1].rest_length_m",
                 "(missing)", "or rest_ratio > 0");
  ExpectRejected(With("/structure/strings/1/stiffness_n_m", -1),
                 "structure.strings[1].stiffness_n_m", "-1", ">= 0");
  ExpectRejected(With("/structure/bars/0/mass_kg", -0.5), "structure.bars[0].mass_kg", "-0.5",
                 ">= 0");
  ExpectRejected(Without("/structure/bars/0/mass_kg"), "structure.bars[0].mass_kg", "(missing)",
                 "required");
  ExpectRejected(With("/structure/dim", 1), "structure.dim", "1", "an integer in [2, 3]");
  ExpectRejected(Without("/structure/allowed_stress_pa"), "structure.allowed_stress_pa",
                 "(missing)", "when a string has area_m2");
}

}  // namespace
}  // namespace tbridge
