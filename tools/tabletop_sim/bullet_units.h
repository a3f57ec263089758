// Conversions between the generator's SI/Eigen world and Bullet's single-precision units.
// Bullet's tolerances (contact breaking threshold 0.02, split-impulse threshold 0.04, ...) are
// tuned for objects of roughly 0.1-10 units; household boxes are 2-30 cm, so Bullet works in
// decimetres and every length crossing this boundary is scaled by kBulletScale.
#pragma once

#include <LinearMath/btTransform.h>

#include "tools/tabletop_sim/pose.h"

namespace ksmc::tools::tabletop_sim {

inline constexpr double kBulletScale = 10.0;  // Bullet units per metre

inline btVector3 to_bullet_vector(const Eigen::Vector3d& v) {
  return btVector3(static_cast<btScalar>(v.x() * kBulletScale), static_cast<btScalar>(v.y() * kBulletScale),
                   static_cast<btScalar>(v.z() * kBulletScale));
}

inline btTransform to_bullet(const Pose& p) {
  const Eigen::Quaterniond q = p.q.normalized();
  return btTransform(btQuaternion(static_cast<btScalar>(q.x()), static_cast<btScalar>(q.y()),
                                  static_cast<btScalar>(q.z()), static_cast<btScalar>(q.w())),
                     to_bullet_vector(p.t));
}

inline Pose from_bullet(const btTransform& tr) {
  Pose p;
  const btVector3& o = tr.getOrigin();
  p.t = Eigen::Vector3d(o.x(), o.y(), o.z()) / kBulletScale;
  const btQuaternion r = tr.getRotation();
  p.q = Eigen::Quaterniond(r.w(), r.x(), r.y(), r.z()).normalized();
  return p;
}

}  // namespace ksmc::tools::tabletop_sim
