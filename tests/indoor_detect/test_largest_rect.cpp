// The largest rectangle of a mask, and the FSU's inner rectangle of a free-space component that
// fills its bounding box poorly (a ring of corridors round a courtyard the sensor never saw).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/detect/fsu.h"
#include "stdlib/indoor/detect/largest_rect.h"
#include "synthetic_map.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::detect;
using ksmc::tests::indoor_detect::raster;

namespace {

long brute_force_area(const cv::Mat1b& m) {
  long best = 0;
  for (int r0 = 0; r0 < m.rows; ++r0)
    for (int c0 = 0; c0 < m.cols; ++c0)
      for (int r1 = r0; r1 < m.rows; ++r1)
        for (int c1 = c0; c1 < m.cols; ++c1)
          if (cv::countNonZero(m(cv::Range(r0, r1 + 1), cv::Range(c0, c1 + 1))) == (r1 - r0 + 1) * (c1 - c0 + 1))
            best = std::max(best, static_cast<long>(r1 - r0 + 1) * (c1 - c0 + 1));
  return best;
}

// A square of free corridors `width` cells wide round an unknown courtyard, turned by `deg`
// about the canvas centre: no wall anywhere, as a SLAM map shows glass it saw through.
ClassGrid ring_map(double deg, int side = 200, int width = 30) {
  ClassGrid g(300, 300, static_cast<std::uint8_t>(Cell::Unknown));
  auto fill = [&](double half, Cell v) {
    const cv::RotatedRect rr({150.0f, 150.0f}, {static_cast<float>(2 * half), static_cast<float>(2 * half)}, static_cast<float>(deg));
    cv::Point2f p[4];
    rr.points(p);
    cv::Point q[4];
    for (int i = 0; i < 4; ++i) q[i] = cv::Point(static_cast<int>(std::lround(p[i].x)), static_cast<int>(std::lround(p[i].y)));
    cv::fillConvexPoly(g, q, 4, cv::Scalar(static_cast<int>(v)));
  };
  fill(side / 2.0, Cell::Free);
  fill(side / 2.0 - width, Cell::Unknown);
  return g;
}

double free_share(const ClassGrid& g, const OrientedRect& r) {
  int n = 0, free = 0;
  const double c = std::cos(r.theta), s = std::sin(r.theta);
  for (double u = -0.5 * r.w + 0.5; u < 0.5 * r.w; u += 1.0)
    for (double v = -0.5 * r.h + 0.5; v < 0.5 * r.h; v += 1.0) {
      const int col = static_cast<int>(std::floor(r.cx + c * u - s * v)), row = static_cast<int>(std::floor(r.cy + s * u + c * v));
      ++n;
      free += row >= 0 && col >= 0 && row < g.rows && col < g.cols && g(row, col) == static_cast<std::uint8_t>(Cell::Free);
    }
  return n == 0 ? 0.0 : static_cast<double>(free) / n;
}

}  // namespace

TEST_CASE("largest_rectangle: the largest all-set rectangle of a mask", "[fsu]") {
  CHECK(largest_rectangle(cv::Mat1b(5, 7, static_cast<unsigned char>(0))).area() == 0);
  CHECK(largest_rectangle(cv::Mat1b(5, 7, static_cast<unsigned char>(1))) == cv::Rect(0, 0, 7, 5));
  // An L: a 10 x 3 bar and a 3 x 8 leg; the bar wins.
  cv::Mat1b l(12, 12, static_cast<unsigned char>(0));
  l(cv::Rect(1, 1, 10, 3)).setTo(255);
  l(cv::Rect(1, 1, 3, 8)).setTo(255);
  CHECK(largest_rectangle(l) == cv::Rect(1, 1, 10, 3));
  // Random masks against brute force: the area is the largest, the rectangle all set.
  std::mt19937 rng(7);
  for (int t = 0; t < 200; ++t) {
    cv::Mat1b m(1 + static_cast<int>(rng() % 9), 1 + static_cast<int>(rng() % 9));
    const unsigned density = 40 + rng() % 55;
    for (auto& v : m) v = (rng() % 100) < density ? 255 : 0;
    const cv::Rect r = largest_rectangle(m);
    INFO("trial " << t);
    CHECK(static_cast<long>(r.area()) == brute_force_area(m));
    if (r.area() > 0) CHECK(cv::countNonZero(m(r)) == r.area());
  }
}

TEST_CASE("FSU: a component that fills its box poorly also gives its largest inner rectangle", "[fsu]") {
  for (double deg : {0.0, 25.0}) {
    INFO("deg " << deg);
    const ClassGrid g = ring_map(deg);
    FsuParams p;
    p.frame_deg = deg;
    const auto cands = detect_fsu_units(g, cv::Mat1b(), p);
    // The ring's box (courtyard and all), then one straight corridor of the ring.
    REQUIRE(cands.size() == 2);
    CHECK(cands[0].rect.area() > 0.9 * 200 * 200);
    CHECK(free_share(g, cands[0].rect) < 0.6);
    const OrientedRect& in = cands[1].rect;
    CHECK(std::max(in.w, in.h) == Approx(200).margin(6));
    CHECK(std::min(in.w, in.h) == Approx(30).margin(5));
    CHECK(free_share(g, in) > 0.9);
    // Switched off: the box alone, as before.
    p.inner_below = 0.0;
    CHECK(detect_fsu_units(g, cv::Mat1b(), p).size() == 1);
  }
  // Once that corridor is explained, the next refresh offers the next piece of what is left.
  const ClassGrid g = ring_map(0.0);
  FsuParams p;
  p.frame_deg = 0.0;
  const OrientedRect first = detect_fsu_units(g, cv::Mat1b(), p)[1].rect;
  const auto next = detect_fsu_units(g, raster(g, {first}), p);
  REQUIRE(next.size() == 2);
  CHECK(free_share(g, next[1].rect) > 0.9);
  CHECK(std::min(next[1].rect.w, next[1].rect.h) == Approx(30).margin(5));
  CHECK(std::abs(next[1].rect.cx - first.cx) + std::abs(next[1].rect.cy - first.cy) > 50.0);  // another side
}
