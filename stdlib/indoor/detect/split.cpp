#include "stdlib/indoor/detect/split.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "stdlib/indoor/detect/frame.h"

namespace ksmc::stdlib::indoor::detect {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Piece {
  double coord, lo, hi;  // perpendicular position and extent along the cut
};

struct Cut {
  bool horizontal;  // parallel to the unit's w-axis: cuts its two sides along h
  double coord;
  double weight;
};

// Groups pieces by position; weight = length of the union of their extents.
void cluster(std::vector<Piece> pieces, bool horizontal, const SplitParams& p, std::vector<Cut>& out) {
  std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
    return std::tie(a.coord, a.lo, a.hi) < std::tie(b.coord, b.lo, b.hi);
  });
  std::size_t i = 0;
  while (i < pieces.size()) {
    std::size_t j = i;
    double wsum = 0, csum = 0;
    std::vector<std::pair<double, double>> iv;
    while (j < pieces.size() && (j == i || pieces[j].coord - csum / wsum <= p.merge_distance)) {
      const double len = std::max(1e-9, pieces[j].hi - pieces[j].lo);
      wsum += len;
      csum += len * pieces[j].coord;
      iv.push_back({pieces[j].lo, pieces[j].hi});
      ++j;
    }
    std::sort(iv.begin(), iv.end());
    double covered = 0, cur_lo = iv[0].first, cur_hi = iv[0].second;
    for (std::size_t k = 1; k < iv.size(); ++k) {
      if (iv[k].first > cur_hi) {
        covered += cur_hi - cur_lo;
        cur_lo = iv[k].first;
        cur_hi = iv[k].second;
      } else {
        cur_hi = std::max(cur_hi, iv[k].second);
      }
    }
    covered += cur_hi - cur_lo;
    out.push_back({horizontal, csum / wsum, covered});
    i = j;
  }
}

}  // namespace

std::vector<SplitLine> detect_split_lines(const ClassGrid& grid, const OrientedRect& unit, const SplitParams& p,
                                          GridCheck check) {
  if (check == GridCheck::Full) check_class_grid(grid, "detect_split_lines");
  if (!(unit.w > 0) || !(unit.h > 0) || !std::isfinite(unit.cx) || !std::isfinite(unit.cy) ||
      !std::isfinite(unit.theta))
    throw std::invalid_argument("detect_split_lines: unit must have finite centre/angle and positive extents");
  const Frame f(grid.size(), unit.theta / kDeg);
  const Point2 q = f.to_frame({unit.cx, unit.cy});
  const double ux0 = q.x - 0.5 * unit.w, uy0 = q.y - 0.5 * unit.h;  // unit box in the frame
  const double ux1 = q.x + 0.5 * unit.w, uy1 = q.y + 0.5 * unit.h;
  // Interior patch, local pixel (i, j) = frame point (px0 + i, py0 + j).
  // Clipped to the frame canvas (the rotated map), so a unit reaching outside the map costs
  // no more than the map itself.
  const double px0 = std::max(0.0, std::ceil(ux0 + p.margin)), py0 = std::max(0.0, std::ceil(uy0 + p.margin));
  const double px1 = std::min(double(f.size().width - 1), std::floor(ux1 - p.margin));
  const double py1 = std::min(double(f.size().height - 1), std::floor(uy1 - p.margin));
  const int pw = int(px1 - px0) + 1, ph = int(py1 - py0) + 1;
  std::vector<SplitLine> out;
  if (pw < 3 || ph < 3) return out;
  ClassGrid patch(ph, pw, static_cast<unsigned char>(Cell::Unknown));
  for (int j = 0; j < ph; ++j)
    for (int i = 0; i < pw; ++i) {
      const Point2 m = f.from_frame({px0 + i, py0 + j});
      const int c = int(std::lround(m.x)), r = int(std::lround(m.y));
      if (c >= 0 && r >= 0 && c < grid.cols && r < grid.rows) patch(j, i) = grid(r, c);
    }
  std::vector<Piece> hp, vp;
  for (const auto& s : hough_segments(wall_edge_mask(patch), p.hough)) {
    const double a = std::atan2(s.b.y - s.a.y, s.b.x - s.a.x) / kDeg;
    const double m = std::fmod(std::abs(a), 180.0);
    if (std::min(m, 180.0 - m) <= p.axis_tolerance_deg)
      hp.push_back({py0 + 0.5 * (s.a.y + s.b.y), px0 + std::min(s.a.x, s.b.x), px0 + std::max(s.a.x, s.b.x)});
    else if (std::abs(m - 90.0) <= p.axis_tolerance_deg)
      vp.push_back({px0 + 0.5 * (s.a.x + s.b.x), py0 + std::min(s.a.y, s.b.y), py0 + std::max(s.a.y, s.b.y)});
  }
  std::vector<Cut> cuts;
  cluster(std::move(hp), true, p, cuts);
  cluster(std::move(vp), false, p, cuts);
  for (const auto& c : cuts) {
    if (c.weight < p.min_weight) continue;
    if (c.horizontal) {
      if (c.coord - uy0 < p.min_part || uy1 - c.coord < p.min_part) continue;
      out.push_back({f.from_frame({ux0, c.coord}), f.from_frame({ux1, c.coord}), c.weight});
    } else {
      if (c.coord - ux0 < p.min_part || ux1 - c.coord < p.min_part) continue;
      out.push_back({f.from_frame({c.coord, uy0}), f.from_frame({c.coord, uy1}), c.weight});
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const SplitLine& a, const SplitLine& b) { return a.weight > b.weight; });
  return out;
}

}  // namespace ksmc::stdlib::indoor::detect
