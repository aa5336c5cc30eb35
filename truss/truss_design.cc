#include "truss/truss_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/json_reader.h"
#include "optim/solvers.h"

namespace tbridge {

TrussDesign DesignTruss(const Config& config) {
  if (config.design.solver == SolverKind::kDirect) {
    throw ConfigError(
        "design.solver", "\"direct\"",
        "a structure is sized by an iterative solver: \"auto\", or one of those built in");
  }
  RequireSolverBuiltIn(config.design.solver);
  TrussDesign d{config, BuildTrussModel(config), {}, {}, {}};
  d.sizing = SizeTruss(d.model, config.design.solver, config.design.tolerance,
                       config.design.max_iterations);
  d.check = CheckTruss(d.model, d.model.MemberAreas(d.sizing.group_areas), d.sizing.prestress);
  return d;
}

namespace {

// The number at `key` of the JSON object `j`, named `path` in an error: a finite number.
double NumberAt(const nlohmann::json& j, const char* key, const std::string& path) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_number() ||
      !std::isfinite(j.at(key).get<double>())) {
    throw ConfigError(path, j.is_object() && j.contains(key) ? Show(j.at(key)) : "(missing)",
                      "a finite number");
  }
  return j.at(key).get<double>();
}

// The file's record of the solve, read back as written (the check recomputes what it judges):
// text where present, else "".
std::string RecordText(JsonSection& section, const std::string& key) {
  const nlohmann::json* v = section.Raw(key);
  if (v == nullptr) return "";
  if (!v->is_string())
    throw ConfigError(section.PathOf(key), Show(*v), "a string, as tbridge design writes it");
  return v->get<std::string>();
}

// A number of the record: 0 where absent, NaN where null (how JSON holds a NaN written).
double RecordNumber(JsonSection& section, const std::string& key) {
  const nlohmann::json* v = section.Raw(key);
  if (v == nullptr) return 0.0;
  if (v->is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!v->is_number()) {
    throw ConfigError(section.PathOf(key), Show(*v),
                      "a number or null, as tbridge design writes it");
  }
  return v->get<double>();
}

int RecordCount(JsonSection& section, const std::string& key) {
  return section.Integer(key, 0, 0, std::numeric_limits<int>::max());
}

std::vector<std::string> RecordTexts(JsonSection& section, const std::string& key) {
  const nlohmann::json* v = section.Raw(key);
  std::vector<std::string> out;
  if (v == nullptr) return out;
  const bool texts =
      v->is_array() &&
      std::all_of(v->begin(), v->end(), [](const nlohmann::json& e) { return e.is_string(); });
  if (!texts) {
    throw ConfigError(section.PathOf(key), Show(*v),
                      "a list of strings, as tbridge design writes it");
  }
  for (const nlohmann::json& e : *v) out.push_back(e.get<std::string>());
  return out;
}

// The solver's name: one of kSolverNames.
SolverKind SolverOf(JsonSection& solver) {
  const nlohmann::json* given = solver.Raw("name");
  const std::optional<SolverKind> kind =
      given && given->is_string() ? ValueIn(kSolverNames, given->get<std::string>()) : std::nullopt;
  if (!kind) {
    throw ConfigError(
        "solver.name", given ? Show(*given) : "(missing)",
        "one of " + ChoiceText(AllNames(kSolverNames)) + ", as tbridge design writes it");
  }
  return *kind;
}

KktCertificate KktOf(JsonSection k) {
  KktCertificate c;
  c.stationarity = RecordNumber(k, "stationarity");
  c.feasibility = RecordNumber(k, "feasibility");
  c.complementarity = RecordNumber(k, "complementarity");
  c.second_order = k.Bool("second_order", false);
  c.second_order_by = RecordText(k, "second_order_by");
  c.proved_local_optimum = k.Bool("proved_local_optimum", false);
  c.failed = RecordText(k, "failed");
  c.active_rows = RecordCount(k, "active_rows");
  c.active_bounds = RecordCount(k, "active_bounds");
  c.free_variables = RecordCount(k, "free_variables");
  c.null_space_dimension = RecordCount(k, "null_space_dimension");
  return c;
}

TrussMassAttribution AttributionOf(JsonSection a) {
  TrussMassAttribution out;
  if (const nlohmann::json* by = a.Raw("by_constraint_kg")) {
    if (!by->is_object()) {
      throw ConfigError(a.PathOf("by_constraint_kg"), Show(*by),
                        "an object of masses by constraint kind [kg]");
    }
    JsonSection kinds(*by, a.PathOf("by_constraint_kg"));
    for (auto it = by->begin(); it != by->end(); ++it)
      out.by_constraint_kg.emplace_back(it.key(), RecordNumber(kinds, it.key()));
  }
  out.structure_kg = RecordNumber(a, "structure_kg");
  out.stationarity_residual = RecordNumber(a, "stationarity_residual");
  out.active_rows = RecordCount(a, "active_rows");
  return out;
}

// The sizing as the file records it: the groups' areas and the solver's record. Every key of
// the record is read as the type tbridge design writes, or refused naming it.
TrussSizing SizingOf(JsonSection& file, const TrussModel& m) {
  TrussSizing s;
  s.group_areas.resize(m.num_groups());
  const nlohmann::json* groups = file.Raw("groups");
  if (groups == nullptr || !groups->is_array() ||
      static_cast<int>(groups->size()) != m.num_groups()) {
    throw ConfigError("groups", groups ? Show(*groups) : "(missing)",
                      "one entry per config.structure.groups (" + std::to_string(m.num_groups()) +
                          "), as tbridge design writes it");
  }
  for (int g = 0; g < m.num_groups(); ++g) {
    s.group_areas[g] = NumberAt(groups->at(static_cast<size_t>(g)), "area",
                                "groups[" + std::to_string(g) + "].area");
  }
  JsonSection solver = file.Section("solver", false);
  s.outcome.solver = SolverOf(solver);
  s.outcome.status = RecordText(solver, "status");
  s.outcome.iterations = RecordCount(solver, "iterations");
  s.start = RecordText(solver, "start");
  s.tries = RecordTexts(solver, "tries");
  s.kkt = KktOf(solver.Section("kkt", false));
  if (file.Has("mass_attribution")) s.attribution = AttributionOf(file.Section("mass_attribution"));
  return s;
}

// Each member's prestress as the file gives it (members[].prestress_n), held to be a self-stress:
// an edit that leaves a node unbalanced is refused, naming the node (the linear analysis about
// the prestressed state needs it in equilibrium).
Eigen::VectorXd PrestressOf(const nlohmann::json& members, const TrussModel& m) {
  Eigen::VectorXd n0 = Eigen::VectorXd::Zero(m.num_members());
  for (int e = 0; e < m.num_members(); ++e) {
    const nlohmann::json& member = members.at(static_cast<size_t>(e));
    const std::string path = "members[" + std::to_string(e) + "].prestress_n";
    if (m.num_prestress() > 0) {
      n0[e] = NumberAt(member, "prestress_n", path);
    } else if (member.is_object() && member.contains("prestress_n") &&
               !(member.at("prestress_n").is_number() && member.at("prestress_n") == 0)) {
      throw ConfigError(path, Show(member.at("prestress_n")),
                        "0: config.structure.prestress is \"none\" (set it to \"variable\" "
                        "and re-design to prestress the structure)");
    }
  }
  const Eigen::VectorXd unbalanced = m.Equilibrium() * n0;
  int worst = 0;
  // Round-off of the forces written with 17 digits: 1e-9 of the largest.
  if (unbalanced.size() > 0 &&
      unbalanced.cwiseAbs().maxCoeff(&worst) > 1e-9 * std::max(1.0, n0.cwiseAbs().maxCoeff())) {
    const int node = worst / m.dim;
    throw ConfigError("members[].prestress_n", "(as edited)",
                      "a self-stress: the members' prestress leaves " +
                          std::to_string(unbalanced[worst]) + " N unbalanced at node " +
                          std::to_string(node + 1) +
                          "; change the prestress of the members at a node together so that it "
                          "stays in equilibrium, or re-design");
  }
  return n0;
}

}  // namespace

TrussDesign CheckTrussDesignFile(const nlohmann::json& file) {
  if (!file.is_object() || !file.contains("kind") || file.at("kind") != "structure") {
    throw ConfigError(
        "kind", file.is_object() && file.contains("kind") ? Show(file.at("kind")) : "(missing)",
        "\"structure\": the design file of a structure to design");
  }
  JsonSection root(file, "");
  const nlohmann::json* config_json = root.Raw("config");
  if (config_json == nullptr) throw ConfigError("config", "(missing)", "the design's config");
  const Config config = ParseConfig(*config_json);
  TrussDesign d{config, BuildTrussModel(config), {}, {}, {}};
  const nlohmann::json* given = root.Raw("members");
  if (given == nullptr || !given->is_array() ||
      static_cast<int>(given->size()) != d.model.num_members()) {
    throw ConfigError("members",
                      given == nullptr    ? "(missing)"
                      : given->is_array() ? std::to_string(given->size()) + " members"
                                          : Show(*given),
                      "one entry per member of config.structure.members (" +
                          std::to_string(d.model.num_members()) + ")");
  }
  const nlohmann::json& members = *given;
  d.sizing = SizingOf(root, d.model);
  d.sizing.prestress = PrestressOf(members, d.model);
  Eigen::VectorXd areas(d.model.num_members());
  for (int e = 0; e < d.model.num_members(); ++e) {
    const std::string path = "members[" + std::to_string(e) + "].area";
    areas[e] = NumberAt(members.at(static_cast<size_t>(e)), "area", path);
    if (!(areas[e] > 0))
      throw ConfigError(path, Show(members.at(static_cast<size_t>(e)).at("area")),
                        "an area > 0 [m^2]");
    const double group = d.sizing.group_areas[d.model.members[static_cast<size_t>(e)].group];
    if (areas[e] != group) d.edited.push_back(e);
  }
  d.check = CheckTruss(d.model, areas, d.sizing.prestress);
  return d;
}

}  // namespace tbridge
