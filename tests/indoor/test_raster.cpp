// Row-span rasterisation against a direct point-in-rectangle test, and the cost of incremental
// updates: a wall shift visits the cells between the old and new wall bands only.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "stdlib/indoor/geometry.h"
#include "stdlib/indoor/scored_world.h"

using namespace ksmc::stdlib::indoor;

namespace {
// Signed margin of point p inside r (positive inside, negative outside), in cells.
double margin(const OrientedRect& r, Point2 p) {
  const Point2 l = Frame(r.theta).to_local(p);
  const Point2 c = Frame(r.theta).to_local({r.cx, r.cy});
  return std::min(0.5 * r.w - std::abs(l.x - c.x), 0.5 * r.h - std::abs(l.y - c.y));
}
}  // namespace

TEST_CASE("span rasteriser agrees with point-in-rectangle tests", "[indoor][raster]") {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int rows = 70, cols = 90;
  int inside = 0;
  for (int t = 0; t < 200; ++t) {
    const OrientedRect r{u(rng) * cols, u(rng) * rows, 1 + u(rng) * 50, 1 + u(rng) * 50, (u(rng) - 0.5) * 4};
    const SpanRaster s(r, cols);
    for (int row = 0; row < rows; ++row) {
      const RowSpan sp = s.span(row);
      for (int col = 0; col < cols; ++col) {
        const double m = margin(r, {static_cast<double>(col), static_cast<double>(row)});
        const bool in = col >= sp.x0 && col < sp.x1;
        if (std::abs(m) > 1e-9 && in != (m > 0)) {
          INFO("rect " << r.cx << "," << r.cy << " " << r.w << "x" << r.h << " th " << r.theta << " cell " << col
                       << "," << row);
          FAIL("span and point test disagree");
        }
        inside += in ? 1 : 0;
      }
    }
  }
  CHECK(inside > 10000);
  // Half-open edges: an axis-aligned rectangle [10, 20) x [5, 15) holds exactly 10 x 10 cells.
  const SpanRaster s(OrientedRect{15, 10, 10, 10, 0.0}, cols);
  int n = 0;
  for (int row = 0; row < rows; ++row) {
    const RowSpan sp = s.span(row);
    if (!sp.empty()) {
      CHECK(sp.x0 == 10);
      CHECK(sp.x1 == 20);
      CHECK(row >= 5);
      CHECK(row < 15);
    }
    n += sp.empty() ? 0 : sp.x1 - sp.x0;
  }
  CHECK(n == 100);
}

TEST_CASE("a wall shift visits only the cells it changes", "[indoor][raster]") {
  ScoreParams p;
  p.raster.wall_thickness = 1.0;
  ScoredWorld sw(ClassGrid(200, 300, std::uint8_t{0}), p);
  Unit a;
  a.id = 1;
  a.rect = OrientedRect{150, 100, 200, 120, 0.0};
  sw.apply(Move{KernelKind::Add, {{1, std::nullopt, a}}, {}, {}});
  const auto before = sw.coverage().cells_visited();
  CHECK(before == 200u * 120u);
  Unit b = a;
  b.rect = rect_from_box(shift_box_wall(own_box(a.rect), 1, 3.0), Frame(0.0));  // right wall +3
  sw.apply(Move{KernelKind::Dilate, {{1, a, b}}, {}, {}});
  const auto visited = sw.coverage().cells_visited() - before;
  // Columns 249 (wall -> interior), 250, 251 (new interior) and 252 (new wall) over 118 rows, and
  // 250..252 on the two wall rows (249 stays wall there): 4 x 118 + 3 x 2 cells.
  CHECK(visited == 4u * 118u + 3u * 2u);
  CHECK(sw.log_likelihood() == Approx(sw.recompute_log_likelihood()).epsilon(1e-12));
}

TEST_CASE("a split or merge visits only the cells of the cut walls", "[indoor][raster]") {
  ScoreParams p;
  p.raster.wall_thickness = 1.0;
  ScoredWorld sw(ClassGrid(200, 300, std::uint8_t{0}), p);
  Unit a;
  a.id = 1;
  a.rect = OrientedRect{150, 100, 200, 120, 0.0};  // columns 50..249, rows 40..159
  sw.apply(Move{KernelKind::Add, {{1, std::nullopt, a}}, {}, {}});
  Unit l = a, r = a;
  l.id = 2;
  l.rect = OrientedRect{100, 100, 100, 120, 0.0};  // columns 50..149
  r.id = 3;
  r.rect = OrientedRect{200, 100, 100, 120, 0.0};  // columns 150..249
  const Move split{KernelKind::Split, {{1, a, std::nullopt}, {2, std::nullopt, l}, {3, std::nullopt, r}}, {}, {}};
  auto before = sw.coverage().cells_visited();
  sw.apply(split);
  // Columns 149 and 150 become wall on the 118 interior rows; nothing else changes.
  CHECK(sw.coverage().cells_visited() - before == 2u * 118u);
  CHECK(sw.log_likelihood() == Approx(sw.recompute_log_likelihood()).epsilon(1e-12));
  CHECK(sw.log_prior() == Approx(sw.recompute_log_prior()).epsilon(1e-12));
  before = sw.coverage().cells_visited();
  const double ll = sw.log_likelihood();
  sw.revert(split);  // the merge
  CHECK(sw.coverage().cells_visited() - before == 2u * 118u);
  CHECK(sw.log_likelihood() == Approx(sw.recompute_log_likelihood()).epsilon(1e-12));
  CHECK(sw.log_likelihood() != ll);
  // A change of likelihood class still visits the whole area (the counts move between classes).
  Unit b = a;
  b.lut_class = 1;
  before = sw.coverage().cells_visited();
  sw.apply(Move{KernelKind::Add, {{1, a, b}}, {}, {}});
  CHECK(sw.coverage().cells_visited() - before == 200u * 120u);
  CHECK(sw.log_likelihood() == Approx(sw.recompute_log_likelihood()).epsilon(1e-12));
}

TEST_CASE("rendered prediction follows the cell classes", "[indoor][raster]") {
  ScoreParams p;
  p.raster.wall_thickness = 1.0;
  ScoredWorld sw(ClassGrid(30, 40, std::uint8_t{0}), p);
  Unit a;
  a.id = 1;
  a.rect = OrientedRect{20, 15, 20, 10, 0.0};  // cells 10..29 x 10..19
  Door d;
  d.id = 1;
  Unit b = a;
  b.id = 2;
  b.rect = OrientedRect{20, 25, 20, 10, 0.0};  // cells 10..29 x 20..29
  d.unit_a = 1;
  d.unit_b = 2;
  d.a = {18, 20};
  d.b = {22, 20};
  sw.apply(Move{KernelKind::Add, {{1, std::nullopt, a}, {2, std::nullopt, b}}, {{1, std::nullopt, d}}, {}});
  const cv::Mat1b img = render_predicted(sw.coverage());
  CHECK(img(5, 5) == static_cast<std::uint8_t>(Predicted::Unknown));
  CHECK(img(15, 20) == static_cast<std::uint8_t>(Predicted::Free));
  CHECK(img(15, 10) == static_cast<std::uint8_t>(Predicted::Wall));
  CHECK(img(19, 14) == static_cast<std::uint8_t>(Predicted::Wall));  // a's bottom wall, off the door
  CHECK(img(19, 20) == static_cast<std::uint8_t>(Predicted::Free));  // doorway through both walls
  CHECK(img(20, 20) == static_cast<std::uint8_t>(Predicted::Free));
  for (int r = 0; r < img.rows; ++r)
    for (int c = 0; c < img.cols; ++c) REQUIRE(img(r, c) == static_cast<std::uint8_t>(sw.coverage().predicted(r, c)));
}
