#include "stdlib/segments/detect.h"

#include <algorithm>
#include <cmath>

#include "runtime/io/cancel.h"
#include "runtime/mcmc/rng.h"

namespace ksmc::stdlib::segments {

namespace {

// Total-least-squares line of the points; returns the segment spanning their projections.
Segment fit(const std::vector<Vec2>& pts, const std::vector<std::uint32_t>& idx) {
  Vec2 c{};
  for (auto i : idx) c = c + pts[i];
  c = (1.0 / static_cast<double>(idx.size())) * c;
  double sxx = 0, sxy = 0, syy = 0;
  for (auto i : idx) {
    const Vec2 d = pts[i] - c;
    sxx += d.x * d.x;
    sxy += d.x * d.y;
    syy += d.y * d.y;
  }
  const double theta = 0.5 * std::atan2(2.0 * sxy, sxx - syy);  // principal axis
  const Vec2 u{std::cos(theta), std::sin(theta)};
  double lo = 0, hi = 0;
  bool first = true;
  for (auto i : idx) {
    const double t = dot(pts[i] - c, u);
    if (first || t < lo) lo = t;
    if (first || t > hi) hi = t;
    first = false;
  }
  return canonical(c + lo * u, c + hi * u);
}

std::vector<std::uint32_t> near_points(const std::vector<Vec2>& pts, const Segment& s, double d) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (point_segment_distance(pts[i], s) <= d) out.push_back(static_cast<std::uint32_t>(i));
  return out;
}

}  // namespace

std::vector<Candidate> detect_candidates(const std::vector<Vec2>& points, const RansacParams& params,
                                         std::uint64_t seed) {
  std::vector<Candidate> out;
  const std::size_t n = points.size();
  if (n < 2 || params.candidates <= 0) return out;
  runtime::mcmc::Rng rng(seed ^ 0x5E65E65E65ULL);
  const std::size_t tries = static_cast<std::size_t>(params.candidates) * 20;
  const std::size_t min_in = static_cast<std::size_t>(std::max(2, params.min_inliers));
  for (std::size_t t = 0; t < tries && out.size() < static_cast<std::size_t>(params.candidates); ++t) {
    runtime::io::throw_if_cancelled("segments: RANSAC birth candidates");  // each try reads every point
    const auto i = static_cast<std::uint32_t>(rng.uniform_int(n));
    const auto j = static_cast<std::uint32_t>(rng.uniform_int(n));
    if (i == j) continue;
    const Vec2 p = points[i], q = points[j];
    const double len = dist(p, q);
    if (!(len > 2.0 * params.inlier_dist)) continue;
    const Vec2 u = (1.0 / len) * (q - p);
    // Inliers of the infinite line, sorted along it; keep the run (gaps <= max_gap) holding p.
    std::vector<std::pair<double, std::uint32_t>> on;
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 d = points[k] - p;
      if (std::abs(cross(u, d)) <= params.inlier_dist) on.emplace_back(dot(u, d), static_cast<std::uint32_t>(k));
    }
    std::sort(on.begin(), on.end());
    std::size_t at = 0;
    while (at < on.size() && on[at].second != i) ++at;
    if (at == on.size()) continue;
    std::size_t lo = at, hi = at;
    while (lo > 0 && on[lo].first - on[lo - 1].first <= params.max_gap) --lo;
    while (hi + 1 < on.size() && on[hi + 1].first - on[hi].first <= params.max_gap) ++hi;
    if (hi - lo + 1 < min_in) continue;
    std::vector<std::uint32_t> run;
    for (std::size_t k = lo; k <= hi; ++k) run.push_back(on[k].second);
    std::sort(run.begin(), run.end());
    Candidate c;
    c.seg = fit(points, run);
    c.inliers = near_points(points, c.seg, params.inlier_dist);
    if (c.inliers.size() < min_in) continue;
    bool dup = false;
    for (const Candidate& o : out)
      if (dist(o.seg.a, c.seg.a) < params.inlier_dist && dist(o.seg.b, c.seg.b) < params.inlier_dist) {
        dup = true;
        break;
      }
    if (!dup) out.push_back(std::move(c));
  }
  return out;
}

}  // namespace ksmc::stdlib::segments
