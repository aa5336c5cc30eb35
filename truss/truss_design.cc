#include "truss/truss_design.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "core/json_reader.h"
#include "design/solvers.h"

namespace tbridge {

TrussDesign DesignTruss(const Config& config) {
  if (config.design.solver == "direct") {
    throw ConfigError(
        "design.solver", "\"direct\"",
        "a structure is sized by an iterative solver: \"auto\", or one of those built in");
  }
  RequireSolverBuiltIn(config.design.solver);
  TrussDesign d{config, BuildTrussModel(config), {}, {}, {}};
  d.sizing = SizeTruss(d.model, config.design.solver, config.design.tolerance,
                       config.design.max_iterations);
  d.check = CheckTruss(d.model, d.model.MemberAreas(d.sizing.group_areas));
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
  s.outcome.solver = solver.value("name", "");
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
  return s;
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
  d.check = CheckTruss(d.model, areas);
  return d;
}

}  // namespace tbridge
