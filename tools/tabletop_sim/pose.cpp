#include "tools/tabletop_sim/pose.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ksmc::tools::tabletop_sim {

Pose Pose::inverse() const {
  Pose r;
  r.q = q.conjugate();
  r.t = -(r.q * t);
  return r;
}

Pose operator*(const Pose& a, const Pose& b) {
  Pose r;
  r.q = (a.q * b.q).normalized();
  r.t = a.q * b.t + a.t;
  return r;
}

double rotation_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const double d = std::min(1.0, std::abs(a.normalized().dot(b.normalized())));
  return 2.0 * std::acos(d);
}

Eigen::Quaterniond canonical(const Eigen::Quaterniond& q) {
  Eigen::Quaterniond n = q.normalized();
  if (n.w() < 0.0) n.coeffs() = -n.coeffs();
  return n;
}

Eigen::Quaterniond yaw_rotation(double angle) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()));
}

namespace {
Eigen::Vector3d random_unit_vector(Rng& rng) {
  const double z = rng.uniform(-1.0, 1.0);
  const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}
}  // namespace

Eigen::Quaterniond rotation_about_random_axis(Rng& rng, double angle) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, random_unit_vector(rng)));
}

Eigen::Quaterniond random_tilt(Rng& rng, double angle) {
  const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
  return Eigen::Quaterniond(
      Eigen::AngleAxisd(angle, Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0)));
}

Eigen::Quaterniond uniform_rotation(Rng& rng) {
  const double u1 = rng.uniform();
  const double u2 = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double u3 = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double a = std::sqrt(1.0 - u1);
  const double b = std::sqrt(u1);
  return Eigen::Quaterniond(a * std::sin(u2), a * std::cos(u2), b * std::sin(u3), b * std::cos(u3))
      .normalized();
}

int vertical_axis(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  int best = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(r(2, i)) > std::abs(r(2, best))) best = i;
  }
  return best;
}

double tilt_from_vertical(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  const double c = std::min(1.0, std::abs(r(2, vertical_axis(q))));
  return std::acos(c);
}

}  // namespace ksmc::tools::tabletop_sim
