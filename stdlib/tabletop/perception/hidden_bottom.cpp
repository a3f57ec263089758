#include "stdlib/tabletop/perception/hidden_bottom.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>


namespace ksmc::stdlib::tabletop::perception {

SpaceUnder rays_under(const UprightBox& box, const RayIndex& rays, const HiddenBottomOptions& options, double floor) {
  const double bottom = bottom_height(box);
  const Eigen::Vector3d half(0.5 * box.size.x() - options.inset, 0.5 * box.size.y() - options.inset,
                             0.5 * (bottom - floor) - options.inset);
  if (half.minCoeff() <= 0.0) return {};
  Obb under;
  under.center = Eigen::Vector3d(box.pose.t.x(), box.pose.t.y(), 0.5 * (bottom + floor));
  under.axes = box.pose.q.toRotationMatrix();
  under.half = half;
  return rays_meeting(under, {Obb::from_pose(box.pose, box.size)}, rays, options.margin);
}

int grow_hidden_bottoms(std::vector<UprightBox>& boxes, const RayIndex& rays, double float_gap,
                        const HiddenBottomOptions& options) {
  if (!options.enabled) return 0;
  std::vector<Obb> solid;
  for (const UprightBox& b : boxes) solid.push_back(Obb::from_pose(b.pose, b.size));
  // 5 x 5 points spanning `box`'s footprint (edges included), `dz` along its axis 2 from its centre.
  const auto footprint_grid = [](const UprightBox& box, double dz) {
    const Eigen::Matrix3d r = box.pose.q.toRotationMatrix();
    std::array<Eigen::Vector3d, 25> grid;
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        const Eigen::Vector3d local((i / 4.0 - 0.5) * box.size.x(), (j / 4.0 - 0.5) * box.size.y(), dz);
        grid[static_cast<std::size_t>(5 * i + j)] = box.pose.t + r * local;
      }
    return grid;
  };
  // Only an upright box holds another: a box leaning on this one's side reaches under the
  // edge of its footprint and holds nothing (a box seen as its top, a leaning box's upper edge
  // against its side, was left floating and called hidden).
  std::vector<bool> holds(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) holds[k] = is_upright(boxes[k]);
  // Whether a box other than `self` holds one of the footprint's points `rest_depth` below its bottom.
  const auto rests_on_another = [&](const UprightBox& box, std::size_t self) {
    for (const Eigen::Vector3d& p : footprint_grid(box, -0.5 * box.size.z() - options.rest_depth))
      for (std::size_t k = 0; k < solid.size(); ++k)
        if (k != self && holds[k] && solid[k].contains(p, 0.5 * options.rest_depth)) return true;
    return false;
  };
  // Whether `p` (a height aside) lies over `box`'s footprint shrunk by `inset`.
  const auto over_footprint = [&options](const UprightBox& box, const Eigen::Vector3d& p) {
    const Eigen::Vector3d l = box.pose.q.conjugate() * (p - box.pose.t);
    return std::abs(l.x()) <= 0.5 * box.size.x() - options.inset && std::abs(l.y()) <= 0.5 * box.size.y() - options.inset;
  };
  // The surface under `box`: the highest top, at most `rest_depth` above its bottom, of the
  // boxes other than `self` under one of its footprint's points, or with a point of their top
  // under its footprint (inset: a box flush beside it is not under it; a narrow strip, all a
  // lower box showed of itself, falls between the footprint's points), and that box; the table
  // (0, no box) when none.
  constexpr std::size_t kTable = std::numeric_limits<std::size_t>::max();
  const auto floor_under = [&](const UprightBox& box, std::size_t self) {
    const double bottom = bottom_height(box);
    const std::array<Eigen::Vector3d, 25> grid = footprint_grid(box, 0.0);
    std::pair<double, std::size_t> floor{0.0, kTable};
    for (std::size_t k = 0; k < solid.size(); ++k) {
      const double top = solid[k].max_z();
      if (k == self || !holds[k] || top > bottom + options.rest_depth || top <= floor.first) continue;
      const auto holds_point = [&](const Eigen::Vector3d& p) {
        return solid[k].contains(Eigen::Vector3d(p.x(), p.y(), top - 0.5 * options.rest_depth), 0.5 * options.rest_depth);
      };
      const auto under_box = [&](const Eigen::Vector3d& q) { return over_footprint(box, q); };
      const std::array<Eigen::Vector3d, 25> its_top = footprint_grid(boxes[k], 0.5 * boxes[k].size.z());
      if (std::any_of(grid.begin(), grid.end(), holds_point) || std::any_of(its_top.begin(), its_top.end(), under_box))
        floor = {top, k};
    }
    return floor;
  };
  const auto hidden = [&options](const SpaceUnder& s) {
    const std::size_t all = s.before + s.inside + s.through;
    return s.before >= options.min_rays && static_cast<double>(s.before) >= options.hidden_share * static_cast<double>(all);
  };
  // `box` spans `lo` to `hi` (heights), its footprint kept.
  const auto span = [](UprightBox& box, double lo, double hi) {
    box.size.z() = hi - lo;
    box.pose.t.z() = 0.5 * (lo + hi);
  };
  int grown = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    UprightBox& box = boxes[i];
    if (!is_upright(box)) continue;
    const double bottom = bottom_height(box);
    const auto [floor, under] = floor_under(box, i);
    const bool floats = bottom > float_gap && !rests_on_another(box, i);
    if (floats && bottom - floor > float_gap) {
      if (hidden(rays_under(box, rays, options, floor))) {
        span(box, floor, bottom + box.size.z());
        solid[i] = Obb::from_pose(box.pose, box.size);
        ++grown;
        continue;
      }
    } else if (bottom - floor <= options.close_gap) {
      continue;  // on the table or on a box, or over one with a gap too thin to probe
    }
    // The space under the box is not hidden as a whole (seen past the box under it), or the gap
    // to the box under it is narrower than float_gap: the column over that box may be hidden,
    // its top by this box, which lies on it and overhangs it. Rays that end on this box count
    // as hiding it; the lower box's own do not.
    if (under == kTable || !is_upright(boxes[under])) continue;
    UprightBox& lower = boxes[under];
    Obb column;  // the lower box's footprint (inset, at most to half its width) up to this box's bottom
    column.axes = lower.pose.q.toRotationMatrix();
    column.center = Eigen::Vector3d(lower.pose.t.x(), lower.pose.t.y(), 0.5 * (floor + bottom));
    for (int a = 0; a < 2; ++a)
      column.half(a) = std::max(0.5 * lower.size(a) - options.inset, 0.25 * lower.size(a));
    column.half.z() = 0.5 * (bottom - floor) - options.inset;
    if (column.half.z() <= 0.0) continue;
    if (!hidden(rays_meeting(column, {solid[under]}, rays, options.margin))) continue;
    span(lower, bottom_height(lower), bottom);
    solid[under] = Obb::from_pose(lower.pose, lower.size);
    ++grown;
  }
  return grown;
}

}  // namespace ksmc::stdlib::tabletop::perception
