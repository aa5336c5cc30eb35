#include "io/design_report.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "checks/verdict.h"
#include "design/abutments.h"
#include "io/comfort_report.h"
#include "io/design_loads.h"
#include "optim/kkt_json.h"

namespace tbridge {

namespace {

using nlohmann::json;

// Units of every numeric field, mirroring the document's layout.
json Units() {
  return json{
      {"config",
       "SI units unless the key name says otherwise (beta_deg in degrees); "
       "see configs/README.md"},
      {"topology",
       {{"n", "1"},
        {"p", "1"},
        {"beta_deg", "deg"},
        {"planes", "1"},
        {"nodes", "1"},
        {"bars", "1"},
        {"strings", "1"},
        {"class", "1"},
        {"fixed_nodes", "1 (1-based node numbers)"}}},
      {"deck",
       {{"section_length", "m"},
        {"section_mass", "kg"},
        {"thickness", "m"},
        {"girder_depth", "m"},
        {"node_load", "N"},
        {"total_load", "N"},
        {"beams_mass", "kg"},
        {"check",
         {{"utilisation", "1"},
          {"stress_ed", "Pa"},
          {"stress_rd", "Pa"},
          {"moment_ed", "N m"},
          {"lateral_moment_ed", "N m"},
          {"sag", "m"},
          {"sag_limit", "m"}}}}},
      {"nodes", "m"},
      {"mass_attribution",
       {{"by_constraint_kg", "kg"},
        {"premium_by_constraint_kg", "kg"},
        {"structure_kg", "kg"},
        {"stationarity_residual", "1"},
        {"active_rows", "1"}}},
      {"members",
       {{"binding", {{"multiplier", "as its unit says"}}},
        {"nodes", "1 (1-based node numbers)"},
        {"length", "m"},
        {"force", "N"},
        {"force_min", "N"},
        {"reference_force", "N"},
        {"utilisation", "1 (demand / resistance)"},
        {"demand", "N (for mode slack: the strain measure, 1)"},
        {"resistance", "N (for mode slack: the working strain, 1)"},
        {"force_density", "N/m"},
        {"area", "m^2"},
        {"radius", "m"},
        {"mass", "kg"},
        {"rest_length", "m"},
        {"stiffness", "N/m"},
        {"stress", "Pa"}}},
      {"materials",
       {{"density", "kg/m^3"},
        {"yield_stress", "Pa"},
        {"youngs_modulus", "Pa"},
        {"partial_factor", "1"},
        {"breaking_stress", "Pa"},
        {"end_efficiency", "1"},
        {"design_stress", "Pa"}}},
      {"mass",
       {{"bars", "kg"},
        {"strings", "kg"},
        {"deck_strings", "kg"},
        {"deck_beams", "kg"},
        {"structure", "kg"},
        {"total", "kg"}}},
      {"solver", {{"iterations", "1"}}},
      {"equilibrium_residual_N", "N"},
      {"self_stress_states", "1"},
      {"stability",
       {{"negative_pivots", "1"},
        {"zero_pivots", "1"},
        {"free_dofs", "1"},
        {"reduced_dofs", "1"},
        {"min_pivot", "N/m"},
        {"critical_load_factor", "1"}}},
      {"reactions", {{"node", "1 (1-based node number)"}, {"force", "N"}}},
      {"reaction_envelope",
       {{"supports", {{"node", "1 (1-based node number)"}, {"x", "N"}, {"y", "N"}, {"z", "N"}}},
        {"abutments",
         {{"x", "m"},
          {"nodes", "1 (1-based node numbers)"},
          {"horizontal", {{"max", "N"}, {"capacity", "N"}, {"utilisation", "1"}}},
          {"vertical", {{"max", "N"}, {"capacity", "N"}, {"utilisation", "1"}}}}}}},
      {"deflection_max",
       {{"deflection", "m"}, {"limit", "m"}, {"node", "1 (1-based node number)"}}},
      {"utilisation_max", "1"},
      {"self_weight_iterations", "1"},
      {"comfort", ComfortUnits()},
      {"angle_search",
       {{"low_deg", "deg"},
        {"high_deg", "deg"},
        {"chosen_deg", "deg"},
        {"trials", {{"beta_deg", "deg"}, {"mass_kg", "kg"}, {"utilisation_max", "1"}}}}}};
}

// The strings' and bars' materials as the design used them (each value resolved from
// `material`, `material.strings`, `material.bars` and design.yield_safety_factor).
json MaterialsJson(const Config& config) {
  auto one = [](const MemberMaterial& m) {
    json j{{"density", m.density},
           {"yield_stress", m.yield_stress},
           {"youngs_modulus", m.youngs_modulus},
           {"partial_factor", m.partial_factor},
           {"design_stress", m.DesignStress()},
           {"tension_clause", m.TensionClause()}};
    if (m.cable()) j["breaking_stress"] = m.breaking_stress, j["end_efficiency"] = m.end_efficiency;
    return j;
  };
  return json{{"bars", one(BarMaterial(config))}, {"strings", one(StringMaterial(config))}};
}

// printf into a std::string; the attribute lets the compiler check every format string.
__attribute__((format(printf, 1, 2))) std::string Format(const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  char buffer[256];
  const int n = std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  std::string text;
  if (n >= 0 && static_cast<size_t>(n) < sizeof buffer) {
    text.assign(buffer, static_cast<size_t>(n));
  } else if (n >= 0) {
    text.resize(static_cast<size_t>(n) + 1);
    std::vsnprintf(text.data(), text.size(), format, again);
    text.resize(static_cast<size_t>(n));
  }
  va_end(again);
  return text;
}

int CountDeckStrings(const Design& d) {
  int count = 0;
  for (const MemberSizing& m : d.strings) count += m.kind == MemberKind::kDeckString;
  return count;
}

// The JSON number of `v` appended to `out`: the shortest text that reads back to the same
// double; null when not finite (JSON has no inf or nan). Members and nodes are appended to a
// text buffer written in large blocks: a stream call per field was a third of the paper's
// n = 16 design (250 000 members).
void AppendNumber(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, result.ptr);
  // Keep a double a JSON float ("0.0", not "0") as a JSON library writes it.
  if (std::find_if(buffer, result.ptr, [](char c) { return c == '.' || c == 'e'; }) == result.ptr)
    out += ".0";
}

// A JSON string; names, groups and modes are plain ASCII, but quotes, backslashes and
// control characters are escaped all the same.
void AppendString(std::string& out, const std::string& text) {
  out += '"';
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  out += '"';
}

const MemberBinding* BindingOf(const Design& d, size_t member) {
  return member < d.attribution.members.size() ? &d.attribution.members[member] : nullptr;
}

// The mass split among the kinds of constraint, or null when the design was not sized.
json AttributionJson(const Design& d) {
  const MassAttribution& a = d.attribution;
  if (a.members.empty()) return nullptr;
  json by = json::object(), premium = json::object();
  for (int k = 0; k < kNumConstraintKinds; ++k) {
    by[kConstraintKinds[k]] = a.mass_by_kind_kg[k];
    premium[kConstraintKinds[k]] = a.premium_by_kind_kg[k];
  }
  return {{"by_constraint_kg", by},
          {"premium_by_constraint_kg", premium},
          {"structure_kg", a.structure_kg},
          {"stationarity_residual", a.stationarity_residual},
          {"active_rows", a.active_rows}};
}

// The rule a member's governing check applies, by its mode: EN 1993-1-1's resistances of a
// steel member in tension (6.2.3; a cable's: EN 1993-1-11 6.3.2) or compression (6.2.4) and
// its flexural buckling (6.3.1, the column curve) or the paper's Euler load; the dynamic check
// compares a run's demand with the same resistances; "slack" is the tool's serviceability rule that
// the deck chain (and the 3D bridge's transverse strings) stay taut (README: "The slack measure").
std::string ClauseOf(const MemberSizing& m, const Config& config) {
  const bool bar = m.kind == MemberKind::kBar;
  const bool euler = config.design.bar_resistance == BarResistanceRule::kEuler;
  switch (m.mode) {
    case LimitMode::kSlack:
    case LimitMode::kTaut:
    case LimitMode::kReferenceTaut:
      return "taut under service (tbridge)";
    case LimitMode::kTension:
      return "bar in tension (tbridge)";
    case LimitMode::kDeflection:
      return "EN 1990 A2.4.1 (deflection), stiffness";
    case LimitMode::kBuckling:
      return euler ? "Euler load (paper eq. 46)" : "EN 1993-1-1 6.3.1";
    case LimitMode::kYield:
      return bar ? "EN 1993-1-1 6.2.4" : StringMaterial(config).TensionClause();
    case LimitMode::kServiceability:
      return StringMaterial(config).ServiceClause() + std::string(", characteristic combination");
    case LimitMode::kDynamic:
      if (!bar) return StringMaterial(config).TensionClause() + std::string(" at the run's peak");
      return euler ? "Euler load at the run's peak" : "EN 1993-1-1 6.2.4/6.3.1 at the run's peak";
    default:
      return "";
  }
}

void AppendMember(std::string& out, const MemberSizing& m, const Member& topology_member,
                  const MemberBinding* binding, const Config& config) {
  // Keys in the alphabetical order a JSON library writes them in.
  auto number = [&out](const char* key, double v) {
    out.append(", \"").append(key).append("\": ");
    AppendNumber(out, v);
  };
  auto text = [&out](const char* key, const std::string& v) {
    out.append(", \"").append(key).append("\": ");
    AppendString(out, v);
  };
  out += "{\"area\": ";
  AppendNumber(out, m.area);
  // The constraint that costs the member's group most, and its multiplier (mass attribution).
  if (binding && binding->kind) {
    out += ", \"binding\": {\"case\": ";
    AppendString(out, binding->case_label);
    out += ", \"kind\": ";
    AppendString(out, kConstraintKinds[*binding->kind]);
    out += ", \"multiplier\": ";
    AppendNumber(out, binding->multiplier);
    out += ", \"unit\": ";
    AppendString(out, binding->unit);
    out += "}";
  } else {
    out += ", \"binding\": null";
  }
  text("clause", ClauseOf(m, config));
  number("demand", m.demand);
  number("force", m.force);
  number("force_density", m.force_density);
  number("force_min", m.force_min);
  text("governed_by", NameOf(m.governed_by));
  text("governing_case", m.governing_case);
  text("group", NameOf(topology_member.group));
  number("length", m.length);
  number("mass", m.mass);
  text("mode", NameOf(m.mode));
  text("name", m.name);
  out.append(", \"nodes\": [")
      .append(std::to_string(m.i + 1))
      .append(", ")
      .append(std::to_string(m.j + 1))
      .append("]");
  number("radius", m.radius);
  number("reference_force", m.reference_force);
  number("resistance", m.resistance);
  number("rest_length", m.rest_length);
  // A bar is rigid in the model: it has no axial stiffness to report.
  number("stiffness",
         m.kind == MemberKind::kBar ? std::numeric_limits<double>::quiet_NaN() : m.stiffness);
  number("stress", m.stress);
  text("type", KindName(m.kind));
  number("utilisation", m.utilisation);
  out += "}";
}

json StabilityJson(const StabilityVerdict& v) {
  json out = {{"stable", v.stable},
              {"method", v.method},
              {"negative_pivots", v.negative_pivots},
              {"zero_pivots", v.zero_pivots},
              {"free_dofs", v.free_dofs},
              {"reduced_dofs", v.reduced_dofs},
              {"min_pivot", v.min_pivot}};
  // null: not computed (n > 6), or no positive factor exists.
  out["critical_load_factor"] =
      v.critical_load_factor ? json(*v.critical_load_factor) : json(nullptr);
  out["critical_load_factor_computed"] = v.critical_load_factor_computed;
  return out;
}

// One entry per case and fixed node: {case, node (1-based), force [x, y, z]}; first the
// reference state's, then each statically solved case's.
// What a support reaction holds: the members' forces on the support node and the loads applied
// at the node itself (its share of the members' weight and of the deck), so that the reactions
// and every applied load sum to zero.
constexpr const char* kReactionsInclude =
    "the members' forces on the support and the loads applied at the support node itself (its "
    "share of the "
    "members' weight and of the deck): with them every applied load sums to zero";

// Per support: the largest and smallest of each component over the converged ultimate cases of
// the static check, each with its case.
struct ReactionExtreme {
  double max = -std::numeric_limits<double>::infinity(),
         min = std::numeric_limits<double>::infinity();
  std::string max_case, min_case;
};
std::vector<std::array<ReactionExtreme, 3>> ReactionEnvelope(const Design& d,
                                                             std::vector<int>& supports) {
  const Structure& s = d.topology.structure;
  supports.clear();
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (s.fixed[v]) supports.push_back(v);
  }
  std::vector<std::array<ReactionExtreme, 3>> out(supports.size());
  for (const CaseResponse& c : d.statics.cases) {
    if (!c.converged || d.cases[c.case_index].state != LimitState::kUltimate) continue;
    for (size_t k = 0; k < supports.size(); ++k) {
      for (int a = 0; a < 3; ++a) {
        const double r = c.reactions(a, supports[k]) + 0.0;
        ReactionExtreme& e = out[k][a];
        if (r > e.max) e.max = r, e.max_case = c.label;
        if (r < e.min) e.min = r, e.min_case = c.label;
      }
    }
  }
  return out;
}

json ReactionEnvelopeJson(const Design& d) {
  std::vector<int> supports;
  const auto envelope = ReactionEnvelope(d, supports);
  json list = json::array();
  for (size_t k = 0; k < supports.size(); ++k) {
    json node = {{"node", supports[k] + 1}};
    const char* axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      const ReactionExtreme& e = envelope[k][a];
      if (e.max_case.empty()) continue;
      node[axes[a]] = {
          {"max", e.max}, {"max_case", e.max_case}, {"min", e.min}, {"min_case", e.min_case}};
    }
    list.push_back(node);
  }
  json abutments = json::array();
  for (const AbutmentFinding& a : d.statics.abutments) {
    json nodes = json::array();
    for (const int v : a.nodes) nodes.push_back(v + 1);
    const auto side = [](double demand, const std::string& at, double capacity,
                         double utilisation) {
      return json{{"max", demand},
                  {"case", at},
                  {"capacity", capacity > 0 ? json(capacity) : json(nullptr)},
                  {"utilisation", capacity > 0 ? json(utilisation) : json(nullptr)}};
    };
    abutments.push_back({{"x", a.x_m},
                         {"nodes", nodes},
                         {"horizontal", side(a.horizontal_n, a.horizontal_case,
                                             a.horizontal_capacity_n, a.HorizontalUtilisation())},
                         {"vertical", side(a.vertical_n, a.vertical_case, a.vertical_capacity_n,
                                           a.VerticalUtilisation())}});
  }
  return {{"over", "the ultimate cases of the static check"},
          {"includes", kReactionsInclude},
          {"supports", list},
          {"abutments", abutments}};
}

// One abutment's largest reactions in kN, each with its capacity, utilisation and case:
// "abutment at x = 0 m: H 812.3 kN of 1000 kN (0.812, uls_payload_full); V 95.2 kN (unlimited,
// ...)".
std::string AbutmentLine(const AbutmentFinding& a) {
  const auto side = [](const char* name, double demand, double capacity, double utilisation,
                       const std::string& at) {
    return Format("%s %.4g kN ", name, demand / 1000) +
           (capacity > 0 ? Format("of %.4g kN (%.3f, ", capacity / 1000, utilisation)
                         : std::string("(unlimited, ")) +
           at + ")";
  };
  return Format("  abutment at x = %g m: ", a.x_m) +
         side("H", a.horizontal_n, a.horizontal_capacity_n, a.HorizontalUtilisation(),
              a.horizontal_case) +
         "; " +
         side("V", a.vertical_n, a.vertical_capacity_n, a.VerticalUtilisation(), a.vertical_case);
}

// The angle's search (bridge.beta_deg "auto"), null where the angle was given.
json AngleSearchJson(const AngleSearch& s) {
  if (!s.done) return nullptr;
  json trials = json::array();
  for (const AngleSearch::Trial& t : s.trials) {
    trials.push_back({{"beta_deg", t.beta_deg},
                      {"mass_kg", t.mass_kg},
                      {"pass", t.pass},
                      {"utilisation_max", t.utilisation_max}});
  }
  return {{"low_deg", s.low_deg},
          {"high_deg", s.high_deg},
          {"chosen_deg", s.chosen_deg},
          {"method",
           "golden section on the verified design's mass, to 0.5 deg; masses within 5e-4 equal"},
          {"trials", trials},
          {"note", s.note}};
}

// "angle: beta = 47.08 deg chosen in [10, 60] deg over 12 verified designs; either side 46.5 deg
// 2892.1 kg, 47.7 deg 2891.9 kg", and the note.
std::string AngleSearchLine(const AngleSearch& s) {
  const AngleSearch::Trial *below = nullptr, *above = nullptr;
  for (const AngleSearch::Trial& t : s.trials) {
    if (t.beta_deg < s.chosen_deg && (below == nullptr || t.beta_deg > below->beta_deg)) below = &t;
    if (t.beta_deg > s.chosen_deg && (above == nullptr || t.beta_deg < above->beta_deg)) above = &t;
  }
  const auto text = [](const AngleSearch::Trial* t) {
    if (t == nullptr) return std::string("none tried");
    return Format("%.4g deg %.6g kg", t->beta_deg, t->mass_kg) + (t->pass ? "" : " (FAIL)");
  };
  std::string out =
      Format("angle: beta = %.4g deg chosen in [%g, %g] deg (bridge.beta_deg \"auto\") over ",
             s.chosen_deg, s.low_deg, s.high_deg) +
      Format("%.0f verified designs; either side: ", static_cast<double>(s.trials.size())) +
      text(below) + ", " + text(above);
  if (!s.note.empty()) out += "; " + s.note;
  return out;
}

json ReactionsJson(const Design& d) {
  const Structure& s = d.topology.structure;
  json out = json::array();
  auto add = [&](const std::string& label, const Eigen::Matrix3Xd& r) {
    for (int v = 0; v < s.num_nodes() && v < r.cols(); ++v) {
      if (!s.fixed[v]) continue;
      out.push_back({{"case", label},
                     {"node", v + 1},
                     {"force", {r(0, v) + 0.0, r(1, v) + 0.0, r(2, v) + 0.0}}});
    }
  };
  add("reference", d.reactions);
  for (const CaseResponse& c : d.statics.cases) {
    if (c.converged) add(c.label, c.reactions);
  }
  return out;
}

// Per statically solved case: its largest deck deflection from the drawn geometry.
json DeflectionsJson(const Design& d) {
  json out = json::array();
  for (const CaseResponse& c : d.statics.cases) {
    json e = {{"case", c.label}, {"converged", c.converged}, {"slack_strings", c.slack_strings}};
    e["deflection"] = c.converged ? json(c.deflection_m) : json(nullptr);
    e["node"] = c.deflection_node >= 0 ? json(c.deflection_node + 1) : json(nullptr);
    if (!c.converged) e["message"] = c.message;
    out.push_back(e);
  }
  return out;
}

// The cases sized and checked for, the notes on those left out, and the verdict.
json CasesJson(const Design& d) {
  json out = json::array();
  for (const LoadCase& c : d.cases) {
    out.push_back({{"name", c.name},
                   {"limit_state", LimitStateName(c.state)},
                   {"combination", c.combination},
                   {"travelling", c.station_load != 0}});
  }
  return out;
}

// A group's largest force in the run over its largest in the static counterpart (0 when that
// is 0): the group's figure, beside `amplification`, the largest ratio of one of its members.
double PeakRatio(const GroupAmplification& g) {
  return g.static_peak > 0 ? g.dynamic_peak / g.static_peak : 0.0;
}

json DynamicsJson(const Design& d) {
  json runs = json::array();
  const std::array<Abutment, 2> ends = AbutmentsOf(d.topology.structure, d.config.bridge.span);
  for (const DynamicRun& r : d.dynamics.runs) {
    json reactions = json::array();
    for (size_t a = 0; a < ends.size() && r.done; ++a) {
      reactions.push_back({{"x", ends[a].x_m},
                           {"horizontal_max", r.peak_horizontal_reaction[a]},
                           {"vertical_max", r.peak_vertical_reaction[a]}});
    }
    json groups = json::array();
    for (const GroupAmplification& g : r.groups) {
      groups.push_back({{"group", NameOf(g.group)},
                        {"static_peak", g.static_peak},
                        {"dynamic_peak", g.dynamic_peak},
                        {"peak_ratio", PeakRatio(g)},
                        {"amplification", g.amplification}});
    }
    runs.push_back({{"name", r.name},
                    {"load", r.load},
                    {"done", r.done},
                    {"note", r.note},
                    {"integrator", r.integrator},
                    {"dt", r.dt},
                    {"steps", r.steps},
                    {"duration", r.duration},
                    {"peak_deck_displacement", r.peak_deck_displacement},
                    {"amplification", groups},
                    {"abutment_reactions", reactions}});
  }
  return {{"done", d.dynamics.done},
          {"ran", d.dynamics.ran()},
          {"abutment_reactions_include",
           "each abutment's largest horizontal (in plan) and vertical reaction over the run [N], "
           "characteristic "
           "(the run is at service level): reported, not constrained"},
          {"runs", runs}};
}

// "as_built": what check re-derived of an edited design, or null.
json AsBuiltJson(const Design& d) {
  const AsBuilt& a = d.as_built;
  if (!a.re_derived) return nullptr;
  return {{"re_derived", true},
          {"edited", a.edited},
          {"node_move_max", a.node_move_m},
          {"node", a.node >= 0 ? json(a.node + 1) : json(nullptr)},
          {"force_change_max", a.force_change_n},
          {"force_member", a.force_member},
          {"slack_strings", a.slack_strings}};
}

std::string AsBuiltLine(const AsBuilt& a) {
  std::string edited;
  for (size_t k = 0; k < a.edited.size(); ++k) edited += (k ? ", " : "") + a.edited[k];
  return Format(
      "as built: reference state re-derived (rest lengths and bar lengths kept, each member's "
      "weight from its "
      "area%s%s); nodes moved up to %.4g mm from the drawn geometry%s%s, reference forces changed "
      "up to "
      "%.6g N%s%s; %d strings slack in it",
      edited.empty() ? "" : "; edited: ", edited.c_str(), a.node_move_m * 1e3,
      a.node >= 0 ? " at node " : "", a.node >= 0 ? std::to_string(a.node + 1).c_str() : "",
      a.force_change_n, a.force_member.empty() ? "" : " in ", a.force_member.c_str(),
      a.slack_strings);
}

// The loads a design read back is checked under, where they are not those it was designed for.
std::string LoadsChangedLine(const Config& designed, const Config& config) {
  std::string changed;
  for (const std::string& c : ChangedLoads(designed, config))
    changed += (changed.empty() ? "" : "; ") + c;
  return "loads changed from those designed for: " + changed +
         "; the bridge as designed (members, rest lengths, deck plates) checked under them";
}

json VerdictJson(const Design& d, const Verdict& v) {
  return {{"outcome", VerdictName(v.outcome)},
          {"pass", v.pass},
          {"summary", v.summary},
          {"scope", v.scope},
          {"checks",
           {{"static", CheckStatusName(d.statics.Status())},
            {"dynamic", CheckStatusName(d.dynamics.Status())},
            {"deck_beams", CheckStatusName(v.deck_beams.Status())},
            {"comfort", CheckStatusName(d.comfort.Status())}}},
          {"notes", d.notes}};
}

// A failing design's largest violation, by what the verdict reads (each as its ratio to its
// limit, less 1), and the config keys that move it: what a user can change, not a
// re-statement of the verdict. "" where the design does not fail.
std::string WhatMovesIt(const Design& d, const Verdict& v) {
  if (v.outcome != VerdictOutcome::kFail) return "";
  struct Violation {
    double over = -1;
    std::string kind, keys;
  };
  std::vector<Violation> found;
  double members = 0;
  for (const auto* list : {&d.bars, &d.strings}) {
    for (const MemberSizing& m : *list) members = std::max(members, m.utilisation);
  }
  found.push_back(
      {members - 1, "a member's strength",
       "bridge.beta_deg and bridge.n (a deeper substructure carries the load with less "
       "force), the material's yield_stress, design.max_sizings (where the sizing stopped "
       "before a design passed)"});
  found.push_back({v.deck_beams.utilisation - 1, "the deck beams' bending",
                   "bridge.n (shorter deck sections)"});
  found.push_back(
      {v.deck_beams.SagRatio() - 1, "the deck beams' sag", "loads.deck_sag_limit, bridge.n"});
  if (d.statics.done && d.statics.deflection_limit_m > 0) {
    found.push_back({d.statics.deflection_max_m / d.statics.deflection_limit_m - 1,
                     "the deflection", "loads.deflection_limit, bridge.beta_deg, bridge.n"});
  }
  for (const AbutmentFinding& a : d.statics.abutments) {
    found.push_back({a.HorizontalUtilisation() - 1, "an abutment's horizontal reaction",
                     "supports.horizontal_capacity_n, bridge.beta_deg (a deeper substructure "
                     "thrusts less), bridge.n, design.deck_string_min_radius (the deck chain's "
                     "prestress floor thrusts on the abutments)"});
    found.push_back(
        {a.VerticalUtilisation() - 1, "an abutment's vertical reaction",
         "supports.vertical_capacity_n, bridge.payload, loads.superimposed_dead_n_per_m"});
  }
  for (const ComfortMode& m : d.comfort.modes) {
    if (m.pass) continue;
    const double over =
        m.acceleration_m_s2 > m.limit_m_s2 && m.limit_m_s2 > 0
            ? m.acceleration_m_s2 / m.limit_m_s2 - 1
            : (m.lock_in_pedestrians > 0 ? d.comfort.pedestrians / m.lock_in_pedestrians - 1 : 0);
    found.push_back(
        {over,
         "comfort (" + std::string(NameOf(m.direction)) + " mode " + std::to_string(m.index) + ")",
         "comfort.comfort_level, comfort.traffic_class, bridge.beta_deg, bridge.n, "
         "design.max_sizings"});
  }
  if (!d.stability.stable) {
    found.push_back({std::numeric_limits<double>::infinity(), "stability",
                     "design.deck_string_min_radius, design.transverse_string_min_radius"});
  }
  const auto worst =
      std::max_element(found.begin(), found.end(),
                       [](const Violation& a, const Violation& b) { return a.over < b.over; });
  if (worst == found.end() || !(worst->over > 0)) return "";
  const std::string by =
      std::isfinite(worst->over) ? Format(", %.3g %% over its limit", 100 * worst->over) : "";
  return "what moves it: the largest violation is " + worst->kind + by + "; keys: " + worst->keys;
}

// The topology section: the counts and the fixed nodes (1-based).
json TopologyJson(const Design& d) {
  const Structure& s = d.topology.structure;
  json fixed = json::array();
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (v < static_cast<int>(s.fixed.size()) && s.fixed[v]) fixed.push_back(v + 1);
  }
  return {{"n", d.config.bridge.n},
          {"p", d.config.bridge.p},
          {"beta_deg", d.config.bridge.beta_deg},
          {"planes", d.topology.planes},
          {"nodes", s.num_nodes()},
          {"bars", s.num_bars()},
          {"strings", s.num_strings()},
          {"class", s.TensegrityClass()},
          {"fixed_nodes", fixed}};
}

// The deck section, with the check of its beams.
json DeckJson(const Design& d, const DeckBeamCheck& beams) {
  const json deck_check = {{"status", CheckStatusName(beams.Status())},
                           {"utilisation", beams.utilisation},
                           {"stress_ed", beams.stress_ed_pa},
                           {"stress_rd", beams.stress_rd_pa},
                           {"moment_ed", beams.moment_ed_nm},
                           {"lateral_moment_ed", beams.lateral_moment_ed_nm},
                           {"governing_case", beams.governing_case},
                           {"sag", beams.sag_m},
                           {"sag_limit", beams.sag_limit_m},
                           {"sag_case", beams.sag_case}};
  return {{"section_length", d.deck.section_length},
          {"section_mass", d.deck.section_mass},
          {"thickness", d.deck.thickness},
          {"section", NameOf(d.config.design.deck_section)},
          {"girder_depth", d.deck.girder_depth > 0 ? json(d.deck.girder_depth) : json()},
          {"node_load", d.deck.node_load},
          {"total_load", d.deck.total_load},
          {"beams_mass", d.deck.beams_mass},
          {"sized_by", d.deck.sized_by},
          {"check", deck_check}};
}

json MassJson(const Design& d) {
  return {{"bars", d.mass.bars},
          {"strings", d.mass.strings},
          {"deck_strings", d.mass.deck_strings},
          {"deck_beams", d.mass.deck_beams},
          {"structure", d.mass.structure},
          {"total", d.mass.total}};
}

// The solver section, with its optimality certificate when one was computed.
json SolverJson(const Design& d) {
  return {{"name", NameOf(d.solver.solver)},
          {"status", d.solver.status},
          {"iterations", d.solver.iterations},
          {"problem", d.solver_form},
          {"kkt", d.resizing.kkt ? KktJson(*d.resizing.kkt) : json(nullptr)}};
}

// A design read from its file (tbridge check) was not sized here: no record, rather than
// one that reads "not converged".
json ResizingJson(const Design& d) {
  return d.solver_form == kReadFromFile ? json(nullptr)
                                        : json{{"iterations", d.resizing.iterations},
                                               {"converged", d.resizing.converged},
                                               {"tolerance", d.resizing.tolerance},
                                               {"structure_mass_kg", d.resizing.structure_mass_kg},
                                               {"utilisation_max", d.resizing.utilisation_max},
                                               {"changes", d.resizing.changes},
                                               {"second_start_kg", d.resizing.second_start_kg},
                                               {"optima", d.resizing.optima},
                                               {"why", d.resizing.why},
                                               {"comfort_rows", d.resizing.comfort_rows}};
}

// The "members" and "nodes" sections, streamed one per line.
void WriteMembersAndNodes(const Design& d, std::ostream& os) {
  const Structure& s = d.topology.structure;
  // Members and nodes go through a buffer written to the stream a block at a time.
  std::string text;
  constexpr size_t kBlock = 1 << 20;
  text.reserve(kBlock + 4096);
  // Writes the buffer once it holds a block, or at once with `all`.
  const auto flush = [&os, &text](bool all) {
    if (!all && text.size() < kBlock) return;
    os.write(text.data(), static_cast<std::streamsize>(text.size()));
    text.clear();
  };
  text += "  \"members\": [";
  const char* separator = "\n    ";
  for (int j = 0; j < s.num_members(); ++j) {
    text += separator;
    AppendMember(text, d.MemberAt(j), s.MemberAt(j), BindingOf(d, static_cast<size_t>(j)),
                 d.config);
    separator = ",\n    ";
    flush(false);
  }
  text += "\n  ],\n  \"nodes\": [";
  separator = "\n    [";
  for (int v = 0; v < s.num_nodes(); ++v) {
    text += separator;
    for (int a = 0; a < 3; ++a) {
      if (a) text += ", ";
      AppendNumber(text, s.nodes(a, v));
    }
    separator = "],\n    [";
    flush(false);
  }
  text += s.num_nodes() ? "]\n  ],\n" : "\n  ],\n";
  flush(true);
}

// Appends a line of text to `out`.
auto LineAppender(std::string& out) {
  return [&out](const std::string& text) { out += text + "\n"; };
}

// The bridge, its topology and its deck.
void AppendSummaryHead(std::string& out, const Design& d) {
  const Structure& s = d.topology.structure;
  const BridgeConfig& b = d.config.bridge;
  const auto line = LineAppender(out);

  line(Format("%s bridge: n = %d, p = %d, beta = %g deg, span %g m, payload %g N",
              b.planes == 1 ? "planar substructure" : "3D coupled", b.n, b.p, b.beta_deg, b.span,
              b.payload));
  if (d.angle.done) line(AngleSearchLine(d.angle));
  line(Format("topology: %d nodes (%d fixed), %d bars, %d strings (%d deck), class %d",
              s.num_nodes(), s.num_nodes() - s.num_free_nodes(), s.num_bars(), s.num_strings(),
              CountDeckStrings(d), s.TensegrityClass()));
  const std::string section =
      d.deck.girder_depth > 0
          ? Format("two girders %.4g mm deep (rolled-I proportions, %.4g cm² each)",
                   d.deck.girder_depth * 1e3, GirderArea(d.deck.girder_depth) * 1e4)
          : Format("thickness %.4g mm", d.deck.thickness * 1e3);
  line(
      Format("deck: section l = %.4g m, m_d = %.5g kg, %s; f = %.6g N per deck node, F_tot = "
             "%.6g N",
             d.deck.section_length, d.deck.section_mass, section.c_str(), d.deck.node_load,
             d.deck.total_load));
}

// The deck beams, the solver (or the file the design was read from) and the stability.
void AppendSummaryDesign(std::string& out, const Design& d, const DeckBeamCheck& beams) {
  const auto line = LineAppender(out);
  line(
      Format("deck beams: %s set by %s; bending utilisation %.4f (%s), sag %.4g mm of l_d / "
             "%g = %.4g mm (%s)",
             d.deck.girder_depth > 0 ? "girders' depth" : "thickness", d.deck.sized_by.c_str(),
             beams.utilisation, beams.governing_case.c_str(), beams.sag_m * 1e3,
             d.config.loads.deck_sag_limit, beams.sag_limit_m * 1e3,
             beams.sag_case.empty() ? "no serviceability case" : beams.sag_case.c_str()));
  if (d.solver_form == kReadFromFile) {
    line(Format("design: read from its file, checked as written; equilibrium residual %.2e N",
                d.equilibrium_residual));
    if (d.as_built.re_derived) line(AsBuiltLine(d.as_built));
    if (d.designed_for) line(LoadsChangedLine(*d.designed_for, d.config));
  } else {
    line(Format(
        "solver: %s on the %s problem, status %s after %d iterations; equilibrium residual %.2e N; "
        "self-stress states: %d",
        NameOf(d.solver.solver), d.solver_form.c_str(), d.solver.status.c_str(),
        d.solver.iterations, d.equilibrium_residual, d.self_stress_states));
  }
  const StabilityVerdict& v = d.stability;
  std::string critical = "not computed (n > 6)";
  if (v.critical_load_factor_computed) {
    critical = v.critical_load_factor ? Format("%.4g", *v.critical_load_factor)
                                      : std::string("none (no softening)");
  }
  line(
      Format("stability: %s (LDL^T of the %d x %d stiffness on the motions that keep bar lengths: "
             "%d negative, "
             "%d zero pivots); critical load factor %s",
             v.stable ? "stable" : "UNSTABLE", v.reduced_dofs, v.reduced_dofs, v.negative_pivots,
             v.zero_pivots, critical.c_str()));
}

// The support reactions of the reference state and, when the statics ran, their envelope
// and the abutments.
void AppendSummaryReactions(std::string& out, const Design& d) {
  const Structure& s = d.topology.structure;
  const auto line = LineAppender(out);
  std::string reactions;
  for (int n = 0; n < s.num_nodes() && n < d.reactions.cols(); ++n) {
    if (!s.fixed[n]) continue;
    reactions += Format("%s node %d (%.6g, %.6g, %.6g)", reactions.empty() ? "" : ";", n + 1,
                        d.reactions(0, n), d.reactions(1, n), d.reactions(2, n));
  }
  line(reactions.size() < 400 ? "support reactions [N], reference state:" + reactions
                              : "support reactions: in the JSON output");
  if (d.statics.done) {
    std::vector<int> supports;
    const auto envelope = ReactionEnvelope(d, supports);
    line("support reactions [N], envelope over the ultimate cases (each holds " +
         std::string(kReactionsInclude) + "):");
    for (size_t k = 0; k < supports.size() && k < 8; ++k) {
      std::string text;
      const char* axes[] = {"H (x)", "V (y)", "z"};
      for (int a = 0; a < d.topology.structure.dim(); ++a) {
        const ReactionExtreme& e = envelope[k][a];
        if (e.max_case.empty()) continue;
        text += Format("%s %s %.6g (%s) to %.6g (%s)", text.empty() ? "" : ";", axes[a], e.min,
                       e.min_case.c_str(), e.max, e.max_case.c_str());
      }
      line(Format("  node %d:%s", supports[k] + 1, text.c_str()));
    }
    for (const AbutmentFinding& a : d.statics.abutments) line(AbutmentLine(a));
  }
}

// The load cases, their notes and the static check.
void AppendSummaryStatics(std::string& out, const Design& d) {
  const auto line = LineAppender(out);
  line(Format(
      "load cases: %zu (%s)%s", d.cases.size(),
      d.config.design.self_weight ? "self-weight in G" : "no self-weight",
      d.self_weight_iterations > 1
          ? Format(", self-weight fixed point in %d sizings", d.self_weight_iterations).c_str()
          : ""));
  for (const std::string& note : d.notes) line("  note: " + note);
  if (d.statics.done) {
    double worst_balance = 0;
    for (const CaseResponse& c : d.statics.cases)
      worst_balance = std::max(worst_balance, c.balance);
    const double margin = d.config.loads.station_margin;
    const std::string stations =
        margin >= 1 ? Format("travelling loads at all %d stations", d.statics.stations)
                    : Format(
                          "travelling loads at all %d stations linearly, nonlinearly within "
                          "loads.station_margin = "
                          "%g of a largest or a limit",
                          d.statics.stations, margin);
    const std::string mirrored =
        d.statics.mirrored > 0
            ? Format(", %d stations as mirror images of solved ones on this symmetric bridge",
                     d.statics.mirrored)
            : "";
    std::string loss;
    for (const std::string& state : d.statics.prestress_states)
      loss += (loss.empty() ? "" : "; ") + state;
    if (!loss.empty()) {
      loss = Format(
          "; each case also %s (design.prestress_loss %g, design.rest_length_tolerance %g)",
          loss.c_str(), d.config.design.prestress_loss, d.config.design.rest_length_tolerance);
    }
    line(Format(
        "static check: %d nonlinear solves%s (%s%s); largest "
        "deflection %.4g m (%s), limit span / %g = %.4g m; reactions balance the loads to %.1e",
        d.statics.nonlinear_solves, mirrored.c_str(), stations.c_str(), loss.c_str(),
        d.statics.deflection_max_m,
        d.statics.deflection_case.empty() ? "no serviceability case"
                                          : d.statics.deflection_case.c_str(),
        d.config.loads.deflection_limit, d.statics.deflection_limit_m, worst_balance));
  }
}

// The sizings of the resizing loop, the optimality certificate and the comfort rows.
void AppendSummaryResizing(std::string& out, const Design& d, const Verdict& verdict) {
  const auto line = LineAppender(out);
  if (d.resizing.iterations > 1) {
    line(Format("resizing: %d designs, structure %.4g kg -> %.4g kg (%s); %s",
                d.resizing.iterations, d.resizing.structure_mass_kg.front(), d.mass.structure,
                verdict.pass ? "the lightest that passed" : "none passed: the last design",
                d.resizing.converged
                    ? Format("converged: a sizing within %g of the last passing design's mass",
                             d.resizing.tolerance)
                          .c_str()
                    : "did not converge"));
    // Each sizing: its mass, its largest utilisation under the checks, and what that changed;
    // the settling sizing of a converged run is not checked.
    const Resizing& r = d.resizing;
    for (size_t k = 0; k + 1 < r.structure_mass_kg.size(); ++k) {
      if (k < r.utilisation_max.size()) {
        line(Format("  sizing %zu: %.6g kg, utilisation_max %.6f%s%s", k + 1,
                    r.structure_mass_kg[k + 1], r.utilisation_max[k],
                    k < r.changes.size() ? "; then " : "",
                    k < r.changes.size() ? r.changes[k].c_str() : ""));
      } else {
        line(
            Format("  sizing %zu: %.6g kg, within %g of the last passing design's mass: settled, "
                   "not checked",
                   k + 1, r.structure_mass_kg[k + 1], r.tolerance));
      }
    }
    if (!r.optima.empty()) line("  " + r.optima);
  }
  if (d.resizing.kkt) {
    const KktCertificate& k = *d.resizing.kkt;
    line(k.proved_local_optimum
             ? Format("optimality: first- and second-order conditions hold (stationarity %.1e, "
                      "feasibility %.1e, "
                      "complementarity %.1e; second order by %s)",
                      k.stationarity, k.feasibility, k.complementarity, k.second_order_by.c_str())
             : "optimality: not proved: " + k.failed);
  }
  for (const std::string& row : d.resizing.comfort_rows) line("comfort row of the sizing: " + row);
}

// One line per dynamic run.
void AppendSummaryDynamics(std::string& out, const Design& d) {
  const auto line = LineAppender(out);
  if (d.dynamics.done && d.dynamics.runs.empty())
    line("dynamic check: no dynamic load among loads.cases");
  for (const DynamicRun& r : d.dynamics.runs) {
    if (!r.done) {
      line("dynamic check, " + r.name + ": " + r.note);
      continue;
    }
    std::string amp;
    for (const GroupAmplification& g : r.groups) {
      amp += Format("%s %s %.3g (%.3g)", amp.empty() ? "" : ",", NameOf(g.group), PeakRatio(g),
                    g.amplification);
    }
    line(Format(
        "dynamic check, %s (%s): %s at dt = %.3g s, %ld steps; peak deck displacement %.4g m; peak "
        "reactions per abutment (characteristic) H %.4g / %.4g kN, V %.4g / %.4g kN; per group, "
        "peak force "
        "over its static peak (largest member's ratio):%s",
        r.name.c_str(), r.load.c_str(), r.integrator.c_str(), r.dt, r.steps,
        r.peak_deck_displacement, r.peak_horizontal_reaction[0] / 1000,
        r.peak_horizontal_reaction[1] / 1000, r.peak_vertical_reaction[0] / 1000,
        r.peak_vertical_reaction[1] / 1000, amp.c_str()));
  }
}

// The member table, its first `max_member_rows` rows.
void AppendSummaryMembers(std::string& out, const Design& d, int max_member_rows) {
  const auto line = LineAppender(out);
  line(
      "members (force: the largest over the ultimate cases, tension for strings, compression for "
      "bars; "
      "util. = demand / resist., the governing demand, static or dynamic, against its resistance; "
      "for mode slack "
      "the strain measure against the working strain):");
  line(Format("  %-9s %-11s %9s %11s %8s %9s %11s %9s  %-11s %11s %11s %6s  %s", "name", "type",
              "s [m]", "force [N]", "r [mm]", "L0 [m]", "k_s [N/m]", "m [kg]", "governed by",
              "demand [N]", "resist. [N]", "util.", "governing case (mode; clause)"));
  std::vector<const MemberSizing*> rows;
  for (const MemberSizing& m : d.bars) rows.push_back(&m);
  for (const MemberSizing& m : d.strings) rows.push_back(&m);
  const size_t shown = std::min(rows.size(), static_cast<size_t>(std::max(max_member_rows, 0)));
  for (size_t k = 0; k < shown; ++k) {
    const MemberSizing& m = *rows[k];
    const bool bar = m.kind == MemberKind::kBar;
    line(Format(
        "  %-9s %-11s %9.4f %11.2f %8.2f %9s %11s %9.4f  %-11s %11.6g %11.6g %6.3f  %s (%s; %s)",
        m.name.c_str(), KindName(m.kind), m.length, m.force, m.radius * 1e3,
        bar ? "-" : Format("%.4f", m.rest_length).c_str(),
        bar ? "-" : Format("%.4e", m.stiffness).c_str(), m.mass, NameOf(m.governed_by), m.demand,
        m.resistance, m.utilisation, m.governing_case.c_str(), NameOf(m.mode),
        ClauseOf(m, d.config).c_str()));
  }
  if (shown < rows.size()) {
    line(
        Format("  ... %zu more members omitted (all are in the JSON output)", rows.size() - shown));
  }
  line("");
}

// The masses and what the structure's mass pays for.
void AppendSummaryMass(std::string& out, const Design& d) {
  const auto line = LineAppender(out);
  line("mass [kg]:");
  line(Format("  bars                         %12.3f", d.mass.bars));
  line(Format("  strings (non-deck)           %12.3f", d.mass.strings));
  line(Format("  bars + strings (eq. 49)      %12.3f", d.mass.bars + d.mass.strings));
  line(Format("  deck strings                 %12.3f", d.mass.deck_strings));
  line(Format("  structure                    %12.3f", d.mass.structure));
  line(Format("  deck beams                   %12.3f", d.mass.deck_beams));
  line(Format("  total                        %12.3f", d.mass.total));
  const MassAttribution& a = d.attribution;
  if (!a.members.empty()) {
    line("");
    line(
        Format("what the structure's mass pays for [kg] (the verified sizing's multipliers; "
               "stationarity residual "
               "%.1e):",
               a.stationarity_residual));
    line(Format("  %-21s %12s %22s", "constraint", "mass", "premium over first"));
    for (int k = 0; k < kNumConstraintKinds; ++k) {
      line(Format("  %-21s %12.3f %22.3f", kConstraintKinds[k], a.mass_by_kind_kg[k],
                  a.premium_by_kind_kg[k]));
    }
  }
}

}  // namespace

void WriteDesignJson(const Design& d, std::ostream& os) {
  // The small sections as JSON values; nodes and members are streamed one per line, so the
  // memory stays that of the design itself.
  const json topology = TopologyJson(d);
  const Verdict verdict = DesignVerdict(d);
  const DeckBeamCheck& beams = verdict.deck_beams;
  const json deck = DeckJson(d, beams);
  const json mass = MassJson(d);
  const json solver = SolverJson(d);
  auto field = [&os](const char* key, const json& value, bool last = false) {
    std::string text = value.dump(2);
    for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 3))
      text.insert(at + 1, "  ");
    os << "  \"" << key << "\": " << text << (last ? "\n" : ",\n");
  };

  os << "{\n";
  field("angle_search", AngleSearchJson(d.angle));
  field("as_built", AsBuiltJson(d));
  field("cases", CasesJson(d));
  field("comfort", ComfortJson(d));
  field("config", ToJson(d.config));
  field("deck", deck);
  field("designed_for", DesignLoadsJson(d.designed_for ? *d.designed_for : d.config));
  field("deflection_max", DeflectionsJson(d));
  field("dynamic_check", DynamicsJson(d));
  field("equilibrium_residual_N", d.equilibrium_residual);
  field("loads_changed",
        d.designed_for ? ChangedLoads(*d.designed_for, d.config) : std::vector<std::string>{});
  field("mass", mass);
  field("mass_attribution", AttributionJson(d));
  field("materials", MaterialsJson(d.config));
  WriteMembersAndNodes(d, os);
  field("reaction_envelope", ReactionEnvelopeJson(d));
  field("reactions", ReactionsJson(d));
  field("resizing", ResizingJson(d));
  field("self_weight_iterations", d.self_weight_iterations);
  field("self_stress_states", d.self_stress_states);
  field("solver", solver);
  field("stability", StabilityJson(d.stability));
  field("topology", topology);
  field("units", Units());
  field("utilisation_max", verdict.utilisation_max);
  field("verdict", VerdictJson(d, verdict), true);
  os << "}\n";
}

std::string DesignSummary(const Design& d, int max_member_rows) {
  std::string out;
  AppendSummaryHead(out, d);
  const Verdict verdict = DesignVerdict(d);
  const DeckBeamCheck& beams = verdict.deck_beams;
  AppendSummaryDesign(out, d, beams);
  AppendSummaryReactions(out, d);
  AppendSummaryStatics(out, d);
  AppendSummaryResizing(out, d, verdict);
  AppendSummaryDynamics(out, d);
  const auto line = LineAppender(out);
  for (const std::string& text : ComfortSummaryLines(d)) line(text);
  line(verdict.summary);
  if (const std::string lever = WhatMovesIt(d, verdict); !lever.empty()) line(lever);
  line("scope: " + verdict.scope);
  line("");

  AppendSummaryMembers(out, d, max_member_rows);

  AppendSummaryMass(out, d);
  return out;
}

}  // namespace tbridge
