#include "tools/tabletop_sim/corruption.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ksmc::tools::tabletop_sim {

bool estimate_is_consistent(std::span<const Box> boxes, const Relations& rel, const std::vector<bool>& removed,
                            const CorruptionParams& params) {
  const auto hidden = hidden_boxes(boxes.size(), rel, removed);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (removed[i]) continue;
    if (hidden[i]) {
      if (lowest_z(boxes[i]) <= params.min_hidden_height) return false;
      continue;
    }
    const int ii = static_cast<int>(i);
    bool touches_present = false;
    bool touched_removed = false;
    auto visit = [&](int other) {
      if (other == kTableIndex || !removed[static_cast<std::size_t>(other)]) {
        touches_present = true;
      } else {
        touched_removed = true;
      }
    };
    for (const auto& [a, b] : rel.support) {
      if (a == ii) visit(b);
      if (b == ii) visit(a);
    }
    for (const auto& [a, b] : rel.contact) {
      if (a == ii) visit(b);
      if (b == ii) visit(a);
    }
    if (touched_removed && !touches_present) return false;  // would hover without being "hidden"
  }
  return true;
}

std::vector<bool> hidden_boxes(std::size_t count, const Relations& rel, const std::vector<bool>& removed) {
  std::vector<bool> has_object_support(count, false);
  std::vector<bool> has_present_support(count, false);
  for (const auto& [upper, lower] : rel.support) {
    const auto u = static_cast<std::size_t>(upper);
    if (lower == kTableIndex) {
      has_present_support[u] = true;
      continue;
    }
    has_object_support[u] = true;
    if (!removed[static_cast<std::size_t>(lower)]) has_present_support[u] = true;
  }
  std::vector<bool> hidden(count, false);
  for (std::size_t i = 0; i < count; ++i) {
    hidden[i] = !removed[i] && has_object_support[i] && !has_present_support[i];
  }
  return hidden;
}

std::vector<bool> choose_undetected(Rng& rng, std::span<const Box> boxes, const Relations& rel,
                                    const CorruptionParams& params) {
  std::vector<bool> removed(boxes.size(), false);
  std::vector<bool> supporter(boxes.size(), false);
  for (const auto& [upper, lower] : rel.support) {
    if (lower != kTableIndex) supporter[static_cast<std::size_t>(lower)] = true;
  }
  for (std::size_t j = 0; j < boxes.size(); ++j) {
    if (!supporter[j] || !rng.bernoulli(params.hidden_rate)) continue;
    removed[j] = true;
    const bool leaves_one = std::count(removed.begin(), removed.end(), false) > 0;
    if (!leaves_one || !estimate_is_consistent(boxes, rel, removed, params)) removed[j] = false;
  }
  return removed;
}

std::string_view to_string(FalseKind kind) {
  switch (kind) {
    case FalseKind::none: return "none";
    case FalseKind::extra_intersecting: return "extra_intersecting";
    case FalseKind::moved_intersecting: return "moved_intersecting";
    case FalseKind::extra_floating: return "extra_floating";
    case FalseKind::moved_floating: return "moved_floating";
    case FalseKind::shifted_copy: return "shifted_copy";
    case FalseKind::duplicate: return "duplicate";
    case FalseKind::wrong_size: return "wrong_size";
    case FalseKind::flipped: return "flipped";
  }
  return "none";
}

std::optional<Box> place_intersecting(Rng& rng, const BoxItem& item, const Box& target, const CorruptionParams& params) {
  for (int attempt = 0; attempt < 30; ++attempt) {
    Box b;
    b.size = item.size;
    b.pose.q = rng.bernoulli(0.5) ? yaw_rotation(rng.uniform(0.0, 2.0 * std::numbers::pi)) : uniform_rotation(rng);
    // Direction away from the target's centre, mostly sideways/upwards.
    const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const double z = rng.uniform(-0.2, 0.9);
    const double rxy = std::sqrt(1.0 - z * z);
    const Eigen::Vector3d dir(rxy * std::cos(phi), rxy * std::sin(phi), z);
    const double depth = rng.uniform(params.min_penetration, params.max_penetration);
    auto overlap_at = [&](double s) {
      b.pose.t = target.pose.t + s * dir;
      return sat_overlap(b, target);
    };
    if (overlap_at(0.0) < depth) continue;  // both too thin for this depth
    double lo = 0.0;
    double hi = 0.5 * (b.size.norm() + target.size.norm()) + 0.01;
    if (overlap_at(hi) >= depth) continue;
    for (int it = 0; it < 50; ++it) {  // overlap decreases along the ray: bisect for the depth
      const double mid = 0.5 * (lo + hi);
      (overlap_at(mid) >= depth ? lo : hi) = mid;
    }
    overlap_at(lo);
    if (lowest_z(b) < -0.002) continue;  // keep it out of the table top
    return b;
  }
  return std::nullopt;
}

std::optional<Box> place_floating(Rng& rng, const BoxItem& item, std::span<const Box> others,
                                  const Eigen::Vector2d& region, const CorruptionParams& params) {
  for (int attempt = 0; attempt < 60; ++attempt) {
    Box b;
    b.size = item.size;
    const int up = static_cast<int>(rng.weighted_index(item.vertical_axis_odds));
    Eigen::Quaterniond base = Eigen::Quaterniond::Identity();
    if (up == 0) base = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY());
    if (up == 1) base = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX());
    const double tilt = rng.uniform(params.min_float_tilt, params.max_float_tilt);
    b.pose.q = (random_tilt(rng, tilt) * yaw_rotation(rng.uniform(0.0, 2.0 * std::numbers::pi)) * base).normalized();
    b.pose.t = Eigen::Vector3d(rng.uniform(-region.x(), region.x()), rng.uniform(-region.y(), region.y()), 0.0);
    b.pose.t.z() += params.min_float_gap + rng.uniform(0.0, 0.12) - lowest_z(b);
    const bool clear = std::all_of(others.begin(), others.end(), [&](const Box& o) {
      return -sat_overlap(b, o) >= params.min_float_gap || box_distance(b, o) >= params.min_float_gap;
    });
    if (clear) return b;
  }
  return std::nullopt;
}

Pose add_pose_noise(Rng& rng, const Pose& pose, const CorruptionParams& params) {
  const double st = params.sigma_translation / std::sqrt(3.0);
  const double sr = params.sigma_rotation / std::sqrt(3.0);
  Pose p = pose;
  p.t += Eigen::Vector3d(rng.normal(0, st), rng.normal(0, st), rng.normal(0, st));
  const Eigen::Vector3d w(rng.normal(0, sr), rng.normal(0, sr), rng.normal(0, sr));
  const double angle = w.norm();
  if (angle > 0.0) p.q = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, w / angle)) * p.q).normalized();
  return p;
}

}  // namespace ksmc::tools::tabletop_sim
