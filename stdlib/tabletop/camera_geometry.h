// Geometry shared by the synthetic cameras (the Bullet scene generator's camera and depth
// sensor in tools/tabletop_sim, the stereo pair synthesiser in tools/stereo_synth): the rotation of
// a camera looking along a direction, and where a ray enters a box. Eigen only, so either
// library can use it without linking the other.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Geometry>

namespace ksmc::stdlib::tabletop {

// Orientation (in the frame of `forward`) of a camera with OpenCV axes (x right, y down,
// z forward) looking along `forward` with no roll: its x axis stays horizontal (z up).
// `forward` need not be unit length; it must not be vertical.
inline Eigen::Quaterniond look_along(const Eigen::Vector3d& forward) {
  const Eigen::Vector3d z = forward.normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = y;
  r.col(2) = z;
  return Eigen::Quaterniond(r).normalized();
}

// Ray o + s * d against the axis-aligned box [-h, h] (slab test, box frame). Returns the
// parameter s > 0 at which the ray enters the box, or -1 when it misses the box, only
// touches it behind the origin, or starts inside it (no visible surface). `face`, when
// given, receives the face entered: 2 k for the +h[k] side of axis k, 2 k + 1 for -h[k].
inline double ray_enter_box(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& h,
                            int* face = nullptr) {
  double enter = -std::numeric_limits<double>::infinity(), leave = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (std::abs(o[k]) > h[k]) return -1.0;
      continue;
    }
    double s0 = (-h[k] - o[k]) / d[k], s1 = (h[k] - o[k]) / d[k];
    const bool swap = s0 > s1;
    if (swap) std::swap(s0, s1);
    if (s0 > enter) {
      enter = s0;
      if (face != nullptr) *face = swap ? 2 * k : 2 * k + 1;
    }
    leave = std::min(leave, s1);
  }
  if (enter > leave || enter <= 0.0) return -1.0;
  return enter;
}

}  // namespace ksmc::stdlib::tabletop
