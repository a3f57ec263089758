#include "stdlib/indoor/detect/wbu.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include <opencv2/imgproc.hpp>

#include "runtime/io/cancel.h"
#include "stdlib/indoor/detect/frame.h"

namespace ksmc::stdlib::indoor::detect {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Line {
  int coord = 0;         // row of a horizontal line, column of a vertical one
  double support = 0.0;  // summed segment length
};

struct Box {
  int x0, y0, x1, y1;
  double weight;
  long long area() const { return (long long)(x1 - x0) * (y1 - y0); }
};

bool better(const Box& a, const Box& b) {
  if (a.weight != b.weight) return a.weight > b.weight;
  if (a.area() != b.area()) return a.area() > b.area();
  return std::tie(a.y0, a.x0, a.y1, a.x1) < std::tie(b.y0, b.x0, b.y1, b.x1);
}

// Clusters (coordinate, length) pairs: sorted by coordinate, a new line starts when the gap
// to the running weighted mean exceeds merge_distance.
std::vector<Line> cluster_lines(std::vector<std::pair<double, double>> pts, const WbuParams& p, int limit) {
  std::sort(pts.begin(), pts.end());
  std::vector<Line> lines;
  double sum_wc = 0, sum_w = 0;
  auto flush = [&] {
    if (sum_w >= p.min_line_support) {
      const int c = int(std::lround(sum_wc / sum_w));
      if (c >= 0 && c < limit) lines.push_back({c, sum_w});
    }
    sum_wc = sum_w = 0;
  };
  for (const auto& [c, w] : pts) {
    if (sum_w > 0 && c - sum_wc / sum_w > p.merge_distance) flush();
    sum_wc += c * w;
    sum_w += w;
  }
  if (sum_w > 0) flush();
  if (lines.size() > p.max_lines_per_axis) {
    std::stable_sort(lines.begin(), lines.end(), [](const Line& a, const Line& b) { return a.support > b.support; });
    lines.resize(p.max_lines_per_axis);
  }
  std::sort(lines.begin(), lines.end(), [](const Line& a, const Line& b) { return a.coord < b.coord; });
  lines.erase(std::unique(lines.begin(), lines.end(), [](const Line& a, const Line& b) { return a.coord == b.coord; }),
              lines.end());
  return lines;
}

// Keeps the best `cap` boxes when the vector grows past a multiple of it.
void prune(std::vector<Box>& boxes, std::size_t cap) {
  if (boxes.size() <= cap) return;
  std::nth_element(boxes.begin(), boxes.begin() + long(cap), boxes.end(), better);
  boxes.resize(cap);
}

struct FrameOutput {
  std::vector<Box> boxes;
  std::vector<Line> hlines, vlines;
  std::size_t enumerated = 0;
};

FrameOutput run_frame(const cv::Mat1b& fgrid, const std::vector<Segment>& segments, const WbuParams& p) {
  FrameOutput out;
  const int rows = fgrid.rows, cols = fgrid.cols;
  cv::Mat1b occ, freem;
  cv::compare(fgrid, cv::Scalar(double(Cell::Occupied)), occ, cv::CMP_EQ);
  cv::compare(fgrid, cv::Scalar(double(Cell::Free)), freem, cv::CMP_EQ);

  // 1. Wall segments near the frame axes, clustered into lines.
  std::vector<std::pair<double, double>> hpts, vpts;
  for (const auto& s : segments) {
    const double a = std::atan2(s.b.y - s.a.y, s.b.x - s.a.x) / kDeg;
    double m = std::fmod(std::abs(a), 180.0);
    if (std::min(m, 180.0 - m) <= p.axis_tolerance_deg) hpts.push_back({0.5 * (s.a.y + s.b.y), s.length()});
    else if (std::abs(m - 90.0) <= p.axis_tolerance_deg) vpts.push_back({0.5 * (s.a.x + s.b.x), s.length()});
  }
  out.hlines = cluster_lines(std::move(hpts), p, rows);
  out.vlines = cluster_lines(std::move(vpts), p, cols);
  if (out.hlines.size() < 2 || out.vlines.size() < 2) return out;

  // 2. Prefix sums of wall matches (eq. 3.13-3.14 with perpendicular tolerance) along rows and
  //    columns, and an integral image of free cells.
  const int t = std::max(0, p.wall_tolerance);
  cv::Mat1b occ_v, occ_h;
  cv::dilate(occ, occ_v, cv::getStructuringElement(cv::MORPH_RECT, {1, 2 * t + 1}));
  cv::dilate(occ, occ_h, cv::getStructuringElement(cv::MORPH_RECT, {2 * t + 1, 1}));
  auto row_prefix = [&](int r) {
    std::vector<int> ps(cols + 1, 0);
    const unsigned char* d = occ_v.ptr<unsigned char>(r);
    for (int x = 0; x < cols; ++x) ps[x + 1] = ps[x] + (d[x] ? 1 : 0);
    return ps;
  };
  auto col_prefix = [&](int c) {
    std::vector<int> ps(rows + 1, 0);
    for (int y = 0; y < rows; ++y) ps[y + 1] = ps[y] + (occ_h(y, c) ? 1 : 0);
    return ps;
  };
  std::vector<std::vector<int>> hps, vps;
  for (const auto& l : out.hlines) hps.push_back(row_prefix(l.coord));
  for (const auto& l : out.vlines) vps.push_back(col_prefix(l.coord));
  cv::Mat1i free_int, occ_int;
  cv::integral(freem / 255, free_int, CV_32S);
  cv::integral(occ / 255, occ_int, CV_32S);
  auto box_sum = [](const cv::Mat1i& in, int x0, int y0, int x1, int y1) {  // half-open box
    return (long long)in(y1, x1) - in(y0, x1) - in(y1, x0) + in(y0, x0);
  };

  // 3. Enumerate every rectangle of two horizontal and two vertical lines.
  const std::size_t nh = out.hlines.size(), nv = out.vlines.size();
  const std::size_t soft_cap = std::max<std::size_t>(4 * p.max_candidates, 1024);
  std::vector<std::size_t> valid;
  for (std::size_t k = 0; k < nh; ++k) {
    runtime::io::throw_if_cancelled("the wall-bounded unit candidates");  // a very large map: seconds per frame
    for (std::size_t l = k + 1; l < nh; ++l) {
      const int y0 = out.hlines[k].coord, y1 = out.hlines[l].coord;
      const int dy = y1 - y0;
      if (dy < p.min_side) continue;
      if (dy > p.max_side) break;
      valid.clear();
      for (std::size_t i = 0; i < nv; ++i) {
        const double w = double(vps[i][y1 + 1] - vps[i][y0]) / double(dy + 1);
        if (w >= p.min_wall_weight) valid.push_back(i);
      }
      for (std::size_t a = 0; a < valid.size(); ++a) {
        const std::size_t i = valid[a];
        const int x0 = out.vlines[i].coord;
        const double wl = double(vps[i][y1 + 1] - vps[i][y0]) / double(dy + 1);
        for (std::size_t b = a + 1; b < valid.size(); ++b) {
          const std::size_t j = valid[b];
          const int x1 = out.vlines[j].coord;
          const int dx = x1 - x0;
          if (dx < p.min_side) continue;
          if (dx > p.max_side) break;
          const double lo = std::min(dx, dy), hi = std::max(dx, dy);
          if (hi > p.max_aspect * lo) continue;
          const double wt = double(hps[k][x1 + 1] - hps[k][x0]) / double(dx + 1);
          if (wt < p.min_wall_weight) continue;
          const double wb = double(hps[l][x1 + 1] - hps[l][x0]) / double(dx + 1);
          if (wb < p.min_wall_weight) continue;
          const double wr = double(vps[j][y1 + 1] - vps[j][y0]) / double(dy + 1);
          // Interior (clear of the walls) must be mostly free and hardly occupied.
          const int ix0 = x0 + t + 1, iy0 = y0 + t + 1, ix1 = x1 - t, iy1 = y1 - t;  // half-open
          const long long interior = (long long)(ix1 - ix0) * (iy1 - iy0);
          if (ix1 <= ix0 || iy1 <= iy0) continue;
          if (double(box_sum(free_int, ix0, iy0, ix1, iy1)) < p.min_free_fraction * double(interior)) continue;
          if (double(box_sum(occ_int, ix0, iy0, ix1, iy1)) > p.max_occupied_fraction * double(interior)) continue;
          out.boxes.push_back({x0, y0, x1, y1, std::min({wl, wr, wt, wb})});
          ++out.enumerated;
          if (out.boxes.size() >= soft_cap) prune(out.boxes, p.max_candidates);
        }
      }
    }
  }
  prune(out.boxes, p.max_candidates);
  return out;
}

}  // namespace

WbuResult detect_wbu_units(const ClassGrid& grid, const WbuParams& p) {
  check_class_grid(grid, "detect_wbu_units");
  if (!(p.min_side > 0) || !(p.max_side >= p.min_side) || !(p.max_aspect >= 1.0) || p.max_candidates == 0)
    throw std::invalid_argument("detect_wbu_units: need 0 < min_side <= max_side, max_aspect >= 1, max_candidates > 0");
  WbuResult res;
  const auto analysis = analyse_orientations(grid, p.orientation);
  for (const auto& o : analysis.peaks) {
    // Frames in (-45, 45]: a map aligned with the image axes is worked on unrotated.
    res.frames_deg.push_back(o.angle_deg > 45.0 ? o.angle_deg - 90.0 : o.angle_deg);
    if (!p.secondary_orientations) break;
  }
  if (res.frames_deg.empty()) res.frames_deg.push_back(0.0);

  struct Tagged {
    Box box;
    std::size_t frame;
  };
  std::vector<Tagged> all;
  for (std::size_t f = 0; f < res.frames_deg.size(); ++f) {
    const Frame frame(grid.size(), res.frames_deg[f]);
    std::vector<Segment> fsegs;
    fsegs.reserve(analysis.segments.size());
    for (const auto& s : analysis.segments) fsegs.push_back({frame.to_frame(s.a), frame.to_frame(s.b)});
    const auto fo = run_frame(frame.warp(grid, static_cast<unsigned char>(Cell::Unknown)), fsegs, p);
    res.enumerated += fo.enumerated;
    for (const auto& b : fo.boxes) all.push_back({b, f});
    const double w = frame.size().width - 1, h = frame.size().height - 1;
    for (const auto& l : fo.hlines)
      res.wall_lines.push_back({frame.from_frame({0, double(l.coord)}), frame.from_frame({w, double(l.coord)})});
    for (const auto& l : fo.vlines)
      res.wall_lines.push_back({frame.from_frame({double(l.coord), 0}), frame.from_frame({double(l.coord), h})});
  }
  std::sort(all.begin(), all.end(), [](const Tagged& a, const Tagged& b) {
    if (better(a.box, b.box)) return true;
    if (better(b.box, a.box)) return false;
    return a.frame < b.frame;
  });
  if (all.size() > p.max_candidates) all.resize(p.max_candidates);

  std::vector<double> weights;
  for (const auto& t : all) {
    const Frame frame(grid.size(), res.frames_deg[t.frame]);
    res.candidates.push_back({frame.rect_from_frame(t.box.x0, t.box.y0, t.box.x1, t.box.y1), t.box.weight});
    weights.push_back(t.box.weight);
  }
  res.sampler = CumulativeSampler(weights);
  return res;
}

}  // namespace ksmc::stdlib::indoor::detect
