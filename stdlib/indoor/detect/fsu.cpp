#include "stdlib/indoor/detect/fsu.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/detect/frame.h"
#include "stdlib/indoor/detect/hough.h"
#include "stdlib/indoor/detect/largest_rect.h"

namespace ksmc::stdlib::indoor::detect {

namespace {

// The largest frame-aligned rectangle inside a component given by its cells in frame
// coordinates (bounding box [x0, x1] x [y0, y1]); nullopt when it is below min_area.
std::optional<OrientedRect> inner_rect(const Frame& f, const std::vector<Point2>& framed, double x0, double y0,
                                       double x1, double y1, const FsuParams& p) {
  const int pad = p.inner_close + 1;
  const int cols = static_cast<int>(std::ceil(x1 - x0)) + 1 + 2 * pad, rows = static_cast<int>(std::ceil(y1 - y0)) + 1 + 2 * pad;
  cv::Mat1b m(rows, cols, static_cast<unsigned char>(0));
  for (const Point2& t : framed)
    m(static_cast<int>(std::lround(t.y - y0)) + pad, static_cast<int>(std::lround(t.x - x0)) + pad) = 255;
  // Rotated cells leave pinholes between them; speckle leaves small holes: close both.
  const int k = std::max(1, p.inner_close);
  cv::morphologyEx(m, m, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_RECT, {2 * k + 1, 2 * k + 1}));
  const cv::Rect r = largest_rectangle(m);
  if (static_cast<double>(r.area()) < p.min_area) return std::nullopt;
  const double rx0 = x0 + r.x - pad, ry0 = y0 + r.y - pad;
  return f.rect_from_frame(rx0 - p.margin, ry0 - p.margin, rx0 + r.width - 1 + p.margin, ry0 + r.height - 1 + p.margin);
}

}  // namespace

std::vector<UnitCandidate> detect_fsu_units(const ClassGrid& grid, const cv::Mat1b& explained, const FsuParams& p) {
  check_class_grid(grid, "detect_fsu_units");
  if (!explained.empty() && (explained.size() != grid.size() || explained.type() != CV_8UC1))
    throw std::invalid_argument("detect_fsu_units: explained mask must be CV_8UC1 of the grid's size");
  cv::Mat1b mask = class_mask(grid, static_cast<unsigned char>(Cell::Free));
  if (!explained.empty()) mask.setTo(0, explained);
  if (p.open_radius > 0)
    cv::morphologyEx(mask, mask, cv::MORPH_OPEN,
                     cv::getStructuringElement(cv::MORPH_RECT, {2 * p.open_radius + 1, 2 * p.open_radius + 1}));
  cv::Mat1i labels, stats;
  cv::Mat1d centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);

  struct Comp {
    int label, area;
  };
  std::vector<Comp> comps;
  for (int l = 1; l < n; ++l)
    if (stats(l, cv::CC_STAT_AREA) >= p.min_area) comps.push_back({l, stats(l, cv::CC_STAT_AREA)});
  std::stable_sort(comps.begin(), comps.end(), [](const Comp& a, const Comp& b) { return a.area > b.area; });
  if (comps.size() > p.max_candidates) comps.resize(p.max_candidates);

  std::vector<UnitCandidate> out;
  for (const auto& c : comps) {
    const int x = stats(c.label, cv::CC_STAT_LEFT), y = stats(c.label, cv::CC_STAT_TOP);
    const int w = stats(c.label, cv::CC_STAT_WIDTH), h = stats(c.label, cv::CC_STAT_HEIGHT);
    std::vector<cv::Point2f> pts;
    pts.reserve(std::size_t(c.area));
    for (int r = y; r < y + h; ++r)
      for (int col = x; col < x + w; ++col)
        if (labels(r, col) == c.label) pts.emplace_back(float(col), float(r));
    OrientedRect rect;
    std::optional<OrientedRect> inner;
    if (p.frame_deg) {
      const Frame f(grid.size(), *p.frame_deg);
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      std::vector<Point2> framed;
      framed.reserve(pts.size());
      for (const auto& q : pts) {
        const Point2 t = f.to_frame({q.x, q.y});
        framed.push_back(t);
        x0 = std::min(x0, t.x), y0 = std::min(y0, t.y), x1 = std::max(x1, t.x), y1 = std::max(y1, t.y);
      }
      rect = f.rect_from_frame(x0 - p.margin, y0 - p.margin, x1 + p.margin, y1 + p.margin);
      if (c.area < p.inner_below * (x1 - x0 + 1.0) * (y1 - y0 + 1.0)) inner = inner_rect(f, framed, x0, y0, x1, y1, p);
    } else {
      const cv::RotatedRect rr = cv::minAreaRect(pts);
      rect = {rr.center.x, rr.center.y, rr.size.width + 2 * p.margin, rr.size.height + 2 * p.margin,
              rr.angle * std::numbers::pi / 180.0};
    }
    out.push_back({rect, std::max(unit_weight(grid, rect, p.wall), p.weight_floor)});
    if (inner) out.push_back({*inner, std::max(unit_weight(grid, *inner, p.wall), p.weight_floor)});
  }
  return out;
}

}  // namespace ksmc::stdlib::indoor::detect
