// PointGrid answers "which points are within r of p" exactly as a scan of all points does,
// for radii below, at and above its cell, with and without its table of column starts (a
// cloud spread so wide that the table would be large, or so far out that cell keys wrap,
// keeps the binary search).
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "stdlib/tabletop/perception/point_grid.h"

using namespace ksmc::stdlib::tabletop::perception;

namespace {

std::vector<int> scan(const Points& pts, const Eigen::Vector3d& p, double r) {
  std::vector<int> out;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if ((pts[i] - p).squaredNorm() <= r * r) out.push_back(static_cast<int>(i));
  return out;
}

void check_queries(const Points& pts, double cell, std::mt19937& rng) {
  const PointGrid grid(pts, cell);
  std::uniform_int_distribution<std::size_t> pick(0, pts.size() - 1);
  std::vector<int> got;
  for (double r : {0.5 * cell, cell, 1.7 * cell, 3.0 * cell}) {
    for (int q = 0; q < 50; ++q) {
      const Eigen::Vector3d p = pts[pick(rng)] + Eigen::Vector3d(0.001, -0.002, 0.0005);
      grid.within(p, r, got);
      std::sort(got.begin(), got.end());
      INFO("radius " << r << " query " << q);
      CHECK(got == scan(pts, p, r));
    }
  }
  // neighbours() is within() at the grid's own radius.
  std::vector<int> a, b;
  grid.neighbours(pts[0], a);
  grid.within(pts[0], cell, b);
  CHECK(a == b);
}

}  // namespace

TEST_CASE("point grid: queries of any radius equal a full scan", "[perception][grid]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3), h(0.0, 0.2);
  Points pts;
  for (int i = 0; i < 3000; ++i) pts.emplace_back(u(rng), u(rng), h(rng));
  check_queries(pts, 0.01, rng);
  // Negative and positive cells, points exactly on cell borders.
  Points border;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j) border.emplace_back(0.01 * i, 0.01 * j, 0.0);
  check_queries(border, 0.01, rng);
}

TEST_CASE("point grid: a cloud spread wide or far out (no column table) answers the same", "[perception][grid]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  Points pts;
  // Two dense clumps 50 m apart: the bounding box has far more columns than points.
  for (int i = 0; i < 500; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
  for (int i = 0; i < 500; ++i) pts.emplace_back(50.0 + u(rng), 50.0 + u(rng), u(rng));
  check_queries(pts, 0.005, rng);
  // One clump 5.2 km out, across the keys' wrap at 2^20 cells, where key order is not
  // column order (the table is not built).
  Points far;
  for (int i = 0; i < 500; ++i) far.emplace_back(5242.88 + u(rng), u(rng), u(rng));  // 2^20 cells of 5 mm
  check_queries(far, 0.005, rng);
}
