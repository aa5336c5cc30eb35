#include "core/structure_config.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/structure_fields.h"

namespace tbridge {

namespace {

std::string Index(const std::string& list, size_t k) {
  return list + "[" + std::to_string(k) + "]";
}

std::string PairText(const std::array<int, 2>& p) {
  return "[" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + "]";
}

void RequirePlanar(double z, const std::string& path) {
  if (z != 0) throw ConfigError(path, Show(z), "must be 0: structure.dim is 2 (x-y plane)");
}

// A list of node numbers naming each node at most once.
void RejectRepeatedNodes(const std::vector<int>& list, const std::string& path) {
  for (size_t a = 0; a < list.size(); ++a) {
    if (std::find(list.begin(), list.begin() + a, list[a]) != list.begin() + a) {
      throw ConfigError(Index(path, a), std::to_string(list[a]), "each node at most once");
    }
  }
}

// Members join two different nodes at different positions, and one list may not join the
// same two nodes twice (their "i-j" names would clash).
template <typename M>
void CheckMembers(const StructureConfig& c, const std::vector<M>& members,
                  const std::string& list) {
  for (size_t a = 0; a < members.size(); ++a) {
    const auto& p = members[a].nodes;
    const std::string path = Index(list, a) + ".nodes";
    if (p[0] == p[1]) throw ConfigError(path, PairText(p), "must join two different nodes");
    if (!(c.Length(p) > 0)) {
      throw ConfigError(path, PairText(p),
                        "joins two nodes at the same position: length must be > 0");
    }
    for (size_t b = 0; b < a; ++b) {
      const auto& q = members[b].nodes;
      if ((p[0] == q[0] && p[1] == q[1]) || (p[0] == q[1] && p[1] == q[0])) {
        throw ConfigError(path, PairText(p), "joins the same nodes as " + Index(list, b));
      }
    }
  }
}

void CheckRestLengths(const StructureConfig& c) {
  for (size_t k = 0; k < c.strings.size(); ++k) {
    const StructureStringConfig& t = c.strings[k];
    const std::string path = Index("structure.strings", k);
    if (t.rest_length_m && t.rest_ratio) {
      throw ConfigError(path + ".rest_ratio", "(given with rest_length_m)",
                        "give either rest_length_m or rest_ratio, not both");
    }
    if (!t.rest_length_m && !t.rest_ratio) {
      throw ConfigError(path + ".rest_length_m", "(missing)",
                        "required: rest_length_m > 0 (m) or rest_ratio > 0");
    }
    if (!(c.RestLength(static_cast<int>(k)) > 0)) {  // a tiny ratio of a short string underflows
      throw ConfigError(path + ".rest_ratio", Show(*t.rest_ratio),
                        "gives a rest length of 0: must give L0 > 0");
    }
  }
}

}  // namespace

void CheckStructureRules(const StructureConfig& c) {
  for (size_t k = 0; k < c.nodes.size() && c.dim == 2; ++k) {
    RequirePlanar(c.nodes[k][2], Index("structure.nodes", k) + "[2]");
  }
  RejectRepeatedNodes(c.pinned, "structure.pinned");
  for (size_t a = 0; a < c.node_masses.size(); ++a) {
    for (size_t b = 0; b < a; ++b) {
      if (c.node_masses[a].node == c.node_masses[b].node) {
        throw ConfigError(Index("structure.node_masses", a) + ".node",
                          std::to_string(c.node_masses[a].node), "each node at most once");
      }
    }
  }
  CheckMembers(c, c.bars, "structure.bars");
  CheckMembers(c, c.strings, "structure.strings");
  CheckRestLengths(c);
  for (size_t k = 0; k < c.loads.size() && c.dim == 2; ++k) {
    RequirePlanar(c.loads[k].force_n[2], Index("structure.loads", k) + ".force_n[2]");
  }
  RejectRepeatedNodes(c.deck_nodes, "structure.deck_nodes");
  for (size_t k = 0; k < c.deck_nodes.size(); ++k) {
    if (std::find(c.pinned.begin(), c.pinned.end(), c.deck_nodes[k]) != c.pinned.end()) {
      throw ConfigError(Index("structure.deck_nodes", k), std::to_string(c.deck_nodes[k]),
                        "is pinned: deck nodes must be free nodes");
    }
  }
  for (size_t k = 0; k < c.strings.size() && !c.allowed_stress_pa; ++k) {
    if (c.strings[k].area_m2) {
      throw ConfigError("structure.allowed_stress_pa", "(missing)",
                        "required (a number > 0) when a string has area_m2, as " +
                            Index("structure.strings", k) +
                            " has: the stress report compares against it");
    }
  }
}

double StructureConfig::Length(const std::array<int, 2>& ends) const {
  double sum = 0;
  for (int d = 0; d < 3; ++d) {
    const double delta = nodes[ends[1] - 1][d] - nodes[ends[0] - 1][d];
    sum += delta * delta;
  }
  return std::sqrt(sum);
}

double StructureConfig::RestLength(int k) const {
  const StructureStringConfig& s = strings[k];
  return s.rest_length_m ? *s.rest_length_m : *s.rest_ratio * Length(s.nodes);
}

StructureConfig ParseStructureConfig(JsonSection section) {
  return ParseSection<StructureConfig>(section, CheckStructureRules);
}

nlohmann::json ToJson(const StructureConfig& c) { return EchoFields(c); }

}  // namespace tbridge
