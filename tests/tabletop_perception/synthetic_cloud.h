// Synthetic clouds for the perception tests: a dense table grid and box surfaces.
#pragma once

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "stdlib/tabletop/perception/cloud_io.h"

namespace ksmc::tests::perception {

namespace pc = ksmc::stdlib::tabletop::perception;

// Table top z = 0, |x| <= hx, |y| <= hy, grid step `step`.
inline void add_table(pc::Points& pts, double hx, double hy, double step) {
  for (double x = -hx; x <= hx; x += step)
    for (double y = -hy; y <= hy; y += step) pts.emplace_back(x, y, 0.0);
}

// Calls f(local point, axis, sign) for a grid of step `step` on each face of a box of half
// sizes `h` (box frame) for which keep(axis, sign) holds.
template <class Keep, class F>
void for_each_face_point(const Eigen::Vector3d& h, double step, Keep keep, F f) {
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      if (!keep(axis, sign)) continue;
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      for (double s = -h[a]; s <= h[a] + 1e-12; s += step)
        for (double t = -h[b]; t <= h[b] + 1e-12; t += step) {
          Eigen::Vector3d local;
          local[axis] = sign * h[axis];
          local[a] = s;
          local[b] = t;
          f(local);
        }
    }
}

// Surface grid of an upright box standing on z = 0 at (cx, cy) with yaw; the bottom face is left out.
inline void add_box(pc::Points& pts, double cx, double cy, double yaw, const Eigen::Vector3d& size, double step) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d c(cx, cy, 0.5 * size.z());
  for_each_face_point(0.5 * size, step, [](int axis, double sign) { return axis != 2 || sign > 0; },
                      [&](const Eigen::Vector3d& local) { pts.push_back(c + r * local); });
}

// Surface grid of a box at any pose, only the faces that face `sensor` (a depth view
// without occlusion by other objects); `noise` m of Gaussian noise along each axis.
inline void add_visible_box(pc::Points& pts, const Eigen::Isometry3d& pose, const Eigen::Vector3d& size, double step,
                            const Eigen::Vector3d& sensor, double noise = 0.0, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  const Eigen::Vector3d h = 0.5 * size;
  const auto faces_sensor = [&](int axis, double sign) {
    Eigen::Vector3d local_n = Eigen::Vector3d::Zero();
    local_n[axis] = sign;
    return (pose.linear() * local_n).dot(sensor - pose * (h[axis] * local_n)) > 0.0;
  };
  for_each_face_point(h, step, faces_sensor, [&](const Eigen::Vector3d& local) {
    Eigen::Vector3d p = pose * local;
    if (noise > 0.0) p += Eigen::Vector3d(n(rng), n(rng), n(rng)) * noise;
    pts.push_back(p);
  });
}

// Maps table-frame points into a tilted "camera" frame, so the front end must find the plane.
inline pc::Points to_sensor(const pc::Points& pts, const Eigen::Isometry3d& sensor_from_table) {
  pc::Points out;
  for (const auto& p : pts) out.push_back(sensor_from_table * p);
  return out;
}

inline Eigen::Isometry3d example_sensor_pose() {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = (Eigen::AngleAxisd(2.2, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()))
                   .toRotationMatrix();
  t.translation() = Eigen::Vector3d(0.05, -0.1, 0.9);
  return t;
}

}  // namespace ksmc::tests::perception
