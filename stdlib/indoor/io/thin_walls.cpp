#include "stdlib/indoor/io/thin_walls.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "stdlib/indoor/detect/hough.h"

namespace ksmc::stdlib::indoor::io {

namespace {

constexpr double kMinSegment = 1.0;  // m: the shortest Hough segment kept
constexpr double kSameAngle = 1.5 * std::numbers::pi / 180.0;
constexpr double kSameLine = 2.0;  // cells across: pieces of one line

bool occupied(const ClassGrid& m, int r, int c) { return m(r, c) == static_cast<std::uint8_t>(Cell::Occupied); }

// Along (dr, dc) through (r, c): the occupied run is at most `max_cells` long and both of its
// ends are Free cells (not unknown, not the map edge).
bool thin_along(const ClassGrid& m, int r, int c, int dr, int dc, int max_cells) {
  int n = 1;
  for (const int side : {-1, 1})
    for (int k = 1;; ++k) {
      const int rr = r + side * dr * k, cc = c + side * dc * k;
      if (rr < 0 || cc < 0 || rr >= m.rows || cc >= m.cols) return false;
      if (!occupied(m, rr, cc)) {
        if (m(rr, cc) != static_cast<std::uint8_t>(Cell::Free)) return false;
        break;
      }
      if (++n > max_cells) return false;
    }
  return true;
}

struct Oriented {
  double angle;  // [0, pi)
  double offset, t0, t1;
};

}  // namespace

cv::Mat1b thin_wall_mask(const ClassGrid& map, int max_cells) {
  cv::Mat1b out(map.rows, map.cols, static_cast<std::uint8_t>(0));
  for (int r = 0; r < map.rows; ++r)
    for (int c = 0; c < map.cols; ++c)
      if (occupied(map, r, c) && (thin_along(map, r, c, 0, 1, max_cells) || thin_along(map, r, c, 1, 0, max_cells)))
        out(r, c) = 255;
  return out;
}

std::vector<WallLine> thin_wall_lines(const ClassGrid& map, double resolution) {
  std::vector<WallLine> out;
  if (map.empty() || !(resolution > 0.0)) return out;
  const int max_cells = std::max(1, static_cast<int>(std::lround(kMaxWallThickness / resolution)));
  detect::HoughParams p;
  p.rho = 1.0;
  p.theta_deg = 0.5;
  p.threshold = 20;
  p.min_length = kMinSegment / resolution;
  p.max_gap = 3.0;
  const auto segments = detect::hough_segments(thin_wall_mask(map, max_cells), p);
  std::vector<Oriented> seg;
  for (const auto& s : segments) {
    double a = std::atan2(s.b.y - s.a.y, s.b.x - s.a.x);
    if (a < 0.0) a += std::numbers::pi;
    if (a >= std::numbers::pi) a -= std::numbers::pi;
    const double dx = std::cos(a), dy = std::sin(a);
    const double ta = dx * s.a.x + dy * s.a.y, tb = dx * s.b.x + dy * s.b.y;
    seg.push_back({a, -dy * s.a.x + dx * s.a.y, std::min(ta, tb), std::max(ta, tb)});
  }
  std::sort(seg.begin(), seg.end(), [](const Oriented& x, const Oriented& y) {
    return x.angle != y.angle ? x.angle < y.angle : (x.offset != y.offset ? x.offset < y.offset : x.t0 < y.t0);
  });
  // Greedy grouping in angle order: a segment joins the first open line of its angle and
  // offset (measured in that line's frame), else opens a line.
  std::vector<char> used(seg.size(), 0);
  for (std::size_t i = 0; i < seg.size(); ++i) {
    if (used[i]) continue;
    const double dx = std::cos(seg[i].angle), dy = std::sin(seg[i].angle);
    WallLine line{{-dy * seg[i].offset, dx * seg[i].offset}, {dx, dy}, {}};
    for (std::size_t j = i; j < seg.size() && seg[j].angle - seg[i].angle <= kSameAngle; ++j) {
      if (used[j]) continue;
      // Segment j's ends in line i's frame.
      const double ca = std::cos(seg[j].angle), sa = std::sin(seg[j].angle);
      const Point2 a{ca * seg[j].t0 - sa * seg[j].offset, sa * seg[j].t0 + ca * seg[j].offset};
      const Point2 b{ca * seg[j].t1 - sa * seg[j].offset, sa * seg[j].t1 + ca * seg[j].offset};
      const double oa = -dy * a.x + dx * a.y, ob = -dy * b.x + dx * b.y;
      if (std::abs(oa - seg[i].offset) > kSameLine || std::abs(ob - seg[i].offset) > kSameLine) continue;
      used[j] = 1;
      const double ta = dx * a.x + dy * a.y, tb = dx * b.x + dy * b.y;
      line.covered.emplace_back(std::min(ta, tb), std::max(ta, tb));
    }
    std::sort(line.covered.begin(), line.covered.end());
    std::vector<std::pair<double, double>> merged;
    for (const auto& iv : line.covered) {
      if (!merged.empty() && iv.first <= merged.back().second) merged.back().second = std::max(merged.back().second, iv.second);
      else merged.push_back(iv);
    }
    line.covered = std::move(merged);
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace ksmc::stdlib::indoor::io
