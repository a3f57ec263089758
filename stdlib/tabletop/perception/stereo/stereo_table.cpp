#include "stdlib/tabletop/perception/stereo/stereo_table.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Dense>

namespace ksmc::stdlib::tabletop::perception::stereo {

std::optional<StereoTable> table_from_points(const std::vector<Eigen::Vector3d>& pts, const TableOptions& o) {
  const auto n = pts.size();
  if (static_cast<int>(n) < std::max(3, o.min_inliers)) return std::nullopt;
  std::mt19937_64 rng(o.seed);
  Eigen::Vector3d best_n = Eigen::Vector3d::UnitZ();
  double best_d = 0.0;
  std::size_t best_count = 0;
  for (int it = 0; it < o.iterations; ++it) {
    const Eigen::Vector3d& a = pts[rng() % n];
    const Eigen::Vector3d& b = pts[rng() % n];
    const Eigen::Vector3d& c = pts[rng() % n];
    Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() < 1e-6) continue;
    normal.normalize();
    double d = -normal.dot(a);
    if (d < 0.0) normal = -normal, d = -d;  // signed distance normal.p + d > 0 on the camera's side
    std::size_t count = 0, below = 0;
    for (const auto& p : pts) {
      const double s = normal.dot(p) + d;
      count += std::abs(s) <= o.tolerance;
      below += s < -2.0 * o.tolerance;
    }
    // The table supports the objects: (almost) nothing is seen beyond it. This rejects the
    // box tops, which can hold more points than the table.
    if (static_cast<double>(below) > o.max_below * static_cast<double>(n)) continue;
    if (count > best_count) best_count = count, best_n = normal, best_d = d;
  }
  if (static_cast<int>(best_count) < o.min_inliers || static_cast<double>(best_count) < o.min_share * static_cast<double>(n))
    return std::nullopt;
  // Weighted least squares on the inliers (stereo depth variance grows as z^4), twice,
  // the second time on the points within 2 rms of the first plane.
  std::vector<Eigen::Vector3d> in;
  for (const auto& p : pts)
    if (std::abs(best_n.dot(p) + best_d) <= o.tolerance) in.push_back(p);
  Eigen::Vector3d z = best_n, centroid = Eigen::Vector3d::Zero();
  for (int round = 0; round < 2; ++round) {
    double wsum = 0.0;
    centroid.setZero();
    for (const auto& p : in) {
      const double w = 1.0 / std::pow(std::max(0.1, p.z()), 4);
      centroid += w * p;
      wsum += w;
    }
    centroid /= wsum;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : in) cov += (p - centroid) * (p - centroid).transpose() / std::pow(std::max(0.1, p.z()), 4);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    z = eig.eigenvectors().col(0).normalized();
    if (round == 1) break;
    double ss = 0.0;
    for (const auto& p : in) ss += std::pow(z.dot(p - centroid), 2);
    const double gate = 2.0 * std::sqrt(ss / static_cast<double>(in.size()));
    std::vector<Eigen::Vector3d> kept;
    for (const auto& p : in)
      if (std::abs(z.dot(p - centroid)) <= gate) kept.push_back(p);
    if (static_cast<int>(kept.size()) < o.min_inliers) break;
    in = std::move(kept);
  }
  if (z.dot(-centroid) < 0.0) z = -z;  // towards the camera (the left camera is at the origin)
  Eigen::Vector3d x = Eigen::Vector3d::UnitX() - z * z.x();
  if (x.norm() < 1e-6) x = Eigen::Vector3d::UnitY() - z * z.y();
  x.normalize();
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  StereoTable t;
  t.table_in_left.q = Eigen::Quaterniond(r).normalized();
  t.table_in_left.t = centroid;
  double hx = 0.0, hy = 0.0, ss = 0.0;
  for (const auto& p : in) {
    const Eigen::Vector3d q = r.transpose() * (p - centroid);
    hx = std::max(hx, std::abs(q.x()));
    hy = std::max(hy, std::abs(q.y()));
    ss += q.z() * q.z();
  }
  t.size = Eigen::Vector3d(2.0 * hx, 2.0 * hy, o.thickness);
  t.inliers = static_cast<int>(in.size());
  t.candidates = static_cast<int>(n);
  t.rms = std::sqrt(ss / static_cast<double>(in.size()));
  return t;
}

}  // namespace ksmc::stdlib::tabletop::perception::stereo
