#include "dynamics/classk.h"

#include <cholmod.h>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <utility>

#include "core/error.h"

namespace tbridge {

namespace {

constexpr const char* kEngine = "class-k dynamics";

std::string NodeName(int node) { return std::to_string(node + 1); }

// One place where a constraint row meets a bar's copy (used only while building A's pattern):
// a bar row (d < 0) is s b on the copy, s = -1 at end i and +1 at end j; a coincidence row is
// s e_d.
struct Touch {
  int row, end, d;
  double sign;
};

// An entry of A (used only while building A's pattern): its constant part and its bars'
// terms, each a coefficient of b_d, or of |b|^2 for d = -1.
struct Entry {
  double constant = 0;
  std::map<std::pair<int, int>, double> bar_terms;  // (bar, d) -> coef
};

// Fill-reducing order (AMD) of A's pattern `entries` ((row, col), row <= col, natural order),
// computed once: new_row[r] is the row of A that natural row r takes.
std::vector<int> FillReducingOrder(int n_rows,
                                   const std::map<std::pair<int, int>, Entry>& entries) {
  const int nnz = static_cast<int>(entries.size());
  std::vector<int> new_row(n_rows);
  for (int r = 0; r < n_rows; ++r) new_row[r] = r;
  if (n_rows > 1) {
    cholmod_common c;
    cholmod_start(&c);
    c.print = 0;
    cholmod_sparse* pattern =
        cholmod_allocate_sparse(n_rows, n_rows, nnz, 1, 1, 1, CHOLMOD_PATTERN, &c);
    if (pattern == nullptr) {
      cholmod_finish(&c);
      throw ModelError(std::string(kEngine) +
                       ": CHOLMOD could not allocate the constraint pattern");
    }
    std::vector<std::vector<int>> by_col(n_rows);
    for (const auto& [rc, e] : entries) by_col[rc.second].push_back(rc.first);
    int* cp = static_cast<int*>(pattern->p);
    int* ri = static_cast<int*>(pattern->i);
    cp[0] = 0;
    for (int col = 0; col < n_rows; ++col) {
      int at = cp[col];
      for (const int row : by_col[col]) ri[at++] = row;
      cp[col + 1] = at;
    }
    std::vector<int> perm(n_rows);
    const int ok = cholmod_amd(pattern, nullptr, 0, perm.data(), &c);
    cholmod_free_sparse(&pattern, &c);
    cholmod_finish(&c);
    if (!ok)
      throw ModelError(std::string(kEngine) + ": CHOLMOD could not order the constraint matrix");
    for (int k = 0; k < n_rows; ++k) new_row[perm[k]] = k;
  }
  return new_row;
}

}  // namespace

// CHOLMOD's state for one workspace. A holds the upper triangle (stype +1) in the system's
// fill-reducing row order, so the factorisation runs in natural order: with a permutation or
// a lower triangle, cholmod_factorize would build a transposed copy of A on every call. The
// triangular solves are done here on the simplicial LDL^T factor, because cholmod_solve2
// (SuiteSparse 5) allocates twice per call even with its reusable workspaces.
struct ClassKWorkspace::Solver {
  cholmod_common common;
  cholmod_sparse* a = nullptr;
  cholmod_factor* factor = nullptr;

  Solver() {
    cholmod_start(&common);
    common.print = 0;
  }
  ~Solver() {
    cholmod_free_factor(&factor, &common);
    cholmod_free_sparse(&a, &common);
    cholmod_finish(&common);
  }
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  // x := A^-1 x with A = L D L^T (unit L below the diagonal, D on it), natural order.
  // CAUTION: performance-sensitive
  void Solve(double* x) const {
    const int n = static_cast<int>(factor->n);
    const int* lp = static_cast<const int*>(factor->p);
    const int* li = static_cast<const int*>(factor->i);
    const int* lnz = static_cast<const int*>(factor->nz);
    const double* lx = static_cast<const double*>(factor->x);
    for (int j = 0; j < n; ++j) {
      const double xj = x[j];
      for (int p = lp[j] + 1; p < lp[j] + lnz[j]; ++p) x[li[p]] -= lx[p] * xj;
    }
    for (int j = 0; j < n; ++j) x[j] /= lx[lp[j]];
    for (int j = n - 1; j >= 0; --j) {
      double xj = x[j];
      for (int p = lp[j] + 1; p < lp[j] + lnz[j]; ++p) xj -= lx[p] * x[li[p]];
      x[j] = xj;
    }
  }
};

// Bars and their copies; node_copies[a] takes node a's copies, its primary first.
void ClassKSystem::PackBars(const DynamicModel& model, std::vector<std::vector<int>>& node_copies) {
  for (size_t k = 0; k < model.bars.size(); ++k) {
    const DynamicBar& b = model.bars[k];
    const std::string name = "bar " + NodeName(b.i) + "-" + NodeName(b.j);
    const bool free_i = !model.fixed[b.i], free_j = !model.fixed[b.j];
    if (!free_i && !free_j) continue;
    PackedBar p{};
    p.oi = b.i * dim_;
    p.oj = b.j * dim_;
    p.rest_sq = b.length * b.length;
    p.model_index = static_cast<int>(k);
    const int bar = static_cast<int>(bars_.size());
    auto add_copy = [&](int node, int end, bool& primary) {
      const int copy = static_cast<int>(copies_.size());
      copies_.push_back({bar, end, node * dim_});
      primary = node_copies[node].empty();
      if (primary) primary_copy_[node] = copy;
      node_copies[node].push_back(copy);
      return copy;
    };
    p.ci = free_i ? add_copy(b.i, 0, p.fi) : -1;
    p.cj = free_j ? add_copy(b.j, 1, p.fj) : -1;
    const double m00 = free_i ? b.mass / 3.0 + (p.fi ? NodeMass(b.i) : 0.0) : 0.0;
    const double m11 = free_j ? b.mass / 3.0 + (p.fj ? NodeMass(b.j) : 0.0) : 0.0;
    const double m01 = free_i && free_j ? b.mass / 6.0 : 0.0;
    if (free_i && free_j) {
      const double det = m00 * m11 - m01 * m01;
      if (!(det > 0))
        throw ModelError(std::string(kEngine) + ": " + name +
                         " has a singular mass matrix (no mass)");
      p.a00 = m11 / det;
      p.a11 = m00 / det;
      p.a01 = -m01 / det;
    } else {
      const double m = free_i ? m00 : m11;
      if (!(m > 0))
        throw ModelError(std::string(kEngine) + ": " + name + " has no mass at its free end");
      (free_i ? p.a00 : p.a11) = 1.0 / m;
    }
    p.w = p.a00 + p.a11 - 2.0 * p.a01;
    bars_.push_back(p);
    AddMassBlock(free_i ? p.oi : -1, free_j ? p.oj : -1, m00, m01, m11);
  }
}

ClassKSystem::ClassKSystem(const DynamicModel& model, const ClassKOptions& options,
                           std::vector<TimedLoad> timed_loads)
    : EngineFrame(model, options, timed_loads, kEngine),
      n_model_bars_(static_cast<int>(model.bars.size())) {
  // Bars and their copies. A node's first copy is its primary: it takes the node's mass and
  // force, and the node's acceleration is read from it.
  primary_copy_.assign(n_n_, -1);
  std::vector<std::vector<int>> node_copies(n_n_);
  PackBars(model, node_copies);

  // Constraint rows in their natural order: bar rows, then dim rows per extra copy.
  n_rows_ = static_cast<int>(bars_.size());
  std::vector<std::vector<Touch>> touches(bars_.size());
  for (int k = 0; k < num_bars(); ++k) {
    if (bars_[k].ci >= 0) touches[k].push_back({k, 0, -1, -1.0});
    if (bars_[k].cj >= 0) touches[k].push_back({k, 1, -1, 1.0});
  }
  for (int a = 0; a < n_n_; ++a) {
    for (size_t r = 1; r < node_copies[a].size(); ++r) {
      const Coincidence c{n_rows_, node_copies[a][r], node_copies[a][0], {0, 0, 0}};
      coincidences_.push_back(c);
      for (int d = 0; d < dim_; ++d) {
        touches[copies_[c.copy].bar].push_back({c.row + d, copies_[c.copy].end, d, 1.0});
        touches[copies_[c.primary].bar].push_back({c.row + d, copies_[c.primary].end, d, -1.0});
      }
      n_rows_ += dim_;
    }
  }

  // A = J M^-1 J^T, bar by bar: every ordered pair of touches of a bar adds
  // sign1 sign2 Minv(end1, end2) times |b|^2 (two bar rows), b_d (bar and coincidence row)
  // or 1 (two coincidence rows on the same axis). Kept: the upper triangle.
  std::map<std::pair<int, int>, Entry> entries;  // (row, col), row <= col, natural order
  for (int k = 0; k < num_bars(); ++k) {
    const PackedBar& p = bars_[k];
    const double minv[2][2] = {{p.a00, p.a01}, {p.a01, p.a11}};
    for (const Touch& t1 : touches[k]) {
      for (const Touch& t2 : touches[k]) {
        if (t1.row > t2.row) continue;
        const double coef = t1.sign * t2.sign * minv[t1.end][t2.end];
        Entry& e = entries[{t1.row, t2.row}];
        if (t1.d < 0 && t2.d < 0) {
          e.bar_terms[{k, -1}] += coef;
        } else if (t1.d < 0 || t2.d < 0) {
          e.bar_terms[{k, t1.d < 0 ? t2.d : t1.d}] += coef;
        } else if (t1.d == t2.d) {
          e.constant += coef;
        }  // else a structural zero, kept so the pattern does not depend on the values
      }
    }
  }

  // Fill-reducing order (AMD), computed once on the pattern.
  const std::vector<int> new_row = FillReducingOrder(n_rows_, entries);

  // The permuted upper triangle in compressed columns, with its constant and bar parts.
  std::map<std::pair<int, int>, const Entry*> permuted;  // (col, row) -> entry: CSC order
  for (const auto& [rc, e] : entries) {
    const int r = new_row[rc.first], s = new_row[rc.second];
    permuted[{std::max(r, s), std::min(r, s)}] = &e;
  }
  a_col_.assign(n_rows_ + 1, 0);
  for (const auto& [cr, e] : permuted) {
    const int at = static_cast<int>(a_row_.size());
    ++a_col_[cr.first + 1];
    a_row_.push_back(cr.second);
    a_const_.push_back(e->constant);
    for (const auto& [bd, coef] : e->bar_terms) {
      if (coef != 0) a_bar_.push_back({at, bd.first, bd.second, coef});
    }
  }
  for (int col = 0; col < n_rows_; ++col) a_col_[col + 1] += a_col_[col];
  for (PackedBar& p : bars_) p.row = new_row[&p - bars_.data()];
  for (Coincidence& c : coincidences_) {
    for (int d = 0; d < dim_; ++d) c.rows[d] = new_row[c.row + d];
  }

  std::vector<bool> has_bar(n_n_);
  for (int a = 0; a < n_n_; ++a) has_bar[a] = !node_copies[a].empty();
  AddNodes(model, has_bar);
}

ClassKWorkspace::ClassKWorkspace(const ClassKSystem& system)
    : force(Eigen::VectorXd::Zero(system.coordinates())),
      u(Eigen::VectorXd::Zero(system.dim() * system.num_copies())),
      jt_mu(Eigen::VectorXd::Zero(system.dim() * system.num_copies())),
      b(Eigen::VectorXd::Zero(system.dim() * system.num_bars())),
      bar_length_sq(Eigen::VectorXd::Zero(system.num_bars())),
      mu(Eigen::VectorXd::Zero(system.num_constraints())),
      solver(std::make_unique<Solver>()) {
  const int n = system.num_constraints();
  if (n == 0) return;
  cholmod_common& c = solver->common;
  // Natural order (A is stored permuted), simplicial LDL^T: refactorisation then works in
  // the factor's own storage.
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_NATURAL;
  c.postorder = 0;
  c.supernodal = CHOLMOD_SIMPLICIAL;
  c.final_ll = 0;
  const int nnz = static_cast<int>(system.a_row_.size());
  solver->a = cholmod_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL, &c);
  if (solver->a == nullptr) {
    throw ModelError(std::string(kEngine) + ": CHOLMOD could not allocate the constraint matrix");
  }
  std::memcpy(solver->a->p, system.a_col_.data(), sizeof(int) * system.a_col_.size());
  std::memcpy(solver->a->i, system.a_row_.data(), sizeof(int) * system.a_row_.size());
  solver->factor = cholmod_analyze(solver->a, &c);
  if (solver->factor == nullptr || solver->factor->ordering != CHOLMOD_NATURAL) {
    throw ModelError(std::string(kEngine) + ": CHOLMOD could not analyse the constraint matrix");
  }
  // One evaluation at rest: CHOLMOD allocates the numeric factor and its work arrays.
  const Eigen::VectorXd y = system.RestState();
  Eigen::VectorXd dy(y.size());
  system.Derivative(0.0, y.data(), dy.data(), *this);
  if (solver->factor->is_super || solver->factor->is_ll ||
      solver->factor->ordering != CHOLMOD_NATURAL) {
    throw ModelError(std::string(kEngine) +
                     ": CHOLMOD did not keep a simplicial LDL^T factor in natural order");
  }
}

ClassKWorkspace::~ClassKWorkspace() = default;

long ClassKWorkspace::factor_nonzeros() const {
  if (solver->factor == nullptr) return 0;
  const int* lnz = static_cast<const int*>(solver->factor->nz);
  long total = 0;
  for (size_t j = 0; j < solver->factor->n; ++j) total += lnz[j];
  return total;
}

void ClassKWorkspace::Refactorise() {
  if (solver->a != nullptr) cholmod_factorize(solver->a, solver->factor, &solver->common);
}

void ClassKSystem::BarForceDensities(const ClassKWorkspace& ws, Eigen::VectorXd& out) const {
  out.setZero(n_model_bars_);
  for (const PackedBar& p : bars_) out(p.model_index) = ws.mu(p.row);
}

template <int D, bool Damped, bool Stabilised>
void ClassKSystem::DerivativeImpl(double t, const double* y, double* dy,
                                  ClassKWorkspace& ws) const {
  // CAUTION: performance-sensitive. Flat loops over preallocated buffers; CHOLMOD refactorises
  // into the factor and work arrays it allocated during the workspace's warm-up evaluation.
  const int c = coordinates();
  const double* x = y;
  const double* v = y + c;
  double* f = ws.force.data();
  ws.damper_power = StartDerivative<D, Damped>(
      t, y, dy, f, ws.record_strings);  // x' = v; loads, strings (eqs 16-17)
  ws.record_strings = nullptr;

  ClassKWorkspace::Solver& s = *ws.solver;
  double* rhs = ws.mu.data();  // the right-hand side, solved in place into mu
  double* u = ws.u.data();
  double* bvec = ws.b.data();
  double* l2v = ws.bar_length_sq.data();
  [[maybe_unused]] const double two_zeta_omega = 2.0 * options_.zeta * options_.omega_rad_s;
  [[maybe_unused]] const double half_omega_sq = 0.5 * options_.omega_rad_s * options_.omega_rad_s;

  // Per bar: b, u = M^-1 F on its copies, and its row of the right-hand side.
  for (size_t k = 0; k < bars_.size(); ++k) {
    const PackedBar& p = bars_[k];
    double* b = bvec + k * D;
    double fi[D], fj[D], ui[D], uj[D];
    double l2 = 0, bd2 = 0, bdu = 0, bbd = 0;
    for (int d = 0; d < D; ++d) {
      b[d] = x[p.oj + d] - x[p.oi + d];
      const double bd = v[p.oj + d] - v[p.oi + d];
      fi[d] = p.fi ? f[p.oi + d] : 0.0;
      fj[d] = p.fj ? f[p.oj + d] : 0.0;
      ui[d] = p.a00 * fi[d] + p.a01 * fj[d];
      uj[d] = p.a01 * fi[d] + p.a11 * fj[d];
      l2 += b[d] * b[d];
      bd2 += bd * bd;
      bdu += b[d] * (uj[d] - ui[d]);
      if constexpr (Stabilised) bbd += b[d] * bd;
    }
    l2v[k] = l2;
    double numerator = bd2 + bdu;
    if constexpr (Stabilised) numerator += two_zeta_omega * bbd + half_omega_sq * (l2 - p.rest_sq);
    rhs[p.row] = -numerator;
    for (int d = 0; d < D; ++d) {
      if (p.ci >= 0) u[p.ci * D + d] = ui[d];
      if (p.cj >= 0) u[p.cj * D + d] = uj[d];
    }
  }
  for (const Coincidence& q : coincidences_) {
    for (int d = 0; d < D; ++d) rhs[q.rows[d]] = -(u[q.copy * D + d] - u[q.primary * D + d]);
  }

  // A's values, numeric refactorisation in place, solve (pattern and order fixed).
  const double* mu = rhs;
  if (s.a != nullptr) {
    double* a = static_cast<double*>(s.a->x);
    std::memcpy(a, a_const_.data(), sizeof(double) * a_const_.size());
    for (const BarEntry& e : a_bar_)
      a[e.at] += e.coef * (e.d < 0 ? l2v[e.bar] : bvec[e.bar * D + e.d]);
    cholmod_factorize(s.a, s.factor, &s.common);
    if (s.common.status != CHOLMOD_OK || s.factor->minor != s.factor->n) {
      throw ModelError(std::string(kEngine) +
                       ": the constraint matrix J M^-1 J^T is not positive definite at t = " +
                       std::to_string(t) + " s (dependent bar constraints or a collapsed bar)");
    }
    s.Solve(rhs);
  }

  // J^T mu on the copies: every copy belongs to exactly one bar end, then the coincidences.
  double* jt = ws.jt_mu.data();
  for (size_t k = 0; k < bars_.size(); ++k) {
    const PackedBar& p = bars_[k];
    const double m = mu[p.row];
    for (int d = 0; d < D; ++d) {
      if (p.ci >= 0) jt[p.ci * D + d] = -m * bvec[k * D + d];
      if (p.cj >= 0) jt[p.cj * D + d] = m * bvec[k * D + d];
    }
  }
  for (const Coincidence& q : coincidences_) {
    for (int d = 0; d < D; ++d) {
      jt[q.copy * D + d] += mu[q.rows[d]];
      jt[q.primary * D + d] -= mu[q.rows[d]];
    }
  }
  // Node accelerations from the primary copies: a = u + M^-1 J^T mu.
  double* acc = dy + c;
  for (const PackedBar& p : bars_) {
    for (int d = 0; d < D; ++d) {
      const double gi = p.ci >= 0 ? jt[p.ci * D + d] : 0.0;
      const double gj = p.cj >= 0 ? jt[p.cj * D + d] : 0.0;
      if (p.ci >= 0 && p.fi) acc[p.oi + d] = u[p.ci * D + d] + p.a00 * gi + p.a01 * gj;
      if (p.cj >= 0 && p.fj) acc[p.oj + d] = u[p.cj * D + d] + p.a01 * gi + p.a11 * gj;
    }
  }
  FinishDerivative<D>(f, dy);
  ws.damper_power += MassDamping<D>(y, dy);
}

void ClassKSystem::Derivative(double t, const double* y, double* dy, ClassKWorkspace& ws) const {
  Evaluate(*this, t, y, dy, ws);
}

}  // namespace tbridge
