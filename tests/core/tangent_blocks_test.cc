// The string's tangent block (core/tangent_blocks.h), the one the statics, stability, modal
// analysis, linear response and truss analysis all assemble, against the derivative of the
// string's force by finite differences and against what a projector is.
#include "core/tangent_blocks.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "core/string_law.h"

namespace tbridge {
namespace {

// The force t(L) u a taut string of stiffness k and rest length l0 puts on its end j, with
// d = x_j - x_i.
Eigen::Vector3d StringForce(const Eigen::Vector3d& d, double k, double l0) {
  return -StringTension(k, l0, d.norm()) * d.normalized();
}

TEST_CASE("the string's tangent block is minus the derivative of its end force",
          "[tangent_blocks]") {
  const double k = 1e5, l0 = 1.1;  // [N/m], [m]: a string stretched 6 % at d below
  const Eigen::Vector3d d(0.6, 0.8, 0.6);
  const double length = d.norm(), q = StringTension(k, l0, length) / length;
  const Eigen::Matrix3d block = StringTangentBlock(d / length, k, q);
  // Central differences, step h: truncation ~ |f'''| h^2 ~ k h^2 / L^2 = 1e-7 N/m and rounding
  // ~ 1e-16 t / h = 1e-6 N/m, against entries of 1e5 N/m: 1e-9 relative (1e-4 N/m) holds them,
  // and the geometric part (q = 5.7e3 N/m) left out would miss it by seven decades.
  const double h = 1e-6;
  Eigen::Matrix3d fd;
  for (int c = 0; c < 3; ++c) {
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    step[c] = h;
    fd.col(c) = -(StringForce(d + step, k, l0) - StringForce(d - step, k, l0)) / (2 * h);
  }
  INFO("block\n" << block << "\nfinite differences\n" << fd);
  CHECK((block - fd).norm() <= 1e-9 * block.norm());
  // A slack string has no force: then the block is its material part alone, k u u^T.
  CHECK((StringTangentBlock(d / length, k, 0.0) - StringMaterialBlock(d / length, k)).norm() ==
        0.0);  // exact: the geometric part is 0 x (I - u u^T)
}

TEST_CASE("the tangent block is linear in stiffness and force density: its own derivative",
          "[tangent_blocks]") {
  const Eigen::Vector3d u = Eigen::Vector3d(1, 2, 2) / 3.0;
  const double k = 3e6, q = 2e4, dk = 5e3, dq = -7e2;
  const Eigen::Matrix3d change =
      StringTangentBlock(u, k + dk, q + dq) - StringTangentBlock(u, k, q);
  // The difference of two blocks of ~3e6 N/m carries their rounding, 1e-16 x 3e6 a few times.
  CHECK((change - StringTangentBlock(u, dk, dq)).norm() <=
        1e-8 * StringTangentBlock(u, dk, dq).norm());
}

TEST_CASE("the normal projector annihilates u, keeps what is normal to it, and is planar in 2D",
          "[tangent_blocks]") {
  const Eigen::Vector3d u = Eigen::Vector3d(3, 4, 0) / 5.0;
  const Eigen::Matrix3d p = NormalProjector(u);
  CHECK((p * u).norm() <= 1e-15);      // rounding of entries of O(1)
  CHECK((p * p - p).norm() <= 1e-15);  // a projector: idempotent to rounding
  CHECK((p * Eigen::Vector3d(-4, 3, 0) - Eigen::Vector3d(-4, 3, 0)).norm() <= 1e-14);
  const Eigen::Matrix3d planar = NormalProjector(u, 2);
  CHECK(planar(2, 2) == 0.0);  // nothing out of the plane: exact zeros
  CHECK(planar.topLeftCorner(2, 2) == p.topLeftCorner(2, 2));  // the same in the plane, bit for bit
  const Eigen::Matrix3d g = StringGeometricBlock(u, 40.0, 2);
  CHECK(g.row(2).isZero(0.0));
  CHECK(g.col(2).isZero(0.0));
}

}  // namespace
}  // namespace tbridge
