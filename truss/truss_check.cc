#include "truss/truss_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "truss/truss_nonlinear.h"

namespace tbridge {

namespace {

constexpr double kPi = std::numbers::pi;
// The frequencies reported where no limit asks for more.
constexpr int kReportedModes = 6;

// Member e's utilisation and its mode of failure under force n (tension > 0) at area a.
std::pair<double, TrussFailure> MemberUtilisation(const TrussModel& m, int e, double n, double a) {
  const TrussMember& member = m.members[static_cast<size_t>(e)];
  const TrussGroup& g = m.groups[static_cast<size_t>(member.group)];
  if (n >= 0) {
    if (g.kind == TrussKind::kBar)
      return {1 + n / (g.allowed_compression * a), TrussFailure::kTensionInBar};
    return {n / (g.allowed_tension * a), TrussFailure::kTension};
  }
  if (g.kind == TrussKind::kString) return {1 - n / (g.allowed_tension * a), TrussFailure::kSlack};
  std::pair<double, TrussFailure> out{-n / (g.allowed_compression * a), TrussFailure::kCompression};
  if (g.euler) {
    const double u = -n * m.buckling_factor / m.EulerLoad(e, a);
    if (u > out.first) out = {u, TrussFailure::kBuckling};
  }
  return out;
}

// The support reactions of case c: each pinned node's reaction balances the members' forces on
// it, its own loads and its share of the members' weight.
// `pull(e, u)`: the force member e exerts on its node i (TrussAnalysis::Pull, or the nonlinear
// one).
template <class Pull>
Eigen::Matrix3Xd Reactions(const TrussModel& m, int c, const Eigen::VectorXd& areas,
                           const Pull& pull_of, const TrussCaseResponse& r) {
  const TrussCase& lc = m.cases[static_cast<size_t>(c)];
  Eigen::Matrix3Xd out = Eigen::Matrix3Xd::Zero(3, m.nodes.cols());
  for (int e = 0; e < m.num_members(); ++e) {
    const TrussMember& member = m.members[static_cast<size_t>(e)];
    const double half_weight = 0.5 * lc.factor * m.density * m.gravity * member.length * areas[e];
    const Eigen::Vector3d pull = pull_of(e, r.u);  // on node i
    const Eigen::Vector3d down(0, -half_weight, 0);
    if (m.fixed[static_cast<size_t>(member.i)]) out.col(member.i) -= pull + down;
    if (m.fixed[static_cast<size_t>(member.j)]) out.col(member.j) -= -pull + down;
  }
  for (int k = 0; k < out.cols(); ++k) {
    if (m.fixed[static_cast<size_t>(k)]) out.col(k) -= lc.node_loads.col(k);
  }
  return out;
}

// Every applied load of case c (its loads and the members' weight), summed.
Eigen::Vector3d AppliedTotal(const TrussModel& m, int c, const Eigen::VectorXd& areas) {
  const TrussCase& lc = m.cases[static_cast<size_t>(c)];
  Eigen::Vector3d sum = lc.node_loads.rowwise().sum();
  sum.y() -= lc.factor * m.gravity * m.MassOfMembers(areas);
  return sum;
}

void CheckMembers(const TrussModel& m, const Eigen::VectorXd& areas, TrussCheck& out) {
  out.members.resize(static_cast<size_t>(m.num_members()));
  for (int e = 0; e < m.num_members(); ++e) {
    TrussMemberCheck& mc = out.members[static_cast<size_t>(e)];
    mc.area = areas[e];
    mc.utilisation = -std::numeric_limits<double>::infinity();
    for (int c = 0; c < static_cast<int>(out.cases.size()); ++c) {
      const double n = out.cases[static_cast<size_t>(c)].forces[e];
      const auto [u, mode] = MemberUtilisation(m, e, n, areas[e]);
      if (u > mc.utilisation) mc = {areas[e], n, u, mode, c};
    }
    if (out.cases.empty()) mc.utilisation = 0;
  }
}

void CheckDisplacements(const TrussModel& m, TrussCheck& out) {
  for (const TrussDisplacementLimit& d : m.displacement_limits) {
    TrussLimitCheck lc{
        "node " + std::to_string(d.node + 1) + " " + NameOf(static_cast<Axis>(d.axis)), 0, d.max, 0,
        0};
    for (int c = 0; c < static_cast<int>(out.cases.size()); ++c) {
      const double u = std::abs(out.cases[static_cast<size_t>(c)].u[d.dof]);
      if (u > lc.value) lc.value = u, lc.governing_case = c;
    }
    lc.utilisation = lc.value / d.max;
    out.displacements.push_back(lc);
  }
}

void CheckFrequencies(const TrussModel& m, const TrussAnalysis& analysis, TrussCheck& out) {
  const int limits = static_cast<int>(m.min_frequencies_hz.size());
  if (limits == 0 && m.num_free > kTrussMaxModalDofs) return;  // none asked, too many to report
  const TrussModes modes = analysis.Modes(std::max(limits, kReportedModes), false);
  out.frequencies_hz = modes.eigenvalues.cwiseMax(0.0).cwiseSqrt() / (2 * kPi);
  for (int k = 0; k < limits; ++k) {
    const double f = k < out.frequencies_hz.size() ? out.frequencies_hz[k] : 0.0;
    const double min = m.min_frequencies_hz[static_cast<size_t>(k)];
    out.frequencies.push_back(
        {"mode " + std::to_string(k + 1), f, min,
         f > 0 ? std::pow(min / f, 2) : std::numeric_limits<double>::infinity(), -1});
  }
}

// The keys that move a member's row: its group's largest area where it is there, else its area
// (which a converged sizing would have raised, or an edited file lowered).
std::string MemberLever(const TrussModel& m, int e, double area) {
  const int g = m.members[static_cast<size_t>(e)].group;
  const std::string group = "structure.groups[" + std::to_string(g) + "]";
  if (area >= m.groups[static_cast<size_t>(g)].max_area * (1 - 1e-9)) {
    return group + ".max_area_m2 (the group is at its largest area), or that member's loads";
  }
  return "the area of " + group + " (\"" + m.groups[static_cast<size_t>(g)].name +
         "\"): larger, by a sizing that converges (design.max_iterations, design.solver) or in the "
         "file";
}

// The largest utilisation, what it is and the keys that move it.
void Verdict(const TrussModel& m, TrussCheck& out) {
  out.utilisation_max = 0;
  out.governing = "nothing";
  const auto take = [&out](double u, const std::string& what, const std::string& lever) {
    if (u > out.utilisation_max) out.utilisation_max = u, out.governing = what, out.lever = lever;
  };
  for (int e = 0; e < m.num_members() && !out.cases.empty(); ++e) {
    const TrussMemberCheck& mc = out.members[static_cast<size_t>(e)];
    take(mc.utilisation,
         "member " + m.MemberName(e) + " (" + NameOf(mc.governed_by) + ", case " +
             m.cases[static_cast<size_t>(mc.governing_case)].name + ")",
         MemberLever(m, e, mc.area));
  }
  for (size_t k = 0; k < out.displacements.size(); ++k) {
    const TrussLimitCheck& d = out.displacements[k];
    take(d.utilisation,
         "displacement of " + d.what + " (case " +
             m.cases[static_cast<size_t>(std::max(d.governing_case, 0))].name + ")",
         "structure.limits.displacements[" + std::to_string(k) +
             "].max_m, or the groups' max_area_m2");
  }
  for (size_t k = 0; k < out.frequencies.size(); ++k) {
    take(out.frequencies[k].utilisation, "frequency of " + out.frequencies[k].what,
         "structure.limits.min_frequencies_hz[" + std::to_string(k) +
             "], structure.node_masses, or the groups' max_area_m2");
  }
  out.pass = out.utilisation_max <= 1 + kTrussPassTolerance;
  if (out.pass) out.lever.clear();
}

}  // namespace

Eigen::VectorXd TrussCheck::Areas() const {
  Eigen::VectorXd a(static_cast<int>(members.size()));
  for (size_t e = 0; e < members.size(); ++e) a[static_cast<int>(e)] = members[e].area;
  return a;
}

TrussCheck CheckTruss(const TrussModel& m, const Eigen::VectorXd& areas,
                      const Eigen::VectorXd& prestress) {
  TrussCheck out;
  out.prestress = prestress.size() ? prestress : Eigen::VectorXd::Zero(m.num_members());
  const TrussAnalysis analysis(m, areas, out.prestress);
  const TrussNonlinearStatics nonlinear(m, areas, out.prestress);
  out.cases = SolveTrussCases(m, &analysis, areas, out.prestress, false);
  const auto pull = [&](int e, const Eigen::VectorXd& u) {
    return m.analysis == TrussAnalysisKind::kNonlinear ? nonlinear.Pull(e, u) : analysis.Pull(e, u);
  };
  for (int c = 0; c < static_cast<int>(m.cases.size()); ++c) {
    out.reactions.push_back(Reactions(m, c, areas, pull, out.cases[static_cast<size_t>(c)]));
    const Eigen::Vector3d residual =
        out.reactions.back().rowwise().sum() + AppliedTotal(m, c, areas);
    out.equilibrium_residual = std::max(out.equilibrium_residual, residual.norm());
  }
  CheckMembers(m, areas, out);
  CheckDisplacements(m, out);
  CheckFrequencies(m, analysis, out);
  Verdict(m, out);
  return out;
}

}  // namespace tbridge
