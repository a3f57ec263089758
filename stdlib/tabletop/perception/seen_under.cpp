#include "stdlib/tabletop/perception/seen_under.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "stdlib/tabletop/line_of_sight.h"
#include "stdlib/tabletop/perception/footprint.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

// Whether the points under the cut stand back from `box`'s outline by options.margin on some
// side (their 2 % and 98 % quantiles along its axes): faces of a narrower box under it.
bool set_back(const UprightBox& box, const Points& lower, const SeenUnderOptions& options) {
  const Eigen::Matrix3d r = box.pose.q.toRotationMatrix();
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<double> c;
    c.reserve(lower.size());
    for (const auto& p : lower) c.push_back(r.col(axis).dot(p - box.pose.t));
    std::sort(c.begin(), c.end());
    const double lo = c[c.size() / 50], hi = c[c.size() - 1 - c.size() / 50];
    const double half = 0.5 * box.size[axis];
    if (lo > -half + options.margin || hi < half - options.margin) return true;
  }
  return false;
}

// The column under `box`'s top face (SeenUnderOptions::top_band): the minimal rectangle of the
// points within top_band of its top, over the box's height; the box itself when the top has
// fewer than min_top_points.
UprightBox under_top(const UprightBox& box, const Points& points, const SeenUnderOptions& options) {
  const double top = bottom_height(box) + box.size.z();
  std::vector<Eigen::Vector2d> face;
  for (const auto& p : points)
    if (p.z() >= top - options.top_band) face.emplace_back(p.x(), p.y());
  if (face.size() < options.min_top_points) return box;
  const Rect2 r = min_area_rect(face, options.top_trim);
  UprightBox column = box;
  column.pose.t.head<2>() = r.center;
  column.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(std::atan2(r.u.y(), r.u.x()), Eigen::Vector3d::UnitZ()));
  column.size.head<2>() = 2.0 * r.half;
  return column;
}

}  // namespace

double seen_under_height(const UprightBox& box, const RayIndex& rays, const SeenUnderOptions& options) {
  const FreeSpace& seen = rays.free_space();
  Obb solid;
  solid.center = box.pose.t;
  solid.axes = box.pose.q.toRotationMatrix();
  solid.half = Eigen::Vector3d(0.5 * box.size.x() - options.inset, 0.5 * box.size.y() - options.inset, 0.5 * box.size.z());
  if (solid.half.x() <= 0.0 || solid.half.y() <= 0.0 || options.min_rays == 0) return 0.0;
  const Eigen::Vector3d o = in_box_axes(solid, seen.sensor - solid.center);
  const Eigen::Vector3d half = 0.5 * box.size;
  std::vector<double> highest;  // per crossing ray, the highest z of its part inside the box
  rays.for_each_toward(solid, [&](std::size_t ray) {
    const Eigen::Vector3d& p = seen.points[ray];
    // Points on the box's side faces (within `margin` of them) are its own surface; depth
    // noise along a grazing ray would carry their lines of sight into it.
    const Eigen::Vector3d l = in_box_axes(solid, p - solid.center).cwiseAbs();
    const double side = std::max(l.x() - half.x(), l.y() - half.y());
    if (l.z() <= half.z() + options.margin && side > -options.margin && side <= options.margin) return;
    const Eigen::Vector3d seg = p - seen.sensor;
    const double len = seg.norm();
    if (len <= options.margin) return;
    double enter = 0.0, leave = 1.0 - options.margin / len;
    if (!slab_span(solid, o, in_box_axes(solid, seg), enter, leave)) return;
    highest.push_back(seen.sensor.z() + std::max(enter * seg.z(), leave * seg.z()));
  });
  if (highest.size() < options.min_rays) return 0.0;
  const auto kth = highest.begin() + static_cast<std::ptrdiff_t>(options.min_rays - 1);
  std::nth_element(highest.begin(), kth, highest.end(), std::greater<>());
  return *kth;
}

std::vector<UprightBox> cut_seen_under(const UprightBox& box, const Points& points, const RayIndex& rays,
                                       const BoxFitOptions& fit, const SideStepOptions& sides,
                                       const SeenUnderOptions& options) {
  if (!options.enabled) return {};
  if (!is_upright(box)) return {};
  const double bottom = bottom_height(box), top = bottom + box.size.z();
  const double base = bottom > fit.float_gap ? bottom : 0.0;  // a floating box's lower part floats too
  double cut = seen_under_height(box, rays, options);
  if (top - cut < options.min_upper && options.top_band > 0.0) {  // the strips of a merged box: its top alone
    const UprightBox column = under_top(box, points, options);
    const auto sides_of = [](const UprightBox& b) {  // short side, long side
      return std::pair{std::min(b.size.x(), b.size.y()), std::max(b.size.x(), b.size.y())};
    };
    const auto [box_short, box_long] = sides_of(box);
    const auto [top_short, top_long] = sides_of(column);
    const bool narrower = std::max(box_short - top_short, box_long - top_long) > options.top_excess;
    if (narrower && top_short * top_long >= options.top_cover * box_short * box_long)
      cut = seen_under_height(column, rays, options);
  }
  if (cut <= base + options.min_cut || top - cut < options.min_upper) return {};
  Points upper, lower;
  for (const auto& p : points) (p.z() > cut ? upper : lower).push_back(p);
  if (upper.size() < options.min_points) return {};
  const bool lower_box = lower.size() >= options.min_points;
  if (lower_box && !set_back(box, lower, options)) return {};
  std::vector<UprightBox> out;
  if (lower_box) out = fit_column(lower, base, fit, sides);
  for (const UprightBox& b : fit_column(upper, cut, fit, sides)) out.push_back(b);
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
