// The data-driven detector behind BIRTH (`detect.ransac`): candidate segments found by
// RANSAC on the whole cloud once per run (seeded), each refined by a total-least-squares fit
// of its inlier run and cut at gaps wider than `max_gap`. Near-duplicates are dropped.
#pragma once

#include <cstdint>
#include <vector>

#include "stdlib/segments/geometry.h"

namespace ksmc::stdlib::segments {

struct RansacParams {
  int min_inliers = 8;
  double inlier_dist = 0.03;  // metres
  int candidates = 300;       // at most this many candidates
  double max_gap = 0.30;      // metres: a larger gap between inliers ends a run
  bool operator==(const RansacParams&) const = default;
};

struct Candidate {
  Segment seg;                           // canonical
  std::vector<std::uint32_t> inliers;    // points within inlier_dist of the segment
};

// Deterministic for a given cloud, params and seed (own RNG stream). Candidate order is
// the order found.
std::vector<Candidate> detect_candidates(const std::vector<Vec2>& points, const RansacParams& params,
                                         std::uint64_t seed);

}  // namespace ksmc::stdlib::segments
