#include "checks/comfort_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "bridge/design_model.h"
#include "core/error.h"

namespace tbridge {

namespace {

// Every mode densely up to this many free DOFs (the planar bridge to n = 5), else the lowest
// kLowestModes by the sparse solver: the deck modes under the triggers (5 Hz) are among the
// lowest of a bridge. The dense decomposition is cubic in the DOFs: at n = 7 (about 500) it took
// 0.1 s per model, 7 % of the verified design, where the sparse solver takes a few ms.
constexpr int kAllModesMaxDofs = 150;
constexpr int kLowestModes = 40;

double DeckArea(const Design& d) { return d.config.bridge.span * d.config.bridge.deck_width; }

// The deck area each deck node carries [m²]: one section of its plane's share of the width, as
// the deck beams' mass is shared (AddDeckInertia).
double NodeDeckArea(const Design& d) {
  return d.deck.section_length * d.config.bridge.deck_width / d.config.bridge.planes;
}

double Trigger(const ComfortConfig& c, DeckMotion motion) {
  if (motion == DeckMotion::kLateral) return c.horizontal_trigger_hz;
  return motion == DeckMotion::kTorsional ? c.torsional_trigger_hz : c.vertical_trigger_hz;
}

// Sétra 2006 (2.4.3): in lateral ranges 1 and 2 the acceleration must stay below 0.10 m/s², the
// threshold of lateral lock-in, whatever the comfort level allows.
constexpr double kLateralLockInAcceleration = 0.10;

double Limit(const ComfortConfig& c, LoadAxis axis) {
  const double level = ComfortLevelBound(axis, c.comfort_level);
  if (axis == LoadAxis::kVertical) return std::min(level, c.vertical_limit_m_s2);
  const bool crowd = c.traffic_class == TrafficClass::kI || c.traffic_class == TrafficClass::kII;
  return std::min(level, crowd ? c.crowd_horizontal_limit_m_s2 : c.horizontal_limit_m_s2);
}

// The index of the `rank`-th mode of `motion` (0-based) among `modes`; -1 when there is none.
int NthOf(const DeckModes& modes, DeckMotion motion, int rank) {
  for (size_t k = 0; k < modes.motions.size(); ++k) {
    if (modes.motions[k].motion != motion) continue;
    if (rank-- == 0) return static_cast<int>(k);
  }
  return -1;
}

// Step 2 for one relevant mode, then its response (RespondAt).
ComfortMode Assess(const Design& d, const ComfortCheck& check, const Mode& mode,
                   const DeckMotionReport& motion, double empty_hz) {
  ComfortMode m;
  m.direction = motion.motion;
  m.share = motion.share[static_cast<int>(motion.motion)];
  m.node = motion.peak_node;
  m.modal_mass_kg = 1.0 / (motion.peak_displacement * motion.peak_displacement);
  double weight = 0;  // sum A_k |phi_k| / phi_max over the deck nodes
  for (const int a : d.topology.deck_nodes) weight += std::abs(mode.shape(motion.axis, a));
  m.load_weight_m2 = weight * NodeDeckArea(d) / motion.peak_displacement;
  RespondAt(m, check, d, mode.frequency_hz, empty_hz);
  return m;
}

}  // namespace

LoadAxis LoadAxisOf(DeckMotion direction) {
  if (direction == DeckMotion::kLateral) return LoadAxis::kLateral;
  if (direction == DeckMotion::kLongitudinal) return LoadAxis::kLongitudinal;
  return LoadAxis::kVertical;
}

void RespondAt(ComfortMode& m, const ComfortCheck& check, const Design& d, double crowd_hz,
               double empty_hz) {
  const ComfortConfig& c = d.config.comfort;
  const LoadAxis axis = LoadAxisOf(m.direction);
  m.frequency_hz = crowd_hz;
  m.frequency_empty_hz = empty_hz;
  const int riskiest = RiskRangeOver(axis, crowd_hz, empty_hz);
  m.range = riskiest;
  m.limit_m_s2 = Limit(c, axis);
  if (axis == LoadAxis::kLateral && riskiest <= 2)
    m.limit_m_s2 = std::min(m.limit_m_s2, kLateralLockInAcceleration);
  m.psi = m.equivalent_pedestrians = m.modal_force_n = m.acceleration_m_s2 = 0;
  // Every range the frequencies meet, with its class's load case: the largest acceleration
  // governs. The riskiest range's case alone missed the second harmonic where the frequencies
  // span ranges 2 and 3 (2.59 to 2.97 Hz: case 1's psi is 0 there, case 3's is not).
  std::ostringstream model;
  bool loaded = false;
  for (const int range : RiskRangesOver(axis, crowd_hz, empty_hz)) {
    const std::optional<CrowdLoadCase> load = LoadCaseFor(check.traffic_class, range);
    if (!load) continue;
    const double psi = PsiOver(axis, load->harmonic, crowd_hz, empty_hz);
    const double pedestrians =
        EquivalentPedestrians(check.damping_ratio, check.pedestrians, load->very_dense);
    const double force =
        PedestrianForceN(axis, load->harmonic) * pedestrians * psi / DeckArea(d) * m.load_weight_m2;
    const double acceleration = force / (2.0 * check.damping_ratio * m.modal_mass_kg);
    if (loaded && acceleration <= m.acceleration_m_s2) continue;
    loaded = true;
    m.range = range;
    m.psi = psi;
    m.equivalent_pedestrians = pedestrians;
    m.modal_force_n = force;
    m.acceleration_m_s2 = acceleration;
    model.str("");
    model << "Sétra case " << load->number << ": " << PedestrianForceN(axis, load->harmonic)
          << " N x " << (load->very_dense ? "1.85 sqrt(n)" : "10.8 sqrt(xi n)") << " = "
          << pedestrians << " pedestrians x psi " << psi << " over " << DeckArea(d) << " m^2";
  }
  if (!loaded)
    model << "none: Sétra asks no load case of class " << NameOf(check.traffic_class)
          << " in range " << riskiest;
  m.load_model = model.str();
  m.comfort_class = ComfortLevelName(ComfortLevelReached(axis, m.acceleration_m_s2));
  m.pass = m.acceleration_m_s2 <= m.limit_m_s2;
  m.lock_in_pedestrians = 0;
  if (axis == LoadAxis::kLateral) {
    m.lock_in_pedestrians = LockInPedestrians(check.damping_ratio, crowd_hz, m.modal_mass_kg);
    if (riskiest <= 2 && check.pedestrians >= m.lock_in_pedestrians) m.pass = false;
  }
}

DynamicModel ComfortModel(const Design& d, bool crowded) {
  const ComfortConfig& c = d.config.comfort;
  ModelOptions options;
  options.gravity_on_structure = d.config.design.self_weight;
  options.deck_inertia = true;
  // The pedestrians stand where the payload would, spread over the deck: their weight as a
  // share of it.
  const double crowd_weight_n = TrafficDensity(c.traffic_class) * DeckArea(d) *
                                c.pedestrian_mass_kg * d.config.design.gravity;
  options.payload_share = crowded ? crowd_weight_n / d.config.bridge.payload : 0.0;
  return BuildDynamicModel(d, options);
}

DeckModes ComputeDeckModes(const DynamicModel& model, double above_hz) {
  int free_nodes = 0;
  for (const bool fixed : model.fixed) free_nodes += fixed ? 0 : 1;
  ModalOptions options;
  options.count = free_nodes * model.dim <= kAllModesMaxDofs ? 0 : kLowestModes;
  options.highest = false;
  DeckModes out;
  for (;;) {
    out.modal = ComputeModes(model, options);
    const std::vector<Mode>& modes = out.modal.modes;
    if (options.count == 0 || out.modal.all_modes || modes.empty() ||
        modes.back().frequency_hz > above_hz)
      break;
    options.count *= 2;
  }
  for (const Mode& m : out.modal.modes) out.motions.push_back(ProjectOnDeckMotions(model, m.shape));
  return out;
}

Eigen::Matrix3Xd CrowdModeLoad(const Design& d, const Mode& mode, const DeckMotionReport& motion,
                               double pressure_n_m2) {
  Eigen::Matrix3Xd load = Eigen::Matrix3Xd::Zero(3, mode.shape.cols());
  const double node_force = pressure_n_m2 * NodeDeckArea(d);
  for (const int a : d.topology.deck_nodes) {
    const double u = mode.shape(motion.axis, a);
    if (u != 0) load(motion.axis, a) = u > 0 ? node_force : -node_force;
  }
  return load;
}

ComfortCheck CheckComfort(const Design& d) { return AnalyseComfort(d).check; }

ComfortAnalysis AnalyseComfort(const Design& d) {
  const ComfortConfig& c = d.config.comfort;
  ComfortAnalysis analysis;
  ComfortCheck& out = analysis.check;
  out.traffic_class = c.traffic_class;
  out.comfort_level = c.comfort_level;
  out.damping_ratio = c.damping_ratio ? *c.damping_ratio : ConstructionDamping(c.construction);
  out.density_per_m2 = TrafficDensity(c.traffic_class);
  out.pedestrians = out.density_per_m2 * DeckArea(d);
  out.crowd_mass_kg = out.pedestrians * c.pedestrian_mass_kg;
  out.planar = d.topology.planes == 1;
  if (KeepsPaperSwitches(d.config)) {
    out.note = "the paper's switches: comfort is not checked";
    return analysis;
  }
  if (!c.check) {
    out.note = "comfort.check is false";
    return analysis;
  }
  DeckModes& crowded = analysis.crowded;
  DeckModes& empty = analysis.empty;
  try {
    const double above_hz = kNearTrigger * std::max({c.vertical_trigger_hz, c.horizontal_trigger_hz,
                                                     c.torsional_trigger_hz});
    analysis.crowded_model = ComfortModel(d, true);
    analysis.empty_model = ComfortModel(d, false);
    crowded = ComputeDeckModes(analysis.crowded_model, above_hz);
    empty = ComputeDeckModes(analysis.empty_model, above_hz);
  } catch (const ModelError& e) {
    out.note = std::string("no modes: ") + e.what();
    return analysis;
  }
  out.done = true;
  if (out.planar) out.note = "planar bridge: lateral and torsional comfort not checked";
  std::map<DeckMotion, int> rank;  // how many modes of each motion came before
  for (size_t k = 0; k < crowded.modal.modes.size(); ++k) {
    const Mode& mode = crowded.modal.modes[k];
    const DeckMotionReport& motion = crowded.motions[k];
    if (motion.motion == DeckMotion::kLocal) continue;
    const int empty_index = NthOf(empty, motion.motion, rank[motion.motion]++);
    const double empty_hz = empty_index >= 0
                                ? empty.modal.modes[static_cast<size_t>(empty_index)].frequency_hz
                                : mode.frequency_hz;
    const double lower_hz = std::min(mode.frequency_hz, empty_hz),
                 trigger_hz = Trigger(c, motion.motion);
    if (!(lower_hz < kNearTrigger * trigger_hz)) continue;
    ComfortMode m = Assess(d, out, mode, motion, empty_hz);
    m.index = static_cast<int>(k) + 1;
    analysis.modes.push_back(m);
    analysis.crowded_mode.push_back(static_cast<int>(k));
    analysis.empty_mode.push_back(empty_index);
    if (!(lower_hz < trigger_hz)) continue;
    out.required = true;
    out.modes.push_back(m);
  }
  if (!crowded.modal.all_modes && !crowded.modal.modes.empty() &&
      crowded.modal.modes.back().frequency_hz < c.vertical_trigger_hz) {
    out.note += std::string(out.note.empty() ? "" : "; ") + "the lowest " +
                std::to_string(crowded.modal.modes.size()) +
                " modes were found, all below the trigger";
  }
  return analysis;
}

}  // namespace tbridge
