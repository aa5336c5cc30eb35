#include "core/dynamics_config.h"

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

namespace {

// Largest node number accepted before the structure is known; the simulation checks the
// real node count.
constexpr int kMaxNode = 1 << 20;

}  // namespace

DynamicsConfig ParseDynamicsConfig(JsonSection s) {
  DynamicsConfig d;
  d.duration = s.Number("duration", d.duration, Range::Closed(1e-9, 1e6));
  d.dt = s.Number("dt", d.dt, Range::Closed(1e-12, 1.0));
  if (d.dt > d.duration) {
    throw ConfigError(s.PathOf("dt"), std::to_string(d.dt),
                      "must not exceed duration = " + std::to_string(d.duration));
  }
  d.integrator = s.Choice("integrator", d.integrator, {"auto", "rk4", "dopri5", "sdirk3"});
  d.engine = s.Choice("engine", d.engine, {"auto", "class1", "classk"});
  d.rtol = s.Number("rtol", d.rtol, Range::Closed(1e-14, 1e-1));
  d.atol = s.Number("atol", d.atol, Range::Closed(1e-16, 1.0));
  d.string_mass = s.Choice("string_mass", d.string_mass, {"bars", "nodes", "off"});
  d.damping_c = s.Number("damping_c", d.damping_c, Range::Closed(0.0, 1e9));
  {
    JsonSection st = s.Section("stabilisation");
    d.stabilisation.enabled = st.Bool("enabled", d.stabilisation.enabled);
    d.stabilisation.omega_rad_s =
        st.Number("omega_rad_s", d.stabilisation.omega_rad_s, Range::Closed(1e-6, 1e9));
    d.stabilisation.zeta = st.Number("zeta", d.stabilisation.zeta, Range::Closed(0.0, 1e3));
    st.Finish();
  }
  d.prestrain = ObjectList<PrestrainConfig>(s, "prestrain", [](JsonSection p) {
    PrestrainConfig c;
    c.group = p.Choice("group", std::nullopt, {"deck", "substructure", "transverse"});
    c.ratio = p.Number("ratio", std::nullopt, Range{0.0, 1.5, true, false});
    p.Finish();
    return c;
  });
  for (size_t a = 0; a < d.prestrain.size(); ++a) {
    for (size_t b = 0; b < a; ++b) {
      if (d.prestrain[a].group == d.prestrain[b].group) {
        throw ConfigError(s.PathOf("prestrain") + "[" + std::to_string(a) + "].group",
                          "\"" + d.prestrain[a].group + "\"", "each group at most once");
      }
    }
  }
  {
    JsonSection p = s.Section("perturbation");
    d.perturbation.bar_class = p.Integer("bar_class", d.perturbation.bar_class, 0, kMaxNode);
    d.perturbation.delta = p.Number("delta", d.perturbation.delta, Range::Closed(-100.0, 100.0));
    p.Finish();
  }
  d.initial = ObjectList<NodeInitialConfig>(s, "initial", [](JsonSection p) {
    NodeInitialConfig c;
    c.node = p.Integer("node", std::nullopt, 1, kMaxNode);
    c.displacement = p.Vector3("displacement", std::array<double, 3>{0, 0, 0});
    c.velocity = p.Vector3("velocity", std::array<double, 3>{0, 0, 0});
    p.Finish();
    return c;
  });
  d.loads = ObjectList<LoadStepConfig>(s, "loads", [](JsonSection p) {
    LoadStepConfig c;
    c.t_start = p.Number("t_start", std::nullopt, Range::NonNegative());
    c.t_end = p.Number("t_end", std::nullopt, Range::NonNegative());
    if (c.t_end <= c.t_start) {
      throw ConfigError(p.PathOf("t_end"), std::to_string(c.t_end),
                        "must be greater than t_start = " + std::to_string(c.t_start));
    }
    c.node = p.Integer("node", std::nullopt, 1, kMaxNode);
    c.force = p.Vector3("force", std::array<double, 3>{0, 0, 0});
    p.Finish();
    return c;
  });
  {
    JsonSection r = s.Section("record");
    d.record.nodes = r.Integers("nodes", d.record.nodes, 1, kMaxNode);
    d.record.every = r.Integer("every", d.record.every, 1, 1 << 30);
    d.record.csv = r.Bool("csv", d.record.csv);
    d.record.bar_forces = r.Bool("bar_forces", d.record.bar_forces);
    r.Finish();
  }
  {
    JsonSection f = s.Section("frequency");
    d.frequency.enabled = f.Bool("enabled", d.frequency.enabled);
    d.frequency.every = f.Integer("every", d.frequency.every, 1, 1 << 30);
    f.Finish();
  }
  {
    JsonSection g = s.Section("guard");
    d.guard.max_bar_length_error =
        g.Number("max_bar_length_error", d.guard.max_bar_length_error, Range{0.0, 1.0, true, false});
    d.guard.max_energy_growth =
        g.Number("max_energy_growth", d.guard.max_energy_growth, Range{0.0, 1e6, true, false});
    g.Finish();
  }
  d.gravity_on_structure = s.Bool("gravity_on_structure", d.gravity_on_structure);
  {
    JsonSection l = s.Section("limits");
    // Whole numbers of steps; int counters in the driver hold up to 2^31 - 1.
    d.limits.max_steps = l.Integer("max_steps", static_cast<int>(d.limits.max_steps), 1, 2000000000);
    d.limits.max_output_bytes = l.Number("max_output_bytes", d.limits.max_output_bytes, Range::Closed(1.0, 1e15));
    l.Finish();
  }
  s.Finish();
  return d;
}

nlohmann::json ToJson(const DynamicsConfig& d) {
  nlohmann::json prestrain = nlohmann::json::array();
  for (const PrestrainConfig& p : d.prestrain) prestrain.push_back({{"group", p.group}, {"ratio", p.ratio}});
  nlohmann::json initial = nlohmann::json::array();
  for (const NodeInitialConfig& i : d.initial) {
    initial.push_back({{"node", i.node}, {"displacement", i.displacement}, {"velocity", i.velocity}});
  }
  nlohmann::json loads = nlohmann::json::array();
  for (const LoadStepConfig& l : d.loads) {
    loads.push_back({{"t_start", l.t_start}, {"t_end", l.t_end}, {"node", l.node}, {"force", l.force}});
  }
  return {{"duration", d.duration},
          {"dt", d.dt},
          {"integrator", d.integrator},
          {"engine", d.engine},
          {"rtol", d.rtol},
          {"atol", d.atol},
          {"string_mass", d.string_mass},
          {"damping_c", d.damping_c},
          {"stabilisation",
           {{"enabled", d.stabilisation.enabled},
            {"omega_rad_s", d.stabilisation.omega_rad_s},
            {"zeta", d.stabilisation.zeta}}},
          {"prestrain", prestrain},
          {"perturbation", {{"bar_class", d.perturbation.bar_class}, {"delta", d.perturbation.delta}}},
          {"initial", initial},
          {"loads", loads},
          {"record",
           {{"nodes", d.record.nodes}, {"every", d.record.every}, {"csv", d.record.csv}, {"bar_forces", d.record.bar_forces}}},
          {"frequency", {{"enabled", d.frequency.enabled}, {"every", d.frequency.every}}},
          {"guard",
           {{"max_bar_length_error", d.guard.max_bar_length_error},
            {"max_energy_growth", d.guard.max_energy_growth}}},
          {"gravity_on_structure", d.gravity_on_structure},
          {"limits", {{"max_steps", d.limits.max_steps}, {"max_output_bytes", d.limits.max_output_bytes}}}};
}

}  // namespace tbridge
