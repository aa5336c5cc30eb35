// The certificate of local optimality on small programs whose optima and multipliers are known
// in closed form, and on points that must fail it: not stationary, infeasible, a saddle, a
// multiplier on a row with slack, a violated row deep among many.

#include "optim/kkt_certificate.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tbridge {
namespace {

const double kInf = std::numeric_limits<double>::infinity();

// min -x1 - x2 s.t. 1 - x1 >= 0, 1 - x2 >= 0 (rows), x >= 0 (bounds), with rows `active`.
KktInput LinearProgram(double x1, double x2, std::vector<int> active) {
  KktInput in;
  in.x = Eigen::Vector2d(x1, x2);
  in.lo_x = Eigen::Vector2d::Zero();
  in.hi_x = Eigen::Vector2d::Constant(kInf);
  in.grad_f = Eigen::Vector2d(-1, -1);
  in.slack = Eigen::Vector2d(1 - x1, 1 - x2);
  in.active = active;
  in.jac_active = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(active.size()), 2);
  for (size_t k = 0; k < active.size(); ++k)
    in.jac_active(static_cast<Eigen::Index>(k), active[k]) = -1;
  return in;
}

// min x1 + x2 s.t. 2 - x1^2 - x2^2 >= 0, no bounds: the minimum (-1, -1), lambda = 1/2.
KktInput Circle(double x1, double x2) {
  KktInput in;
  in.x = Eigen::Vector2d(x1, x2);
  in.lo_x = Eigen::Vector2d::Constant(-kInf);
  in.hi_x = Eigen::Vector2d::Constant(kInf);
  in.at = [](const Eigen::VectorXd& y, Eigen::VectorXd& g, Eigen::MatrixXd& J) {
    g = Eigen::Vector2d(1, 1);
    J = -2 * y.transpose();
  };
  in.at(in.x, in.grad_f, in.jac_active);
  in.slack = Eigen::VectorXd::Constant(1, 2 - x1 * x1 - x2 * x2);
  in.active = {0};
  return in;
}

// min x s.t. x >= 0 as a row, n = 1: the minimum at 0 with lambda = 1.
KktInput HalfLine(double x) {
  KktInput in;
  in.x = Eigen::VectorXd::Constant(1, x);
  in.lo_x = Eigen::VectorXd::Constant(1, -kInf);
  in.hi_x = Eigen::VectorXd::Constant(1, kInf);
  in.grad_f = Eigen::VectorXd::Ones(1);
  in.slack = Eigen::VectorXd::Constant(1, x);
  in.active = {0};
  in.jac_active = Eigen::MatrixXd::Ones(1, 1);
  return in;
}

TEST_CASE("a linear program's vertex is proved by its multipliers alone", "[design][kkt]") {
  const KktCertificate c = CertifyLocalOptimum(LinearProgram(1, 1, {0, 1}));
  INFO(c.failed);
  CHECK(c.proved_local_optimum);
  CHECK(c.second_order_by == "vertex");  // no `at` given: only the vertex can prove it
  CHECK(c.active_rows == 2);
  CHECK(c.active_bounds == 0);  // x = 1 is far from the bound 0
  CHECK(c.free_variables == 2);
  CHECK(c.null_space_dimension == 0);
  // grad f = -e1 - e2 = lambda1 (-e1) + lambda2 (-e2): exact in floating point, 1e-12 for the
  // least squares' rounding.
  REQUIRE(c.multipliers.size() == 2);
  CHECK(c.multipliers[0] == Approx(1).margin(1e-12));
  CHECK(c.multipliers[1] == Approx(1).margin(1e-12));
  CHECK(c.largest_multiplier == Approx(1).margin(1e-12));
  CHECK(c.stationarity <= 1e-12);  // the same rounding
  CHECK(c.failed.empty());

  // Control: only x1's row given as active, the gradient's x2 part has nothing to balance it:
  // the residual is |(0, -1)|_inf / 1 = 1 exactly.
  const KktCertificate one = CertifyLocalOptimum(LinearProgram(1, 1, {0}));
  CHECK_FALSE(one.proved_local_optimum);
  CHECK(one.stationarity == Approx(1).margin(1e-12));
  CHECK(one.failed.find("stationarity") != std::string::npos);
}

TEST_CASE("a weakly active row does not make a vertex", "[design][kkt]") {
  // min -x1 with the same rows: at (1, 1) lambda = (1, 0). Two rows are active, but the one on
  // x2 carries no multiplier, so f does not rise at first order along x2: that direction is
  // left to the Hessian.
  KktInput in = LinearProgram(1, 1, {0, 1});
  in.grad_f = Eigen::Vector2d(-1, 0);
  const KktCertificate without = CertifyLocalOptimum(in);
  CHECK(without.stationarity <= 1e-12);  // first order holds exactly
  CHECK(without.multipliers[1] == 0);    // NNLS leaves the unneeded column out
  CHECK(without.null_space_dimension == 1);
  CHECK_FALSE(without.second_order);  // no Hessian given, and not a vertex
  CHECK(without.failed.find("second order") != std::string::npos);

  // With the (zero) Hessian of a linear program the reduced Hessian is 0: PSD, proved.
  const Eigen::MatrixXd jac = in.jac_active;
  in.at = [jac](const Eigen::VectorXd&, Eigen::VectorXd& g, Eigen::MatrixXd& J) {
    g = Eigen::Vector2d(-1, 0);
    J = jac;
  };
  const KktCertificate with = CertifyLocalOptimum(in);
  INFO(with.failed);
  CHECK(with.proved_local_optimum);
  CHECK(with.second_order_by == "reduced Hessian");
  CHECK(std::abs(with.smallest_curvature) <= 1e-9);  // exact differences of constants
}

TEST_CASE("a smooth optimum on a curved constraint is proved by its reduced Hessian",
          "[design][kkt]") {
  const KktCertificate c = CertifyLocalOptimum(Circle(-1, -1));
  INFO(c.failed);
  CHECK(c.proved_local_optimum);
  CHECK(c.second_order_by == "reduced Hessian");
  CHECK(c.null_space_dimension == 1);  // the tangent (1, -1) / sqrt 2
  // grad f = (1, 1) = lambda (2, 2): lambda = 1/2 exactly, 1e-12 for rounding.
  CHECK(c.multipliers[0] == Approx(0.5).margin(1e-12));
  // The Lagrangian's Hessian is -lambda (-2 I) = 2 lambda I = I, on the tangent 1. Central
  // differences of a linear grad L are exact but for rounding, eps |grad L| / h ~ 1e-10.
  CHECK(c.smallest_curvature == Approx(1).margin(1e-8));
  CHECK(c.stationarity <= 1e-12);
  CHECK(c.feasibility <= 1e-15);  // 2 - 1 - 1 is exact
}

TEST_CASE("an active upper bound enters with its sign", "[design][kkt]") {
  // min -x1 + (x2 - 0.3)^2, x1 <= 1, -1 <= x2 <= 1, no rows: the minimum (1, 0.3), mu_hi = 1 on
  // x1, and the x2 direction free with curvature 2.
  KktInput in;
  in.x = Eigen::Vector2d(1, 0.3);
  in.lo_x = Eigen::Vector2d(-kInf, -1);
  in.hi_x = Eigen::Vector2d(1, 1);
  in.grad_f = Eigen::Vector2d(-1, 0);
  in.slack = Eigen::VectorXd(0);
  in.jac_active = Eigen::MatrixXd(0, 2);
  in.at = [](const Eigen::VectorXd& y, Eigen::VectorXd& g, Eigen::MatrixXd& J) {
    g = Eigen::Vector2d(-1, 2 * (y[1] - 0.3));
    J = Eigen::MatrixXd(0, 2);
  };
  const KktCertificate c = CertifyLocalOptimum(in);
  INFO(c.failed);
  CHECK(c.proved_local_optimum);
  CHECK(c.active_bounds == 1);
  CHECK(c.free_variables == 1);
  CHECK(c.bound_multipliers[0] == Approx(-1).margin(1e-12));  // < 0: an upper bound
  CHECK(c.bound_multipliers[1] == 0);
  CHECK(c.smallest_curvature == Approx(2).margin(1e-8));  // as above, rounding ~ 1e-10

  // Control: the same point against a lower bound x1 >= 1 instead cannot balance -e1 with +mu.
  in.lo_x[0] = 1;
  in.hi_x[0] = kInf;
  const KktCertificate wrong = CertifyLocalOptimum(in);
  CHECK_FALSE(wrong.proved_local_optimum);
  CHECK(wrong.stationarity == Approx(1).margin(1e-12));
}

TEST_CASE("points that are not local minima fail the certificate, naming why", "[design][kkt]") {
  SECTION("feasible but not stationary") {
    // On the circle at (-sqrt 2, 0): grad g = (2 sqrt 2, 0) cannot produce grad f's x2 part,
    // the residual (0, 1) of |grad f|_inf = 1.
    const KktCertificate c = CertifyLocalOptimum(Circle(-std::sqrt(2.0), 0));
    CHECK_FALSE(c.proved_local_optimum);
    CHECK(c.stationarity == Approx(1).margin(1e-12));
    CHECK(c.feasibility <= 1e-15);  // on the boundary to rounding: 2 - sqrt(2)^2 = -4.4e-16
    CHECK(c.failed.find("stationarity") != std::string::npos);
    CHECK(c.failed.find("feasibility") == std::string::npos);
  }
  SECTION("infeasible") {
    // (-1.1, -1.1): 2 - 2.42 = -0.42, stationary (lambda = 1 / 2.2) but outside the circle.
    const KktCertificate c = CertifyLocalOptimum(Circle(-1.1, -1.1));
    CHECK_FALSE(c.proved_local_optimum);
    CHECK(c.stationarity <= 1e-12);
    CHECK(c.feasibility == Approx(0.42).epsilon(1e-12));
    CHECK(c.failed.find("feasibility") != std::string::npos);
  }
  SECTION("a bound violated") {
    // The vertex of the linear program with x2 pushed 1e-3 below its bound 0 (and its row
    // given as inactive, slack 1 + 1e-3): x2's bound is active with violation 1e-3.
    KktInput in = LinearProgram(1, -1e-3, {0});
    in.grad_f = Eigen::Vector2d(-1, 1);
    const KktCertificate c = CertifyLocalOptimum(in);
    CHECK(c.stationarity <= 1e-12);  // -e1 from row 0, +e2 from x2's lower bound
    CHECK(c.feasibility == Approx(1e-3).epsilon(1e-12));
    CHECK(c.failed.find("feasibility") != std::string::npos);
  }
  SECTION("a saddle") {
    // min -x1^2 + x2 s.t. x2 >= 0 (a row) at (0, 0): grad f = (0, 1) = 1 * (0, 1), but along
    // the row's tangent x1 the Hessian is -2.
    KktInput in;
    in.x = Eigen::Vector2d::Zero();
    in.lo_x = Eigen::Vector2d::Constant(-kInf);
    in.hi_x = Eigen::Vector2d::Constant(kInf);
    in.at = [](const Eigen::VectorXd& y, Eigen::VectorXd& g, Eigen::MatrixXd& J) {
      g = Eigen::Vector2d(-2 * y[0], 1);
      J = Eigen::RowVector2d(0, 1);
    };
    in.at(in.x, in.grad_f, in.jac_active);
    in.slack = Eigen::VectorXd::Zero(1);
    in.active = {0};
    const KktCertificate c = CertifyLocalOptimum(in);
    CHECK(c.stationarity <= 1e-12);  // first order holds
    CHECK(c.feasibility == 0);
    CHECK(c.complementarity == 0);
    CHECK_FALSE(c.second_order);
    CHECK_FALSE(c.proved_local_optimum);
    CHECK(c.smallest_curvature == Approx(-2).margin(1e-8));  // rounding ~ 1e-10, as above
    CHECK(c.failed.find("second order") != std::string::npos);
  }
  SECTION("a multiplier on a row with slack") {
    // Control: at x = 0 the row holds with equality, lambda = 1, a vertex (n = 1, one row).
    const KktCertificate at_zero = CertifyLocalOptimum(HalfLine(0));
    CHECK(at_zero.proved_local_optimum);
    CHECK(at_zero.second_order_by == "vertex");
    // At x = 0.5 the row is inactive: left out of `active`, nothing balances grad f = 1 and
    // stationarity fails; complementarity is over the active rows only, so it is 0.
    KktInput omitted = HalfLine(0.5);
    omitted.active.clear();
    omitted.jac_active = Eigen::MatrixXd(0, 1);
    const KktCertificate c0 = CertifyLocalOptimum(omitted);
    CHECK(c0.stationarity == Approx(1).margin(1e-12));
    CHECK(c0.complementarity == 0);
    // Given as active at x = 1e-3, it balances grad f with lambda = 1 on slack 1e-3:
    // lambda * slack / |grad f| = 1e-3 exactly.
    const KktCertificate c = CertifyLocalOptimum(HalfLine(1e-3));
    CHECK(c.stationarity <= 1e-12);
    CHECK(c.multipliers[0] == Approx(1).margin(1e-12));
    CHECK(c.complementarity == Approx(1e-3).epsilon(1e-12));
    CHECK_FALSE(c.proved_local_optimum);
    CHECK(c.failed.find("complementarity") != std::string::npos);
  }
}

TEST_CASE("the feasibility is the largest violation over every row", "[design][kkt]") {
  // The linear program's vertex among 10^5 rows: its two rows at 12 345 and 67 890, the rest
  // with slack in [0.1, 1.1).
  const Eigen::Index rows = 100000;
  KktInput in = LinearProgram(1, 1, {0, 1});
  in.slack = 0.6 * Eigen::VectorXd::Ones(rows) + 0.5 * Eigen::VectorXd::Random(rows);
  in.active = {12345, 67890};
  in.slack[12345] = in.slack[67890] = 0;
  const KktCertificate clean = CertifyLocalOptimum(in);
  INFO(clean.failed);
  CHECK(clean.proved_local_optimum);  // control: nothing violated
  CHECK(clean.feasibility == 0);

  // One inactive row deep in the vector violated by 2.5e-4: found, and the proof fails.
  in.slack[98765] = -2.5e-4;
  const KktCertificate c = CertifyLocalOptimum(in);
  CHECK(c.feasibility == 2.5e-4);  // a copy of the entry, no arithmetic
  CHECK_FALSE(c.proved_local_optimum);
  CHECK(c.failed.find("feasibility") != std::string::npos);
  CHECK(c.stationarity <= 1e-12);  // the rest of the certificate unchanged

  // A row that could not be evaluated counts as violated.
  in.slack[98765] = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::isinf(CertifyLocalOptimum(in).feasibility));
}

TEST_CASE("malformed input throws", "[design][kkt]") {
  KktInput in = LinearProgram(1, 1, {0, 1});
  in.active = {0, 2};  // slack has 2 rows
  CHECK_THROWS_AS(CertifyLocalOptimum(in), std::invalid_argument);
  in = LinearProgram(1, 1, {0, 1});
  in.jac_active = Eigen::MatrixXd::Zero(1, 2);
  CHECK_THROWS_AS(CertifyLocalOptimum(in), std::invalid_argument);
}

}  // namespace
}  // namespace tbridge
