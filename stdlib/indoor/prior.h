// Weak prior p(W) = alpha1 * alpha2 (eq. 3.3-3.5), in log space:
//   log alpha1 = theta * log psi1, theta = number of pairs of adjacent walls (walls of two
//     different units lying within `adjacency_distance` of each other) whose included angle is
//     neither parallel nor perpendicular within `angle_tolerance`. Units are exact rectangles,
//     so a unit's own corners are always right angles; the count is over neighbouring units.
//   log alpha2 = (sum over cells of max(sigma - 1, 0)) * log psi2 (cell-wise overlap).
// Both counts are integers kept incrementally by ScoredWorld.
#pragma once

#include <cstdint>
#include <span>

#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor {

struct WeakPriorParams {
  double psi1 = 0.1;                            // in (0, 1)
  double psi2 = 0.5;                            // in (0, 1)
  double angle_tolerance = 5.0 * 3.14159265358979323846 / 180.0;  // radians
  double adjacency_distance = 2.0;              // cells
  void validate() const;                        // throws std::invalid_argument
};

// Misaligned adjacent wall pairs between two units.
int misaligned_wall_pairs(const Unit& a, const Unit& b, const WeakPriorParams& p);

// Sum of misaligned_wall_pairs over the unordered pairs of units of `world` that involve at
// least one unit of `ids` (ids absent from the world are skipped; ids must be distinct).
std::int64_t misaligned_pairs_involving(const World& world, std::span<const UnitId> ids,
                                        const WeakPriorParams& p);

// theta of the whole world (all pairs), for verification.
std::int64_t misaligned_pairs_total(const World& world, const WeakPriorParams& p);

double weak_log_prior(std::int64_t theta, std::int64_t overlap, const WeakPriorParams& p);

}  // namespace ksmc::stdlib::indoor
