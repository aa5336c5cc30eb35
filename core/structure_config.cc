#include "core/structure_config.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

namespace {

// Bounds the scene before any array is sized from it (hostile input, the fuzz target).
constexpr int kMaxStructureNodes = 1 << 20;

std::string Index(const std::string& list, size_t k) {
  return list + "[" + std::to_string(k) + "]";
}

std::string PairText(const std::array<int, 2>& p) {
  return "[" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + "]";
}

std::vector<std::array<double, 3>> ParseNodes(JsonSection& s, int dim) {
  const std::string key = s.PathOf("nodes");
  const nlohmann::json* raw = s.Raw("nodes");
  if (raw == nullptr)
    throw ConfigError(key, "(missing)", "required: a list of [x, y, z] node positions");
  if (!raw->is_array() || raw->empty() || raw->size() > static_cast<size_t>(kMaxStructureNodes)) {
    throw ConfigError(
        key, Show(*raw),
        "must be a list of 1 to " + std::to_string(kMaxStructureNodes) + " positions [x, y, z]");
  }
  std::vector<std::array<double, 3>> nodes;
  for (size_t k = 0; k < raw->size(); ++k) {
    const nlohmann::json& e = (*raw)[k];
    bool ok = e.is_array() && e.size() == 3;
    for (size_t d = 0; ok && d < 3; ++d) ok = e[d].is_number() && std::isfinite(e[d].get<double>());
    if (!ok)
      throw ConfigError(Index(key, k), Show(e), "must be a list of 3 finite numbers [x, y, z] (m)");
    const std::array<double, 3> p{e[0].get<double>(), e[1].get<double>(), e[2].get<double>()};
    if (dim == 2 && p[2] != 0) {
      throw ConfigError(Index(key, k) + "[2]", Show((*raw)[k][2]),
                        "must be 0: structure.dim is 2 (x-y plane)");
    }
    nodes.push_back(p);
  }
  return nodes;
}

// A 1-based node number list, each at most once.
std::vector<int> NodeSet(JsonSection& s, const std::string& key, int n_nodes) {
  const std::vector<int> list = s.Integers(key, std::vector<int>{}, 1, n_nodes);
  for (size_t a = 0; a < list.size(); ++a) {
    if (std::find(list.begin(), list.begin() + a, list[a]) != list.begin() + a) {
      throw ConfigError(Index(s.PathOf(key), a), std::to_string(list[a]), "each node at most once");
    }
  }
  return list;
}

std::array<int, 2> MemberEnds(JsonSection& s, const StructureConfig& c) {
  const int n_nodes = static_cast<int>(c.nodes.size());
  const std::vector<int> ends = s.Integers("nodes", std::nullopt, 1, n_nodes);
  if (ends.size() != 2) {
    throw ConfigError(s.PathOf("nodes"), std::to_string(ends.size()) + " numbers",
                      "must be two node numbers [i, j] in [1, " + std::to_string(n_nodes) + "]");
  }
  const std::array<int, 2> pair{ends[0], ends[1]};
  if (pair[0] == pair[1])
    throw ConfigError(s.PathOf("nodes"), PairText(pair), "must join two different nodes");
  if (!(c.Length(pair) > 0)) {
    throw ConfigError(s.PathOf("nodes"), PairText(pair),
                      "joins two nodes at the same position: length must be > 0");
  }
  return pair;
}

// Members of one list may not join the same two nodes twice (their "i-j" names would clash).
template <typename M>
void RejectRepeats(const std::vector<M>& members, const std::string& list) {
  for (size_t a = 0; a < members.size(); ++a) {
    for (size_t b = 0; b < a; ++b) {
      const auto& p = members[a].nodes;
      const auto& q = members[b].nodes;
      if ((p[0] == q[0] && p[1] == q[1]) || (p[0] == q[1] && p[1] == q[0])) {
        throw ConfigError(Index(list, a) + ".nodes", PairText(p),
                          "joins the same nodes as " + Index(list, b));
      }
    }
  }
}

StructureStringConfig ParseString(JsonSection p, const StructureConfig& c) {
  StructureStringConfig t;
  t.nodes = MemberEnds(p, c);
  t.stiffness_n_m = p.Number("stiffness_n_m", std::nullopt, Range::NonNegative());
  t.damping_n_s_m = p.Number("damping_n_s_m", t.damping_n_s_m, Range::NonNegative());
  if (p.Has("rest_length_m") && p.Has("rest_ratio")) {
    throw ConfigError(p.PathOf("rest_ratio"), "(given with rest_length_m)",
                      "give either rest_length_m or rest_ratio, not both");
  }
  if (p.Has("rest_ratio")) {
    t.rest_ratio = p.Number("rest_ratio", std::nullopt, Range::Positive());
  } else if (p.Has("rest_length_m")) {
    t.rest_length_m = p.Number("rest_length_m", std::nullopt, Range::Positive());
  } else {
    throw ConfigError(p.PathOf("rest_length_m"), "(missing)",
                      "required: rest_length_m > 0 (m) or rest_ratio > 0");
  }
  t.mass_kg = p.Number("mass_kg", t.mass_kg, Range::NonNegative());
  if (p.Has("area_m2")) t.area_m2 = p.Number("area_m2", std::nullopt, Range::Positive());
  p.Finish();
  return t;
}

}  // namespace

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

StructureConfig ParseStructureConfig(JsonSection s) {
  StructureConfig c;
  c.dim = s.Integer("dim", c.dim, 2, 3);
  c.nodes = ParseNodes(s, c.dim);
  const int n_nodes = static_cast<int>(c.nodes.size());
  c.pinned = NodeSet(s, "pinned", n_nodes);
  c.node_masses = ObjectList<StructureNodeMass>(s, "node_masses", [&](JsonSection p) {
    StructureNodeMass m;
    m.node = p.Integer("node", std::nullopt, 1, n_nodes);
    m.mass_kg = p.Number("mass_kg", std::nullopt, Range::NonNegative());
    p.Finish();
    return m;
  });
  for (size_t a = 0; a < c.node_masses.size(); ++a) {
    for (size_t b = 0; b < a; ++b) {
      if (c.node_masses[a].node == c.node_masses[b].node) {
        throw ConfigError(Index(s.PathOf("node_masses"), a) + ".node",
                          std::to_string(c.node_masses[a].node), "each node at most once");
      }
    }
  }
  c.bars = ObjectList<StructureBarConfig>(s, "bars", [&](JsonSection p) {
    StructureBarConfig b;
    b.nodes = MemberEnds(p, c);
    b.mass_kg = p.Number("mass_kg", std::nullopt, Range::NonNegative());
    p.Finish();
    return b;
  });
  RejectRepeats(c.bars, s.PathOf("bars"));
  c.strings = ObjectList<StructureStringConfig>(s, "strings",
                                                [&](JsonSection p) { return ParseString(p, c); });
  RejectRepeats(c.strings, s.PathOf("strings"));
  for (size_t k = 0; k < c.strings.size(); ++k) {
    if (!(c.RestLength(static_cast<int>(k)) > 0)) {  // a tiny ratio of a short string underflows
      throw ConfigError(Index(s.PathOf("strings"), k) + ".rest_ratio",
                        Show(*c.strings[k].rest_ratio),
                        "gives a rest length of 0: must give L0 > 0");
    }
  }
  c.loads = ObjectList<StructureLoad>(s, "loads", [&](JsonSection p) {
    StructureLoad l;
    l.node = p.Integer("node", std::nullopt, 1, n_nodes);
    l.force_n = p.Vector3("force_n", std::nullopt);
    if (c.dim == 2 && l.force_n[2] != 0) {
      throw ConfigError(p.PathOf("force_n") + "[2]", Show(l.force_n[2]),
                        "must be 0: structure.dim is 2 (x-y plane)");
    }
    p.Finish();
    return l;
  });
  c.deck_nodes = NodeSet(s, "deck_nodes", n_nodes);
  for (size_t k = 0; k < c.deck_nodes.size(); ++k) {
    if (std::find(c.pinned.begin(), c.pinned.end(), c.deck_nodes[k]) != c.pinned.end()) {
      throw ConfigError(Index(s.PathOf("deck_nodes"), k), std::to_string(c.deck_nodes[k]),
                        "is pinned: deck nodes must be free nodes");
    }
  }
  if (s.Has("allowed_stress_pa"))
    c.allowed_stress_pa = s.Number("allowed_stress_pa", std::nullopt, Range::Positive());
  for (size_t k = 0; k < c.strings.size() && !c.allowed_stress_pa; ++k) {
    if (c.strings[k].area_m2) {
      throw ConfigError(s.PathOf("allowed_stress_pa"), "(missing)",
                        "required (a number > 0) when a string has area_m2, as " +
                            Index(s.PathOf("strings"), k) +
                            " has: the stress report compares against it");
    }
  }
  c.gravity_m_s2 = s.Number("gravity_m_s2", c.gravity_m_s2, Range::Closed(0.0, 100.0));
  s.Finish();
  return c;
}

nlohmann::json ToJson(const StructureConfig& c) {
  nlohmann::json masses = nlohmann::json::array(), bars = nlohmann::json::array(),
                 strings = nlohmann::json::array(), loads = nlohmann::json::array();
  for (const StructureNodeMass& m : c.node_masses)
    masses.push_back({{"node", m.node}, {"mass_kg", m.mass_kg}});
  for (const StructureBarConfig& b : c.bars)
    bars.push_back({{"nodes", b.nodes}, {"mass_kg", b.mass_kg}});
  for (const StructureStringConfig& t : c.strings) {
    nlohmann::json j = {{"nodes", t.nodes},
                        {"stiffness_n_m", t.stiffness_n_m},
                        {"damping_n_s_m", t.damping_n_s_m},
                        {"mass_kg", t.mass_kg}};
    if (t.rest_length_m) j["rest_length_m"] = *t.rest_length_m;
    if (t.rest_ratio) j["rest_ratio"] = *t.rest_ratio;
    if (t.area_m2) j["area_m2"] = *t.area_m2;
    strings.push_back(j);
  }
  for (const StructureLoad& l : c.loads)
    loads.push_back({{"node", l.node}, {"force_n", l.force_n}});
  nlohmann::json j = {{"dim", c.dim},
                      {"nodes", c.nodes},
                      {"pinned", c.pinned},
                      {"node_masses", masses},
                      {"bars", bars},
                      {"strings", strings},
                      {"loads", loads},
                      {"deck_nodes", c.deck_nodes},
                      {"gravity_m_s2", c.gravity_m_s2}};
  if (c.allowed_stress_pa) j["allowed_stress_pa"] = *c.allowed_stress_pa;
  return j;
}

}  // namespace tbridge
