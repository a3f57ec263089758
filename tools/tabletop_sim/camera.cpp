#include "tools/tabletop_sim/camera.h"

#include <array>
#include <cmath>
#include <numbers>

#include "stdlib/tabletop/camera_geometry.h"

namespace ksmc::tools::tabletop_sim {

using stdlib::tabletop::look_along;

Pose draw_camera_pose(Rng& rng, const CameraPlacement& placement) {
  const Eigen::Vector3d target(rng.uniform(-placement.target_jitter, placement.target_jitter),
                               rng.uniform(-placement.target_jitter, placement.target_jitter), 0.0);
  const double azimuth = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double elevation = rng.uniform(placement.min_elevation, placement.max_elevation);
  const double distance = rng.uniform(placement.min_distance, placement.max_distance);
  const Eigen::Vector3d centre =
      target + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                          std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  Pose p;
  p.t = centre;
  p.q = look_along(target - centre);
  return p;
}

std::optional<Eigen::Vector2d> project(const Camera& camera, const Pose& table_from_camera,
                                       const Eigen::Vector3d& point_in_table) {
  const Eigen::Vector3d pc = table_from_camera.q.conjugate() * (point_in_table - table_from_camera.t);
  if (pc.z() <= 1e-6) return std::nullopt;
  return Eigen::Vector2d(camera.fx * pc.x() / pc.z() + camera.cx, camera.fy * pc.y() / pc.z() + camera.cy);
}

namespace {

bool in_image(const Camera& camera, const Eigen::Vector2d& uv, double border) {
  return uv.x() >= border && uv.y() >= border && uv.x() <= camera.width - border &&
         uv.y() <= camera.height - border;
}

struct Face {
  int axis;
  double sign;
  double weight;  // projected area seen by the camera
};

}  // namespace

std::optional<Keypoints> sample_keypoints(Rng& rng, const Camera& camera, const Pose& table_from_camera,
                                          const Box& object, std::span<const Box> occluders,
                                          const KeypointParams& params) {
  const Eigen::Matrix3d r = object.pose.rotation();
  const Eigen::Vector3d h = 0.5 * object.size;
  const Eigen::Vector3d eye = table_from_camera.t;

  std::vector<Face> faces;
  std::vector<double> weights;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      const Eigen::Vector3d normal = sign * r.col(axis);
      const Eigen::Vector3d centre = object.pose.t + normal * h[axis];
      const double cosine = normal.dot((eye - centre).normalized());
      if (cosine < 0.1) continue;  // back face or seen at a grazing angle
      const double area = object.size.prod() / object.size[axis];
      faces.push_back({axis, sign, area * cosine});
      weights.push_back(area * cosine);
    }
  }
  if (faces.empty()) return std::nullopt;

  const int wanted = rng.uniform_int(params.min_count, params.max_count);
  Keypoints kp;
  for (int attempt = 0; attempt < wanted * params.tries_per_point && static_cast<int>(kp.model.size()) < wanted;
       ++attempt) {
    const Face& f = faces[rng.weighted_index(weights)];
    Eigen::Vector3d local;
    local[f.axis] = f.sign * h[f.axis];
    for (int k = 1; k < 3; ++k) {
      const int other = (f.axis + k) % 3;
      local[other] = rng.uniform(-0.97, 0.97) * h[other];  // keep off the very edges
    }
    const Eigen::Vector3d world = object.pose.apply(local);
    const auto uv = project(camera, table_from_camera, world);
    if (!uv || !in_image(camera, *uv, params.border)) continue;
    const Eigen::Vector3d dir = world - eye;
    bool hidden = false;
    for (const Box& o : occluders) {
      if (segment_hits_box(eye, dir, 1.0 - 1e-4, o)) {
        hidden = true;
        break;
      }
    }
    if (hidden) continue;
    kp.model.push_back(local);
    kp.image.push_back(*uv);
  }
  if (static_cast<int>(kp.model.size()) < params.min_count) return std::nullopt;

  for (auto& uv : kp.image) {
    uv += Eigen::Vector2d(rng.normal(0.0, params.pixel_sigma), rng.normal(0.0, params.pixel_sigma));
    if (!rng.bernoulli(params.outlier_rate)) continue;
    const double radius = rng.uniform(params.outlier_min, params.outlier_max);
    for (int t = 0; t < 8; ++t) {
      const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
      const Eigen::Vector2d moved = uv + radius * Eigen::Vector2d(std::cos(phi), std::sin(phi));
      if (in_image(camera, moved, 0.0)) {
        uv = moved;
        ++kp.outliers;
        break;
      }
    }
  }
  return kp;
}

}  // namespace ksmc::tools::tabletop_sim
