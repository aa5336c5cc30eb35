#include "io/design_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/member_area.h"
#include "core/string_law.h"
#include "design/as_built.h"
#include "design/equilibrium.h"
#include "design/limit_mode.h"
#include "io/design_loads.h"
#include "io/design_report.h"
#include "statics/static_solve.h"

namespace tbridge {

namespace {

using nlohmann::json;

// file[key] as a number, or a ConfigError naming `where`.
double Number(const json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_number()) {
    throw ConfigError(where + "." + key,
                      j.is_object() && j.contains(key) ? j.at(key).dump() : "(missing)",
                      "a number, as tbridge design writes it");
  }
  return j.at(key).get<double>();
}

// A member property the file gives beside the area (radius, mass, stiffness, length) must be
// what the area gives. tbridge design writes each double in the shortest form that reads back
// exactly (std::to_chars), and derives them by the same expressions as here: a re-read design
// differs by a few units in the last place at most. 1e-12 relative is thousands of those, and
// catches an edit of any of the first 12 significant digits.
constexpr double kDerivedTolerance = 1e-12;

void RequireDerived(const json& member, const char* key, double derived, const std::string& where,
                    const std::string& name, const std::string& how) {
  const double given = Number(member, key, where);
  const double difference = std::abs(given - derived);
  if (difference <= kDerivedTolerance * std::abs(derived)) return;
  throw ConfigError(
      where + "." + key, NumberText(given),
      "member " + name + ": its nodes, area and rest length give " + how + " = " +
          NumberText(derived) + " (relative difference " +
          NumberText(difference / std::max(std::abs(derived), 1e-300)) +
          "); tbridge check reads a member from its area and rest length alone, so an edit "
          "of this key would be ignored: edit the config and run tbridge design instead");
}

bool Derives(const json& member, const char* key, double derived, const std::string& where) {
  return std::abs(Number(member, key, where) - derived) <= kDerivedTolerance * std::abs(derived);
}

// A member whose radius, mass or stiffness is not what its area and rest length give was edited
// by hand: refused, naming the key that was edited (told apart by which of the others still
// agree) and what to change with it, as check reads a member from its area and rest length. A
// string whose stiffness and reference force are those of another rest length had its rest
// length edited: k_file (s - E A / k_file) is then its reference force to rounding (1e-9: the
// file's shortest round-trip digits leave 1e-13 of it, where a stiffness edited by 1e-9 moves it
// by about 1e-6).
void RequireSection(const json& j, const MemberSizing& m, const MemberMaterial& mat, bool bar,
                    const std::string& where) {
  const bool radius = Derives(j, "radius", m.radius, where),
             mass = Derives(j, "mass", m.mass, where),
             stiffness = bar || Derives(j, "stiffness", m.stiffness, where);
  if (radius && mass && stiffness) return;
  const std::string with =
      "`radius` = sqrt(area / pi) = " + NumberText(m.radius) +
      " m, `mass` = density x area x length = " + NumberText(m.mass) + " kg" +
      (bar ? "" : ", `stiffness` = E x area / rest_length = " + NumberText(m.stiffness) + " N/m");
  const std::string then = "; tbridge check then checks the member as built";
  if (!radius && !mass && (bar || !stiffness)) {
    throw ConfigError(where + ".area", NumberText(m.area),
                      "member " + m.name +
                          ": its area was edited without the keys that follow it: set " + with +
                          then);
  }
  if (!radius) {
    const double r = Number(j, "radius", where), area = std::numbers::pi * r * r;
    throw ConfigError(
        where + ".radius", NumberText(r),
        "member " + m.name + ": its radius was edited alone; the section is `area`: for " +
            "this radius set `area` = pi r^2 = " + NumberText(area) +
            " m^2 and the keys that follow it (`mass`" + (bar ? "" : ", `stiffness`") + ")" + then);
  }
  if (!mass) {
    throw ConfigError(where + ".mass", NumberText(Number(j, "mass", where)),
                      "member " + m.name + ": its mass follows its area: " + with +
                          " as the area gives, or change `area` with all three");
  }
  const double k = Number(j, "stiffness", where);
  const double old_rest = mat.youngs_modulus * m.area / k;
  if (std::abs(k * (m.length - old_rest) - m.reference_force) <=
      1e-9 * std::max(std::abs(m.reference_force), 1.0)) {
    throw ConfigError(where + ".rest_length", NumberText(m.rest_length),
                      "member " + m.name + ": its rest length was edited from " +
                          NumberText(old_rest) +
                          " m without its stiffness: set `stiffness` = E x " +
                          "area / rest_length = " + NumberText(m.stiffness) +
                          " N/m; tbridge check then re-derives the reference state as built");
  }
  throw ConfigError(where + ".stiffness", NumberText(k),
                    "member " + m.name +
                        ": its stiffness follows `area` and `rest_length` (E x area / "
                        "rest_length = " +
                        NumberText(m.stiffness) +
                        " N/m): change either of them, with the stiffness they give");
}

// The deck as the file gives it, which must be the config's: the members' reference forces
// carry its weight, so a deck of another thickness is another design.
void RequireDeck(const json& file, const Deck& deck) {
  const json& j = file.contains("deck") ? file.at("deck") : json();
  const std::pair<const char*, double> derived[] = {
      {"thickness", deck.thickness},       {"section_length", deck.section_length},
      {"section_mass", deck.section_mass}, {"beams_mass", deck.beams_mass},
      {"total_load", deck.total_load},     {"node_load", deck.node_load}};
  std::vector<std::pair<const char*, double>> checked(std::begin(derived), std::end(derived));
  if (deck.girder_depth > 0) checked.emplace_back("girder_depth", deck.girder_depth);
  for (const auto& [key, value] : checked) {
    const double given = Number(j, key, "deck");
    if (std::abs(given - value) <= kDerivedTolerance * std::abs(value)) continue;
    throw ConfigError(
        std::string("deck.") + key, NumberText(given),
        "the config gives " + NumberText(value) + " (" + deck.sized_by +
            "); the members' reference forces carry the deck's weight, so an edit of the deck is "
            "another design: edit the config (loads, deck_sag_limit) and run tbridge design");
  }
}

// file[key] as the mode its text names, kNone when it is absent or null; anything else that
// names no mode is a ConfigError naming the key, the value and the texts tbridge writes.
LimitMode ModeIn(const json& j, const char* key, const std::string& where) {
  if (!j.contains(key) || j.at(key).is_null()) return LimitMode::kNone;
  const json& v = j.at(key);
  if (v.is_string()) {
    if (const std::optional<LimitMode> mode = LimitModeNamed(v.get<std::string>())) return *mode;
  }
  std::vector<std::string> allowed;
  for (const Named<LimitMode>& n : kLimitModeNames) allowed.emplace_back(n.name);
  throw ConfigError(where + "." + key, Show(v), "must be one of " + ChoiceText(allowed));
}

// Whether a bar's area was edited: a bar has no stiffness or rest length that would tell, but
// its resistance in the file (`m.resistance`, of its governing `m.mode`) is what its check found
// at the area it was designed with (yield A sigma_w, buckling chi A f_y / gamma_M1, a run's peak
// against the smaller of the two); 1e-9 relative allows the file's digits and no real edit.
bool BarAreaEdited(const MemberSizing& m, const BarRule& rule, double youngs_modulus) {
  const BarCapacity cap = BarResistance(m.area, m.length, rule, youngs_modulus);
  const double now = m.mode == LimitMode::kYield      ? cap.yield
                     : m.mode == LimitMode::kBuckling ? cap.buckling
                     : m.mode == LimitMode::kDynamic  ? std::min(cap.yield, cap.buckling)
                                                      : std::numeric_limits<double>::quiet_NaN();
  return m.resistance > 0 && std::isfinite(now) &&
         std::abs(now - m.resistance) > 1e-9 * m.resistance;
}

// The design file `tbridge design` writes for `design`, as JSON (to edit and read back).
json FileOf(const Design& design) {
  std::ostringstream text;
  WriteDesignJson(design, text);
  return json::parse(text.str());
}

const json& MemberOf(const json& file, std::size_t index, const Structure& s) {
  const json& list = file.at("members");
  const std::string where = "members[" + std::to_string(index) + "]";
  if (index >= list.size())
    throw ConfigError("members", std::to_string(list.size()) + " members",
                      "the config draws " + std::to_string(s.num_members()));
  const json& m = list[index];
  const ::tbridge::Member& e = s.MemberAt(static_cast<int>(index));
  const json want = {e.i + 1, e.j + 1};
  if (!m.is_object() || !m.contains("nodes") || m.at("nodes") != want) {
    throw ConfigError(where + ".nodes",
                      m.is_object() && m.contains("nodes") ? m.at("nodes").dump() : "(missing)",
                      "the config draws this member between nodes " + want.dump());
  }
  return m;
}

// The angle a design of bridge.beta_deg "auto" chose: its topology.beta_deg, from which the
// geometry is drawn.
double ChosenAngle(const json& file) {
  const json* beta = file.contains("topology") && file.at("topology").is_object() &&
                             file.at("topology").contains("beta_deg")
                         ? &file.at("topology").at("beta_deg")
                         : nullptr;
  if (beta == nullptr || !beta->is_number() ||
      !(beta->get<double>() > 0 && beta->get<double>() < 90)) {
    throw ConfigError(
        "topology.beta_deg", beta == nullptr ? "(missing)" : Show(*beta),
        "the angle a design of config.bridge.beta_deg \"auto\" chose, in (0, 90) deg");
  }
  return beta->get<double>();
}

// The bridge as designed: its deck plates sized for the loads it was designed for, which the
// file records beside the config; the config's loads, where an engineer changed them, are the
// loads it is checked under (d.designed_for).
Config DesignedConfig(const json& file, Design& d) {
  Config designed =
      file.contains("designed_for") ? WithDesignLoads(d.config, file.at("designed_for")) : d.config;
  if (!ChangedLoads(designed, d.config).empty()) {
    if (KeepsPaperSwitches(d.config)) {
      throw ConfigError(
          "config.bridge.payload", NumberText(d.config.bridge.payload),
          "the paper's one case puts the payload into the deck's own load (eq. 9): its design "
          "is checked under the loads it was designed for; edit the config and run tbridge design");
    }
    Validate(designed);
    d.designed_for = designed;
  }
  return designed;
}

// The drawn geometry: as the config draws it, to 1e-9 m; or, `as_built`, the as-built
// geometry, with every bar of its drawn length and every support where it was `drawn`.
void ReadNodes(const json& nodes, Design& d, bool as_built, const Eigen::Matrix3Xd& drawn) {
  const Structure& s = d.topology.structure;
  for (int v = 0; v < s.num_nodes(); ++v) {
    const json& p = nodes[v];
    bool same = p.is_array() && p.size() == 3;
    for (int a = 0; same && a < 3; ++a)
      same = p[a].is_number() && std::abs(p[a].get<double>() - s.nodes(a, v)) <= 1e-9;
    if (!same && as_built && p.is_array() && p.size() == 3 && p[0].is_number() &&
        p[1].is_number() && p[2].is_number()) {
      d.topology.structure.nodes.col(v) =
          Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
      continue;
    }
    if (!same) {
      throw ConfigError("nodes[" + std::to_string(v) + "]", p.dump(),
                        "the config draws node " + std::to_string(v + 1) + " at [" +
                            NumberText(s.nodes(0, v)) + ", " + NumberText(s.nodes(1, v)) + ", " +
                            NumberText(s.nodes(2, v)) + "]");
    }
  }
  if (as_built) {
    for (int v = 0; v < s.num_nodes(); ++v) {
      if (s.fixed[v] && (s.nodes.col(v) - drawn.col(v)).norm() > 1e-9) {
        throw ConfigError(
            "nodes[" + std::to_string(v) + "]", "(a support moved)",
            "node " + std::to_string(v + 1) + " is a support: where the config draws it");
      }
    }
    for (const ::tbridge::Member& e : s.bars) {
      const double drawn_length = (drawn.col(e.j) - drawn.col(e.i)).norm();
      if (std::abs(s.Length(e) - drawn_length) > 1e-9) {
        throw ConfigError("nodes",
                          "(bar " + Structure::Name(e) + " " + NumberText(s.Length(e)) + " m long)",
                          "an as-built geometry keeps every bar at its drawn length, " +
                              NumberText(drawn_length) + " m");
      }
    }
  }
}

// A member as written: area (and rest length) as written, the rest derived from them; a member
// whose reference force is not what it carries as read is added to `edited`.
MemberSizing ReadMember(const json& file, int k, const Structure& s,
                        const MemberMaterial& bar_material, const MemberMaterial& string_material,
                        const BarRule& rule, std::vector<std::string>& edited) {
  const int nb = s.num_bars();
  const json& j = MemberOf(file, k, s);
  const std::string where = "members[" + std::to_string(k) + "]";
  const bool bar = k < nb;
  const ::tbridge::Member& e = s.MemberAt(k);
  MemberSizing m;
  m.name = Structure::Name(e);
  m.kind = bar                             ? MemberKind::kBar
           : e.group == MemberGroup::kDeck ? MemberKind::kDeckString
                                           : MemberKind::kString;
  m.i = e.i;
  m.j = e.j;
  m.length = s.Length(e);
  m.area = Number(j, "area", where);
  if (!(m.area >= 0) || !std::isfinite(m.area))
    throw ConfigError(where + ".area", NumberText(m.area), "a finite area >= 0 [m^2]");
  m.radius = RadiusOfArea(m.area);
  const MemberMaterial& mat = bar ? bar_material : string_material;
  m.mass = MassOfArea(mat.density, m.area, m.length);
  m.reference_force = Number(j, "reference_force", where);
  m.rest_length = bar ? m.length : Number(j, "rest_length", where);
  if (!bar) {
    if (!(m.rest_length > 0))
      throw ConfigError(where + ".rest_length", NumberText(m.rest_length), "a rest length > 0 [m]");
    m.stiffness = AxialStiffness(mat.youngs_modulus, m.area, m.rest_length);
    // The string's tension at the drawn geometry is its reference force: 1e-6 relative
    // allows the file's rounding and the design's own sizing tolerance, and no real edit.
    // Otherwise its area or rest length was edited: the reference state is re-derived.
    const double tension = StringTension(m.stiffness, m.rest_length, m.length);
    if (std::abs(tension - m.reference_force) > 1e-6 * std::max(std::abs(m.reference_force), 1.0)) {
      edited.push_back(m.name);
    }
  }
  RequireDerived(j, "length", m.length, where, m.name, "the length between its nodes");
  if (bar) {
    if (!j.contains("stiffness") || !j.at("stiffness").is_null()) {
      throw ConfigError(
          where + ".stiffness", j.contains("stiffness") ? j.at("stiffness").dump() : "(missing)",
          "member " + m.name + " is a bar, rigid in the model: null, as tbridge design writes it");
    }
  }
  RequireSection(j, m, mat, bar, where);
  // Its governing finding as written (check recomputes it): written again, as WithAreas writes a
  // design, its resistance still tells an edited bar.
  m.mode = ModeIn(j, "mode", where);
  m.resistance = j.contains("resistance") && j.at("resistance").is_number()
                     ? j.at("resistance").get<double>()
                     : 0.0;
  if (bar && BarAreaEdited(m, rule, mat.youngs_modulus)) edited.push_back(m.name);
  m.force = m.reference_force;
  m.force_density = m.force / m.length;
  m.stress = m.area > 0 ? m.force / m.area : 0.0;
  m.governed_by = ModeIn(j, "governed_by", where);
  return m;
}

// A file check wrote with its reference state re-derived: as built, and it says so again.
void RecordAsBuilt(const json& file, Design& d, const Eigen::Matrix3Xd& drawn) {
  const Structure& s = d.topology.structure;
  const int ns = s.num_strings();
  const json& a = file.at("as_built");
  d.as_built.re_derived = true;
  d.as_built.edited = a.value("edited", std::vector<std::string>{});
  for (int v = 0; v < s.num_nodes(); ++v) {
    const double move = (s.nodes.col(v) - drawn.col(v)).norm();
    if (move > d.as_built.node_move_m) d.as_built.node_move_m = move, d.as_built.node = v;
  }
  for (int k = 0; k < ns; ++k)
    d.as_built.slack_strings += d.strings[k].reference_force <= 0 ? 1 : 0;
}

}  // namespace

Design ReadDesign(const json& file) {
  if (!file.is_object() || !file.contains("config") || !file.contains("members") ||
      !file.contains("nodes") || !file.at("members").is_array() || !file.at("nodes").is_array()) {
    throw ConfigError("(root)", "(a JSON value)",
                      "a design file of tbridge design, with config, members and nodes");
  }
  Design d;
  d.config = ParseConfig(file.at("config"));
  if (d.config.structure)
    throw ConfigError("config.structure", "(present)", "a design file's config describes a bridge");
  if (d.config.bridge.beta_auto) d.config.bridge.beta_deg = ChosenAngle(file);
  const Config designed = DesignedConfig(file, d);
  DesignInputs in = PrepareDesign(designed);
  d.topology = std::move(in.topology);
  RequireDeck(file, in.deck);
  d.deck = in.deck;
  d.actions = d.designed_for ? MakeActions(d.config, d.topology, d.deck) : std::move(in.actions);
  d.cases = MakeLoadCases(d.config, d.deck, d.notes);
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars(), ns = s.num_strings();
  const MemberMaterial bar_material = BarMaterial(d.config),
                       string_material = StringMaterial(d.config);
  const BarRule rule = BarRuleOf(d.config);

  // The drawn geometry: as the config draws it, to 1e-9 m (the file's 17 digits hold it
  // exactly); or, in a file check wrote with its reference state re-derived ("as_built"), the
  // as-built geometry, with every bar of its drawn length (to 1e-9 m: bars are rigid).
  const json& nodes = file.at("nodes");
  if (static_cast<int>(nodes.size()) != s.num_nodes()) {
    throw ConfigError("nodes", std::to_string(nodes.size()) + " nodes",
                      "the config draws " + std::to_string(s.num_nodes()));
  }
  const bool as_built = file.contains("as_built") && file.at("as_built").is_object() &&
                        file.at("as_built").value("re_derived", false);
  const Eigen::Matrix3Xd drawn = s.nodes;
  ReadNodes(nodes, d, as_built, drawn);

  // Members: area (and rest length) as written, the rest derived from them.
  if (static_cast<int>(file.at("members").size()) != nb + ns) {
    throw ConfigError("members", std::to_string(file.at("members").size()) + " members",
                      "the config draws " + std::to_string(nb + ns));
  }
  std::vector<double> masses(nb + ns);
  std::vector<std::string> edited;  // members whose reference force is not what they carry as read
  d.reference_forces.resize(nb + ns);
  for (int k = 0; k < nb + ns; ++k) {
    const bool bar = k < nb;
    const MemberSizing m = ReadMember(file, k, s, bar_material, string_material, rule, edited);
    masses[k] = m.mass;
    d.reference_forces[k] = m.reference_force;
    (bar ? d.bars : d.strings).push_back(m);
  }
  d.mass = MassesOf(d.bars, d.strings, d.deck.beams_mass);

  // The reference state: its loads from the members as read, its forces in equilibrium with them.
  d.actions.base[kSelfWeight] = SelfWeightLoads(s, masses, d.config.design.gravity);
  d.reference = ReferenceCase(d.config, d.cases);
  d.loads = d.actions.Loads(d.reference);
  // 1e-8 of the largest member force: the design leaves 1e-10 of it (design.tolerance), the
  // file's digits nothing; a member's weight changed by an edited area shows at once.
  auto residual_of = [&d] {
    const Eigen::VectorXd residual =
        EquilibriumResidual(BuildEquilibrium(d.topology.structure), d.reference_forces, d.loads);
    d.equilibrium_residual = residual.size() ? residual.cwiseAbs().maxCoeff() : 0.0;
    return d.equilibrium_residual <= 1e-8 * std::max(d.reference_forces.cwiseAbs().maxCoeff(), 1.0);
  };
  // Edited members (an area with its radius, mass and stiffness; a rest length), or a weight
  // the forces no longer balance: the reference state they carry as built is re-derived.
  if (!edited.empty() || !residual_of()) {
    SolveAsBuilt(d, std::move(edited), drawn);
    if (!residual_of()) {
      throw ConfigError(
          "members[].reference_force", "(the re-derived reference forces)",
          "they leave " + NumberText(d.equilibrium_residual) +
              " N unbalanced at a node: the as-built reference state did not converge");
    }
  } else if (as_built) {
    RecordAsBuilt(file, d, drawn);
  }
  AssessReferenceState(d);
  d.solver.solver = SolverKind::kNone;
  d.solver.status = kReadFromFile;
  d.solver.success = true;
  d.solver_form = kReadFromFile;
  return d;
}

Design WithAreas(const Design& design, const std::vector<double>& areas) {
  json file = FileOf(design);
  json& members = file.at("members");
  if (areas.size() != members.size()) {
    throw ConfigError("areas", std::to_string(areas.size()) + " areas",
                      "one per member: " + std::to_string(members.size()));
  }
  const size_t nb = design.bars.size();
  const MemberMaterial bar_material = BarMaterial(design.config),
                       string_material = StringMaterial(design.config);
  for (size_t k = 0; k < areas.size(); ++k) {
    const MemberMaterial& mat = k < nb ? bar_material : string_material;
    const double a = areas[k];
    if (!(a >= 0) || !std::isfinite(a)) {
      throw ConfigError("areas[" + std::to_string(k) + "]", NumberText(a),
                        "a finite area >= 0 [m^2]");
    }
    json& m = members[k];
    m["area"] = a;
    m["radius"] = RadiusOfArea(a);
    m["mass"] = MassOfArea(mat.density, a, m.at("length").get<double>());
    if (!m.at("stiffness").is_null())
      m["stiffness"] = AxialStiffness(mat.youngs_modulus, a, m.at("rest_length").get<double>());
  }
  return ReadDesign(file);
}

}  // namespace tbridge
