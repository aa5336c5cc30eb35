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

bool Contains(const std::vector<int>& list, int v) {
  return std::find(list.begin(), list.end(), v) != list.end();
}

// The scene's keys that a structure to design does not take: it gives `members` instead.
void RejectSceneKeys(const StructureConfig& c) {
  const auto refuse = [](const char* key, const char* value) {
    throw ConfigError(std::string("structure.") + key, value,
                      "not allowed with structure.members: a structure to design gives members "
                      "in groups, its loads in load_cases; bars, strings, loads, deck_nodes and "
                      "allowed_stress_pa belong to a scene for `tbridge simulate`");
  };
  if (!c.bars.empty()) refuse("bars", "(given with members)");
  if (!c.strings.empty()) refuse("strings", "(given with members)");
  if (!c.loads.empty()) refuse("loads", "(given with members)");
  if (!c.deck_nodes.empty()) refuse("deck_nodes", "(given with members)");
  if (c.allowed_stress_pa) refuse("allowed_stress_pa", "(given with members)");
}

// The keys of the scene's designable form left over where no member is given.
void RejectDesignKeysWithoutMembers(const StructureConfig& c) {
  const auto refuse = [](const char* key) {
    throw ConfigError(std::string("structure.") + key, "(given without members)",
                      "a structure to design needs structure.members (a scene gives bars and "
                      "strings and takes no groups, load cases or limits)");
  };
  if (!c.groups.empty()) refuse("groups");
  if (!c.load_cases.empty()) refuse("load_cases");
  if (!c.limits.displacements.empty() || !c.limits.min_frequencies_hz.empty()) refuse("limits");
  if (c.prestress != StructurePrestress::kNone) refuse("prestress");
  if (c.analysis != TrussAnalysisKind::kLinear) refuse("analysis");
}

void CheckGroups(const StructureConfig& c) {
  for (size_t k = 0; k < c.members.size(); ++k) {
    const std::string& name = c.members[k].group;
    const bool known = std::any_of(c.groups.begin(), c.groups.end(),
                                   [&](const StructureGroupConfig& g) { return g.name == name; });
    if (!known) {
      throw ConfigError(Index("structure.members", k) + ".group", "\"" + name + "\"",
                        "must name one of structure.groups[].name");
    }
  }
  for (size_t g = 0; g < c.groups.size(); ++g) {
    const StructureGroupConfig& group = c.groups[g];
    const std::string path = Index("structure.groups", g);
    for (size_t h = 0; h < g; ++h) {
      if (c.groups[h].name == group.name) {
        throw ConfigError(path + ".name", "\"" + group.name + "\"",
                          "each group name once: " + Index("structure.groups", h) + " has it");
      }
    }
    if (group.max_area_m2 && *group.max_area_m2 < group.min_area_m2) {
      throw ConfigError(path + ".max_area_m2", Show(*group.max_area_m2),
                        "must be >= min_area_m2 = " + Show(group.min_area_m2));
    }
    const bool tension = group.kind != TrussKind::kBar,
               compression = group.kind != TrussKind::kString;
    // Without load cases (frequency limits alone) no stress is checked, and none is needed.
    const bool loaded = !c.load_cases.empty();
    if (loaded && tension && !group.allowed_tension_pa) {
      throw ConfigError(path + ".allowed_tension_pa", "(missing)",
                        "required (a stress > 0, Pa) for a group of kind \"" +
                            std::string(NameOf(group.kind)) + "\"");
    }
    if (!tension && group.allowed_tension_pa) {
      throw ConfigError(path + ".allowed_tension_pa", Show(*group.allowed_tension_pa),
                        "not allowed for a group of kind \"bar\": a bar carries compression only");
    }
    if (loaded && compression && !group.allowed_compression_pa) {
      throw ConfigError(path + ".allowed_compression_pa", "(missing)",
                        "required (a stress > 0, Pa) for a group of kind \"" +
                            std::string(NameOf(group.kind)) + "\"");
    }
    if (!compression && group.allowed_compression_pa) {
      throw ConfigError(
          path + ".allowed_compression_pa", Show(*group.allowed_compression_pa),
          "not allowed for a group of kind \"string\": a string carries tension only");
    }
    if (group.kind == TrussKind::kString && group.buckling == BucklingRule::kEuler) {
      throw ConfigError(path + ".buckling", "\"euler\"",
                        "a string carries no compression: \"auto\" or \"none\"");
    }
    const bool used =
        std::any_of(c.members.begin(), c.members.end(),
                    [&](const StructureMemberConfig& m) { return m.group == group.name; });
    if (!used)
      throw ConfigError(path + ".name", "\"" + group.name + "\"", "no member is in this group");
  }
}

void CheckLoadCases(const StructureConfig& c) {
  if (c.load_cases.empty() && c.limits.min_frequencies_hz.empty()) {
    throw ConfigError("structure.load_cases", "(missing)",
                      "a structure to design needs at least one load case, or frequency limits "
                      "(structure.limits.min_frequencies_hz)");
  }
  for (size_t k = 0; k < c.load_cases.size(); ++k) {
    const StructureLoadCase& l = c.load_cases[k];
    const std::string path = Index("structure.load_cases", k);
    for (size_t h = 0; h < k; ++h) {
      if (c.load_cases[h].name == l.name) {
        throw ConfigError(path + ".name", "\"" + l.name + "\"",
                          "each case name once: " + Index("structure.load_cases", h) + " has it");
      }
    }
    for (size_t f = 0; f < l.loads.size() && c.dim == 2; ++f) {
      RequirePlanar(l.loads[f].force_n[2], Index(path + ".loads", f) + ".force_n[2]");
    }
  }
}

void CheckDisplacementLimits(const StructureConfig& c) {
  const std::vector<StructureDisplacementLimit>& list = c.limits.displacements;
  for (size_t k = 0; k < list.size(); ++k) {
    const std::string path = Index("structure.limits.displacements", k);
    const int nodes = static_cast<int>(c.nodes.size());
    if (list[k].node > nodes) {
      throw ConfigError(path + ".node", std::to_string(list[k].node),
                        "must be " + IntegerRangeText(1, nodes) + " (the node count)");
    }
    if (Contains(c.pinned, list[k].node)) {
      throw ConfigError(path + ".node", std::to_string(list[k].node),
                        "is pinned: a displacement limit is on a free node");
    }
    if (c.dim == 2 && list[k].axis == Axis::kZ) {
      throw ConfigError(path + ".axis", "\"z\"", "must be \"x\" or \"y\": structure.dim is 2");
    }
    for (size_t h = 0; h < k; ++h) {
      if (list[h].node == list[k].node && list[h].axis == list[k].axis) {
        throw ConfigError(path, std::to_string(list[k].node) + " " + NameOf(list[k].axis),
                          "each node and axis once: structure.limits.displacements[" +
                              std::to_string(h) + "] has it");
      }
    }
  }
}

void CheckDesignable(const StructureConfig& c) {
  RejectSceneKeys(c);
  CheckMembers(c, c.members, "structure.members");
  CheckGroups(c);
  CheckLoadCases(c);
  CheckDisplacementLimits(c);
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
  if (c.Designable()) {
    CheckDesignable(c);
  } else {
    RejectDesignKeysWithoutMembers(c);
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
