// Synthetic clouds for the perception tests: a dense table grid and box surfaces.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

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

// The height, relative to its centre, of the lowest corner of a box of `size` turned by
// `rotation` (at most 0).
inline double lowest_corner(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& size) {
  double low = 0.0;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d corner((c & 1 ? 0.5 : -0.5) * size.x(), (c & 2 ? 0.5 : -0.5) * size.y(), (c & 4 ? 0.5 : -0.5) * size.z());
    low = std::min(low, (rotation * corner).z());
  }
  return low;
}

// A box of `size` turned by `rotation`, its centre over (x, y), its lowest corner on z = 0.
inline Eigen::Isometry3d on_table(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& size, double x = 0.0,
                                  double y = 0.0) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = rotation;
  p.translation() = Eigen::Vector3d(x, y, -lowest_corner(rotation, size));
  return p;
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

// A depth view by ray casting: rays from `sensor` through a grid of `step` radians around
// the direction to `target` (half-width `fov` radians), each keeping its nearest hit among
// the boxes (pose, size) and the table top z = 0 (|x| <= hx, |y| <= hy). Occlusion included.
struct CastBox {
  Eigen::Isometry3d pose;
  Eigen::Vector3d size;
};
inline pc::Points cast_view(const Eigen::Vector3d& sensor, const Eigen::Vector3d& target, double fov, double step,
                            const std::vector<CastBox>& boxes, double hx, double hy) {
  const Eigen::Vector3d f = (target - sensor).normalized();
  const Eigen::Vector3d right = f.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d up = right.cross(f);
  pc::Points out;
  for (double a = -fov; a <= fov; a += step)
    for (double b = -fov; b <= fov; b += step) {
      const Eigen::Vector3d d = (f + std::tan(a) * right + std::tan(b) * up).normalized();
      double best = d.z() < 0.0 ? -sensor.z() / d.z() : 1e9;
      const Eigen::Vector3d on_table = sensor + best * d;
      if (std::abs(on_table.x()) > hx || std::abs(on_table.y()) > hy) best = 1e9;
      for (const CastBox& box : boxes) {
        const Eigen::Vector3d o = box.pose.inverse() * sensor, l = box.pose.linear().transpose() * d;
        double enter = 0.0, leave = 1e9;
        for (int k = 0; k < 3; ++k) {
          if (std::abs(l[k]) < 1e-12) {
            if (std::abs(o[k]) > 0.5 * box.size[k]) leave = -1.0;
            continue;
          }
          double s0 = (-0.5 * box.size[k] - o[k]) / l[k], s1 = (0.5 * box.size[k] - o[k]) / l[k];
          if (s0 > s1) std::swap(s0, s1);
          enter = std::max(enter, s0);
          leave = std::min(leave, s1);
        }
        if (enter <= leave && enter < best) best = enter;
      }
      if (best < 1e9) out.push_back(sensor + best * d);
    }
  return out;
}

// An upright box for cast_view: (cx, cy) centre, bottom face at `bottom`, turned `yaw` about z.
inline CastBox upright_box(double cx, double cy, double bottom, const Eigen::Vector3d& size, double yaw = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(cx, cy, bottom + 0.5 * size.z());
  return {pose, size};
}

// Maps table-frame points into a tilted "camera" frame, so the front end must find the plane.
inline pc::Points to_sensor(const pc::Points& pts, const Eigen::Isometry3d& sensor_from_table) {
  pc::Points out;
  for (const auto& p : pts) out.push_back(sensor_from_table * p);
  return out;
}

// A view of `boxes` on a 1.0 x 0.8 m table from `sensor` toward (0, 0.05, 0.05), 0.35 rad
// half-width, 0.0015 rad steps: in the table frame, and in the sensor's own frame (the sensor
// at the origin, axes as the table's), as scene_from_points takes a depth camera's cloud.
inline pc::Points table_view(const Eigen::Vector3d& sensor, const std::vector<CastBox>& boxes) {
  return cast_view(sensor, Eigen::Vector3d(0.0, 0.05, 0.05), 0.35, 0.0015, boxes, 0.5, 0.4);
}
inline pc::Points sensor_view(const Eigen::Vector3d& sensor, const std::vector<CastBox>& boxes) {
  Eigen::Isometry3d sensor_from_table = Eigen::Isometry3d::Identity();
  sensor_from_table.translation() = -sensor;
  return to_sensor(table_view(sensor, boxes), sensor_from_table);
}

inline Eigen::Isometry3d example_sensor_pose() {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = (Eigen::AngleAxisd(2.2, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()))
                   .toRotationMatrix();
  t.translation() = Eigen::Vector3d(0.05, -0.1, 0.9);
  return t;
}

}  // namespace ksmc::tests::perception
