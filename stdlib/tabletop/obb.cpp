#include "stdlib/tabletop/obb.h"

#include <algorithm>
#include <cmath>

namespace ksmc::stdlib::tabletop {

Obb Obb::from_pose(const Pose& pose, const Eigen::Vector3d& size) {
  Obb b;
  b.center = pose.t;
  b.axes = pose.rotation();
  b.half = 0.5 * size;
  return b;
}

Eigen::Vector3d Obb::vertex(int k) const {
  Eigen::Vector3d local;
  for (int i = 0; i < 3; ++i) local[i] = ((k >> i) & 1) ? half[i] : -half[i];
  return center + axes * local;
}

std::array<Eigen::Vector3d, 8> Obb::vertices() const {
  std::array<Eigen::Vector3d, 8> v;
  for (int k = 0; k < 8; ++k) v[static_cast<std::size_t>(k)] = vertex(k);
  return v;
}

std::array<Eigen::Vector3d, 2> Obb::edge(int k) const {
  // Edges along axis a = k / 4; the other two sign bits come from k % 4.
  const int a = k / 4;
  const int rest = k % 4;
  const int b = (a + 1) % 3;
  const int c = (a + 2) % 3;
  const int base = (((rest >> 0) & 1) << b) | (((rest >> 1) & 1) << c);
  return {vertex(base), vertex(base | (1 << a))};
}

double Obb::min_z() const {
  // Extent of the box along z: centre ± Σ half_i |axis_i.z|.
  double r = 0.0;
  for (int i = 0; i < 3; ++i) r += half[i] * std::abs(axes(2, i));
  return center.z() - r;
}

double Obb::max_z() const {
  double r = 0.0;
  for (int i = 0; i < 3; ++i) r += half[i] * std::abs(axes(2, i));
  return center.z() + r;
}

Eigen::Vector3d Obb::closest_point(const Eigen::Vector3d& p) const {
  Eigen::Vector3d local = axes.transpose() * (p - center);
  for (int i = 0; i < 3; ++i) local[i] = std::clamp(local[i], -half[i], half[i]);
  return center + axes * local;
}

double Obb::distance_to(const Eigen::Vector3d& p) const { return (p - closest_point(p)).norm(); }

bool Obb::contains(const Eigen::Vector3d& p, double slack) const {
  const Eigen::Vector3d local = axes.transpose() * (p - center);
  for (int i = 0; i < 3; ++i)
    if (std::abs(local[i]) > half[i] + slack) return false;
  return true;
}

}  // namespace ksmc::stdlib::tabletop
