// The "structure" section's designable form (members in groups, load cases, limits: truss/):
// strict parsing, every bad input a ConfigError naming the key, the echo, and the scene's keys and
// the bridge's sections kept apart from it.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "config_expect.h"
#include "core/config.h"
#include "core/error.h"

namespace tbridge {
namespace {

using nlohmann::json;
using test::ExpectRejected;

// A planar two-bar truss to design with every key of the designable form.
json GoodTruss() {
  return json::parse(R"({
    "structure": {
      "dim": 2,
      "nodes": [[0, 0, 0], [0, 3, 0], [4, 0, 0]],
      "pinned": [1, 2],
      "node_masses": [{"node": 3, "mass_kg": 10}],
      "members": [{"nodes": [1, 3], "group": "chord"}, {"nodes": [2, 3], "group": "tie"}],
      "groups": [
        {"name": "chord", "kind": "bar", "min_area_m2": 1e-5, "max_area_m2": 1e-2,
         "allowed_compression_pa": 2e8, "buckling": "euler"},
        {"name": "tie", "kind": "string", "min_area_m2": 1e-5, "allowed_tension_pa": 3e8}
      ],
      "load_cases": [{"name": "down", "factor": 1.5, "loads": [{"node": 3, "force_n": [0, -1000, 0]}]}],
      "limits": {"displacements": [{"node": 3, "axis": "y", "max_m": 0.01}], "min_frequencies_hz": [5]}
    },
    "material": {"density": 7850, "youngs_modulus": 2.1e11},
    "design": {"self_weight": true, "solver": "auto"}
  })");
}

json With(const std::string& where, const json& value) {
  json c = GoodTruss();
  c[json::json_pointer(where)] = value;
  return c;
}

json Without(const std::string& where) {
  json c = GoodTruss();
  const json::json_pointer p(where);
  c[p.parent_pointer()].erase(p.back());
  return c;
}

TEST_CASE("structure to design: read as written, echoed back to itself", "[config]") {
  const Config c = ParseConfig(GoodTruss());
  REQUIRE(c.structure);
  const StructureConfig& s = *c.structure;
  CHECK(s.Designable());
  CHECK(s.members.size() == 2);
  CHECK(s.groups[0].kind == TrussKind::kBar);
  CHECK(*s.groups[0].max_area_m2 == 1e-2);
  CHECK(!s.groups[1].max_area_m2);
  CHECK(s.load_cases[0].factor == 1.5);
  CHECK(s.limits.displacements[0].axis == Axis::kY);
  CHECK(c.material.youngs_modulus == 2.1e11);
  const json echoed = ToJson(c);
  CHECK(ToJson(ParseConfig(echoed)) == echoed);
  // Only the keys a structure's design reads are echoed: no yield stress, no deck.
  CHECK(!echoed["material"].contains("yield_stress"));
  CHECK(!echoed["design"].contains("deck_string_min_radius"));
}

TEST_CASE("structure to design: bad input names the key", "[config]") {
  // The issue's list: a member joining a node to itself, a load on a missing node, a
  // displacement limit on a pinned node.
  ExpectRejected(With("/structure/members/0/nodes", json{3, 3}), "structure.members[0].nodes",
                 "[3, 3]", "two different nodes");
  ExpectRejected(With("/structure/load_cases/0/loads/0/node", 4),
                 "structure.load_cases[0].loads[0].node", "4", "an integer in [1, 3]");
  ExpectRejected(With("/structure/limits/displacements/0/node", 1),
                 "structure.limits.displacements[0].node", "1", "is pinned");
  ExpectRejected(With("/structure/limits/displacements/0/node", 9),
                 "structure.limits.displacements[0].node", "9", "the node count");
  // Groups: a member's group must exist; a group needs members, one name, the allowed stresses of
  // its kind and none of another's.
  ExpectRejected(With("/structure/members/1/group", "cable"), "structure.members[1].group",
                 "\"cable\"", "one of structure.groups[].name");
  json twice = GoodTruss();
  twice["structure"]["groups"].push_back(twice["structure"]["groups"][0]);
  ExpectRejected(twice, "structure.groups[2].name", "\"chord\"", "each group name once");
  ExpectRejected(Without("/structure/groups/1/allowed_tension_pa"),
                 "structure.groups[1].allowed_tension_pa", "(missing)", "required");
  ExpectRejected(With("/structure/groups/1/allowed_compression_pa", 1e8),
                 "structure.groups[1].allowed_compression_pa", "100000000", "tension only");
  ExpectRejected(With("/structure/groups/0/allowed_tension_pa", 1e8),
                 "structure.groups[0].allowed_tension_pa", "100000000", "compression only");
  ExpectRejected(With("/structure/groups/1/buckling", "euler"), "structure.groups[1].buckling",
                 "\"euler\"", "no compression");
  ExpectRejected(With("/structure/groups/0/max_area_m2", 1e-6), "structure.groups[0].max_area_m2",
                 "1e-06", ">= min_area_m2");
  ExpectRejected(With("/structure/groups/0/kind", "beam"), "structure.groups[0].kind", "beam",
                 "\"string\", \"bar\", \"truss\"");
  json unused = GoodTruss();
  unused["structure"]["groups"].push_back(
      {{"name", "spare"}, {"kind", "string"}, {"min_area_m2", 1e-5}, {"allowed_tension_pa", 1e8}});
  ExpectRejected(unused, "structure.groups[2].name", "\"spare\"", "no member");
  // Cases and limits.
  ExpectRejected(With("/structure/load_cases/0/factor", 0), "structure.load_cases[0].factor", "0",
                 "> 0");
  ExpectRejected(With("/structure/load_cases/0/loads/0/force_n", json{0, -1, 2}),
                 "structure.load_cases[0].loads[0].force_n[2]", "2", "must be 0");
  ExpectRejected(With("/structure/limits/displacements/0/axis", "z"),
                 "structure.limits.displacements[0].axis", "\"z\"", "structure.dim is 2");
  ExpectRejected(With("/structure/limits/displacements/0/max_m", -1),
                 "structure.limits.displacements[0].max_m", "-1", "> 0");
  json unloaded = Without("/structure/load_cases");
  unloaded["structure"]["limits"].erase("min_frequencies_hz");
  ExpectRejected(unloaded, "structure.load_cases", "(missing)", "at least one load case");
  ExpectRejected(With("/structure/prestress", "fixed"), "structure.prestress", "fixed",
                 "\"none\", \"variable\"");
}

TEST_CASE("structure to design: kept apart from the scene and the bridge", "[config]") {
  // Both forms together are an error, named at the scene's key.
  ExpectRejected(With("/structure/bars", json::array({{{"nodes", {1, 3}}, {"mass_kg", 1}}})),
                 "structure.bars", "(given with members)", "not allowed with structure.members");
  ExpectRejected(With("/structure/loads", json::array({{{"node", 3}, {"force_n", {0, -1, 0}}}})),
                 "structure.loads", "(given with members)", "load_cases");
  // The bridge's keys of material and design are refused, not ignored; its sections too.
  ExpectRejected(With("/material/yield_stress", 3.55e8), "material.yield_stress", "355000000",
                 "not read for a structure to design");
  ExpectRejected(With("/design/deck_string_min_radius", 0.01), "design.deck_string_min_radius",
                 "0.01", "design takes self_weight");
  ExpectRejected(With("/loads", json::object()), "loads", "(section)", "structure.load_cases");
  // The designable keys without members are a scene's error.
  json scene = GoodTruss();
  scene["structure"].erase("members");
  ExpectRejected(scene, "structure.groups", "(given without members)", "needs structure.members");
  json prestressed_scene = json::parse(R"({"structure": {"dim": 2, "nodes": [[0, 0, 0], [1, 0, 0]],
      "pinned": [1], "bars": [{"nodes": [1, 2], "mass_kg": 1}], "prestress": "variable"}})");
  ExpectRejected(prestressed_scene, "structure.prestress", "(given without members)",
                 "needs structure.members");
}

}  // namespace
}  // namespace tbridge
