#include "statics/static_solve.h"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/string_law.h"
#include "core/tangent_blocks.h"

namespace tbridge {

namespace {

// The free coordinates: dim per free node, x-y only for a planar structure.
struct DofMap {
  int dim = 3;
  std::vector<int> first;  // per node, its first unknown or -1 (fixed)
  int count = 0;
};

DofMap MapDofs(const Structure& s) {
  DofMap m;
  m.dim = s.dim();
  m.first.assign(s.num_nodes(), -1);
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (!s.fixed[v]) m.first[v] = m.count, m.count += m.dim;
  }
  return m;
}

// Adds `force` on node v to the residual (free coordinates only).
void AddForce(const DofMap& map, int v, const Eigen::Vector3d& force, Eigen::VectorXd& r) {
  if (map.first[v] < 0) return;
  for (int a = 0; a < map.dim; ++a) r[map.first[v] + a] += force[a];
}

// Residual of equilibrium at the free coordinates and of the bar constraints.
void Residual(const StaticModel& m, const DofMap& map, const Eigen::Matrix3Xd& x,
              const Eigen::VectorXd& lambda, const Eigen::Matrix3Xd& loads, Eigen::VectorXd& r,
              Eigen::VectorXd& g) {
  const Structure& s = m.structure;
  r.setZero(map.count);
  for (int v = 0; v < s.num_nodes(); ++v) AddForce(map, v, loads.col(v), r);
  for (int k = 0; k < s.num_strings(); ++k) {
    const Member& e = s.strings[k];
    const Eigen::Vector3d d = x.col(e.j) - x.col(e.i);
    const double len = d.norm();
    const double t = StringTension(m.string_stiffness[k], m.string_rest_length[k], len);
    AddForce(map, e.i, t / len * d, r);
    AddForce(map, e.j, -t / len * d, r);
  }
  g.resize(s.num_bars());
  for (int b = 0; b < s.num_bars(); ++b) {
    const Member& e = s.bars[b];
    const Eigen::Vector3d d = x.col(e.j) - x.col(e.i);
    AddForce(map, e.i, -2.0 * lambda[b] * d, r);
    AddForce(map, e.j, 2.0 * lambda[b] * d, r);
    const double l = s.Length(e);
    g[b] = d.squaredNorm() - l * l;
  }
}

// The entries of the saddle-point matrix [dR/dx  C^T; C  0] at (x, lambda), each passed to
// `sink(row, col, value)` in an order that depends only on the structure (a slack string keeps
// its entries), so that a pattern built once can take them by position.
template <class Sink>
void EmitNewtonEntries(const StaticModel& m, const DofMap& map, const Eigen::Matrix3Xd& x,
                       const Eigen::VectorXd& lambda, Sink&& sink) {
  const Structure& s = m.structure;
  const int n = map.count, dim = map.dim;
  // Block [[B, -B], [-B, B]] between nodes i and j. Unlike AddPairBlock it passes zero entries
  // too: the Newton matrix's pattern is built once and then filled by position.
  auto pair_block = [&](int i, int j, const Eigen::Matrix3d& B) {
    const int ends[2] = {i, j};
    for (int p = 0; p < 2; ++p) {
      for (int q = 0; q < 2; ++q) {
        if (map.first[ends[p]] < 0 || map.first[ends[q]] < 0) continue;
        const double sign = p == q ? 1.0 : -1.0;
        for (int a = 0; a < dim; ++a) {
          for (int c = 0; c < dim; ++c)
            sink(map.first[ends[p]] + a, map.first[ends[q]] + c, sign * B(a, c));
        }
      }
    }
  };
  for (int k = 0; k < s.num_strings(); ++k) {
    const Member& e = s.strings[k];
    const Eigen::Vector3d d = x.col(e.j) - x.col(e.i);
    const double len = d.norm();
    const Eigen::Vector3d u = d / len;
    if (len <= m.string_rest_length[k]) {
      // Slack: no force. A 1e-6 share of its axial stiffness keeps the Newton matrix regular
      // while a string chatters across its rest length (the residual stays exact).
      pair_block(e.i, e.j, -StringMaterialBlock(u, 1e-6 * m.string_stiffness[k]));
      continue;
    }
    const double tension = StringTension(m.string_stiffness[k], m.string_rest_length[k], len);
    // dR/dx of a string is minus its tangent stiffness
    pair_block(e.i, e.j, -StringTangentBlock(u, m.string_stiffness[k], tension / len));
  }
  for (int b = 0; b < s.num_bars(); ++b) {
    const Member& e = s.bars[b];
    pair_block(e.i, e.j, 2.0 * lambda[b] * Eigen::Matrix3d::Identity());
    const Eigen::Vector3d d = x.col(e.j) - x.col(e.i);
    const int row = n + b;
    for (int a = 0; a < dim; ++a) {
      if (map.first[e.j] >= 0) {
        sink(row, map.first[e.j] + a, 2.0 * d[a]);
        sink(map.first[e.j] + a, row, 2.0 * d[a]);
      }
      if (map.first[e.i] >= 0) {
        sink(row, map.first[e.i] + a, -2.0 * d[a]);
        sink(map.first[e.i] + a, row, -2.0 * d[a]);
      }
    }
  }
}

// The saddle-point matrix at (x, lambda), assembled afresh.
Eigen::SparseMatrix<double> Jacobian(const StaticModel& m, const DofMap& map,
                                     const Eigen::Matrix3Xd& x, const Eigen::VectorXd& lambda) {
  std::vector<Eigen::Triplet<double>> t;
  EmitNewtonEntries(m, map, x, lambda, [&t](int r, int c, double v) { t.emplace_back(r, c, v); });
  const int size = map.count + m.structure.num_bars();
  Eigen::SparseMatrix<double> J(size, size);
  J.setFromTriplets(t.begin(), t.end());
  return J;
}

// The saddle-point matrix of one solve, its pattern built once: each Newton step writes the
// entries into their places. Assembling from triplets at every step took 14 % of the verified
// default at n = 7 (the static check's hundreds of solves, five to six steps each).
class NewtonMatrix {
 public:
  NewtonMatrix(const StaticModel& m, const DofMap& map, const Eigen::Matrix3Xd& x,
               const Eigen::VectorXd& lambda)
      : J_(Jacobian(m, map, x, lambda)) {
    J_.makeCompressed();
    EmitNewtonEntries(m, map, x, lambda, [this](int r, int c, double) {
      const int* begin = J_.innerIndexPtr() + J_.outerIndexPtr()[c];
      const int* end = J_.innerIndexPtr() + J_.outerIndexPtr()[c + 1];
      slots_.push_back(static_cast<int>(std::lower_bound(begin, end, r) - J_.innerIndexPtr()));
    });
  }
  const Eigen::SparseMatrix<double>& At(const StaticModel& m, const DofMap& map,
                                        const Eigen::Matrix3Xd& x, const Eigen::VectorXd& lambda) {
    double* values = J_.valuePtr();
    std::fill(values, values + J_.nonZeros(), 0.0);
    size_t k = 0;
    EmitNewtonEntries(m, map, x, lambda, [&](int, int, double v) { values[slots_[k++]] += v; });
    return J_;
  }

 private:
  Eigen::SparseMatrix<double> J_;
  std::vector<int> slots_;  // per entry, in emission order: its place in J_'s values
};

}  // namespace

struct StaticWorkspace::Impl {
  const StaticModel* model = nullptr;  // the model the pattern and analysis are of
  KluFactor lu;
  std::optional<NewtonMatrix> newton;
  bool analysed = false;
};

StaticWorkspace::StaticWorkspace() : impl_(std::make_unique<Impl>()) {}
StaticWorkspace::~StaticWorkspace() = default;

StaticState StateAt(const StaticModel& m, const Eigen::Matrix3Xd& nodes,
                    const Eigen::VectorXd& bar_compression, const Eigen::Matrix3Xd& loads) {
  const Structure& s = m.structure;
  StaticState out;
  out.nodes = nodes;
  out.bar_compression = bar_compression;
  out.string_tension.resize(s.num_strings());
  // Net force of the members and loads on every node; at a fixed node the reaction cancels it.
  Eigen::Matrix3Xd net = loads;
  for (int k = 0; k < s.num_strings(); ++k) {
    const Member& e = s.strings[k];
    const Eigen::Vector3d d = nodes.col(e.j) - nodes.col(e.i);
    const double len = d.norm();
    const double t = StringTension(m.string_stiffness[k], m.string_rest_length[k], len);
    out.string_tension[k] = t;
    net.col(e.i) += t / len * d;
    net.col(e.j) -= t / len * d;
  }
  for (int b = 0; b < s.num_bars(); ++b) {
    const Member& e = s.bars[b];
    const Eigen::Vector3d d = nodes.col(e.j) - nodes.col(e.i);
    const double len = d.norm();
    net.col(e.i) -= bar_compression[b] / len * d;
    net.col(e.j) += bar_compression[b] / len * d;
  }
  out.reactions = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (s.fixed[v]) out.reactions.col(v) = -net.col(v);
  }
  return out;
}

namespace {

// The multipliers of bar compressions C: lambda_b = C_b / (2 l_b).
Eigen::VectorXd Multipliers(const Structure& s, const Eigen::VectorXd& bar_compression) {
  Eigen::VectorXd lambda(s.num_bars());
  for (int b = 0; b < s.num_bars(); ++b)
    lambda[b] = bar_compression[b] / (2.0 * s.Length(s.bars[b]));
  return lambda;
}

// Tolerances: forces to 1e-10 of the largest load or member force (a few hundred rounding
// steps of the sums at a node); this is that force scale.
double ForceScale(const StaticState& start, const Eigen::Matrix3Xd& start_loads,
                  const Eigen::Matrix3Xd& loads) {
  double force_scale = std::max(loads.cwiseAbs().maxCoeff(), start_loads.cwiseAbs().maxCoeff());
  if (start.bar_compression.size())
    force_scale = std::max(force_scale, start.bar_compression.cwiseAbs().maxCoeff());
  if (start.string_tension.size())
    force_scale = std::max(force_scale, start.string_tension.cwiseAbs().maxCoeff());
  force_scale = std::max(force_scale, 1e-300);
  return force_scale;
}

// Takes the Newton `step` into the nodes `x` and the multipliers `lambda`, limited to a tenth of
// the shortest bar `min_bar`, so a slack switch cannot throw the structure across a
// configuration.
void TakeLimitedStep(const Structure& s, const DofMap& map, double min_bar,
                     const Eigen::VectorXd& step, Eigen::Matrix3Xd& x, Eigen::VectorXd& lambda) {
  const int nb = s.num_bars();
  double largest = 0;
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (map.first[v] >= 0) largest = std::max(largest, step.segment(map.first[v], map.dim).norm());
  }
  const double scale = largest > 0.1 * min_bar ? 0.1 * min_bar / largest : 1.0;
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (map.first[v] >= 0) x.col(v).head(map.dim) += scale * step.segment(map.first[v], map.dim);
  }
  lambda += scale * step.tail(nb);
}

}  // namespace

StaticTangent::StaticTangent(const StaticModel& model, const StaticState& state)
    : model_(model), state_(state) {
  const DofMap map = MapDofs(model.structure);
  first_ = map.first;
  dim_ = map.dim;
  free_ = map.count;
  const Eigen::SparseMatrix<double> matrix =
      Jacobian(model, map, state.nodes, Multipliers(model.structure, state.bar_compression));
  ok_ = lu_.Analyse(matrix) && lu_.Factorise(matrix);
  rhs_.setZero(free_ + model.structure.num_bars());
}

void StaticTangent::Solve(const Eigen::Matrix3Xd& dloads, Eigen::Matrix3Xd& displacement,
                          Eigen::VectorXd& force_change) {
  const Structure& s = model_.structure;
  const int nb = s.num_bars(), ns = s.num_strings();
  rhs_.setZero();
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (first_[v] >= 0) rhs_.segment(first_[v], dim_) = -dloads.col(v).head(dim_);
  }
  step_ = rhs_;
  lu_.Solve(step_);
  displacement.setZero(3, s.num_nodes());
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (first_[v] >= 0) displacement.col(v).head(dim_) = step_.segment(first_[v], dim_);
  }
  force_change.resize(nb + ns);
  for (int b = 0; b < nb; ++b) force_change[b] = 2.0 * s.Length(s.bars[b]) * step_[free_ + b];
  for (int k = 0; k < ns; ++k) {
    const Member& e = s.strings[k];
    const Eigen::Vector3d d = state_.nodes.col(e.j) - state_.nodes.col(e.i);
    const double len = d.norm();
    const bool taut = len > model_.string_rest_length[k];
    force_change[nb + k] = taut ? model_.string_stiffness[k] *
                                      d.dot(displacement.col(e.j) - displacement.col(e.i)) / len
                                : 0.0;
  }
}

StaticResult SolveStatic(const StaticModel& m, const StaticState& start,
                         const Eigen::Matrix3Xd& start_loads, const Eigen::Matrix3Xd& loads,
                         const StaticTangent* tangent, StaticWorkspace* workspace) {
  const Structure& s = m.structure;
  const DofMap map = MapDofs(s);
  const int nb = s.num_bars();
  Eigen::Matrix3Xd x = start.nodes;
  Eigen::VectorXd lambda = Multipliers(s, start.bar_compression);
  const bool reuse = tangent != nullptr && tangent->ok();
  // Tolerances: forces to 1e-10 of the largest load or member force (a few hundred rounding
  // steps of the sums at a node); bar lengths to 1e-12 relative.
  const double force_scale = ForceScale(start, start_loads, loads);
  double min_bar = 1e300;
  for (const Member& e : s.bars) min_bar = std::min(min_bar, s.Length(e));
  StaticResult out;
  Eigen::VectorXd r, g, rhs(map.count + nb), step;
  // The Newton matrix's pattern does not change (a slack string keeps its entries), so it is
  // analysed once per solve, or once per workspace.
  StaticWorkspace::Impl local;
  StaticWorkspace::Impl& ws = workspace != nullptr ? *workspace->impl_ : local;
  if (ws.model != &m) {
    ws.model = &m;
    ws.newton.reset();
    ws.analysed = false;
  }
  KluFactor& lu = ws.lu;
  std::optional<NewtonMatrix>& newton = ws.newton;
  bool& analysed = ws.analysed;
  double done = 0, dt = 1.0;
  auto converged = [&](const Eigen::VectorXd& rr, const Eigen::VectorXd& gg) {
    const double rmax = rr.size() ? rr.cwiseAbs().maxCoeff() : 0.0;
    double gmax = 0;
    for (int b = 0; b < nb; ++b)
      gmax = std::max(gmax, std::abs(gg[b]) / std::pow(s.Length(s.bars[b]), 2));
    return rmax <= 1e-10 * force_scale && gmax <= 1e-12;
  };
  while (done < 1.0) {
    const double target = std::min(1.0, done + dt);
    const Eigen::Matrix3Xd f = start_loads + target * (loads - start_loads);
    const Eigen::Matrix3Xd x0 = x;
    const Eigen::VectorXd lambda0 = lambda;
    bool ok = false;
    for (int it = 0; it < 40; ++it) {
      Residual(m, map, x, lambda, f, r, g);
      if (converged(r, g)) {
        ok = true;
        break;
      }
      ++out.newton_iterations;
      rhs << -r, -g;
      step = rhs;
      if (reuse && done == 0 && it == 0) {
        tangent->lu_.Solve(step);  // at `start`, whose matrix the tangent holds
      } else {
        if (!newton) newton.emplace(m, map, x, lambda);
        const Eigen::SparseMatrix<double>& J = newton->At(m, map, x, lambda);
        if (!analysed && !(analysed = lu.Analyse(J))) break;
        if (!lu.Factorise(J)) break;
        lu.Solve(step);
      }
      if (!step.allFinite()) break;
      TakeLimitedStep(s, map, min_bar, step, x, lambda);
    }
    ++out.load_steps;
    if (ok) {
      done = target;
      dt = std::min(1.0, 2.0 * dt);
      continue;
    }
    x = x0;
    lambda = lambda0;
    dt *= 0.5;
    if (dt < 1e-4) {
      out.message =
          "Newton did not converge below a load step of 1e-4 of the load (at " +
          std::to_string(done) +
          " of it): the structure has no nearby equilibrium (a mechanism, or strings slack)";
      break;
    }
  }
  out.converged = done >= 1.0;
  Eigen::VectorXd compression(nb);
  for (int b = 0; b < nb; ++b) compression[b] = 2.0 * lambda[b] * s.Length(s.bars[b]);
  out.state = StateAt(m, x, compression, loads);
  Residual(m, map, x, lambda, loads, r, g);
  out.residual = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
  for (int k = 0; k < s.num_strings(); ++k) out.slack_strings += out.state.string_tension[k] == 0.0;
  return out;
}

StaticResult StaticSeries::Solve(const Eigen::Matrix3Xd& loads) {
  StaticResult r = last_ ? SolveStatic(model_, *last_, last_loads_, loads, nullptr, &workspace_)
                         : SolveStatic(model_, start_, start_loads_, loads, tangent_, &workspace_);
  if (r.converged) {
    last_ = r.state;
    last_loads_ = loads;
  } else {
    last_.reset();
  }
  return r;
}

}  // namespace tbridge
