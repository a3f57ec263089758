#include "stdlib/indoor/detect/door.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/detect/hough.h"
#include "stdlib/indoor/detect/wall_score.h"

namespace ksmc::stdlib::indoor::detect {
namespace {

using Interval = std::pair<double, double>;

// One shortened wall of a unit and its band.
struct Band {
  int unit = 0;
  Point2 a;             // start of the shortened wall
  Point2 d;             // unit direction along the wall
  Point2 n;             // unit normal
  double length = 0.0;  // of the shortened wall
  std::array<cv::Point2d, 4> poly{};
  cv::Rect bbox;
};

double dot(Point2 u, Point2 v) { return u.x * v.x + u.y * v.y; }
Point2 sub(Point2 u, Point2 v) { return {u.x - v.x, u.y - v.y}; }
Point2 at(const Band& b, double t) { return {b.a.x + t * b.d.x, b.a.y + t * b.d.y}; }

std::vector<Band> make_bands(const std::vector<OrientedRect>& units, const DoorParams& p) {
  std::vector<Band> bands;
  for (std::size_t u = 0; u < units.size(); ++u) {
    const auto c = units[u].corners();
    for (int k = 0; k < 4; ++k) {
      const Point2 A = c[k], B = c[(k + 1) % 4];
      const double L = std::hypot(B.x - A.x, B.y - A.y);
      if (L - 2 * p.shorten <= 1.0) continue;
      Band b;
      b.unit = int(u);
      b.d = {(B.x - A.x) / L, (B.y - A.y) / L};
      b.n = {-b.d.y, b.d.x};
      b.a = {A.x + p.shorten * b.d.x, A.y + p.shorten * b.d.y};
      b.length = L - 2 * p.shorten;
      const Point2 e = at(b, b.length);
      const Point2 off{p.expand * b.n.x, p.expand * b.n.y};
      b.poly = {cv::Point2d(b.a.x + off.x, b.a.y + off.y), cv::Point2d(e.x + off.x, e.y + off.y),
                cv::Point2d(e.x - off.x, e.y - off.y), cv::Point2d(b.a.x - off.x, b.a.y - off.y)};
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (const auto& q : b.poly) x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
      b.bbox = cv::Rect(cv::Point(int(std::floor(x0)), int(std::floor(y0))), cv::Point(int(std::ceil(x1)) + 1, int(std::ceil(y1)) + 1));
      bands.push_back(b);
    }
  }
  return bands;
}

void fill(cv::Mat1b& roi_mask, const Band& b, cv::Point origin) {
  cv::Point pts[4];
  for (int i = 0; i < 4; ++i)
    pts[i] = cv::Point(int(std::lround(b.poly[i].x)) - origin.x, int(std::lround(b.poly[i].y)) - origin.y);
  cv::fillConvexPoly(roi_mask, pts, 4, cv::Scalar(255));
}

// Step 3 + first half of step 4 on one wall: verified, merged intervals within [t0, t1].
std::vector<Interval> verified_parts(const ClassGrid& grid, const Band& b, double t0, double t1, const DoorParams& p) {
  std::vector<Interval> out;
  const double len = t1 - t0;
  if (len <= 0) return out;
  const int n = std::max(1, int(std::lround(len / p.segment_length)));
  const double step = len / n;
  const DoorScoreParams probe{int(std::lround(p.expand))};
  for (int i = 0; i < n; ++i) {
    const double s0 = t0 + i * step, s1 = s0 + step;
    if (door_weight(grid, at(b, s0), at(b, s1), probe) < p.verify_weight) continue;
    if (!out.empty() && s0 - out.back().second <= p.merge_gap) out.back().second = s1;
    else out.push_back({s0, s1});
  }
  return out;
}

}  // namespace

std::vector<DoorCandidate> detect_doors(const ClassGrid& grid, const std::vector<OrientedRect>& units,
                                        const DoorParams& p, GridCheck check) {
  if (check == GridCheck::Full) check_class_grid(grid, "detect_doors");
  for (std::size_t u = 0; u < units.size(); ++u) {
    const auto& r = units[u];
    if (!(r.w > 0) || !(r.h > 0) || !std::isfinite(r.cx) || !std::isfinite(r.cy) || !std::isfinite(r.theta))
      throw std::invalid_argument("detect_doors: unit " + std::to_string(u) +
                                  " must have finite centre/angle and positive extents");
  }
  if (!(p.segment_length > 0) || !(p.expand >= 0) || !(p.min_door <= p.max_door))
    throw std::invalid_argument("detect_doors: need segment_length > 0, expand >= 0, min_door <= max_door");

  const std::vector<Band> bands = make_bands(units, p);
  const cv::Rect map_rect(0, 0, grid.cols, grid.rows);
  const double cos_max = std::cos(p.max_angle_deg * std::numbers::pi / 180.0);
  std::vector<DoorCandidate> out;
  for (std::size_t i = 0; i < bands.size(); ++i)
    for (std::size_t j = i + 1; j < bands.size(); ++j) {
      const Band& A = bands[i];
      const Band& B = bands[j];
      if (A.unit == B.unit) continue;
      if (std::abs(dot(A.d, B.d)) < cos_max) continue;
      const cv::Rect roi = A.bbox & B.bbox & map_rect;
      if (roi.area() <= 0) continue;
      // Step 2: overlap of the two bands, by connected components.
      cv::Mat1b ma = cv::Mat1b::zeros(roi.size()), mb = cv::Mat1b::zeros(roi.size()), ov;
      fill(ma, A, roi.tl());
      fill(mb, B, roi.tl());
      cv::bitwise_and(ma, mb, ov);
      cv::Mat1i labels, stats;
      cv::Mat1d centroids;
      const int ncomp = cv::connectedComponentsWithStats(ov, labels, stats, centroids, 8, CV_32S);
      for (int l = 1; l < ncomp; ++l) {
        if (stats(l, cv::CC_STAT_AREA) < p.min_overlap_cells) continue;
        double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
        for (int r = 0; r < labels.rows; ++r)
          for (int c = 0; c < labels.cols; ++c) {
            if (labels(r, c) != l) continue;
            const Point2 q{double(c + roi.x), double(r + roi.y)};
            const double ta = dot(sub(q, A.a), A.d), tb = dot(sub(q, B.a), B.d);
            a0 = std::min(a0, ta), a1 = std::max(a1, ta), b0 = std::min(b0, tb), b1 = std::max(b1, tb);
          }
        a0 = std::max(a0, 0.0), a1 = std::min(a1, A.length);
        b0 = std::max(b0, 0.0), b1 = std::min(b1, B.length);
        // Steps 3-4 on both walls.
        const auto pa = verified_parts(grid, A, a0, a1, p);
        const auto pb = verified_parts(grid, B, b0, b1, p);
        for (const auto& ia : pa)
          for (const auto& ib : pb) {
            // Wall B's interval in wall A's parameter.
            double s0 = dot(sub(at(B, ib.first), A.a), A.d), s1 = dot(sub(at(B, ib.second), A.a), A.d);
            if (s0 > s1) std::swap(s0, s1);
            const double lo = std::max(ia.first, s0), hi = std::min(ia.second, s1);
            if (hi - lo < p.min_door || hi - lo > p.max_door) continue;
            // Mid line between the two walls.
            const Point2 mid_a = at(A, 0.5 * (lo + hi));
            const double offset = dot(sub(B.a, mid_a), B.n) * (dot(A.n, B.n) < 0 ? -1.0 : 1.0);
            const Point2 shift{0.5 * offset * A.n.x, 0.5 * offset * A.n.y};
            const Point2 d0 = at(A, lo), d1 = at(A, hi);
            DoorCandidate dc;
            dc.a = {d0.x + shift.x, d0.y + shift.y};
            dc.b = {d1.x + shift.x, d1.y + shift.y};
            dc.weight = door_weight(grid, dc.a, dc.b, DoorScoreParams{int(std::lround(p.expand))});
            dc.unit_a = std::min(A.unit, B.unit);
            dc.unit_b = std::max(A.unit, B.unit);
            if (dc.weight > 0.0) out.push_back(dc);
          }
      }
    }
  std::stable_sort(out.begin(), out.end(), [](const DoorCandidate& x, const DoorCandidate& y) {
    return std::tie(x.unit_a, x.unit_b, x.a.x, x.a.y) < std::tie(y.unit_a, y.unit_b, y.a.x, y.a.y);
  });
  return out;
}

}  // namespace ksmc::stdlib::indoor::detect
