#include "truss/truss_nonlinear.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/member_area.h"

namespace tbridge {

namespace {

// Newton's iterations in one load step: it converges quadratically, in 3-6 from a good start.
constexpr int kNewtonIterations = 40;
// The smallest load step tried before the solve gives up.
constexpr double kSmallestLoadStep = 1.0 / 1024;
// Equilibrium: the residual within this of the largest load or prestress, or a Newton step
// within kStepTolerance of the largest member's length (where the residual is round-off: a
// member's force is N0 + k (l - L), and l carries 1e-16 of L times k L = E A, 1e-5 N and more
// on a stiff member).
constexpr double kResidualTolerance = 1e-11;
constexpr double kStepTolerance = 1e-13;

}  // namespace

TrussNonlinearStatics::TrussNonlinearStatics(const TrussModel& model,
                                             const Eigen::VectorXd& member_areas,
                                             const Eigen::VectorXd& prestress)
    : model_(model),
      areas_(member_areas),
      prestress_(prestress.size() ? prestress : Eigen::VectorXd::Zero(model.num_members())) {}

Eigen::Vector3d TrussNonlinearStatics::Direction(int e, const Eigen::VectorXd& u,
                                                 double& length) const {
  const TrussMember& m = model_.members[static_cast<size_t>(e)];
  const Eigen::Vector3d chord = m.length * m.direction + RelativeDisplacement(model_, e, u);
  length = chord.norm();
  return chord / length;
}

double TrussNonlinearStatics::Force(int e, double length) const {
  const TrussMember& m = model_.members[static_cast<size_t>(e)];
  return prestress_[e] +
         AxialStiffness(model_.youngs_modulus, areas_[e], m.length) * (length - m.length);
}

Eigen::Vector3d TrussNonlinearStatics::Pull(int e, const Eigen::VectorXd& u) const {
  double l = 0;
  const Eigen::Vector3d d = Direction(e, u, l);
  return Force(e, l) * d;
}

Eigen::VectorXd TrussNonlinearStatics::Residual(const Eigen::VectorXd& f,
                                                const Eigen::VectorXd& u) const {
  Eigen::VectorXd r = f;
  for (int e = 0; e < model_.num_members(); ++e) ScatterPull(model_, e, Pull(e, u), r);
  return r;
}

std::unique_ptr<TrussFactor> TrussNonlinearStatics::Tangent(const Eigen::VectorXd& u) const {
  std::vector<Eigen::Matrix3d> blocks;
  for (int e = 0; e < model_.num_members(); ++e) {
    double l = 0;
    const Eigen::Vector3d d = Direction(e, u, l);
    const TrussMember& m = model_.members[static_cast<size_t>(e)];
    blocks.push_back(
        MemberBlock(d, l, AxialStiffness(model_.youngs_modulus, areas_[e], m.length), Force(e, l)));
  }
  return FactoriseStiffness(model_, AssembleStiffness(model_, blocks));
}

bool TrussNonlinearStatics::Newton(const Eigen::VectorXd& f, Eigen::VectorXd& u) const {
  double scale = f.size() ? f.cwiseAbs().maxCoeff() : 0.0, longest = 0;
  for (int e = 0; e < model_.num_members(); ++e) {
    scale = std::max(scale, std::abs(prestress_[e]));
    longest = std::max(longest, model_.members[static_cast<size_t>(e)].length);
  }
  Eigen::VectorXd x = u;
  for (int k = 0; k < kNewtonIterations; ++k) {
    const Eigen::VectorXd r = Residual(f, x);
    if (!r.allFinite()) return false;
    if (r.cwiseAbs().maxCoeff() <= kResidualTolerance * std::max(scale, 1e-30)) {
      u = x;
      return true;
    }
    Eigen::VectorXd step;
    try {
      step = Tangent(x)->solve(r);
    } catch (const ModelError&) {
      return false;  // the tangent lost its stiffness on the way: a smaller load step
    }
    x += step;
    if (step.cwiseAbs().maxCoeff() <= kStepTolerance * longest) {
      u = x;
      return true;
    }
  }
  return false;
}

TrussCaseResponse TrussNonlinearStatics::Solve(int c, bool sensitivities) const {
  const TrussCase& lc = model_.cases[static_cast<size_t>(c)];
  const Eigen::VectorXd f = model_.CaseLoads(c, areas_);
  TrussCaseResponse r;
  r.u = Eigen::VectorXd::Zero(model_.num_free);
  double reached = 0, step = 1;
  while (reached < 1) {
    const double next = std::min(1.0, reached + step);
    if (Newton(next * f, r.u)) {
      reached = next;
      step = std::min(1.0, 2 * step);
    } else if ((step /= 2) < kSmallestLoadStep) {
      throw ModelError("the nonlinear static solve of case \"" + lc.name +
                       "\" does not converge beyond " + std::to_string(reached) +
                       " of its load (a snap-through, or a mechanism the prestress does not "
                       "hold): larger areas or prestress, or structure.analysis \"linear\"");
    }
  }
  r.forces.resize(model_.num_members());
  for (int e = 0; e < model_.num_members(); ++e) {
    double l = 0;
    Direction(e, r.u, l);
    r.forces[e] = Force(e, l);
  }
  if (sensitivities) Sensitivities(c, r);
  return r;
}

void TrussNonlinearStatics::Sensitivities(int c, TrussCaseResponse& r) const {
  const TrussCase& lc = model_.cases[static_cast<size_t>(c)];
  const int ng = model_.num_groups(), nv = model_.num_variables(), nm = model_.num_members();
  const std::unique_ptr<TrussFactor> tangent = Tangent(r.u);
  std::vector<Eigen::Vector3d> d(static_cast<size_t>(nm));
  Eigen::VectorXd stretch(nm);  // l - L
  for (int e = 0; e < nm; ++e) {
    double l = 0;
    d[static_cast<size_t>(e)] = Direction(e, r.u, l);
    stretch[e] = l - model_.members[static_cast<size_t>(e)].length;
  }
  // dR/dv at fixed u: a group's area moves its members' forces by E (l - L) / L, an amplitude
  // every member's by its share of the self-stress state; each along its current direction.
  r.du.resize(model_.num_free, nv);
  for (int v = 0; v < nv; ++v) {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(model_.num_free);
    if (v < ng) {
      rhs += lc.factor * model_.WeightPerArea(v);
      for (const int e : model_.groups[static_cast<size_t>(v)].members) {
        const double dn =
            model_.youngs_modulus / model_.members[static_cast<size_t>(e)].length * stretch[e];
        ScatterPull(model_, e, dn * d[static_cast<size_t>(e)], rhs);
      }
    } else {
      for (int e = 0; e < nm; ++e)
        ScatterPull(model_, e, model_.self_stress(e, v - ng) * d[static_cast<size_t>(e)], rhs);
    }
    r.du.col(v) = tangent->solve(rhs);
  }
  r.dforces.resize(nm, nv);
  for (int e = 0; e < nm; ++e) {
    const TrussMember& m = model_.members[static_cast<size_t>(e)];
    const double k = AxialStiffness(model_.youngs_modulus, areas_[e], m.length);
    for (int v = 0; v < nv; ++v)
      r.dforces(e, v) =
          k * d[static_cast<size_t>(e)].dot(RelativeDisplacement(model_, e, r.du.col(v)));
    AddForcePartials(model_, e, stretch[e], r.dforces);
  }
}

std::vector<TrussCaseResponse> SolveTrussCases(const TrussModel& model, const TrussAnalysis* linear,
                                               const Eigen::VectorXd& member_areas,
                                               const Eigen::VectorXd& prestress,
                                               bool sensitivities) {
  std::vector<TrussCaseResponse> out;
  const int cases = static_cast<int>(model.cases.size());
  if (model.analysis == TrussAnalysisKind::kNonlinear) {
    const TrussNonlinearStatics statics(model, member_areas, prestress);
    for (int c = 0; c < cases; ++c) out.push_back(statics.Solve(c, sensitivities));
  } else {
    for (int c = 0; c < cases; ++c) out.push_back(linear->Solve(c, sensitivities));
  }
  return out;
}

}  // namespace tbridge
