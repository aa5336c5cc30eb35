#include "truss/truss_design.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
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

// The sizing as the file records it: the groups' areas and the solver's record.
TrussSizing SizingOf(const nlohmann::json& file, const TrussModel& m) {
  TrussSizing s;
  s.group_areas.resize(m.num_groups());
  const nlohmann::json& groups = file.at("groups");
  for (int g = 0; g < m.num_groups(); ++g) {
    s.group_areas[g] = NumberAt(groups.at(static_cast<size_t>(g)), "area",
                                "groups[" + std::to_string(g) + "].area");
  }
  const nlohmann::json& solver = file.at("solver");
  // Text only: a name of another type is refused as a wrong one (value() would throw on it).
  const nlohmann::json* given = solver.contains("name") ? &solver.at("name") : nullptr;
  const std::string name = given && given->is_string() ? given->get<std::string>() : "";
  const std::optional<SolverKind> kind = ValueIn(kSolverNames, name);
  if (!kind) {
    throw ConfigError(
        "solver.name", given ? Show(*given) : "(missing)",
        "one of " + ChoiceText(AllNames(kSolverNames)) + ", as tbridge design writes it");
  }
  s.outcome.solver = *kind;
  s.outcome.status = solver.value("status", "");
  s.outcome.iterations = solver.value("iterations", 0);
  s.start = solver.value("start", "");
  s.tries = solver.value("tries", std::vector<std::string>{});
  const nlohmann::json& k = solver.at("kkt");
  s.kkt.stationarity = k.value("stationarity", 0.0);
  s.kkt.feasibility = k.value("feasibility", 0.0);
  s.kkt.complementarity = k.value("complementarity", 0.0);
  s.kkt.second_order = k.value("second_order", false);
  s.kkt.second_order_by = k.value("second_order_by", "");
  s.kkt.proved_local_optimum = k.value("proved_local_optimum", false);
  s.kkt.failed = k.value("failed", "");
  s.kkt.active_rows = k.value("active_rows", 0);
  s.kkt.active_bounds = k.value("active_bounds", 0);
  s.kkt.free_variables = k.value("free_variables", 0);
  s.kkt.null_space_dimension = k.value("null_space_dimension", 0);
  if (file.contains("mass_attribution") && file.at("mass_attribution").is_object()) {
    const nlohmann::json& a = file.at("mass_attribution");
    if (a.contains("by_constraint_kg") && a.at("by_constraint_kg").is_object()) {
      for (auto it = a.at("by_constraint_kg").begin(); it != a.at("by_constraint_kg").end(); ++it)
        s.attribution.by_constraint_kg.emplace_back(it.key(),
                                                    it->is_number() ? it->get<double>() : 0.0);
    }
    s.attribution.structure_kg = a.value("structure_kg", 0.0);
    s.attribution.stationarity_residual = a.value("stationarity_residual", 0.0);
    s.attribution.active_rows = a.value("active_rows", 0);
  }
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
  if (!file.is_object() || file.value("kind", "") != "structure") {
    throw ConfigError(
        "kind", file.is_object() && file.contains("kind") ? Show(file.at("kind")) : "(missing)",
        "\"structure\": the design file of a structure to design");
  }
  const Config config = ParseConfig(file.at("config"));
  TrussDesign d{config, BuildTrussModel(config), {}, {}, {}};
  const nlohmann::json& members = file.at("members");
  if (!members.is_array() || static_cast<int>(members.size()) != d.model.num_members()) {
    throw ConfigError(
        "members", members.is_array() ? std::to_string(members.size()) + " members" : Show(members),
        "one entry per member of config.structure.members (" +
            std::to_string(d.model.num_members()) + ")");
  }
  d.sizing = SizingOf(file, d.model);
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
