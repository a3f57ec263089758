#include "stdlib/tabletop/obb_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "stdlib/tabletop/obb_sat.h"

namespace ksmc::stdlib::tabletop {

double segment_segment_closest(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                               const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
                               Eigen::Vector3d& on_p, Eigen::Vector3d& on_q) {
  // Minimise |p0 + s u - (q0 + t v)|² over s, t in [0, 1].
  const Eigen::Vector3d u = p1 - p0;
  const Eigen::Vector3d v = q1 - q0;
  const Eigen::Vector3d w = p0 - q0;
  const double a = u.dot(u);
  const double e = v.dot(v);
  const double f = v.dot(w);
  constexpr double tiny = 1e-300;
  double s = 0.0;
  double t = 0.0;
  if (a <= tiny && e <= tiny) {
    s = t = 0.0;
  } else if (a <= tiny) {
    s = 0.0;
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = u.dot(w);
    if (e <= tiny) {
      t = 0.0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = u.dot(v);
      const double denom = a * e - b * b;  // ≥ 0, 0 for parallel segments
      // Parallel (or nearly): any s works for the infinite lines; start at s = 0.
      s = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  on_p = p0 + s * u;
  on_q = q0 + t * v;
  return (on_p - on_q).squaredNorm();
}

ClosestPoints obb_closest_points(const Obb& a, const Obb& b) {
  ClosestPoints res;
  const SatResult sat = obb_sat(a, b);
  if (sat.overlapping) {
    res.overlapping = true;
    res.distance = 0.0;
    // A representative common point: the point of b closest to a's centre, pulled into a.
    res.on_b = b.closest_point(a.center);
    res.on_a = a.closest_point(res.on_b);
    return res;
  }
  double best = std::numeric_limits<double>::infinity();
  auto consider = [&](double sq, const Eigen::Vector3d& pa, const Eigen::Vector3d& pb) {
    if (sq < best) {
      best = sq;
      res.on_a = pa;
      res.on_b = pb;
    }
  };
  const auto va = a.vertices();
  const auto vb = b.vertices();
  for (std::size_t k = 0; k < 8; ++k) {
    const Eigen::Vector3d cb = b.closest_point(va[k]);
    consider((va[k] - cb).squaredNorm(), va[k], cb);
    const Eigen::Vector3d ca = a.closest_point(vb[k]);
    consider((vb[k] - ca).squaredNorm(), ca, vb[k]);
  }
  // Edge k joins vertices base and base | (1 << axis) (same numbering as Obb::edge).
  std::array<std::array<std::size_t, 2>, 12> edges{};
  for (int k = 0; k < 12; ++k) {
    const int axis = k / 4, rest = k % 4;
    const int base = (((rest >> 0) & 1) << ((axis + 1) % 3)) | (((rest >> 1) & 1) << ((axis + 2) % 3));
    edges[static_cast<std::size_t>(k)] = {static_cast<std::size_t>(base), static_cast<std::size_t>(base | (1 << axis))};
  }
  for (const auto& ea : edges) {
    for (const auto& eb : edges) {
      Eigen::Vector3d pa;
      Eigen::Vector3d pb;
      const double sq = segment_segment_closest(va[ea[0]], va[ea[1]], vb[eb[0]], vb[eb[1]], pa, pb);
      consider(sq, pa, pb);
    }
  }
  res.distance = std::sqrt(best);
  return res;
}

}  // namespace ksmc::stdlib::tabletop
