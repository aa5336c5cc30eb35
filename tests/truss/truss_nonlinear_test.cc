// The geometrically nonlinear statics of a pin-jointed structure (truss/truss_nonlinear.h)
// against closed forms: a prestressed string pulled across, a shallow two-bar truss before and
// beyond its limit load; its derivatives are held to central differences in
// truss_sizing_test.cc.
#include "truss/truss_nonlinear.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/config.h"
#include "core/error.h"

namespace tbridge {
namespace {

constexpr double kE = 2e11, kArea = 1e-4;

// Two members from supports at (-b, 0) and (b, 0) to node 3 at (0, h), P down on node 3, in the
// x-y plane, analysed nonlinearly.
TrussModel TwoMembers(double b, double h, double p, const char* kind) {
  nlohmann::json group = {{"name", "g"}, {"kind", kind}, {"min_area_m2", kArea}};
  if (std::string(kind) != "bar") group["allowed_tension_pa"] = 1e9;
  if (std::string(kind) != "string") group["allowed_compression_pa"] = 1e9;
  const nlohmann::json j = {
      {"structure",
       {{"dim", 2},
        {"nodes", {{-b, 0, 0}, {b, 0, 0}, {0, h, 0}}},
        {"pinned", {1, 2}},
        {"members", {{{"nodes", {1, 3}}, {"group", "g"}}, {{"nodes", {2, 3}}, {"group", "g"}}}},
        {"groups", {group}},
        {"load_cases", {{{"name", "p"}, {"loads", {{{"node", 3}, {"force_n", {0, -p, 0}}}}}}}},
        {"analysis", "nonlinear"}}},
      {"material", {{"youngs_modulus", kE}, {"density", 7850}}},
      {"design", {{"self_weight", false}}}};
  return BuildTrussModel(ParseConfig(j));
}

TEST_CASE("truss nonlinear statics: a prestressed string pulled across", "[truss]") {
  // Two collinear strings of half-length a and prestress N0, P across at the middle: at the sag
  // v, each is l = sqrt(a^2 + v^2) long and carries N = N0 + k (l - a), k = E A / a, and the
  // node balances where 2 N v / l = P. P is taken from v = a / 20 (a sag a linear analysis,
  // v = P a / (2 N0), puts at 0.098 a here, twice off), and the solve must return that v.
  const double a = 2, n0 = 5e3, v = a / 20;
  const double l = std::hypot(a, v), n = n0 + kE * kArea / a * (l - a), p = 2 * n * v / l;
  const TrussModel m = TwoMembers(a, 0, p, "string");
  const TrussNonlinearStatics statics(m, Eigen::Vector2d(kArea, kArea), Eigen::Vector2d(n0, n0));
  const TrussCaseResponse r = statics.Solve(0, false);
  // Newton's equilibrium to 1e-11 of the largest force: the sag and forces to about 1e-10.
  CHECK(r.u[1] == Approx(-v).epsilon(1e-9));
  CHECK(r.u[0] == Approx(0).margin(1e-12 * a));
  CHECK(r.forces[0] == Approx(n).epsilon(1e-9));
  CHECK(r.forces[1] == Approx(n).epsilon(1e-9));
}

TEST_CASE("truss nonlinear statics: a shallow two-bar truss to and beyond its limit load",
          "[truss]") {
  // The von Mises truss: bars from (+-b, 0) to the apex at height h, P down. At a drop w each bar
  // is l = sqrt(b^2 + (h - w)^2) long, carries N = k (l - L), and P = -2 N (h - w) / l. Its
  // limit load is the largest P on the way to w = h: found here on a fine grid of w.
  const double b = 2, h = 0.2, length = std::hypot(b, h), k = kE * kArea / length;
  const auto load = [&](double w) {
    const double l = std::hypot(b, h - w);
    return -2 * k * (l - length) * (h - w) / l;
  };
  double limit = 0, w_limit = 0;
  for (int i = 1; i < 200000; ++i) {
    const double w = h * i / 200000.0;
    if (load(w) > limit) limit = load(w), w_limit = w;
  }
  // Half the limit load: the drop on the first branch, by bisection of load(w) = P below w_limit.
  const double p = 0.5 * limit;
  double lo = 0, hi = w_limit;
  for (int i = 0; i < 200; ++i) ((load(0.5 * (lo + hi)) < p) ? lo : hi) = 0.5 * (lo + hi);
  const TrussModel m = TwoMembers(b, h, p, "bar");
  const TrussNonlinearStatics statics(m, Eigen::Vector2d(kArea, kArea));
  const TrussCaseResponse r = statics.Solve(0, false);
  // Equilibrium to 1e-11: the drop to about 1e-9 (the bisection is exact to round-off).
  CHECK(-r.u[1] == Approx(0.5 * (lo + hi)).epsilon(1e-8));
  // A linear analysis would put the apex at a drop of P L^3 / (2 E A h^2), 22 % short here: the
  // test tells the two apart.
  CHECK(-r.u[1] > 1.1 * p * std::pow(length, 3) / (2 * kE * kArea * h * h));
  // Beyond the limit load there is no equilibrium on the branch from the drawn shape: the solve
  // says so, naming the case, rather than return the snapped-through shape (every Newton
  // iterate's tangent must be positive definite, and the way over passes where it is not).
  const TrussModel over = TwoMembers(b, h, 1.02 * limit, "bar");
  const TrussNonlinearStatics failing(over, Eigen::Vector2d(kArea, kArea));
  try {
    const TrussCaseResponse snapped = failing.Solve(0, false);
    FAIL("returned a drop of " << -snapped.u[1] << " m beyond the limit load");
  } catch (const ModelError& e) {
    CHECK_THAT(e.what(), Catch::Contains("case \"p\"") && Catch::Contains("does not converge"));
  }
}

}  // namespace
}  // namespace tbridge
