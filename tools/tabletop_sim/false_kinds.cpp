#include "tools/tabletop_sim/false_kinds.h"

#include <cmath>
#include <numbers>

namespace ksmc::tools::tabletop_sim {

std::optional<Box> shifted_copy(Rng& rng, const Box& original, const FalseKindParams& params) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const Eigen::Vector3d dir(std::cos(phi), std::sin(phi), 0.0);
    const double depth = rng.uniform(params.min_shift, params.max_shift);
    Box b = original;
    auto overlap_at = [&](double s) {
      b.pose.t = original.pose.t + s * dir;
      return sat_overlap(b, original);
    };
    double lo = 0.0;
    double hi = original.size.norm() + 0.01;
    if (overlap_at(lo) < depth || overlap_at(hi) >= depth) continue;
    for (int it = 0; it < 50; ++it) {
      const double mid = 0.5 * (lo + hi);
      (overlap_at(mid) >= depth ? lo : hi) = mid;
    }
    overlap_at(lo);
    return b;
  }
  return std::nullopt;
}

std::optional<Box> duplicate_detection(Rng& rng, const Box& original, const FalseKindParams& params) {
  Box b = original;
  const Eigen::Vector3d dir = rotation_about_random_axis(rng, rng.uniform(0.0, std::numbers::pi)) * Eigen::Vector3d::UnitX();
  b.pose.t += rng.uniform(params.min_duplicate_offset, params.max_duplicate_offset) * dir.normalized();
  b.pose.q = (rotation_about_random_axis(rng, rng.uniform(params.min_duplicate_turn, params.max_duplicate_turn)) *
              original.pose.q).normalized();
  if (lowest_z(b) < -0.004) b.pose.t.z() += -0.004 - lowest_z(b);  // no deeper into the table than noise puts it
  return b;
}

std::optional<Box> wrong_size(Rng& rng, const Box& original, const FalseKindParams& params) {
  const int up = vertical_axis(original.pose.q);
  for (int attempt = 0; attempt < 10; ++attempt) {
    Box b = original;
    const double factor = rng.bernoulli(0.5) ? rng.uniform(0.5, 0.75) : rng.uniform(1.35, 1.7);
    b.size[up] *= factor;
    if (rng.bernoulli(0.5)) {
      const int other = (up + 1 + rng.uniform_int(0, 1)) % 3;
      b.size[other] *= rng.bernoulli(0.5) ? rng.uniform(0.6, 0.8) : rng.uniform(1.25, 1.5);
    }
    if (std::abs(b.size[up] - original.size[up]) >= params.min_size_error) return b;
  }
  return std::nullopt;
}

std::optional<Box> flipped(Rng& rng, const Box& original, const FalseKindParams& params) {
  const int up = vertical_axis(original.pose.q);
  const int axis = (up + 1 + rng.uniform_int(0, 1)) % 3;  // turn about this horizontal axis
  const int new_up = 3 - up - axis;
  if (std::abs(original.size[new_up] - original.size[up]) < params.min_flip_change) return std::nullopt;
  Box b = original;
  const Eigen::Vector3d world_axis = original.pose.q * Eigen::Vector3d::Unit(axis);
  b.pose.q = (Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, world_axis)) * original.pose.q).normalized();
  return b;
}

}  // namespace ksmc::tools::tabletop_sim
