#include "design/verification.h"

#include <algorithm>
#include <sstream>

namespace tbridge {

namespace {

// A member sized exactly to its resistance may read 1 + a few rounding steps.
constexpr double kUtilisationRounding = 1e-9;

bool AnyOver(const std::vector<MemberFinding>& members) {
  return std::any_of(members.begin(), members.end(), [](const MemberFinding& f) {
    return f.utilisation > 1.0 + kUtilisationRounding;
  });
}

}  // namespace

const char* CheckStatusName(CheckStatus status) {
  switch (status) {
    case CheckStatus::kPassed:
      return "passed";
    case CheckStatus::kFailed:
      return "failed";
    case CheckStatus::kNotRequired:
      return "not_required";
    case CheckStatus::kNotRun:
      break;
  }
  return "not_run";
}

void RaiseFinding(MemberFinding& f, double demand, double resistance,
                  const std::string& governing_case, LimitMode mode) {
  const double u = demand / resistance;
  if (!(u > f.utilisation)) return;
  f.utilisation = u;
  f.demand = demand;
  f.resistance = resistance;
  f.governing_case = governing_case;
  f.mode = mode;
}

void RaiseSlackFinding(MemberFinding& f, double strain, double working_stress,
                       double youngs_modulus, const std::string& governing_case) {
  const double working_strain = working_stress / youngs_modulus;
  RaiseFinding(f, working_strain - strain, working_strain, governing_case, LimitMode::kSlack);
}

CheckStatus StaticCheck::Status() const {
  if (!done) return CheckStatus::kNotRun;
  bool over = AnyOver(members);
  for (const AbutmentFinding& a : abutments) {
    over = over || std::max(a.HorizontalUtilisation(), a.VerticalUtilisation()) > 1 + 1e-9;
  }
  const bool fails = !all_converged || deflection_max_m > deflection_limit_m || over;
  return fails ? CheckStatus::kFailed : CheckStatus::kPassed;
}

CheckStatus DynamicCheck::Status() const {
  if (AnyOver(members)) return CheckStatus::kFailed;
  if (!done || !NotDone().empty()) return CheckStatus::kNotRun;
  return CheckStatus::kPassed;
}

CheckStatus ComfortCheck::Status() const {
  if (!done) return CheckStatus::kNotRun;
  if (!required) return CheckStatus::kNotRequired;
  for (const ComfortMode& m : modes) {
    if (!m.pass) return CheckStatus::kFailed;
  }
  return CheckStatus::kPassed;
}

std::string ComfortCheck::Failures() const {
  std::ostringstream os;
  for (const ComfortMode& m : modes) {
    if (m.pass) continue;
    if (os.tellp() > 0) os << "; ";
    os << NameOf(m.direction) << " mode " << m.index << " at " << m.frequency_hz << " Hz: ";
    if (m.acceleration_m_s2 > m.limit_m_s2) {
      os << m.acceleration_m_s2 << " m/s^2 > " << m.limit_m_s2 << " m/s^2 (" << m.load_model << ")";
    } else {
      os << pedestrians << " pedestrians > the " << m.lock_in_pedestrians << " that lock in";
    }
  }
  return os.str();
}

}  // namespace tbridge
