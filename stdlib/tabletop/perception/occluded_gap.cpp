#include "stdlib/tabletop/perception/occluded_gap.h"

#include <cmath>

#include "stdlib/tabletop/perception/ray_meeting.h"

namespace ksmc::stdlib::tabletop::perception {

std::optional<UprightBox> bridge_occluded_gap(const UprightBox& a, const UprightBox& b, const RayIndex& rays,
                                              const OccludedGapOptions& o) {
  if (!o.enabled || !is_upright(a) || !is_upright(b)) return std::nullopt;
  if (std::abs(bottom_height(a) - bottom_height(b)) > o.tolerance || std::abs(a.size.z() - b.size.z()) > o.tolerance)
    return std::nullopt;
  const Eigen::Matrix3d ra = a.pose.q.toRotationMatrix(), rb = b.pose.q.toRotationMatrix();
  const Eigen::Vector3d between = b.pose.t - a.pose.t;
  // a's side along the line between the two, and b's side along a's.
  const int k = std::abs(ra.col(0).dot(between)) >= std::abs(ra.col(1).dot(between)) ? 0 : 1;
  const int kb = std::abs(rb.col(0).dot(ra.col(k))) >= std::abs(rb.col(1).dot(ra.col(k))) ? 0 : 1;
  if (std::abs(rb.col(kb).dot(ra.col(k))) < std::cos(o.max_turn_deg * 3.14159265358979323846 / 180.0))
    return std::nullopt;
  const Eigen::Vector3d along = ra.col(k), across = ra.col(1 - k);
  if (std::abs(between.dot(across)) > o.tolerance || std::abs(a.size(1 - k) - b.size(1 - kb)) > o.tolerance)
    return std::nullopt;
  const double d = between.dot(along), sign = d >= 0.0 ? 1.0 : -1.0;
  const double gap = std::abs(d) - 0.5 * (a.size(k) + b.size(kb));
  if (gap < o.min_gap || gap > o.max_gap) return std::nullopt;

  const double bottom = std::min(bottom_height(a), bottom_height(b));
  const double top = std::max(bottom_height(a) + a.size.z(), bottom_height(b) + b.size.z());
  const double width = 0.5 * (a.size(1 - k) + b.size(1 - kb));
  Obb space;  // the hidden middle
  space.axes = ra;
  space.center = a.pose.t + (sign * 0.5 * (a.size(k) + gap)) * along;
  space.center.z() = 0.5 * (bottom + top);
  space.half(k) = 0.5 * gap - o.inset;
  space.half(1 - k) = 0.5 * width - o.inset;
  space.half(2) = 0.5 * (top - bottom) - o.inset;
  if (space.half.minCoeff() <= 0.0) return std::nullopt;
  const SpaceUnder s = rays_meeting(space, {Obb::from_pose(a.pose, a.size), Obb::from_pose(b.pose, b.size)}, rays, o.margin);
  const std::size_t all = s.before + s.inside + s.through;
  if (s.before < o.min_rays || static_cast<double>(s.before) < o.hidden_share * static_cast<double>(all))
    return std::nullopt;

  // From a's far end to b's far end, a's turn, the two's mean cross-section.
  const double from = -0.5 * a.size(k), to = std::abs(d) + 0.5 * b.size(kb);
  UprightBox out = a;
  out.size(k) = to - from;
  out.size(1 - k) = width;
  out.size.z() = top - bottom;
  out.pose.t = a.pose.t + (sign * 0.5 * (from + to)) * along + (0.5 * between.dot(across)) * across;
  out.pose.t.z() = 0.5 * (bottom + top);
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
