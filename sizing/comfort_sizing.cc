#include "sizing/comfort_sizing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/material.h"
#include "core/member_area.h"
#include "dynamics/modal_sensitivity.h"

namespace tbridge {

namespace {

// The window's ends are found on frequency scales in steps of 0.2 %, then bisected to 1e-7,
// within a factor of three either way (nine times the stiffness): beyond it a bound is left to
// the next design's rows.
constexpr double kScaleStep = 1.002;
constexpr double kLargestScale = 3.0;
// A sizing moves a mode at most this factor in frequency: the Rayleigh quotient of the held shape
// foretells a far move poorly (the default at n = 3: asked 2.6 -> 4.9 Hz, its modes came out at
// 3.1 and 3.9 Hz, their shapes another), and the next sizing goes on from the new shape.
constexpr double kLargestStep = 1.5;
// Each bound is posed this much inside the window (relative, on the frequency): the row holds the
// static state under the crowd and the members' weight of the design it starts from, which the
// new design's own move a little.
constexpr double kFrequencyMargin = 1e-3;
// The rows' modes are followed among the lowest modes of their model, up to this many beyond the
// highest a row starts from: a sizing reorders a few (it moves a mode at most kLargestStep), and
// the lowest modes of a large model cost one shift-invert Lanczos solve, where all modes to twice
// the highest frequency (the deck's local modes among them) took most of a sizing of the 40 m
// footbridge at n = 6.
constexpr int kFollowedBeyond = 8;

// Whether `mode` passes with both its frequencies scaled by s.
bool PassesAt(const ComfortMode& mode, const ComfortCheck& check, const Design& d, double s) {
  ComfortMode moved = mode;
  RespondAt(moved, check, d, mode.frequency_hz * s, mode.frequency_empty_hz * s);
  return moved.pass;
}

// From scale `from` in the direction of `step` (> 1 up, < 1 down): the first scale at which the
// mode's pass differs from its pass at `from`, bisected to the last scale with its pass at `from`
// where that passes, else to the first that passes; none within kLargestScale of 1.
std::optional<double> WindowEnd(const ComfortMode& mode, const ComfortCheck& check, const Design& d,
                                double step, double from = 1.0) {
  const bool at_one = PassesAt(mode, check, d, from);
  double inside = from;
  for (double s = from * step; s < kLargestScale && s > 1.0 / kLargestScale; s *= step) {
    if (PassesAt(mode, check, d, s) == at_one) {
      inside = s;
      continue;
    }
    double outside = s;
    while (std::abs(outside - inside) > 1e-7) {
      const double mid = 0.5 * (inside + outside);
      (PassesAt(mode, check, d, mid) == at_one ? inside : outside) = mid;
    }
    return at_one ? inside : outside;
  }
  return std::nullopt;
}

// A row's bound: `frequency_hz` as its target, at most kLargestStep from where the mode is (a
// farther target is approached over several sizings).
ComfortRow Bounded(ComfortRow row, bool lower, double now_hz, double frequency_hz,
                   const std::string& what) {
  const double step_hz = lower ? std::min(frequency_hz, now_hz * kLargestStep)
                               : std::max(frequency_hz, now_hz / kLargestStep);
  const double omega =
      2.0 * M_PI * step_hz * (lower ? 1.0 + kFrequencyMargin : 1.0 - kFrequencyMargin);
  row.lower = lower;
  row.target_omega2 = omega * omega;
  std::ostringstream os;
  os << what << (lower ? " above " : " below ") << frequency_hz << " Hz";
  if (step_hz != frequency_hz) os << " (this sizing " << step_hz << " Hz)";
  row.label = os.str();
  return row;
}

// What a comfort row reads of the design's members, per member [bars; strings]: its drawn length
// and (strings) rest length, and the materials.
struct RowMembers {
  int bars = 0;
  std::vector<double> length, rest_length;  // [m]
  double string_modulus = 0, bar_density = 0, string_density = 0;
};

RowMembers RowMembersOf(const Design& d) {
  RowMembers out;
  out.bars = static_cast<int>(d.bars.size());
  for (const MemberSizing& b : d.bars) {
    out.length.push_back(b.length);
    out.rest_length.push_back(b.length);
  }
  for (const MemberSizing& s : d.strings) {
    out.length.push_back(s.length);
    out.rest_length.push_back(s.rest_length);
  }
  const MemberMaterial bars = BarMaterial(d.config), strings = StringMaterial(d.config);
  out.string_modulus = strings.youngs_modulus;
  out.bar_density = bars.density;
  out.string_density = strings.density;
  return out;
}

ComfortRow RowOf(const RowMembers& members, const DynamicModel& model, const Mode& mode) {
  const ModeEnergies e = ModeEnergiesOf(model, mode, ModelOptions{}.string_mass);
  const size_t nm = members.length.size();
  ComfortRow row;
  row.omega2 = mode.omega_squared;
  row.by_area.assign(nm, 0.0);
  row.by_force.assign(nm, 0.0);
  row.mass_by_area.assign(nm, 0.0);
  for (size_t k = 0; k < nm; ++k) {
    if (static_cast<int>(k) < members.bars) {
      // A rigid bar: its compression's geometric stiffness and its mass rho A l.
      row.by_force[k] = e.by_force[k];
      row.mass_by_area[k] = e.mass_energy[k] * members.bar_density * members.length[k];
    } else {
      // A string: k = (E A + T_ref) / l (its rest length makes it carry T_ref at its drawn
      // length l), and the state's tension follows T_ref one for one (to its strain).
      row.by_area[k] = e.by_stiffness[k] * members.string_modulus / members.length[k];
      row.by_force[k] = e.by_stiffness[k] / members.length[k] + e.by_force[k];
      row.mass_by_area[k] = e.mass_energy[k] * members.string_density * members.rest_length[k];
    }
  }
  return row;
}

// A model the rows follow their modes in (ComfortRow::follow): the comfort model of the design
// at its static state, the design's areas and reference forces, and the modes of the model last
// moved, which the rows of one point share: each point asks for one moved model's modes, found
// once however many rows read it (the 40 m footbridge at n = 6 poses several on one model).
struct HeldModel {
  RowMembers members;
  DynamicModel model;
  std::vector<double> area;
  Eigen::VectorXd force;
  int modes = 0;  // the lowest this many modes are sought
  struct Moved {
    std::vector<double> area;
    Eigen::VectorXd force;
    std::optional<DynamicModel> model;  // none where the moved model has no modes
    ModalResult modes;
  };
  mutable std::mutex mutex;
  mutable std::shared_ptr<const Moved> last;
};

// `held` moved to areas a and reference forces f as the row's coefficients assume, so that the
// row's gradient is the moved eigenvalue's own: each string's axial stiffness by (E dA + dF) / l
// and its tension by dF at the state's length, each member's own mass by rho dA l (a string's on
// its rest length, shared as the model shares string mass); the bars' forces follow the nodes'
// equilibrium, as the model finds them.
DynamicModel MovedModel(const HeldModel& held, const std::vector<double>& a,
                        const Eigen::VectorXd& force) {
  DynamicModel m = held.model;
  const RowMembers& r = held.members;
  for (int j = 0; j < r.bars; ++j) {
    const size_t k = static_cast<size_t>(j);
    m.bars.mass[k] += MassOfArea(r.bar_density, a[k] - held.area[k], r.length[k]);
  }
  std::vector<double> added(m.strings.size(), 0.0);
  for (size_t q = 0; q < m.strings.size(); ++q) {
    const size_t k = static_cast<size_t>(r.bars) + q;
    const Eigen::Index e = static_cast<Eigen::Index>(k);
    const double da = a[k] - held.area[k], df = force[e] - held.force[e];
    const double s = (m.positions.col(m.strings.j[q]) - m.positions.col(m.strings.i[q])).norm();
    const double k0 = m.strings.stiffness[q];
    const double tension = k0 * (s - m.strings.rest_length[q]) + df;
    const double k1 = k0 + TautStringStiffness(r.string_modulus, da, df, r.length[k]);
    if (!(k1 > 0)) throw ModelError("a string's stiffness falls to zero");
    m.strings.stiffness[q] = k1;
    m.strings.rest_length[q] = s - tension / k1;
    m.strings.area[q] = a[k];
    added[q] = MassOfArea(r.string_density, da, r.rest_length[k]);
    m.strings.mass[q] += added[q];
  }
  ForEachStringMassShare(m, ModelOptions{}.string_mass, [&](int q, int node, int bar, int count) {
    const double half = 0.5 * added[static_cast<size_t>(q)];
    if (bar < 0) {
      m.node_mass(node) += half;
    } else {
      m.bars.mass[static_cast<size_t>(bar)] += half / count;
    }
  });
  return m;
}

// The held model moved to (a, force) and its modes: the last found where the point is the same.
std::shared_ptr<const HeldModel::Moved> MovedModes(const HeldModel& held,
                                                   const std::vector<double>& a,
                                                   const Eigen::VectorXd& force) {
  const std::lock_guard<std::mutex> lock(held.mutex);
  if (held.last && held.last->area == a && held.last->force.size() == force.size() &&
      held.last->force == force) {
    return held.last;
  }
  auto moved = std::make_shared<HeldModel::Moved>();
  moved->area = a;
  moved->force = force;
  try {
    moved->model = MovedModel(held, a, force);
    ModalOptions options;
    options.count = held.modes;
    options.highest = false;
    options.solver = ModalSolver::kSparse;  // the lowest few; every mode where they are nearly all
    moved->modes = ComputeModes(*moved->model, options);
  } catch (const ModelError&) {
    moved->model.reset();
  }
  held.last = moved;
  return held.last;
}

// The row of the mode of shape `shape` at areas a and reference forces `force`: of the moved
// model's modes, the one whose shape is closest to it (the largest modal assurance criterion), so
// that the row keeps to its mode where modes cross. A model without modes gives a row of NaN,
// which the solvers step back from.
ComfortRow Follow(const HeldModel& held, const Eigen::Matrix3Xd& shape,
                  const std::vector<double>& a, const Eigen::VectorXd& force) {
  const std::shared_ptr<const HeldModel::Moved> moved = MovedModes(held, a, force);
  const Mode* best = nullptr;
  double best_mac = -1;
  const double held_norm = shape.squaredNorm();
  if (moved->model) {
    for (const Mode& mode : moved->modes.modes) {
      const double dot = (mode.shape.array() * shape.array()).sum();
      const double mac = dot * dot / (mode.shape.squaredNorm() * held_norm);
      if (mac > best_mac) {
        best_mac = mac;
        best = &mode;
      }
    }
  }
  if (best != nullptr) return RowOf(held.members, *moved->model, *best);
  ComfortRow nan;
  nan.omega2 = std::numeric_limits<double>::quiet_NaN();
  nan.by_area.assign(a.size(), 0.0);
  nan.by_force = nan.by_area;
  nan.mass_by_area = nan.by_area;
  return nan;
}

}  // namespace

std::optional<double> PieceBelow(const ComfortMode& mode, const ComfortCheck& check,
                                 const Design& d) {
  if (!mode.pass) return WindowEnd(mode, check, d, 1.0 / kScaleStep);
  const std::optional<double> lower_end = WindowEnd(mode, check, d, 1.0 / kScaleStep);
  if (!lower_end) return std::nullopt;
  return WindowEnd(mode, check, d, 1.0 / kScaleStep, *lower_end / kScaleStep);
}

ComfortRow ComfortRowOf(const Design& d, const DynamicModel& model, const Mode& mode) {
  return RowOf(RowMembersOf(d), model, mode);
}

std::vector<ComfortRow> ComfortRowsOf(const Design& d, const ComfortAnalysis& a,
                                      const std::set<std::string>& below, BelowPassing passing) {
  std::vector<ComfortRow> out;
  if (!d.config.comfort.sizing_constraint || !a.check.done) return out;
  // Each row follows its mode (ComfortRow::follow) from the models it was found in.
  const RowMembers members = RowMembersOf(d);
  const std::vector<double> areas = MemberAreas(d);
  int highest = 0;  // the highest mode a row starts from, 1-based
  for (size_t i = 0; i < a.modes.size(); ++i)
    highest = std::max({highest, a.crowded_mode[i] + 1, a.empty_mode[i] + 1});
  const auto held = [&](const DynamicModel& model) {
    auto h = std::make_shared<HeldModel>();
    h->members = members;
    h->model = model;
    h->area = areas;
    h->force = d.reference_forces;
    h->modes = highest + kFollowedBeyond;
    return std::shared_ptr<const HeldModel>(std::move(h));
  };
  const std::shared_ptr<const HeldModel> crowded_model = held(a.crowded_model);
  const std::shared_ptr<const HeldModel> empty_model = held(a.empty_model);
  const auto Following = [&](const std::shared_ptr<const HeldModel>& model, const Mode& mode) {
    ComfortRow row = RowOf(members, model->model, mode);
    row.follow = [model, shape = mode.shape](const std::vector<double>& at,
                                             const Eigen::VectorXd& force) {
      return Follow(*model, shape, at, force);
    };
    return row;
  };
  std::map<DeckMotion, int> rank;  // how many modes of each motion came before
  for (size_t i = 0; i < a.modes.size(); ++i) {
    const ComfortMode& m = a.modes[i];
    const Mode& crowded = a.crowded.modal.modes[static_cast<size_t>(a.crowded_mode[i])];
    if (!(crowded.omega_squared > 0))
      continue;  // an unstable design: the sizing's stability rows hold it
    const std::string name =
        std::string(NameOf(m.direction)) + " " + std::to_string(++rank[m.direction]);
    const int empty = a.empty_mode[i];
    // The rows on the crowded frequency (lower bounds: its interval's lower end) and on the empty
    // one (upper bounds).
    const auto crowded_row = [&] {
      ComfortRow row = Following(crowded_model, crowded);
      row.key = name + " crowded";
      return row;
    };
    const auto empty_row = [&] {
      ComfortRow row = Following(empty_model, a.empty.modal.modes[static_cast<size_t>(empty)]);
      row.key = name + " empty";
      return row;
    };
    std::ostringstream what;
    what << NameOf(m.direction) << " mode " << m.index << " (" << m.frequency_hz << " Hz crowded, "
         << m.frequency_empty_hz << " Hz empty, " << (m.pass ? "passes" : "fails") << ")";
    if (below.count(name) != 0 && !(m.pass && passing == BelowPassing::kHeldInItsWindow)) {
      // The piece below: the mode held under its top, on its empty frequency where it has one
      // (the higher of the two), as the sizing that tries it asks (ComfortRowsOf).
      if (const std::optional<double> top = PieceBelow(m, a.check, d)) {
        out.push_back(empty >= 0
                          ? Bounded(empty_row(), false, m.frequency_empty_hz,
                                    m.frequency_empty_hz * *top,
                                    what.str() + ": the piece below, empty")
                          : Bounded(crowded_row(), false, m.frequency_hz, m.frequency_hz * *top,
                                    what.str() + ": the piece below, crowded"));
        out.back().below = true;
        continue;
      }
    }
    const std::optional<double> up = WindowEnd(m, a.check, d, kScaleStep);
    const std::optional<double> down = WindowEnd(m, a.check, d, 1.0 / kScaleStep);
    if (!m.pass) {
      // Up, to the least frequency at which it passes, as the deflection and strength rows push
      // the same way: a design that softened a failing mode below its range would be a more
      // flexible bridge than its deflection limit asks for (the 3D bridge at n = 1, sent down,
      // was asked 1.38 -> 1.07 Hz in torsion and its sizing lost its way).
      out.push_back(Bounded(
          crowded_row(), true, m.frequency_hz, m.frequency_hz * (up ? *up : kLargestScale),
          what.str() + (up ? ": crowded" : ": no frequency up to 3 times passes; crowded")));
      continue;
    }
    if (down) {
      out.push_back(Bounded(crowded_row(), true, m.frequency_hz, m.frequency_hz * *down,
                            what.str() + ": crowded"));
    }
    if (up && empty >= 0) {
      out.push_back(Bounded(empty_row(), false, m.frequency_empty_hz, m.frequency_empty_hz * *up,
                            what.str() + ": empty"));
    }
  }
  return out;
}

double CorrectComfortRows(const SizingProblem& problem, const Eigen::VectorXd& x,
                          std::vector<ComfortRow>& next) {
  std::map<std::string, ComfortRow*> found;
  for (ComfortRow& row : next) found[row.key] = &row;
  double worst = 0;
  for (int r = 0; r < problem.num_constraints(); ++r) {
    const SizingRow& row = problem.rows()[static_cast<size_t>(r)];
    if (row.kind != SizingRow::kComfort) continue;
    const auto it = found.find(problem.comfort_rows()[static_cast<size_t>(row.member)].key);
    if (it == found.end() || !(it->second->omega2 > 0)) continue;
    ComfortRow& again = *it->second;
    const double ratio = problem.ComfortOmega2(r, x) / again.omega2;
    worst = std::max(worst, std::abs(ratio - 1.0));
    const double factor = std::clamp(ratio, 1.0, kLargestCorrection);
    again.target_omega2 *= again.lower ? factor : 1.0 / factor;
  }
  return worst;
}

bool EaseComfortRows(std::vector<ComfortRow>& rows) {
  bool eased = false;
  for (ComfortRow& row : rows) {
    const bool away = row.lower ? row.target_omega2 > row.omega2 : row.target_omega2 < row.omega2;
    if (!away || !(row.omega2 > 0)) continue;
    row.target_omega2 = std::sqrt(row.target_omega2 * row.omega2);
    row.label += " (eased)";
    eased = true;
  }
  return eased;
}

}  // namespace tbridge
