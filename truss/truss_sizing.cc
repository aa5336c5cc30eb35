#include "truss/truss_sizing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

#include "core/error.h"
#include "optim/solvers.h"
#include "truss/truss_nonlinear.h"

namespace tbridge {

const char* TrussRowName(TrussRowKind kind) {
  switch (kind) {
    case TrussRowKind::kTension:
      return "tension";
    case TrussRowKind::kCompression:
      return "compression";
    case TrussRowKind::kBuckling:
      return "buckling";
    case TrussRowKind::kTaut:
      return "taut";
    case TrussRowKind::kNoTension:
      return "no_tension";
    case TrussRowKind::kDisplacement:
      return "displacement";
    case TrussRowKind::kFrequency:
      return "frequency";
  }
  return "tension";
}

namespace {

constexpr double kPi = std::numbers::pi;
// The certificate's tolerance on stationarity, feasibility and complementarity: the rows are
// utilisations' complements, so 1e-6 is a millionth of a member's resistance.
constexpr double kCertificateTolerance = 1e-6;
// Ipopt's iterations from each start of a non-convex program (it converges in 50 on the 10-bar
// displacement problem).
constexpr int kSecondOpinionIterations = 500;
// A row is active in the certificate within this of its bound (as the bridge's sizing takes it).
constexpr double kActiveRow = 1e-4;

// The member rows its kind poses in one case.
void AddMemberRows(const TrussModel& m, int c, int e, std::vector<TrussRow>& rows) {
  const TrussGroup& g = m.groups[static_cast<size_t>(m.members[static_cast<size_t>(e)].group)];
  const auto add = [&](TrussRowKind k) { rows.push_back({k, c, e, 1, 0}); };
  if (g.kind != TrussKind::kBar) add(TrussRowKind::kTension);
  if (g.kind != TrussKind::kString) add(TrussRowKind::kCompression);
  if (g.euler && g.kind != TrussKind::kString) add(TrussRowKind::kBuckling);
  if (g.kind == TrussKind::kString) add(TrussRowKind::kTaut);
  if (g.kind == TrussKind::kBar) add(TrussRowKind::kNoTension);
}

// A member row's value and its derivative in the group areas, from the member's force N and
// dN/dA (a row of `dforces`), at its area A.
double MemberRow(const TrussModel& m, const TrussRow& row, double force, double area,
                 const Eigen::RowVectorXd& dforce, Eigen::RowVectorXd* grad) {
  const TrussMember& e = m.members[static_cast<size_t>(row.index)];
  const TrussGroup& g = m.groups[static_cast<size_t>(e.group)];
  // Each row is s N / A^p (+ 1 where it is a utilisation's complement).
  double s = 0, constant = 0;
  int p = 1;
  switch (row.kind) {
    case TrussRowKind::kTension:
      s = -1 / g.allowed_tension, constant = 1;
      break;
    case TrussRowKind::kCompression:
      s = 1 / g.allowed_compression, constant = 1;
      break;
    case TrussRowKind::kBuckling:  // the Euler load is P_E(1) A^2 (TrussModel::EulerLoad)
      s = m.buckling_factor / m.EulerLoad(row.index, 1.0), constant = 1, p = 2;
      break;
    case TrussRowKind::kTaut:
      s = 1 / g.allowed_tension;
      break;
    default:  // kNoTension
      s = -1 / g.allowed_compression;
      break;
  }
  const double ap = std::pow(area, p);
  if (grad != nullptr) {
    *grad = s * dforce / ap;
    (*grad)[e.group] -= p * s * force / (ap * area);
  }
  return constant + s * force / ap;
}

// The modes the frequency rows read: each limit's and the following ones', where there are.
int ModesAsked(const TrussModel& m) {
  const int limits = static_cast<int>(m.min_frequencies_hz.size());
  return limits == 0 ? 0 : std::min(limits + kTrussFollowingModes, m.num_free);
}

double OmegaSquared(double hz) { return std::pow(2 * kPi * hz, 2); }

}  // namespace

std::vector<TrussRow> TrussRows(const TrussModel& m) {
  std::vector<TrussRow> rows;
  for (int c = 0; c < static_cast<int>(m.cases.size()); ++c) {
    for (int e = 0; e < m.num_members(); ++e) AddMemberRows(m, c, e, rows);
    for (int d = 0; d < static_cast<int>(m.displacement_limits.size()); ++d) {
      rows.push_back({TrussRowKind::kDisplacement, c, d, 1, 0});
      rows.push_back({TrussRowKind::kDisplacement, c, d, -1, 0});
    }
  }
  for (int k = 0; k < static_cast<int>(m.min_frequencies_hz.size()); ++k) {
    for (int j = k; j <= k + kTrussFollowingModes && j < ModesAsked(m); ++j) {
      rows.push_back({TrussRowKind::kFrequency, -1, k, 1, j});
    }
  }
  return rows;
}

Eigen::VectorXd TrussRowValues(const TrussModel& m, const std::vector<TrussRow>& rows,
                               const Eigen::VectorXd& variables, Eigen::MatrixXd* jacobian) {
  const bool grad = jacobian != nullptr;
  const Eigen::VectorXd areas = m.MemberAreas(variables), prestress = m.Prestress(variables);
  // The linear analysis where it is read: the linear statics, or the modes. The nonlinear
  // statics factorise their own tangents (the first of them this one).
  std::optional<TrussAnalysis> analysis;
  if (m.analysis == TrussAnalysisKind::kLinear || ModesAsked(m) > 0)
    analysis.emplace(m, areas, prestress);
  const std::vector<TrussCaseResponse> responses =
      SolveTrussCases(m, analysis ? &*analysis : nullptr, areas, prestress, grad);
  TrussModes modes;
  if (ModesAsked(m) > 0) modes = analysis->Modes(ModesAsked(m), grad);
  const int nv = m.num_variables();
  Eigen::VectorXd g(static_cast<int>(rows.size()));
  if (grad) jacobian->setZero(static_cast<int>(rows.size()), nv);
  Eigen::RowVectorXd row_grad(nv);
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const TrussRow& row = rows[static_cast<size_t>(r)];
    row_grad.setZero();
    if (row.kind == TrussRowKind::kFrequency) {
      const double target = OmegaSquared(m.min_frequencies_hz[static_cast<size_t>(row.index)]);
      const bool exists = row.mode < modes.eigenvalues.size();
      g[r] = exists ? modes.eigenvalues[row.mode] / target - 1
                    : std::numeric_limits<double>::infinity();
      if (grad && exists) row_grad = modes.deigenvalues.row(row.mode) / target;
    } else if (row.kind == TrussRowKind::kDisplacement) {
      const TrussCaseResponse& res = responses[static_cast<size_t>(row.load_case)];
      const TrussDisplacementLimit& d = m.displacement_limits[static_cast<size_t>(row.index)];
      g[r] = 1 - row.sign * res.u[d.dof] / d.max;
      if (grad) row_grad = -row.sign * res.du.row(d.dof) / d.max;
    } else {
      const TrussCaseResponse& res = responses[static_cast<size_t>(row.load_case)];
      const double area = variables[m.members[static_cast<size_t>(row.index)].group];
      const Eigen::RowVectorXd dforce =
          grad ? Eigen::RowVectorXd(res.dforces.row(row.index)) : row_grad;
      g[r] = MemberRow(m, row, res.forces[row.index], area, dforce, grad ? &row_grad : nullptr);
    }
    if (grad) jacobian->row(r) = row_grad;
  }
  return g;
}

namespace {

// The largest magnitude of the entries of v, or 1 where all are 0.
double Largest(const Eigen::VectorXd& v) {
  const double big = v.size() ? v.cwiseAbs().maxCoeff() : 0.0;
  return big > 0 ? big : 1.0;
}

// The program in the variables x_v = v / ref_v, the mass over the start's: each area over the
// start's, every self-stress amplitude over the start's largest (an amplitude may start at 0 or
// below). The solvers' tolerances then read alike on every structure.
class TrussProblem : public NlpProblem {
 public:
  TrussProblem(const TrussModel& m, std::vector<TrussRow> rows, const Eigen::VectorXd& start)
      : m_(m), rows_(std::move(rows)), ref_(start), mass_ref_(m.Mass(start)) {
    const int np = m_.num_prestress();
    if (np > 0) ref_.tail(np).setConstant(Largest(start.tail(np)));
    start_ = start.cwiseQuotient(ref_);
    for (int r = 0; r < num_constraints(); ++r) {
      for (int g = 0; g < num_variables(); ++g) pattern_.emplace_back(r, g);
    }
  }
  int num_variables() const override { return m_.num_variables(); }
  int num_constraints() const override { return static_cast<int>(rows_.size()); }
  void VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    lo = Eigen::VectorXd::Constant(num_variables(), -kInf);
    hi = Eigen::VectorXd::Constant(num_variables(), kInf);
    for (int g = 0; g < m_.num_groups(); ++g) {
      lo[g] = m_.groups[static_cast<size_t>(g)].min_area / ref_[g];
      hi[g] = m_.groups[static_cast<size_t>(g)].max_area / ref_[g];
    }
  }
  void ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override {
    lo = Eigen::VectorXd::Zero(num_constraints());
    hi = Eigen::VectorXd::Constant(num_constraints(), std::numeric_limits<double>::infinity());
  }
  double Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const override {
    return m_.Mass(x.cwiseProduct(ref_)) / mass_ref_;
  }
  void ObjectiveGradient(const Eigen::Ref<const Eigen::VectorXd>& x,
                         Eigen::Ref<Eigen::VectorXd> grad) const override {
    (void)x;
    grad.setZero();  // a prestress weighs nothing
    for (int g = 0; g < m_.num_groups(); ++g) {
      grad[g] = m_.density * m_.groups[static_cast<size_t>(g)].length_sum * ref_[g] / mass_ref_;
    }
  }
  void Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                   Eigen::Ref<Eigen::VectorXd> g) const override {
    Evaluate(x);
    g = g_;
  }
  const Pattern& JacobianPattern() const override { return pattern_; }
  void JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double* values) const override {
    Evaluate(x);
    for (size_t k = 0; k < pattern_.size(); ++k)
      values[k] = jac_(pattern_[k].first, pattern_[k].second);
  }
  bool DenseJacobian(const Eigen::Ref<const Eigen::VectorXd>& x,
                     Eigen::MatrixXd& jac) const override {
    Evaluate(x);
    jac = jac_;
    return true;
  }
  const Pattern& HessianPattern() const override { return no_hessian_; }  // Ipopt: L-BFGS
  void HessianValues(const Eigen::Ref<const Eigen::VectorXd>&, double, const double*,
                     double*) const override {}

  // The sizing's variables (TrussModel::num_variables) at x.
  Eigen::VectorXd Variables(const Eigen::VectorXd& x) const { return x.cwiseProduct(ref_); }
  // The start in x.
  const Eigen::VectorXd& Start() const { return start_; }

 private:
  // The rows and their Jacobian in x at x, kept for the next call at the same point.
  void Evaluate(const Eigen::Ref<const Eigen::VectorXd>& x) const {
    if (x_.size() == x.size() && x_ == x) return;
    Eigen::MatrixXd jac_a;
    g_ = TrussRowValues(m_, rows_, x.cwiseProduct(ref_), &jac_a);
    jac_ = jac_a * ref_.asDiagonal();
    x_ = x;
  }

  const TrussModel& m_;
  std::vector<TrussRow> rows_;
  Eigen::VectorXd ref_, start_;
  double mass_ref_;
  Pattern pattern_, no_hessian_;
  mutable Eigen::VectorXd x_, g_;
  mutable Eigen::MatrixXd jac_;
};

Eigen::VectorXd Clamped(const TrussModel& m, double area) {
  Eigen::VectorXd a(m.num_groups());
  for (int g = 0; g < m.num_groups(); ++g) {
    a[g] = std::clamp(area, m.groups[static_cast<size_t>(g)].min_area,
                      m.groups[static_cast<size_t>(g)].max_area);
  }
  return a;
}

// The sizing's variables: the group areas, then the self-stress amplitudes.
Eigen::VectorXd Variables(const Eigen::VectorXd& areas, const Eigen::VectorXd& amplitudes) {
  Eigen::VectorXd v(areas.size() + amplitudes.size());
  v << areas, amplitudes;
  return v;
}

// The self-stress amplitudes nearest to strings in tension and bars in compression (the
// least-squares projection of those signs on the orthonormal states), scaled to a largest
// member force of 1 N; empty without prestress.
Eigen::VectorXd PrestressDirection(const TrussModel& m) {
  Eigen::VectorXd signs = Eigen::VectorXd::Zero(m.num_members());
  for (int e = 0; e < m.num_members(); ++e) {
    const TrussKind kind =
        m.groups[static_cast<size_t>(m.members[static_cast<size_t>(e)].group)].kind;
    signs[e] = kind == TrussKind::kString ? 1.0 : kind == TrussKind::kBar ? -1.0 : 0.0;
  }
  const Eigen::VectorXd amplitudes = m.self_stress.transpose() * signs;
  return amplitudes / Largest(m.self_stress * amplitudes);
}

// The rows' worst at a start: the largest utilisation of a strength or displacement row, and
// whether a frequency row or a sign row (taut, no tension) fails.
struct StartShortfall {
  double strength = 0, displacement = 0;
  bool frequency = false, sign = false;
};

StartShortfall ShortfallOf(const std::vector<TrussRow>& rows, const Eigen::VectorXd& g) {
  StartShortfall s;
  for (int r = 0; r < g.size(); ++r) {
    switch (rows[static_cast<size_t>(r)].kind) {
      case TrussRowKind::kFrequency:
        s.frequency = s.frequency || g[r] < 0;
        break;
      case TrussRowKind::kTaut:
      case TrussRowKind::kNoTension:
        s.sign = s.sign || g[r] < 0;
        break;
      case TrussRowKind::kDisplacement:
        s.displacement = std::max(s.displacement, 1 - g[r]);
        break;
      default:
        s.strength = std::max(s.strength, 1 - g[r]);
    }
  }
  return s;
}

// One area for every group, raised until every row holds: a stress or displacement row's
// utilisation falls as 1 / area without self-weight (so one scaling nearly does it), a
// frequency's rises with the stiffness over the mass. A prestress, where it is variable, starts
// at the largest load and is raised where a string goes slack or a mechanism's displacement
// is too large (its stiffness is the prestress's). A few dozen analyses at most.
Eigen::VectorXd UniformStart(const TrussModel& m, const std::vector<TrussRow>& rows) {
  double area = 0;
  for (const TrussGroup& g : m.groups) area = std::max(area, g.min_area);
  const Eigen::VectorXd direction = PrestressDirection(m);
  double level = 1;  // [N]
  for (const TrussCase& c : m.cases) level = std::max(level, Largest(c.loads));
  for (int k = 0; k < 60; ++k) {
    Eigen::VectorXd g;
    try {
      g = TrussRowValues(m, rows, Variables(Clamped(m, area), level * direction), nullptr);
    } catch (const ModelError&) {
      if (m.num_prestress() == 0) throw;
      level *= 2;  // a mechanism the prestress does not yet stiffen enough
      continue;
    }
    const StartShortfall s = ShortfallOf(rows, g);
    const double worst = std::max(s.strength, s.displacement);
    if (worst <= 1 && !s.frequency && !s.sign) break;
    area *= std::max({worst * 1.01, s.frequency ? 1.5 : 1.0, 1.0});
    if (m.num_prestress() > 0) {
      level *= std::max({s.sign ? 2.0 : 1.0, s.displacement > 1 ? s.displacement * 1.01 : 1.0});
    }
  }
  return Variables(Clamped(m, area), level * direction);
}

// `start` with its group areas replaced by `areas`.
Eigen::VectorXd WithAreas(const Eigen::VectorXd& start, const Eigen::VectorXd& areas) {
  Eigen::VectorXd v = start;
  v.head(areas.size()) = areas;
  return v;
}

// The fully stressed design (each group's area scaled by its members' largest stress or buckling
// utilisation, ten times), then scaled as one until every displacement limit holds: the
// classic start of a stress-governed truss, in another basin than a uniform one where a
// displacement limit meets stress limits of small members.
Eigen::VectorXd FullyStressedStart(const TrussModel& m, const std::vector<TrussRow>& rows,
                                   const Eigen::VectorXd& uniform) {
  Eigen::VectorXd a = uniform;
  for (int k = 0; k < 10; ++k) {
    const Eigen::VectorXd g = TrussRowValues(m, rows, a, nullptr);
    Eigen::VectorXd use = Eigen::VectorXd::Zero(m.num_groups());
    for (int r = 0; r < g.size(); ++r) {
      const TrussRow& row = rows[static_cast<size_t>(r)];
      const bool strength = row.kind == TrussRowKind::kTension ||
                            row.kind == TrussRowKind::kCompression ||
                            row.kind == TrussRowKind::kBuckling;
      if (strength) {
        const int group = m.members[static_cast<size_t>(row.index)].group;
        use[group] = std::max(use[group], 1 - g[r]);
      }
    }
    for (int gi = 0; gi < m.num_groups(); ++gi) {
      const TrussGroup& group = m.groups[static_cast<size_t>(gi)];
      a[gi] = std::clamp(a[gi] * use[gi], group.min_area, group.max_area);
    }
  }
  for (int k = 0; k < 20; ++k) {
    const double worst = ShortfallOf(rows, TrussRowValues(m, rows, a, nullptr)).displacement;
    if (worst <= 1) break;
    for (int gi = 0; gi < m.num_groups(); ++gi)
      a[gi] = std::min(a[gi] * worst * 1.01, m.groups[static_cast<size_t>(gi)].max_area);
  }
  return a;
}

std::string Format(const char* format, double v) {
  char text[256];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

// The certificate of x on `problem`: every row within kActiveRow of its bound is active.
// The active rows' Jacobian at y.
void ActiveRows(const TrussProblem& problem, const std::vector<int>& active,
                const Eigen::VectorXd& y, Eigen::MatrixXd& out) {
  Eigen::MatrixXd all;
  problem.DenseJacobian(y, all);
  out.resize(static_cast<int>(active.size()), all.cols());
  for (size_t k = 0; k < active.size(); ++k) out.row(static_cast<int>(k)) = all.row(active[k]);
}

// The certificate's input at x on `problem`, without the second-order hook: every row within
// kActiveRow of its bound is active.
KktInput CertificateInput(const TrussProblem& problem, const Eigen::VectorXd& x) {
  KktInput in;
  const int n = problem.num_variables(), rows = problem.num_constraints();
  in.x = x;
  problem.VariableBounds(in.lo_x, in.hi_x);
  in.grad_f.resize(n);
  problem.ObjectiveGradient(x, in.grad_f);
  Eigen::VectorXd g(rows);
  problem.Constraints(x, g);
  in.slack = g;
  for (int r = 0; r < rows; ++r) {
    if (g[r] <= kActiveRow) in.active.push_back(r);
  }
  ActiveRows(problem, in.active, x, in.jac_active);
  return in;
}

// The certificate of x on `problem` (optim/kkt_certificate.h).
KktCertificate Certify(const TrussProblem& problem, const Eigen::VectorXd& x) {
  KktInput in = CertificateInput(problem, x);
  const int n = problem.num_variables();
  const std::vector<int> active = in.active;
  in.at = [&problem, &active, n](const Eigen::VectorXd& y, Eigen::VectorXd& grad,
                                 Eigen::MatrixXd& jac) {
    grad.resize(n);
    problem.ObjectiveGradient(y, grad);
    ActiveRows(problem, active, y, jac);
  };
  return CertifyLocalOptimum(in, kCertificateTolerance);
}

struct Attempt {
  Eigen::VectorXd variables;  // the group areas, then the self-stress amplitudes
  SolverOutcome outcome;
  KktCertificate kkt;
  double mass = 0;
  std::string start;
  bool feasible() const { return kkt.feasibility <= kCertificateTolerance; }
};

// Whether a is the better design to keep: feasible first, then proved, then lighter.
bool Better(const Attempt& a, const Attempt& b) {
  if (a.feasible() != b.feasible()) return a.feasible();
  if (!a.feasible()) return a.kkt.feasibility < b.kkt.feasibility;
  if (a.kkt.proved_local_optimum != b.kkt.proved_local_optimum) return a.kkt.proved_local_optimum;
  return a.mass < b.mass;
}

Attempt Solve(const TrussModel& m, const std::vector<TrussRow>& rows, const Eigen::VectorXd& start,
              SolverKind solver, const SolverOptions& options, const std::string& label) {
  const TrussProblem problem(m, rows, start);
  Eigen::VectorXd x = problem.Start();
  Attempt a;
  a.start = label;
  try {
    a.outcome = SolveNlp(solver, problem, options, x);
  } catch (const ModelError& e) {  // an iterate that made the structure a mechanism
    a.outcome.solver = solver;
    a.outcome.status = "MODEL_ERROR";
    a.outcome.message = e.what();
    x = problem.Start();
  }
  a.variables = problem.Variables(x);
  a.mass = m.Mass(a.variables);
  a.kkt = Certify(problem, x);
  return a;
}

// Two modes a < b that meet (equal to 1e-6) at frequency limit k's bound.
struct MeetingModes {
  int limit = 0, a = 0, b = 0;
};

std::vector<MeetingModes> MeetingModesOf(const TrussModel& m, const TrussModes& modes) {
  std::vector<MeetingModes> out;
  for (int k = 0; k < static_cast<int>(m.min_frequencies_hz.size()); ++k) {
    const double target = OmegaSquared(m.min_frequencies_hz[static_cast<size_t>(k)]);
    for (int j = k; j + 1 < modes.eigenvalues.size(); ++j) {
      const double a = modes.eigenvalues[j], b = modes.eigenvalues[j + 1];
      if (std::abs(a / target - 1) < 1e-6 && std::abs(b / a - 1) < 1e-6)
        out.push_back({k, j, j + 1});
    }
  }
  return out;
}

// The position in `active` of the frequency row of limit k and mode j.
int ActivePosition(const std::vector<TrussRow>& rows, const std::vector<int>& active, int k,
                   int j) {
  for (size_t p = 0; p < active.size(); ++p) {
    const TrussRow& r = rows[static_cast<size_t>(active[p])];
    if (r.kind == TrussRowKind::kFrequency && r.index == k && r.mode == j)
      return static_cast<int>(p);
  }
  return -1;
}

// Where a frequency limit binds at two modes that meet, the k-th eigenvalue has no derivative,
// only directional ones: the eigenvalues of the pair's 2 x 2 matrix D_ab = phi_a^T (dK - omega^2
// dM) phi_b. The first-order condition there (Overton 1992) asks multipliers [[a, c], [c, b]]
// positive semidefinite on D's entries: the rows of both modes carry a and b, the off-diagonal
// entry 2 D_ab (either sign) carries c. Certified so; the second-order test does not apply.
// Returns the certificate and, in `note`, what it says; `note` stays "" where no modes meet.
KktCertificate CertifyMeetingModes(const TrussModel& m, const std::vector<TrussRow>& rows,
                                   const Eigen::VectorXd& variables, std::string& note) {
  note.clear();
  KktCertificate c;
  if (m.min_frequencies_hz.empty()) return c;
  const TrussAnalysis analysis(m, m.MemberAreas(variables), m.Prestress(variables));
  const TrussModes modes = analysis.Modes(ModesAsked(m), true);
  const std::vector<MeetingModes> pairs = MeetingModesOf(m, modes);
  if (pairs.empty()) return c;
  const TrussProblem problem(m, rows, variables);
  KktInput in = CertificateInput(problem, problem.Start());
  const Eigen::VectorXd scale =
      problem.Variables(Eigen::VectorXd::Ones(variables.size()));  // dv/dx
  for (const MeetingModes& p : pairs) {
    const double target = OmegaSquared(m.min_frequencies_hz[static_cast<size_t>(p.limit)]);
    const Eigen::VectorXd cross =
        2 * analysis.ModeCoupling(modes, p.a, p.b).cwiseProduct(scale) / target;
    for (const double sign : {1.0, -1.0}) {
      in.slack.conservativeResize(in.slack.size() + 1);
      in.slack[in.slack.size() - 1] = 0;
      in.active.push_back(static_cast<int>(in.slack.size()) - 1);
      in.jac_active.conservativeResize(in.jac_active.rows() + 1, Eigen::NoChange);
      in.jac_active.row(in.jac_active.rows() - 1) = sign * cross.transpose();
    }
  }
  c = CertifyLocalOptimum(in, kCertificateTolerance);
  bool semidefinite = true;
  const int first_extra = static_cast<int>(in.active.size()) - 2 * static_cast<int>(pairs.size());
  for (size_t q = 0; q < pairs.size(); ++q) {
    const int pa = ActivePosition(rows, in.active, pairs[q].limit, pairs[q].a);
    const int pb = ActivePosition(rows, in.active, pairs[q].limit, pairs[q].b);
    const double la = pa < 0 ? 0.0 : c.multipliers[pa], lb = pb < 0 ? 0.0 : c.multipliers[pb];
    const int plus = first_extra + 2 * static_cast<int>(q);
    const double lc = c.multipliers[plus] - c.multipliers[plus + 1];
    // Round-off of the multipliers' least squares: 1e-9 of the larger diagonal's square.
    semidefinite = semidefinite && la * lb - lc * lc >= -1e-9 * std::pow(std::max(la, lb), 2);
    note += Format("modes %g and ", pairs[q].a + 1) + Format("%g meet at ", pairs[q].b + 1) +
            Format("f%g", pairs[q].limit + 1) +
            Format(" = %.6g Hz", std::sqrt(modes.eigenvalues[pairs[q].a]) / (2 * kPi)) +
            Format(" (multipliers a = %.3g, ", la) + Format("b = %.3g, ", lb) +
            Format("c = %.3g); ", lc);
  }
  const bool first_order = c.stationarity <= kCertificateTolerance &&
                           c.feasibility <= kCertificateTolerance &&
                           c.complementarity <= kCertificateTolerance;
  note += first_order && semidefinite
              ? "the first-order conditions of a double eigenvalue hold (the pair's multipliers "
                "positive "
                "semidefinite, Overton 1992); the second-order test does not apply there"
              : "the first-order conditions of a double eigenvalue fail: " +
                    (semidefinite
                         ? c.failed
                         : std::string("the pair's multipliers are not positive semidefinite"));
  return c;
}

// The kind a row's or a bound's mass is booked to (TrussMassAttribution).
const char* AttributionKind(TrussRowKind kind) {
  switch (kind) {
    case TrussRowKind::kTension:
    case TrussRowKind::kCompression:
      return "strength";
    case TrussRowKind::kBuckling:
      return "buckling";
    case TrussRowKind::kTaut:
      return "taut_strings";
    case TrussRowKind::kNoTension:
      return "bars_in_compression";
    case TrussRowKind::kDisplacement:
      return "displacement";
    case TrussRowKind::kFrequency:
      return "frequency";
  }
  return "strength";
}

TrussMassAttribution AttributeMass(const TrussModel& m, const std::vector<TrussRow>& rows,
                                   const Eigen::VectorXd& variables) {
  const TrussProblem problem(m, rows, variables);  // x = 1 on the areas
  const Eigen::VectorXd x = problem.Start();
  const KktInput in = CertificateInput(problem, x);
  const KktCertificate c = CertifyLocalOptimum(in, kCertificateTolerance);  // first order only
  TrussMassAttribution out;
  out.structure_kg = m.Mass(variables);
  out.stationarity_residual = c.stationarity;
  out.active_rows = c.active_rows;
  const char* kinds[] = {"strength",     "buckling",  "taut_strings",  "bars_in_compression",
                         "displacement", "frequency", "minimum_sizes", "maximum_sizes"};
  for (const char* k : kinds) out.by_constraint_kg.emplace_back(k, 0.0);
  const auto book = [&out](const std::string& kind, double share) {
    for (auto& [name, kg] : out.by_constraint_kg) {
      if (name == kind) kg += share;
    }
  };
  // f(x) = mass / mass(variables) is 1 here: each term times the mass is its kilograms.
  for (size_t p = 0; p < in.active.size(); ++p) {
    const double share = c.multipliers[static_cast<int>(p)] *
                         in.jac_active.row(static_cast<int>(p)).dot(x) * out.structure_kg;
    book(AttributionKind(rows[static_cast<size_t>(in.active[p])].kind), share);
  }
  for (int v = 0; v < x.size(); ++v) {
    const double mu = c.bound_multipliers[v];
    if (mu != 0) book(mu > 0 ? "minimum_sizes" : "maximum_sizes", mu * x[v] * out.structure_kg);
  }
  return out;
}

}  // namespace

TrussSizing SizeTruss(const TrussModel& m, SolverKind solver, double tolerance,
                      int max_iterations) {
  const std::vector<TrussRow> rows = TrussRows(m);
  SolverOptions options;
  options.tolerance = tolerance;
  options.max_iterations = max_iterations;
  options.acceptable = false;
  const Eigen::VectorXd uniform = UniformStart(m, rows);
  // Stress rows alone make a program whose optimum one start finds; displacement and frequency
  // rows make it non-convex (several local optima; a mode's order changes with the areas), and
  // so does a prestress (the forces move with the areas through its geometric stiffness): more
  // starts, the same rule.
  std::vector<std::pair<std::string, Eigen::VectorXd>> starts{{"uniform", uniform}};
  if (ModesAsked(m) > 0 || !m.displacement_limits.empty() || m.num_prestress() > 0) {
    const double area = uniform.head(m.num_groups()).maxCoeff();
    starts.emplace_back("uniform x 2", WithAreas(uniform, Clamped(m, 2 * area)));
    starts.emplace_back("uniform x 0.5", WithAreas(uniform, Clamped(m, 0.5 * area)));
  }
  if (!m.displacement_limits.empty() && !m.cases.empty()) {
    starts.emplace_back("fully stressed", FullyStressedStart(m, rows, uniform));
  }
  // "auto": the verified sizing's SQP, and Ipopt where the SQP's point is not proved optimal
  // (from that point), or from every start of a non-convex program: the two reach different
  // local optima there (the 10-bar displacement problem: the SQP 5076.67 lb from every start,
  // Ipopt the published 5060.85 lb from two of four, each proved).
  const bool ipopt = solver == SolverKind::kAuto && SolverBuiltIn(SolverKind::kIpopt);
  const bool non_convex = starts.size() > 1;
  const SolverKind first = solver == SolverKind::kAuto ? SolverKind::kSqp : solver;
  TrussSizing out;
  Attempt best;
  bool any = false;
  const auto record = [&out](const Attempt& a) {
    out.tries.push_back(a.start + ": " + NameOf(a.outcome.solver) + " " + a.outcome.status +
                        Format(", %.6g kg, ", a.mass) +
                        (a.kkt.proved_local_optimum ? "proved" : "not proved: " + a.kkt.failed));
  };
  for (const auto& [label, start] : starts) {
    Attempt a = Solve(m, rows, start, first, options, label);
    record(a);
    if (ipopt && (non_convex || !a.kkt.proved_local_optimum)) {
      const bool from_sqp = !non_convex && a.feasible();
      // A start's second opinion need not run to the solver's limit: where Ipopt has not
      // converged in kSecondOpinionIterations (the 10-bar frequency problem's meeting modes:
      // 3000 iterations, 10 s), the SQP's point stands.
      SolverOptions second = options;
      if (non_convex)
        second.max_iterations = std::min(options.max_iterations, kSecondOpinionIterations);
      Attempt b = Solve(m, rows, from_sqp ? a.variables : start, SolverKind::kIpopt, second,
                        label + (from_sqp ? ", then ipopt" : ", ipopt"));
      record(b);
      if (Better(b, a)) a = std::move(b);
    }
    if (!any || Better(a, best)) best = std::move(a);
    any = true;
  }
  if (!best.kkt.proved_local_optimum) {
    std::string note;
    const KktCertificate meeting = CertifyMeetingModes(m, rows, best.variables, note);
    if (!note.empty()) {  // the certificate where modes meet replaces the smooth one's
      best.kkt = meeting;
      best.kkt.proved_local_optimum = false;
      best.kkt.failed = note;
    }
  }
  out.group_areas = best.variables.head(m.num_groups());
  out.prestress = m.Prestress(best.variables);
  out.outcome = best.outcome;
  out.kkt = best.kkt;
  out.start = best.start;
  out.attribution = AttributeMass(m, rows, best.variables);
  return out;
}

}  // namespace tbridge
