#include "truss/truss_analysis.h"

#include <Eigen/Eigenvalues>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/member_area.h"
#include "core/tangent_blocks.h"

namespace tbridge {

namespace {

// The free degree of freedom of `node` along `axis`, or -1.
int DofOf(const TrussModel& m, int node, int axis) {
  return m.dof[static_cast<size_t>(node * m.dim + axis)];
}

}  // namespace

Eigen::Matrix3d MemberBlock(const Eigen::Vector3d& d, double l, double k, double n) {
  return StringTangentBlock(d, k, n / l);
}

Eigen::SparseMatrix<double> AssembleStiffness(const TrussModel& model,
                                              const std::vector<Eigen::Matrix3d>& blocks) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int e = 0; e < model.num_members(); ++e) {
    const TrussMember& m = model.members[static_cast<size_t>(e)];
    const int ends[2] = {m.i, m.j};
    for (int p = 0; p < 2; ++p) {
      for (int q = 0; q < 2; ++q) {
        const double sign = p == q ? 1.0 : -1.0;
        for (int a = 0; a < model.dim; ++a) {
          for (int b = 0; b < model.dim; ++b) {
            const int r = DofOf(model, ends[p], a), c = DofOf(model, ends[q], b);
            if (r >= 0 && c >= 0)
              entries.emplace_back(r, c, sign * blocks[static_cast<size_t>(e)](a, b));
          }
        }
      }
    }
  }
  Eigen::SparseMatrix<double> k(model.num_free, model.num_free);
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

std::unique_ptr<TrussFactor> FactoriseStiffness(const TrussModel& model,
                                                const Eigen::SparseMatrix<double>& stiffness) {
  auto factor = std::make_unique<TrussFactor>(stiffness);
  const Eigen::VectorXd pivots = factor->vectorD();
  const double largest = pivots.size() ? pivots.cwiseAbs().maxCoeff() : 0.0;
  // A pivot this far below the largest is a mechanism, not a soft member: the areas' range of a
  // sizing is a few decades, round-off 1e-16 (a prestress's geometric stiffness, N0 / L against
  // E A / L, is a strain: 1e-5 and more).
  if (factor->info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * largest)) {
    throw ModelError(
        "the structure is a mechanism: its stiffness matrix (" + std::to_string(model.num_free) +
        " free degrees of freedom) is " +
        (pivots.minCoeff() < -1e-12 * largest ? "not positive definite" : "singular") +
        "; pin it or add members" +
        (model.num_prestress() > 0 ? ", or prestress it (its strings in tension)" : ""));
  }
  return factor;
}

Eigen::Vector3d RelativeDisplacement(const TrussModel& model, int e, const Eigen::VectorXd& u) {
  const TrussMember& m = model.members[static_cast<size_t>(e)];
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (int a = 0; a < model.dim; ++a) {
    const int fi = DofOf(model, m.i, a), fj = DofOf(model, m.j, a);
    w[a] = (fj >= 0 ? u[fj] : 0.0) - (fi >= 0 ? u[fi] : 0.0);
  }
  return w;
}

void AddForcePartials(const TrussModel& model, int e, double stretch, Eigen::MatrixXd& dforces) {
  const TrussMember& m = model.members[static_cast<size_t>(e)];
  dforces(e, m.group) += model.youngs_modulus / m.length * stretch;
  for (int q = 0; q < model.num_prestress(); ++q)
    dforces(e, model.num_groups() + q) += model.self_stress(e, q);
}

void ScatterPull(const TrussModel& model, int e, const Eigen::Vector3d& pull,
                 Eigen::VectorXd& out) {
  const TrussMember& m = model.members[static_cast<size_t>(e)];
  for (int a = 0; a < model.dim; ++a) {
    const int fi = DofOf(model, m.i, a), fj = DofOf(model, m.j, a);
    if (fi >= 0) out[fi] += pull[a];
    if (fj >= 0) out[fj] -= pull[a];
  }
}

TrussAnalysis::TrussAnalysis(const TrussModel& model, const Eigen::VectorXd& member_areas,
                             const Eigen::VectorXd& prestress)
    : model_(model),
      areas_(member_areas),
      prestress_(prestress.size() ? prestress : Eigen::VectorXd::Zero(model.num_members())) {
  std::vector<Eigen::Matrix3d> blocks;
  for (int e = 0; e < model_.num_members(); ++e)
    blocks.push_back(Block(e, areas_[e], prestress_[e]));
  stiffness_ = AssembleStiffness(model_, blocks);
  factor_ = FactoriseStiffness(model_, stiffness_);
}

Eigen::Matrix3d TrussAnalysis::Block(int e, double area, double n0) const {
  const TrussMember& m = model_.members[static_cast<size_t>(e)];
  return MemberBlock(m.direction, m.length, AxialStiffness(model_.youngs_modulus, area, m.length),
                     n0);
}

double TrussAnalysis::Elongation(int e, const Eigen::VectorXd& u) const {
  return model_.members[static_cast<size_t>(e)].direction.dot(RelativeDisplacement(model_, e, u));
}

Eigen::Vector3d TrussAnalysis::Pull(int e, const Eigen::VectorXd& u) const {
  const TrussMember& m = model_.members[static_cast<size_t>(e)];
  return Force(e, u) * m.direction +
         Block(e, 0.0, prestress_[e]) * RelativeDisplacement(model_, e, u);
}

double TrussAnalysis::Force(int e, const Eigen::VectorXd& u) const {
  const TrussMember& m = model_.members[static_cast<size_t>(e)];
  return prestress_[e] +
         AxialStiffness(model_.youngs_modulus, areas_[e], m.length) * Elongation(e, u);
}

Eigen::VectorXd TrussAnalysis::StiffnessTimes(int v, const Eigen::VectorXd& u) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(model_.num_free);
  const int ng = model_.num_groups();
  const auto add = [&](int e, double area, double n0) {
    // (K u) at node i is -Block (u_j - u_i), at node j +Block (u_j - u_i).
    ScatterPull(model_, e, -Block(e, area, n0) * RelativeDisplacement(model_, e, u), out);
  };
  if (v < ng) {
    for (const int e : model_.groups[static_cast<size_t>(v)].members) add(e, 1.0, 0.0);
  } else {
    for (int e = 0; e < model_.num_members(); ++e) {
      const double n0 = model_.self_stress(e, v - ng);
      if (n0 != 0) add(e, 0.0, n0);
    }
  }
  return out;
}

TrussCaseResponse TrussAnalysis::Solve(int c, bool sensitivities) const {
  const TrussCase& lc = model_.cases[static_cast<size_t>(c)];
  const int ng = model_.num_groups(), nm = model_.num_members();
  TrussCaseResponse r;
  r.u = factor_->solve(model_.CaseLoads(c, areas_));
  r.forces.resize(nm);
  for (int e = 0; e < nm; ++e) r.forces[e] = Force(e, r.u);
  if (!sensitivities) return r;
  // K du/dv = df/dv - (dK/dv) u: the self-weight moves with a group's area, the stiffness with
  // it and with each self-stress amplitude (its geometric stiffness).
  const int nv = model_.num_variables();
  r.du.resize(model_.num_free, nv);
  for (int v = 0; v < nv; ++v) {
    Eigen::VectorXd rhs = -StiffnessTimes(v, r.u);
    if (v < ng) rhs += lc.factor * model_.WeightPerArea(v);
    r.du.col(v) = factor_->solve(rhs);
  }
  r.dforces.resize(nm, nv);
  for (int e = 0; e < nm; ++e) {
    const TrussMember& m = model_.members[static_cast<size_t>(e)];
    const double k = AxialStiffness(model_.youngs_modulus, areas_[e], m.length);
    for (int v = 0; v < nv; ++v) r.dforces(e, v) = k * Elongation(e, r.du.col(v));
    AddForcePartials(model_, e, Elongation(e, r.u), r.dforces);
  }
  return r;
}

void TrussAnalysis::AddEnds(int e, const Eigen::Matrix3d& same, const Eigen::Matrix3d& across,
                            Eigen::MatrixXd& out) const {
  const TrussMember& m = model_.members[static_cast<size_t>(e)];
  const int ends[2] = {m.i, m.j};
  for (int p = 0; p < 2; ++p) {
    for (int q = 0; q < 2; ++q) {
      const Eigen::Matrix3d& block = p == q ? same : across;
      for (int a = 0; a < model_.dim; ++a) {
        for (int b = 0; b < model_.dim; ++b) {
          const int r = DofOf(model_, ends[p], a), c = DofOf(model_, ends[q], b);
          if (r >= 0 && c >= 0) out(r, c) += block(a, b);
        }
      }
    }
  }
}

Eigen::MatrixXd TrussAnalysis::StiffnessPerVariable(int v) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(model_.num_free, model_.num_free);
  const int ng = model_.num_groups();
  const auto add = [&](int e, double area, double n0) {
    const Eigen::Matrix3d block = Block(e, area, n0);
    AddEnds(e, block, -block, out);
  };
  if (v < ng) {
    for (const int e : model_.groups[static_cast<size_t>(v)].members) add(e, 1.0, 0.0);
  } else {
    for (int e = 0; e < model_.num_members(); ++e) add(e, 0.0, model_.self_stress(e, v - ng));
  }
  return out;
}

Eigen::MatrixXd TrussAnalysis::MassPerVariable(int v) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(model_.num_free, model_.num_free);
  if (v >= model_.num_groups()) return out;  // a prestress moves no mass
  for (const int e : model_.groups[static_cast<size_t>(v)].members) {
    const double per_area = model_.density * model_.members[static_cast<size_t>(e)].length;
    AddEnds(e, per_area / 3 * Eigen::Matrix3d::Identity(),
            per_area / 6 * Eigen::Matrix3d::Identity(), out);
  }
  return out;
}

Eigen::MatrixXd TrussAnalysis::Mass() const {
  Eigen::MatrixXd out = model_.node_mass.asDiagonal();
  for (int e = 0; e < model_.num_members(); ++e) {
    const double mass =
        MassOfArea(model_.density, areas_[e], model_.members[static_cast<size_t>(e)].length);
    AddEnds(e, mass / 3 * Eigen::Matrix3d::Identity(), mass / 6 * Eigen::Matrix3d::Identity(), out);
  }
  return out;
}

TrussModes TrussAnalysis::Modes(int count, bool sensitivities) const {
  if (model_.num_free > kTrussMaxModalDofs) {
    throw ModelError("the frequency limits need the modes of " + std::to_string(model_.num_free) +
                     " free degrees of freedom; the modal analysis takes at most " +
                     std::to_string(kTrussMaxModalDofs));
  }
  const Eigen::MatrixXd k = Eigen::MatrixXd(stiffness_), mass = Mass();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(k, mass);
  if (solver.info() != Eigen::Success) {
    throw ModelError(
        "the modal analysis failed: the mass matrix is not positive definite (a free node "
        "without mass: give it a member or a node mass)");
  }
  TrussModes out;
  const int n = std::min(count, model_.num_free);
  out.eigenvalues = solver.eigenvalues().head(n);
  out.shapes = solver.eigenvectors().leftCols(n);
  if (!sensitivities) return out;
  out.deigenvalues.resize(n, model_.num_variables());
  for (int g = 0; g < model_.num_variables(); ++g) {
    const Eigen::MatrixXd dk = StiffnessPerVariable(g), dm = MassPerVariable(g);
    for (int k2 = 0; k2 < n; ++k2) {
      const Eigen::VectorXd phi = out.shapes.col(k2);
      out.deigenvalues(k2, g) = phi.dot(dk * phi) - out.eigenvalues[k2] * phi.dot(dm * phi);
    }
  }
  return out;
}

Eigen::VectorXd TrussAnalysis::ModeCoupling(const TrussModes& modes, int a, int b) const {
  Eigen::VectorXd out(model_.num_variables());
  const Eigen::VectorXd pa = modes.shapes.col(a), pb = modes.shapes.col(b);
  for (int g = 0; g < model_.num_variables(); ++g) {
    out[g] = pa.dot(StiffnessPerVariable(g) * pb) -
             modes.eigenvalues[a] * pa.dot(MassPerVariable(g) * pb);
  }
  return out;
}

}  // namespace tbridge
