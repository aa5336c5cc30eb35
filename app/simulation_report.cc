#include "app/simulation_report.h"

#include <map>
#include <string>
#include <vector>

namespace tbridge {

namespace {

std::string MemberName(int i, int j) { return std::to_string(i + 1) + "-" + std::to_string(j + 1); }

// The model's geometry as plots need it: equilibrium node positions (1-based order), bars,
// and strings with their rest lengths (after prestrain), so that slack strings (s < L0) can be
// found from any recorded state.
nlohmann::json ModelMembersJson(const DynamicModel& model) {
  nlohmann::json nodes = nlohmann::json::array(), bars = nlohmann::json::array(),
                 strings = nlohmann::json::array();
  for (int v = 0; v < model.num_nodes(); ++v) {
    nodes.push_back({model.positions(0, v), model.positions(1, v), model.positions(2, v)});
  }
  for (const DynamicBar& b : model.bars) bars.push_back({{"nodes", {b.i + 1, b.j + 1}}});
  for (size_t k = 0; k < model.strings.size(); ++k) {
    const DynamicString s = model.strings[k];
    strings.push_back({{"nodes", {s.i + 1, s.j + 1}},
                       {"group", NameOf(model.names.string_group[k])},
                       {"rest_length_m", s.rest_length}});
  }
  std::vector<int> fixed;
  for (int v = 0; v < model.num_nodes(); ++v) {
    if (model.fixed[v]) fixed.push_back(v + 1);
  }
  return {{"positions", nodes}, {"fixed", fixed}, {"bars", bars}, {"strings", strings}};
}

// The model section: its counts, moving mass, bar length classes and members.
nlohmann::json ModelJson(const DynamicModel& model) {
  nlohmann::json classes = nlohmann::json::array();
  const auto groups = BarLengthClasses(model);
  for (size_t c = 0; c < groups.size(); ++c) {
    nlohmann::json bars = nlohmann::json::array();
    for (const int k : groups[c]) bars.push_back(MemberName(model.bars[k].i, model.bars[k].j));
    classes.push_back(
        {{"class", c + 1}, {"length_m", model.bars[groups[c].front()].length}, {"bars", bars}});
  }
  return {{"dim", model.dim},
          {"nodes", model.num_nodes()},
          {"bars", model.bars.size()},
          {"strings", model.strings.size()},
          {"moving_mass_kg", MovingMass(model)},
          {"bar_length_classes", classes},
          {"members", ModelMembersJson(model)}};
}

// The frequency section: the deck's, when the run found one (with its second estimates), else
// why not.
void AddFrequency(const SimulationSummary& s, nlohmann::json& j) {
  if (s.has_frequency) {
    j["frequency"] = {{"method", "dominant spectral peak of the summed vertical deck displacement"},
                      {"periods", {s.frequency.period_s}},
                      {"period_s", s.frequency.period_s},
                      {"frequency_hz", s.frequency.frequency_hz},
                      {"omega_rad_s", s.frequency.omega_rad_s},
                      {"amplitude_m", s.frequency.amplitude}};
    // A second estimate of the same signal: agrees with the spectral peak for periodic motion.
    j["frequency"]["crossings"] =
        s.crossing_frequency
            ? nlohmann::json{{"method", "mean spacing of the mean-level crossings"},
                             {"period_s", s.crossing_frequency->period_s},
                             {"omega_rad_s", s.crossing_frequency->omega_rad_s},
                             {"cycles", s.crossing_frequency->cycles}}
            : nlohmann::json(nullptr);
    // The summed signal shows only the symmetric modes; the mirror-odd projection the rest.
    j["frequency"]["antisymmetric"] =
        s.antisymmetric_frequency
            ? nlohmann::json{{"method",
                              "dominant spectral peak of the deck displacement projected on the "
                              "mirror-odd shape (+1 left of mid-span, -1 right)"},
                             {"period_s", s.antisymmetric_frequency->period_s},
                             {"omega_rad_s", s.antisymmetric_frequency->omega_rad_s},
                             {"frequency_hz", s.antisymmetric_frequency->frequency_hz}}
            : nlohmann::json(nullptr);
  } else if (!s.frequency_note.empty()) {
    j["frequency"] = {{"note", s.frequency_note}};
  }
}

}  // namespace

nlohmann::json SummaryJson(const Config& config, const DynamicModel& model,
                           const SimulationResult& r) {
  const SimulationSummary& s = r.summary;
  nlohmann::json j;
  j["config"] = ToJson(config);
  j["model"] = ModelJson(model);
  j["run"] = {{"integrator", s.integrator},   {"substeps", s.substeps},
              {"engine", s.engine},           {"steps", s.steps},
              {"rejected_steps", s.rejected}, {"evaluations", s.evaluations},
              {"duration_s", s.duration},     {"wall_s", s.wall_seconds}};
  AddFrequency(s, j);
  j["max_string_stress"] = {{"stress_pa", s.max_string_stress},
                            {"string", s.max_stress_string},
                            {"time_s", s.max_stress_time},
                            {"allowed_pa", s.allowed_stress},
                            {"exceeds_allowed", s.stress_exceeds_allowed}};
  nlohmann::json per_string = nlohmann::json::object();
  for (size_t k = 0; k < s.slack.per_string.size(); ++k) {
    if (s.slack.per_string[k] > 0) per_string[model.names.string_name[k]] = s.slack.per_string[k];
  }
  j["slack"] = {{"transitions", s.slack.total},
                {"per_string", per_string},
                {"slack_at_start", s.slack.slack_at_start},
                {"slack_at_end", s.slack.slack_at_end},
                {"strings_ever_slack", s.slack.ever_slack}};
  j["max_bar_length_error"] = s.max_bar_length_error;
  nlohmann::json peak = nlohmann::json::object();
  for (int d = 0; d < model.dim; ++d) {
    const int node = s.peak_deck_node[d];
    peak[std::string(1, "xyz"[d])] = {
        {"displacement_m", s.peak_deck_displacement[d]},
        {"node", node >= 0 ? nlohmann::json(node + 1) : nlohmann::json()},
        {"time_s", s.peak_deck_time[d]}};
  }
  j["peak_deck_displacement"] = peak;
  if (!s.peak_bar_compression.empty()) {
    nlohmann::json bars = nlohmann::json::array();
    for (size_t k = 0; k < model.bars.size(); ++k) {
      bars.push_back({{"bar", MemberName(model.bars[k].i, model.bars[k].j)},
                      {"compression_n", s.peak_bar_compression[k]},
                      {"tension_n", s.peak_bar_tension[k]}});
    }
    j["bar_force_peaks"] = bars;
  }
  const EnergyBalance& e = s.energy;
  j["energy"] = {{"kinetic_start_j", e.kinetic_start},   {"elastic_start_j", e.elastic_start},
                 {"kinetic_end_j", e.kinetic_end},       {"elastic_end_j", e.elastic_end},
                 {"external_work_j", e.external_work},   {"dissipated_j", e.dissipated},
                 {"reference_j", e.reference},           {"max_relative_drift", e.max_drift},
                 {"final_relative_drift", e.final_drift}};
  if (!s.prestrain.empty()) {
    nlohmann::json p = nlohmann::json::array();
    for (const PrestrainReport& pr : s.prestrain) {
      p.push_back({{"group", NameOf(pr.group)},
                   {"ratio", pr.ratio},
                   {"strings", pr.strings},
                   {"implied_stress_pa", pr.max_stress},
                   {"allowed_pa", pr.allowed_stress},
                   {"yield_pa", pr.yield_stress},
                   {"exceeds_allowed", pr.exceeds_allowed}});
    }
    j["prestrain"] = p;
  }
  return j;
}

}  // namespace tbridge
