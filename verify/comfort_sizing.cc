#include "verify/comfort_sizing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "core/material.h"
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
// Rayleigh quotient of the held shape, which the new design's own frequency follows to second
// order in the step.
constexpr double kFrequencyMargin = 1e-3;

// Whether `mode` passes with both its frequencies scaled by s.
bool PassesAt(const ComfortMode& mode, const ComfortCheck& check, const Design& d, double s) {
  ComfortMode moved = mode;
  RespondAt(moved, check, d, mode.frequency_hz * s, mode.frequency_empty_hz * s);
  return moved.pass;
}

// From s = 1 in the direction of `step` (> 1 up, < 1 down): the first scale at which the mode's
// pass differs from its pass at 1, bisected to the last scale with its pass at 1; none within
// kLargestScale.
std::optional<double> WindowEnd(const ComfortMode& mode, const ComfortCheck& check, const Design& d,
                                double step) {
  const bool at_one = PassesAt(mode, check, d, 1.0);
  double inside = 1.0;
  for (double s = step; s < kLargestScale && s > 1.0 / kLargestScale; s *= step) {
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

}  // namespace

ComfortRow ComfortRowOf(const Design& d, const DynamicModel& model, const Mode& mode) {
  const ModeEnergies e = ModeEnergiesOf(model, mode, ModelOptions{}.string_mass);
  const int nb = static_cast<int>(d.bars.size()), nm = nb + static_cast<int>(d.strings.size());
  const MemberMaterial bars = BarMaterial(d.config), strings = StringMaterial(d.config);
  ComfortRow row;
  row.omega2 = mode.omega_squared;
  row.by_area.assign(static_cast<size_t>(nm), 0.0);
  row.by_force.assign(static_cast<size_t>(nm), 0.0);
  row.mass_by_area.assign(static_cast<size_t>(nm), 0.0);
  for (int j = 0; j < nm; ++j) {
    const size_t k = static_cast<size_t>(j);
    if (j < nb) {
      // A rigid bar: its compression's geometric stiffness and its mass rho A l.
      row.by_force[k] = e.by_force[k];
      row.mass_by_area[k] = e.mass_energy[k] * bars.density * d.bars[k].length;
    } else {
      // A string: k = (E A + T_ref) / l (its rest length makes it carry T_ref at its drawn
      // length l), and the state's tension follows T_ref one for one (to its strain).
      const MemberSizing& s = d.strings[k - static_cast<size_t>(nb)];
      row.by_area[k] = e.by_stiffness[k] * strings.youngs_modulus / s.length;
      row.by_force[k] = e.by_stiffness[k] / s.length + e.by_force[k];
      row.mass_by_area[k] = e.mass_energy[k] * strings.density * s.rest_length;
    }
  }
  return row;
}

std::vector<ComfortRow> ComfortRowsOf(const Design& d, const ComfortAnalysis& a) {
  std::vector<ComfortRow> out;
  if (!d.config.comfort.sizing_constraint || !a.check.done) return out;
  std::map<std::string, int> rank;  // how many modes of each motion came before
  for (size_t i = 0; i < a.modes.size(); ++i) {
    const ComfortMode& m = a.modes[i];
    const Mode& crowded = a.crowded.modal.modes[static_cast<size_t>(a.crowded_mode[i])];
    if (!(crowded.omega_squared > 0))
      continue;  // an unstable design: the sizing's stability rows hold it
    const std::string name = m.direction + " " + std::to_string(++rank[m.direction]);
    const int empty = a.empty_mode[i];
    // The rows on the crowded frequency (lower bounds: its interval's lower end) and on the empty
    // one (upper bounds).
    const auto crowded_row = [&] {
      ComfortRow row = ComfortRowOf(d, a.crowded_model, crowded);
      row.key = name + " crowded";
      return row;
    };
    const auto empty_row = [&] {
      ComfortRow row =
          ComfortRowOf(d, a.empty_model, a.empty.modal.modes[static_cast<size_t>(empty)]);
      row.key = name + " empty";
      return row;
    };
    std::ostringstream what;
    what << m.direction << " mode " << m.index << " (" << m.frequency_hz << " Hz crowded, "
         << m.frequency_empty_hz << " Hz empty, " << (m.pass ? "passes" : "fails") << ")";
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
