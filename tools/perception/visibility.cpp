#include "tools/perception/visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "tools/tabletop_sim/box_geometry.h"

namespace ksmc::tools::perception {

namespace {

// Whether a piece of box b's seen surface, spanning lo..hi along its axes (box frame), shows
// its extents.
bool extents_shown(const tools::tabletop_sim::Box& b, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                   double tolerance) {
  if (!(lo.array() <= hi.array()).all()) return false;  // no point seen
  const Eigen::Matrix3d r = b.pose.rotation();
  const bool on_table = tools::tabletop_sim::lowest_z(b) <= tolerance;
  for (int k = 0; k < 3; ++k) {
    if (hi(k) - lo(k) >= b.size(k) - tolerance) continue;
    // Standing on the table along axis k: the table is its bottom, its top must be seen.
    const double up = r(2, k);
    const bool vertical = std::abs(up) >= std::cos(2.0 * 3.14159265358979323846 / 180.0);
    const double top = up > 0.0 ? hi(k) : -lo(k);
    if (on_table && vertical && top >= 0.5 * b.size(k) - tolerance) continue;
    return false;
  }
  return true;
}

}  // namespace

std::vector<BoxView> box_views(const tools::tabletop_sim::Camera& camera,
                               const tools::tabletop_sim::Pose& table_from_camera,
                               std::span<const tools::tabletop_sim::Box> boxes, int stride, double tolerance) {
  const std::size_t n = boxes.size();
  std::vector<long> alone(n, 0), seen(n, 0);
  const Eigen::Matrix3d r = table_from_camera.rotation();
  const Eigen::Vector3d eye = table_from_camera.t;
  const int step = std::max(1, stride);
  // The image's grid (every step-th pixel): the nearest box at each, and where its ray hits it.
  const int gu = (camera.width + step - 1) / step, gv = (camera.height + step - 1) / step;
  std::vector<std::size_t> nearest_at(static_cast<std::size_t>(gu) * static_cast<std::size_t>(gv), n);
  std::vector<Eigen::Vector3d> hit_at(nearest_at.size());
  // The image plane is read one image width and height past each border for `alone`: a box
  // the border cuts is partly unseen (before stop 44 only the pixels inside the image counted,
  // and a book whose top the border cut by a fifth read as 100 % visible).
  for (int v = -camera.height; v < 2 * camera.height; v += step)
    for (int u = -camera.width; u < 2 * camera.width; u += step) {
      const Eigen::Vector3d dir = r * Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      const bool in_image = u >= 0 && u < camera.width && v >= 0 && v < camera.height;
      double best = std::numeric_limits<double>::infinity();
      std::size_t nearest = n;
      for (std::size_t i = 0; i < n; ++i) {
        const double s = tools::tabletop_sim::ray_box(eye, dir, boxes[i]);
        if (s <= 0.0) continue;
        ++alone[i];
        if (s < best) best = s, nearest = i;
      }
      if (!in_image || nearest == n) continue;
      ++seen[nearest];
      const auto cell = static_cast<std::size_t>(v / step) * static_cast<std::size_t>(gu) + static_cast<std::size_t>(u / step);
      nearest_at[cell] = nearest;
      hit_at[cell] = eye + best * dir;
    }
  std::vector<BoxView> out(n);
  for (std::size_t i = 0; i < n; ++i)
    if (alone[i] > 0) out[i].visible = static_cast<double>(seen[i]) / static_cast<double>(alone[i]);
  // Each connected piece of a box's pixels (4-neighbours on the grid): its points' spans along
  // the box's axes. One piece must show the box whole; two ends seen either side of an occluder
  // are two pieces no cloud ties to one box by itself.
  std::vector<char> done(nearest_at.size(), 0);
  std::vector<std::size_t> todo;
  for (std::size_t start = 0; start < nearest_at.size(); ++start) {
    const std::size_t i = nearest_at[start];
    if (i == n || done[start] || out[i].extents_shown) continue;
    const Eigen::Matrix3d to_box = boxes[i].pose.rotation().transpose();
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    todo.assign(1, start);
    done[start] = 1;
    while (!todo.empty()) {
      const std::size_t c = todo.back();
      todo.pop_back();
      const Eigen::Vector3d local = to_box * (hit_at[c] - boxes[i].pose.t);
      lo = lo.cwiseMin(local);
      hi = hi.cwiseMax(local);
      const auto cu = static_cast<int>(c % static_cast<std::size_t>(gu)), cv = static_cast<int>(c / static_cast<std::size_t>(gu));
      for (const auto& [du, dv] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
        const int nu = cu + du, nv = cv + dv;
        if (nu < 0 || nu >= gu || nv < 0 || nv >= gv) continue;
        const std::size_t k = static_cast<std::size_t>(nv) * static_cast<std::size_t>(gu) + static_cast<std::size_t>(nu);
        if (nearest_at[k] != i || done[k]) continue;
        done[k] = 1;
        todo.push_back(k);
      }
    }
    out[i].extents_shown = extents_shown(boxes[i], lo, hi, tolerance);
  }
  return out;
}

}  // namespace ksmc::tools::perception
