#include "tools/tabletop_indep/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ksmc::tools::tabletop_indep {

std::array<Eigen::Vector3d, 8> Obb::corners() const {
  std::array<Eigen::Vector3d, 8> c;
  const Eigen::Vector3d h = half();
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d s((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    c[static_cast<std::size_t>(i)] = centre + rot * s.cwiseProduct(h);
  }
  return c;
}

// Extent of the box along z: the half-size projected on the vertical.
double Obb::bottom() const { return centre.z() - rot.row(2).cwiseAbs().dot(half()); }
double Obb::top() const { return centre.z() + rot.row(2).cwiseAbs().dot(half()); }

int Obb::up_axis() const {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(rot(2, i)) > std::abs(rot(2, k))) k = i;
  return k;
}

double Obb::tilt() const { return std::acos(std::clamp(std::abs(rot(2, up_axis())), 0.0, 1.0)); }

double penetration(const Obb& a, const Obb& b) {
  const Eigen::Vector3d d = b.centre - a.centre;
  const Eigen::Vector3d ha = a.half(), hb = b.half();
  double best = std::numeric_limits<double>::infinity();
  auto test = [&](const Eigen::Vector3d& axis) {
    const double n = axis.norm();
    if (n < 1e-9) return;
    const Eigen::Vector3d u = axis / n;
    const double ra = (a.rot.transpose() * u).cwiseAbs().dot(ha);
    const double rb = (b.rot.transpose() * u).cwiseAbs().dot(hb);
    best = std::min(best, ra + rb - std::abs(d.dot(u)));
  };
  for (int i = 0; i < 3; ++i) test(a.rot.col(i));
  for (int i = 0; i < 3; ++i) test(b.rot.col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) test(a.rot.col(i).cross(b.rot.col(j)));
  return best;
}

Eigen::Matrix3d resting_rotation(int axis, bool flip, double yaw) {
  Eigen::Matrix3d r;
  const double s = flip ? -1.0 : 1.0;
  r.col(axis) = s * Eigen::Vector3d::UnitZ();
  r.col((axis + 1) % 3) = s * Eigen::Vector3d::UnitX();
  r.col((axis + 2) % 3) = Eigen::Vector3d::UnitY();
  if (r.determinant() < 0) r.col((axis + 2) % 3) *= -1.0;
  return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * r;
}

bool over_top(const Obb& b, const Eigen::Vector2d& p, double margin) {
  const Eigen::Vector3d local = b.rot.transpose() * (Eigen::Vector3d(p.x(), p.y(), b.centre.z()) - b.centre);
  const int up = b.up_axis();
  for (int i = 0; i < 3; ++i) {
    if (i == up) continue;
    if (std::abs(local[i]) > 0.5 * b.size[i] - margin) return false;
  }
  return true;
}

double footprint_overlap(const Obb& upper, const Obb& lower, int samples) {
  const int up = upper.up_axis();
  const int a = (up + 1) % 3, c = (up + 2) % 3;
  long inside = 0;
  for (int i = 0; i < samples; ++i) {
    for (int j = 0; j < samples; ++j) {
      Eigen::Vector3d local = Eigen::Vector3d::Zero();
      local[a] = ((i + 0.5) / samples - 0.5) * upper.size[a];
      local[c] = ((j + 0.5) / samples - 0.5) * upper.size[c];
      const Eigen::Vector3d w = upper.centre + upper.rot * local;
      if (over_top(lower, w.head<2>(), 0.0)) ++inside;
    }
  }
  return upper.size[a] * upper.size[c] * static_cast<double>(inside) / (samples * samples);
}

}  // namespace ksmc::tools::tabletop_indep
