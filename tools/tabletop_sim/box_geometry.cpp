#include "tools/tabletop_sim/box_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "tools/tabletop_sim/bullet_units.h"

namespace ksmc::tools::tabletop_sim {

std::array<Eigen::Vector3d, 8> box_vertices(const Box& b) {
  std::array<Eigen::Vector3d, 8> v;
  const Eigen::Vector3d h = 0.5 * b.size;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d local((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                                (i & 4) ? h.z() : -h.z());
    v[static_cast<std::size_t>(i)] = b.pose.apply(local);
  }
  return v;
}

double lowest_z(const Box& b) {
  const Eigen::Matrix3d r = b.pose.rotation();
  const Eigen::Vector3d h = 0.5 * b.size;
  const double reach = std::abs(r(2, 0)) * h.x() + std::abs(r(2, 1)) * h.y() + std::abs(r(2, 2)) * h.z();
  return b.pose.t.z() - reach;
}

double highest_z(const Box& b) {
  const Eigen::Matrix3d r = b.pose.rotation();
  const Eigen::Vector3d h = 0.5 * b.size;
  const double reach = std::abs(r(2, 0)) * h.x() + std::abs(r(2, 1)) * h.y() + std::abs(r(2, 2)) * h.z();
  return b.pose.t.z() + reach;
}

double sat_overlap(const Box& a, const Box& b) {
  const Eigen::Matrix3d ra = a.pose.rotation();
  const Eigen::Matrix3d rb = b.pose.rotation();
  const Eigen::Vector3d ha = 0.5 * a.size;
  const Eigen::Vector3d hb = 0.5 * b.size;
  const Eigen::Vector3d d = b.pose.t - a.pose.t;
  double best = std::numeric_limits<double>::infinity();
  auto test = [&](Eigen::Vector3d axis) {
    const double n = axis.norm();
    if (n < 1e-9) return;  // parallel edges: the face axes already cover this direction
    axis /= n;
    double reach = 0.0;
    for (int i = 0; i < 3; ++i) {
      reach += std::abs(axis.dot(ra.col(i))) * ha[i] + std::abs(axis.dot(rb.col(i))) * hb[i];
    }
    best = std::min(best, reach - std::abs(axis.dot(d)));
  };
  for (int i = 0; i < 3; ++i) {
    test(ra.col(i));
    test(rb.col(i));
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) test(ra.col(i).cross(rb.col(j)));
  }
  return best;
}

double box_distance(const Box& a, const Box& b) {
  constexpr btScalar kMargin = 1e-4f;  // in Bullet units; GJK needs a non-zero margin
  const Eigen::Vector3d ha = 0.5 * a.size * kBulletScale;
  const Eigen::Vector3d hb = 0.5 * b.size * kBulletScale;
  btBoxShape sa(btVector3(static_cast<btScalar>(ha.x()), static_cast<btScalar>(ha.y()),
                          static_cast<btScalar>(ha.z())));
  btBoxShape sb(btVector3(static_cast<btScalar>(hb.x()), static_cast<btScalar>(hb.y()),
                          static_cast<btScalar>(hb.z())));
  sa.setMargin(kMargin);
  sb.setMargin(kMargin);
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector detector(&sa, &sb, &simplex, &epa);
  btGjkPairDetector::ClosestPointInput input;
  input.m_transformA = to_bullet(a.pose);
  input.m_transformB = to_bullet(b.pose);
  btPointCollector out;
  detector.getClosestPoints(input, out, nullptr);
  if (!out.m_hasResult) {
    // GJK found nothing within range: fall back on the SAT bound (always defined).
    return -sat_overlap(a, b);
  }
  return static_cast<double>(out.m_distance) / kBulletScale;
}

bool segment_hits_box(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_s,
                      const Box& b, double shrink) {
  const Eigen::Matrix3d r = b.pose.rotation();
  const Eigen::Vector3d o = r.transpose() * (origin - b.pose.t);
  const Eigen::Vector3d d = r.transpose() * dir;
  const Eigen::Vector3d h = (0.5 * b.size).array() - shrink;
  double lo = 0.0;
  double hi = max_s;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(d[i]) < 1e-15) {
      if (std::abs(o[i]) > h[i]) return false;
      continue;
    }
    double s0 = (-h[i] - o[i]) / d[i];
    double s1 = (h[i] - o[i]) / d[i];
    if (s0 > s1) std::swap(s0, s1);
    lo = std::max(lo, s0);
    hi = std::min(hi, s1);
    if (lo > hi) return false;
  }
  return true;
}

bool footprints_overlap(const Eigen::Vector2d& ca, const Eigen::Vector2d& half_a, double yaw_a,
                        const Eigen::Vector2d& cb, const Eigen::Vector2d& half_b, double yaw_b,
                        double clearance) {
  const std::array<Eigen::Vector2d, 4> axes{
      Eigen::Vector2d(std::cos(yaw_a), std::sin(yaw_a)),
      Eigen::Vector2d(-std::sin(yaw_a), std::cos(yaw_a)),
      Eigen::Vector2d(std::cos(yaw_b), std::sin(yaw_b)),
      Eigen::Vector2d(-std::sin(yaw_b), std::cos(yaw_b))};
  const Eigen::Vector2d d = cb - ca;
  for (const auto& axis : axes) {
    const double ra = std::abs(axis.dot(axes[0])) * half_a.x() + std::abs(axis.dot(axes[1])) * half_a.y();
    const double rb = std::abs(axis.dot(axes[2])) * half_b.x() + std::abs(axis.dot(axes[3])) * half_b.y();
    if (std::abs(axis.dot(d)) > ra + rb + clearance) return false;
  }
  return true;
}

}  // namespace ksmc::tools::tabletop_sim
