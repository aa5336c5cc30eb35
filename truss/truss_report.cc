#include "truss/truss_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/member_area.h"
#include "optim/kkt_json.h"

namespace tbridge {

namespace {

using nlohmann::json;

std::string Format(const char* format, double v) {
  char text[96];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

json Vector(const Eigen::Vector3d& v, int dim) {
  json out = json::array();
  for (int a = 0; a < dim; ++a) out.push_back(v[a]);
  return out;
}

// Each node's displacement in case c, zero at a support.
json Displacements(const TrussModel& m, const TrussCaseResponse& r) {
  json out = json::array();
  for (int k = 0; k < m.nodes.cols(); ++k) {
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    for (int a = 0; a < m.dim; ++a) {
      const int f = m.dof[static_cast<size_t>(k * m.dim + a)];
      if (f >= 0) u[a] = r.u[f];
    }
    out.push_back(Vector(u, m.dim));
  }
  return out;
}

// The length member e is made to so that it carries prestress n0 at area a when fitted at its
// drawn length: L / (1 + n0 / (E A)).
double RestLength(const TrussModel& m, int e, double a, double n0) {
  return RestLengthOfArea(m.youngs_modulus, a, n0, m.members[static_cast<size_t>(e)].length);
}

json Members(const TrussDesign& d) {
  const TrussModel& m = d.model;
  json out = json::array();
  for (int e = 0; e < m.num_members(); ++e) {
    const TrussMember& member = m.members[static_cast<size_t>(e)];
    const TrussMemberCheck& c = d.check.members[static_cast<size_t>(e)];
    const TrussGroup& g = m.groups[static_cast<size_t>(member.group)];
    json forces = json::array();
    for (const TrussCaseResponse& r : d.check.cases) forces.push_back(r.forces[e]);
    out.push_back(
        {{"name", m.MemberName(e)},
         {"nodes", {member.i + 1, member.j + 1}},
         {"group", g.name},
         {"kind", NameOf(g.kind)},
         {"length", member.length},
         {"area", c.area},
         {"mass", MassOfArea(m.density, c.area, member.length)},
         {"prestress_n", d.check.prestress[e]},
         {"rest_length_m", RestLength(m, e, c.area, d.check.prestress[e])},
         {"force", c.force},
         {"forces_by_case", forces},
         {"utilisation", c.utilisation},
         {"governed_by", NameOf(c.governed_by)},
         {"governing_case", d.check.cases.empty()
                                ? json(nullptr)
                                : json(m.cases[static_cast<size_t>(c.governing_case)].name)}});
  }
  return out;
}

json Cases(const TrussDesign& d) {
  const TrussModel& m = d.model;
  json out = json::array();
  for (size_t c = 0; c < d.check.cases.size(); ++c) {
    json reactions = json::array();
    for (int k = 0; k < m.nodes.cols(); ++k) {
      if (m.fixed[static_cast<size_t>(k)]) {
        reactions.push_back({{"node", k + 1}, {"force_n", Vector(d.check.reactions[c].col(k), 3)}});
      }
    }
    out.push_back({{"name", m.cases[c].name},
                   {"factor", m.cases[c].factor},
                   {"displacements", Displacements(m, d.check.cases[c])},
                   {"reactions", reactions}});
  }
  return out;
}

json Limits(const TrussDesign& d) {
  const TrussModel& m = d.model;
  json displacements = json::array(), frequencies = json::array();
  for (const TrussLimitCheck& l : d.check.displacements) {
    displacements.push_back(
        {{"what", l.what},
         {"max_m", l.limit},
         {"value_m", l.value},
         {"utilisation", l.utilisation},
         {"governing_case", l.governing_case < 0
                                ? json(nullptr)
                                : json(m.cases[static_cast<size_t>(l.governing_case)].name)}});
  }
  for (const TrussLimitCheck& l : d.check.frequencies) {
    frequencies.push_back({{"what", l.what},
                           {"min_hz", l.limit},
                           {"value_hz", l.value},
                           {"utilisation", l.utilisation}});
  }
  return {{"displacements", displacements}, {"frequencies", frequencies}};
}

json Solver(const TrussSizing& s) {
  const KktCertificate& k = s.kkt;
  return {{"name", NameOf(s.outcome.solver)},
          {"status", s.outcome.status},
          {"iterations", s.outcome.iterations},
          {"start", s.start},
          {"tries", s.tries},
          {"kkt", KktJson(k)}};
}

json Attribution(const TrussMassAttribution& a) {
  json by = json::object();
  for (const auto& [kind, kg] : a.by_constraint_kg) by[kind] = kg;
  return {{"by_constraint_kg", by},
          {"structure_kg", a.structure_kg},
          {"stationarity_residual", a.stationarity_residual},
          {"active_rows", a.active_rows}};
}

std::string Analysis(const TrussModel& m) {
  const std::string statics =
      m.analysis == TrussAnalysisKind::kNonlinear
          ? "geometrically nonlinear statics: each member's force N0 + E A (l - L) / L along its "
            "turned direction, Newton to equilibrium in the deformed shape"
          : "linear statics: small displacements, each member elastic E A / L";
  const std::string geometric =
      m.num_prestress() > 0 ? " about the prestressed state, with its geometric stiffness N0 / L"
                            : "";
  return statics + geometric + "; modes of the drawn state, consistent member mass";
}

json NotApplicable(const TrussModel& m) {
  json out = {{"deck", "a structure has no deck"},
              {"comfort", "no pedestrian comfort check: not a footbridge"},
              {"dynamic_check", "no time-history runs: the limits are static and modal"}};
  if (m.num_prestress() == 0)
    out["prestress"] = "no self-stress: each member's rest length is its drawn length";
  return out;
}

}  // namespace

void WriteTrussDesignJson(const TrussDesign& d, std::ostream& os) {
  const TrussModel& m = d.model;
  json nodes = json::array();
  for (int k = 0; k < m.nodes.cols(); ++k) nodes.push_back(Vector(m.nodes.col(k), 3));
  json groups = json::array();
  for (int g = 0; g < m.num_groups(); ++g) {
    const TrussGroup& group = m.groups[static_cast<size_t>(g)];
    groups.push_back({{"name", group.name},
                      {"kind", NameOf(group.kind)},
                      {"area", d.sizing.group_areas[g]},
                      {"members", group.members.size()},
                      {"mass", MassOfArea(m.density, d.sizing.group_areas[g], group.length_sum)}});
  }
  double added = 0;
  for (const StructureNodeMass& nm : d.config.structure->node_masses) added += nm.mass_kg;
  const double structure = m.MassOfMembers(d.check.Areas());
  json edited = json::array();
  for (const int e : d.edited) edited.push_back(m.MemberName(e));
  const json out = {
      {"kind", "structure"},
      {"config", ToJson(d.config)},
      {"nodes", nodes},
      {"members", Members(d)},
      {"groups", groups},
      {"cases", Cases(d)},
      {"limits", Limits(d)},
      {"frequencies_hz", d.check.frequencies_hz.size()
                             ? json(std::vector<double>(
                                   d.check.frequencies_hz.data(),
                                   d.check.frequencies_hz.data() + d.check.frequencies_hz.size()))
                             : json::array()},
      {"equilibrium_residual_N", d.check.equilibrium_residual},
      {"mass", {{"structure", structure}, {"node_masses", added}, {"total", structure + added}}},
      {"solver", Solver(d.sizing)},
      {"mass_attribution", Attribution(d.sizing.attribution)},
      {"edited_members", edited},
      {"analysis", Analysis(m)},
      {"not_applicable", NotApplicable(m)},
      {"verdict",
       {{"outcome", d.check.pass ? "PASS" : "FAIL"},
        {"pass", d.check.pass},
        {"utilisation_max", d.check.utilisation_max},
        {"governing", d.check.governing},
        {"lever", d.check.lever},
        {"tolerance", kTrussPassTolerance}}}};
  os << out.dump(2) << "\n";
}

namespace {

// The prestress by kind: the range of each kind's prestress force.
std::string PrestressLine(const TrussDesign& d) {
  const TrussModel& m = d.model;
  std::ostringstream os;
  os << "prestress (a self-stress, " << m.num_prestress()
     << (m.num_prestress() == 1 ? " state" : " states") << ") [kN]:";
  for (const TrussKind kind : {TrussKind::kString, TrussKind::kBar, TrussKind::kTruss}) {
    double lo = 0, hi = 0;
    bool any = false;
    for (int e = 0; e < m.num_members(); ++e) {
      if (m.groups[static_cast<size_t>(m.members[static_cast<size_t>(e)].group)].kind != kind)
        continue;
      const double n = d.check.prestress[e] / 1e3;
      lo = any ? std::min(lo, n) : n, hi = any ? std::max(hi, n) : n, any = true;
    }
    if (any) os << " " << NameOf(kind) << "s " << Format("%.4g", lo) << Format(" to %.4g", hi);
  }
  return os.str() + "\n";
}

}  // namespace

std::string TrussDesignSummary(const TrussDesign& d) {
  const TrussModel& m = d.model;
  std::ostringstream os;
  os << "structure to design: " << m.nodes.cols() << " nodes (" << m.num_free
     << " free degrees of freedom), " << m.num_members() << " members in " << m.num_groups()
     << " groups, " << m.cases.size() << " load cases, " << m.displacement_limits.size()
     << " displacement and " << m.min_frequencies_hz.size() << " frequency limits\n";
  const double mass = m.MassOfMembers(d.check.Areas());
  os << "mass of the members: " << Format("%.6g kg", mass)
     << Format(" (%.6g lb)", mass / 0.45359237) << "\n";
  os << "solver: " << NameOf(d.sizing.outcome.solver) << ", status " << d.sizing.outcome.status
     << " after " << d.sizing.outcome.iterations << " iterations, from the start " << d.sizing.start
     << "\n";
  const KktCertificate& k = d.sizing.kkt;
  os << (k.proved_local_optimum
             ? "optimality: first- and second-order conditions hold (stationarity " +
                   Format("%.1e", k.stationarity) + ", feasibility " +
                   Format("%.1e", k.feasibility) + ", second order by " + k.second_order_by + ")"
             : "optimality: not proved: " + k.failed)
     << "\n";
  os << "mass by what governs [kg]:";
  for (const auto& [kind, kg] : d.sizing.attribution.by_constraint_kg) {
    if (std::abs(kg) >= 5e-4 * d.sizing.attribution.structure_kg)
      os << " " << kind << Format(" %.4g", kg);
  }
  os << "\n";
  os << "groups (area [m^2], mass [kg]):\n";
  for (int g = 0; g < m.num_groups(); ++g) {
    const TrussGroup& group = m.groups[static_cast<size_t>(g)];
    os << "  " << group.name << " (" << NameOf(group.kind) << ", " << group.members.size()
       << " members): " << Format("%.6g", d.sizing.group_areas[g])
       << Format(", %.6g", MassOfArea(m.density, d.sizing.group_areas[g], group.length_sum))
       << "\n";
  }
  if (m.num_prestress() > 0) os << PrestressLine(d);
  for (const TrussLimitCheck& l : d.check.displacements) {
    os << "displacement of " << l.what << ": " << Format("%.6g m", l.value) << " of "
       << Format("%.6g m", l.limit) << Format(" (%.4f)", l.utilisation) << "\n";
  }
  for (const TrussLimitCheck& l : d.check.frequencies) {
    os << "frequency of " << l.what << ": " << Format("%.6g Hz", l.value) << ", at least "
       << Format("%.6g Hz", l.limit) << "\n";
  }
  if (!d.edited.empty()) {
    os << "edited (an area not its group's, checked as written):";
    for (const int e : d.edited) os << " " << m.MemberName(e);
    os << "\n";
  }
  os << (d.check.pass ? "PASS" : "FAIL") << ": utilisation_max "
     << Format("%.6f", d.check.utilisation_max) << " (" << d.check.governing << ")\n";
  if (!d.check.pass) os << "what moves it: " << d.check.lever << "\n";
  return os.str();
}

}  // namespace tbridge
