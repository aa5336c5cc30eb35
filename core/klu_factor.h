// A sparse LU on a fixed pattern by SuiteSparse's KLU: the pattern is analysed once, the first
// factorisation chooses the pivots and the later ones reuse them (klu_refactor, about a third
// of the cost) unless the pivot ratio drops below 1e-12 and below a thousandth of what fresh
// pivots gave, when the pivots are chosen afresh. Made for the small, very sparse matrices that
// are factorised many times (the static solve's Newton matrix, SDIRK3's): on them Eigen's
// supernodal SparseLU costs more (the sweep benchmark's 24 n = 8 SDIRK3 runs: 10.9 s with KLU
// against 17.4 s; the static check of the default at n = 6: BENCHMARKS.md).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace tbridge {

class KluFactor {
 public:
  KluFactor();
  ~KluFactor();
  KluFactor(const KluFactor&) = delete;
  KluFactor& operator=(const KluFactor&) = delete;
  KluFactor(KluFactor&&) noexcept;
  KluFactor& operator=(KluFactor&&) noexcept;

  // Analyses the pattern of `m` (compressed, square); every later matrix must share it.
  bool Analyse(const Eigen::SparseMatrix<double>& m);
  // Factorises `m` (the analysed pattern); false when it is singular.
  bool Factorise(const Eigen::SparseMatrix<double>& m);
  // x := A^-1 x, with A the last matrix factorised; column by column for a matrix.
  void Solve(Eigen::VectorXd& x) const;
  void Solve(Eigen::MatrixXd& x) const;
  // x := A^-T x, column by column.
  void SolveTransposed(Eigen::MatrixXd& x) const;
  // The reciprocal of KLU's estimate of the 1-norm condition number of `m`, the matrix last
  // factorised (Hager's method, as LAPACK's): 0 for a singular matrix.
  double ReciprocalCondition(const Eigen::SparseMatrix<double>& m) const;
  // The factors' entries and the estimated flops of a factorisation (from the analysis).
  double FactorEntries() const;
  double EstimatedFlops() const;

 private:
  struct Impl;  // keeps KLU's header out of here
  std::unique_ptr<Impl> impl_;
};

}  // namespace tbridge
