// SPDX-License-Identifier: MIT
#include "LinearBending.h"

namespace stroma {

bool makeLinearBendingHinge(const TriangleHinge& hinge, const std::array<Vec3d, 4>& rest,
                            double bendingStiffness, double minDistance, LinearBendingHinge& out) {
  const Vec3d& a = rest[0];
  const Vec3d edge = rest[2] - a;
  const double length = edge.norm();
  if (!(length > minDistance)) return false;
  const Vec3d along = edge / length;
  // Height and foot parameter of an opposite vertex.
  auto measure = [&](const Vec3d& p, double& height, double& s) {
    const double t = (p - a).dot(along);
    height = (p - a - t * along).norm();
    s = t / length;
  };
  double Hb, sb, Hd, sd;
  measure(rest[1], Hb, sb);
  measure(rest[3], Hd, sd);
  if (!(Hb > minDistance && Hd > minDistance)) return false;
  out.vertex = {hinge.a, hinge.b, hinge.c, hinge.d};
  out.alpha = {-(1 - sb) / Hb - (1 - sd) / Hd, 1 / Hb, -sb / Hb - sd / Hd, 1 / Hd};
  out.lambda = 2.0 / 3.0 * bendingStiffness * length / (Hb + Hd);
  return true;
}

}  // namespace stroma
