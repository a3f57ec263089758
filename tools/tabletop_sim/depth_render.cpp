#include "tools/tabletop_sim/depth_render.h"

#include <cmath>
#include <limits>

#include "stdlib/tabletop/camera_geometry.h"

namespace ksmc::tools::tabletop_sim {

using stdlib::tabletop::ray_enter_box;

double ray_box(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, const Box& box) {
  const Eigen::Matrix3d r = box.pose.rotation();
  const Eigen::Vector3d o = r.transpose() * (origin - box.pose.t);
  const Eigen::Vector3d d = r.transpose() * dir;
  return ray_enter_box(o, d, 0.5 * box.size);  // -1 also when the origin is inside the box
}

std::vector<Eigen::Vector3d> render_depth(Rng& rng, const Camera& camera, const Pose& table_from_camera,
                                          std::span<const Box> boxes, const TableSpec& table, const DepthParams& params) {
  std::vector<Eigen::Vector3d> out;
  const Eigen::Matrix3d r = table_from_camera.rotation();
  const Eigen::Vector3d eye = table_from_camera.t;
  const int step = std::max(1, params.stride);
  for (int v = 0; v < camera.height; v += step) {
    for (int u = 0; u < camera.width; u += step) {
      const Eigen::Vector3d ray_cam((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      const Eigen::Vector3d dir = r * ray_cam;  // s along dir = depth z
      double best = std::numeric_limits<double>::infinity();
      if (dir.z() < 0.0 && eye.z() > 0.0) {
        const double s = -eye.z() / dir.z();
        const Eigen::Vector3d hit = eye + s * dir;
        if (std::abs(hit.x()) <= table.half_extent.x() && std::abs(hit.y()) <= table.half_extent.y()) best = s;
      }
      for (const Box& b : boxes) {
        const double s = ray_box(eye, dir, b);
        if (s > 0.0 && s < best) best = s;
      }
      const bool missing = params.missing_rate > 0.0 && rng.bernoulli(params.missing_rate);
      const bool hit = std::isfinite(best) && best <= params.max_depth;
      const double noise = rng.normal(0.0, hit ? params.sigma_at_1m * best * best : 0.0);  // drawn always
      if (!hit || missing) continue;
      out.push_back((best + noise) * ray_cam);
    }
  }
  return out;
}

}  // namespace ksmc::tools::tabletop_sim
