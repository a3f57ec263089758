// Synthetic floor plans for the detector tests: a scene of axis-aligned rooms, walls and
// doorways in a model frame, rendered into a class grid rotated by any angle about the
// canvas centre. Expected rectangles are mapped the same way.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/rect.h"

namespace ksmc::tests::indoor_detect {

using stdlib::indoor::Cell;
using stdlib::indoor::ClassGrid;
using stdlib::indoor::OrientedRect;
using stdlib::indoor::Point2;

struct Box {
  double x0, y0, x1, y1;  // wall centre lines in the model frame
};
struct WallSeg {
  double x0, y0, x1, y1;  // axis-aligned wall centre line
};
struct Gap {
  double x0, y0, x1, y1;  // doorway: the part of a wall that is open (axis-aligned, on a wall line)
};

struct Scene {
  int cols = 0, rows = 0;
  double wall_half = 1.5;  // walls are 3 cells thick
  std::vector<Box> rooms;  // free space inside, walls on the border
  std::vector<WallSeg> walls;
  std::vector<Gap> doors;
};

// Three rooms above a corridor: A | B | C over a full-width corridor. Doors A-corridor,
// B-corridor, C-corridor, A-B; the wall B-C is solid. Placed around the canvas centre.
inline Scene office_scene(int cols = 360, int rows = 300) {
  Scene s;
  s.cols = cols;
  s.rows = rows;
  const double ox = cols / 2.0 - 130, oy = rows / 2.0 - 75;  // layout is 260 x 150
  auto B = [&](double x0, double y0, double x1, double y1) { return Box{ox + x0, oy + y0, ox + x1, oy + y1}; };
  s.rooms = {B(0, 0, 100, 100), B(100, 0, 180, 100), B(180, 0, 260, 100), B(0, 100, 260, 150)};
  auto W = [&](double x0, double y0, double x1, double y1) { return WallSeg{ox + x0, oy + y0, ox + x1, oy + y1}; };
  s.walls = {W(0, 0, 260, 0),   W(0, 150, 260, 150), W(0, 0, 0, 150),    W(260, 0, 260, 150),
             W(0, 100, 260, 100), W(100, 0, 100, 100), W(180, 0, 180, 100)};
  auto G = [&](double x0, double y0, double x1, double y1) { return Gap{ox + x0, oy + y0, ox + x1, oy + y1}; };
  s.doors = {G(40, 100, 54, 100), G(130, 100, 144, 100), G(210, 100, 224, 100), G(100, 40, 100, 54)};
  return s;
}

inline Point2 rotate_about(Point2 p, Point2 c, double deg) {
  const double a = deg * std::numbers::pi / 180.0, co = std::cos(a), si = std::sin(a);
  const double dx = p.x - c.x, dy = p.y - c.y;
  return {c.x + co * dx - si * dy, c.y + si * dx + co * dy};
}

inline Point2 centre_of(const Scene& s) { return {0.5 * (s.cols - 1), 0.5 * (s.rows - 1)}; }

// Renders the scene rotated by `deg` (model -> map: rotate about the canvas centre).
inline ClassGrid render(const Scene& s, double deg) {
  ClassGrid g(s.rows, s.cols, static_cast<unsigned char>(Cell::Unknown));
  const Point2 c = centre_of(s);
  for (int r = 0; r < s.rows; ++r)
    for (int col = 0; col < s.cols; ++col) {
      const Point2 m = rotate_about({double(col), double(r)}, c, -deg);
      bool inside = false;
      for (const auto& b : s.rooms)
        inside = inside || (m.x >= b.x0 && m.x <= b.x1 && m.y >= b.y0 && m.y <= b.y1);
      bool wall = false;
      for (const auto& w : s.walls)
        wall = wall || (m.x >= w.x0 - s.wall_half && m.x < w.x1 + s.wall_half && m.y >= w.y0 - s.wall_half &&
                        m.y < w.y1 + s.wall_half);
      bool door = false;
      for (const auto& d : s.doors) {
        const bool vertical = d.x0 == d.x1;
        if (vertical)
          door = door || (m.y >= d.y0 && m.y <= d.y1 && std::abs(m.x - d.x0) <= s.wall_half + 0.5);
        else
          door = door || (m.x >= d.x0 && m.x <= d.x1 && std::abs(m.y - d.y0) <= s.wall_half + 0.5);
      }
      if (wall && !door) g(r, col) = static_cast<unsigned char>(Cell::Occupied);
      else if (inside || door) g(r, col) = static_cast<unsigned char>(Cell::Free);
    }
  return g;
}

inline OrientedRect expected_rect(const Scene& s, const Box& b, double deg) {
  const Point2 c = rotate_about({0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)}, centre_of(s), deg);
  return {c.x, c.y, b.x1 - b.x0, b.y1 - b.y0, deg * std::numbers::pi / 180.0};
}

inline Point2 expected_point(const Scene& s, Point2 model, double deg) { return rotate_about(model, centre_of(s), deg); }

inline double iou(const OrientedRect& a, const OrientedRect& b) {
  auto rr = [](const OrientedRect& r) {
    return cv::RotatedRect(cv::Point2f(float(r.cx), float(r.cy)), cv::Size2f(float(r.w), float(r.h)),
                           float(r.theta * 180.0 / std::numbers::pi));
  };
  std::vector<cv::Point2f> poly;
  const int kind = cv::rotatedRectangleIntersection(rr(a), rr(b), poly);
  double inter = 0.0;
  if (kind != cv::INTERSECT_NONE && poly.size() >= 3) {
    std::vector<cv::Point2f> hull;
    cv::convexHull(poly, hull);
    inter = cv::contourArea(hull);
  }
  return inter / (a.area() + b.area() - inter);
}

// PNG maps: >= 250 free; `bormann` (the benchmark's convention): everything else occupied;
// otherwise <= 50 occupied and the rest unknown (SLAM maps such as lab_b.png).
// The explained mask of a world: 255 inside any of the rectangles (their filled corners).
inline cv::Mat1b raster(const ClassGrid& g, const std::vector<OrientedRect>& rects) {
  cv::Mat1b m = cv::Mat1b::zeros(g.size());
  for (const auto& r : rects) {
    const auto c = r.corners();
    cv::Point pts[4];
    for (std::size_t i = 0; i < 4; ++i) pts[i] = cv::Point(int(std::lround(c[i].x)), int(std::lround(c[i].y)));
    cv::fillConvexPoly(m, pts, 4, cv::Scalar(255));
  }
  return m;
}

inline ClassGrid load_png_map(const std::string& path, bool bormann) {
  const cv::Mat1b img = cv::imread(path, cv::IMREAD_GRAYSCALE);
  ClassGrid g(img.rows, img.cols, static_cast<unsigned char>(Cell::Unknown));
  for (int r = 0; r < img.rows; ++r)
    for (int c = 0; c < img.cols; ++c) {
      const int v = img(r, c);
      if (v >= 250) g(r, c) = static_cast<unsigned char>(Cell::Free);
      else if (bormann || v <= 50) g(r, c) = static_cast<unsigned char>(Cell::Occupied);
    }
  return g;
}

}  // namespace ksmc::tests::indoor_detect
