#include "stdlib/indoor/detect/orientation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ksmc::stdlib::indoor::detect {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double wrap90(double a) {
  double r = std::fmod(a, 90.0);
  if (r < 0) r += 90.0;
  if (r >= 90.0) r -= 90.0;
  return r;
}

double segment_angle_mod90(const Segment& s) {
  return wrap90(std::atan2(s.b.y - s.a.y, s.b.x - s.a.x) / kDeg);
}

}  // namespace

double angle_diff_mod90(double a_deg, double b_deg) {
  const double d = wrap90(a_deg - b_deg);
  return std::min(d, 90.0 - d);
}

std::vector<Orientation> orientations_of(const std::vector<Segment>& segments, const OrientationParams& p) {
  if (!(p.bin_deg > 0.0) || p.bin_deg > 45.0) throw std::invalid_argument("orientations: bin_deg must be in (0, 45]");
  const int nbins = std::max(1, int(std::lround(90.0 / p.bin_deg)));
  const double bin = 90.0 / nbins;
  std::vector<double> hist(nbins, 0.0);
  std::vector<double> ang(segments.size()), len(segments.size());
  double total = 0.0;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    ang[i] = segment_angle_mod90(segments[i]);
    len[i] = segments[i].length();
    total += len[i];
    hist[std::min(nbins - 1, int(ang[i] / bin))] += len[i];
  }
  std::vector<Orientation> out;
  if (total <= 0.0) return out;
  const int half = std::max(0, int(std::lround(p.smooth_deg / bin)));
  std::vector<double> sm(nbins, 0.0);
  for (int b = 0; b < nbins; ++b)
    for (int k = -half; k <= half; ++k) sm[b] += hist[((b + k) % nbins + nbins) % nbins];

  while (out.size() < p.max_orientations) {
    // Best bin not too close to the peaks already found (ties: lowest bin, deterministic).
    int best = -1;
    for (int b = 0; b < nbins; ++b) {
      const double centre = (b + 0.5) * bin;
      bool near = false;
      for (const auto& o : out) near = near || angle_diff_mod90(centre, o.angle_deg) < p.min_separation_deg;
      if (near) continue;
      if (best < 0 || sm[b] > sm[best]) best = b;
    }
    if (best < 0 || sm[best] <= 0.0) break;
    // Refine: circular mean on the 4x angle circle of segments near the bin centre.
    const double guess = (best + 0.5) * bin;
    double sx = 0, sy = 0, support = 0;
    for (std::size_t i = 0; i < ang.size(); ++i) {
      if (angle_diff_mod90(ang[i], guess) > p.window_deg) continue;
      sx += len[i] * std::cos(4.0 * ang[i] * kDeg);
      sy += len[i] * std::sin(4.0 * ang[i] * kDeg);
    }
    double refined = guess;
    if (sx != 0.0 || sy != 0.0) refined = wrap90(std::atan2(sy, sx) / kDeg / 4.0);
    for (std::size_t i = 0; i < ang.size(); ++i)
      if (angle_diff_mod90(ang[i], refined) <= p.window_deg) support += len[i];
    const double conf = support / total;
    if (!out.empty() && conf < p.min_secondary) break;
    out.push_back({refined, conf});
  }
  return out;
}

OrientationAnalysis analyse_orientations(const ClassGrid& grid, const OrientationParams& params) {
  check_class_grid(grid, "analyse_orientations");
  OrientationAnalysis r;
  r.segments = hough_segments(wall_edge_mask(grid), params.hough);
  for (const auto& s : r.segments) r.total_length += s.length();
  r.peaks = orientations_of(r.segments, params);
  return r;
}

Orientation dominant_orientation(const ClassGrid& grid, const OrientationParams& params) {
  auto r = analyse_orientations(grid, params);
  if (r.peaks.empty()) return {};
  return r.peaks.front();
}

}  // namespace ksmc::stdlib::indoor::detect
