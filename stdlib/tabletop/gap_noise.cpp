#include "stdlib/tabletop/gap_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "stdlib/tabletop/extract_stable.h"

namespace ksmc::stdlib::tabletop {

namespace {

// The boxes' footprints overlap (their xy-projections, by the separating axes of the two
// footprints' bounding rectangles — conservative for tilted boxes).
bool footprints_overlap(const Obb& a, const Obb& b) {
  auto half_extent = [](const Obb& o, const Eigen::Vector2d& axis) {
    double r = 0.0;
    for (int i = 0; i < 3; ++i) r += o.half(i) * std::abs(o.axes.col(i).head<2>().dot(axis));
    return r;
  };
  const Eigen::Vector2d d = b.center.head<2>() - a.center.head<2>();
  for (const Obb* o : {&a, &b})
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector2d axis = o->axes.col(i).head<2>();
      if (axis.norm() < 1e-6) continue;
      axis.normalize();
      if (std::abs(d.dot(axis)) > half_extent(a, axis) + half_extent(b, axis)) return false;
    }
  return true;
}

}  // namespace

double rest_gap(std::span<const Obb> boxes, std::size_t i, double stable_tol) {
  const double bottom = boxes[i].min_z();
  double best = bottom;  // the table top is at z = 0
  for (std::size_t j = 0; j < boxes.size(); ++j) {
    if (j == i || tilt_angle(boxes[j]) > stable_tol || boxes[j].max_z() >= boxes[i].center.z()) continue;
    if (!footprints_overlap(boxes[i], boxes[j])) continue;
    const double gap = bottom - boxes[j].max_z();
    if (std::abs(gap) < std::abs(best)) best = gap;
  }
  return best;
}

GapNoise gap_noise(const Scene& scene, double stable_tol, double reach) {
  std::vector<Obb> boxes;
  for (const auto& o : scene.objects) boxes.push_back(o.obb());
  std::vector<double> gaps;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (tilt_angle(boxes[i]) > stable_tol) continue;
    const double best = rest_gap(boxes, i, stable_tol);
    if (std::abs(best) <= reach) gaps.push_back(std::abs(best));
  }
  GapNoise n;
  n.gaps = gaps.size();
  if (gaps.empty()) return n;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  n.sigma = 1.4826 * gaps[gaps.size() / 2];
  return n;
}

double vertical_tolerance(const GapNoise& noise, double k, double lo, double hi, std::size_t min_gaps) {
  if (noise.gaps < min_gaps) return hi;
  return std::clamp(k * noise.sigma, lo, hi);
}

}  // namespace ksmc::stdlib::tabletop
