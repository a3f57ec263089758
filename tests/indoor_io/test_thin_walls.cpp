// Thin walls (stdlib/indoor/io/thin_walls.h) and the segmentation cuts they give
// (wall_gap_cuts.h): a slanted one-cell partition with a door, a partition ending at a doorway
// before the outer wall, and two partitions in line across a walled corridor (no cut).
#include <algorithm>

#include <catch2/catch.hpp>

#include "stdlib/indoor/io/segmentation.h"
#include "stdlib/indoor/io/thin_walls.h"
#include "tests/indoor_io/axis_unit.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;
using ksmc::tests::indoor_io::kFree;
using ksmc::tests::indoor_io::kOcc;
using ksmc::tests::indoor_io::unit;

namespace {

// A walled rectangle of free cells, rows 2..rows+1 and cols 2..cols+1, outer wall 2 cells.
ClassGrid walled(int rows, int cols) {
  ClassGrid g(rows + 4, cols + 4, kOcc);
  for (int r = 2; r < rows + 2; ++r)
    for (int c = 2; c < cols + 2; ++c) g(r, c) = kFree;
  return g;
}

// A one-cell partition leaning one column per 10 rows (5.7 degrees off the grid axes, so no
// row or column holds a straight wall run), from row r0 to r1, without rows [g0, g1].
void slanted_partition(ClassGrid& g, int r0, int r1, int g0 = -1, int g1 = -2) {
  for (int r = r0; r <= r1; ++r)
    if (r < g0 || r > g1) g(r, 80 + (r - 2) / 10) = kOcc;
}

WorldResult one_unit_over(const ClassGrid& g) {
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(2, 1.5, 1.5, g.cols - 2.5, g.rows - 2.5)};
  return w;
}

}  // namespace

TEST_CASE("thin walls: partitions are thin, outer walls and blocks are not") {
  ClassGrid g = walled(80, 160);
  slanted_partition(g, 2, 81);
  for (int r = 20; r < 40; ++r)
    for (int c = 20; c < 40; ++c) g(r, c) = kOcc;  // a 1 m block of furniture
  const cv::Mat1b m = thin_wall_mask(g, 8);
  CHECK(m(2, 80) == 255);
  CHECK(m(50, 84) == 255);
  CHECK(m(1, 40) == 0);  // the outer wall: the map edge beyond it
  CHECK(m(30, 30) == 0);
  CHECK(m(20, 30) == 0);  // the block's edge: 20 cells across
  const auto lines = thin_wall_lines(g, 0.05);
  REQUIRE(lines.size() == 1);
  REQUIRE(lines[0].covered.size() == 1);
  CHECK(lines[0].covered[0].second - lines[0].covered[0].first > 70.0);
  // A 1 m door cut out of the partition (rows 30..49): no line covers the door.
  ClassGrid d = walled(80, 160);
  slanted_partition(d, 2, 81, 30, 49);
  const auto with_door = thin_wall_lines(d, 0.05);
  REQUIRE(!with_door.empty());
  for (const auto& l : with_door)
    for (const auto& [lo, hi] : l.covered) {
      const double ya = l.at(lo).y, yb = l.at(hi).y;
      CHECK(!(std::min(ya, yb) < 32.0 && std::max(ya, yb) > 47.0));
    }
}

TEST_CASE("segmentation: a slanted one-cell partition with a door separates two rooms") {
  ClassGrid g = walled(80, 160);
  slanted_partition(g, 2, 81, 30, 49);
  const cv::Mat1w s = render_segmentation(g, one_unit_over(g));
  CHECK(s(40, 40) != 0);
  CHECK(s(40, 140) != 0);
  CHECK(s(40, 40) != s(40, 140));
  CHECK(s(10, 40) == s(70, 40));
  CHECK(s(10, 140) == s(70, 140));
}

TEST_CASE("segmentation: a partition ending 1 m before the outer wall leaves a doorway, 2 m does not") {
  ClassGrid g = walled(80, 160);
  slanted_partition(g, 2, 61);  // rows 62..81 free: 1 m to the outer wall
  cv::Mat1w s = render_segmentation(g, one_unit_over(g));
  CHECK(s(40, 40) != s(40, 140));
  CHECK(s(75, 40) != s(75, 140));
  ClassGrid open = walled(80, 160);
  slanted_partition(open, 2, 41);  // 2 m of free floor beyond its end: an opening, not a door
  s = render_segmentation(open, one_unit_over(open));
  CHECK(s(40, 40) == s(40, 140));
}

TEST_CASE("segmentation: partitions in line on both sides of a walled corridor do not cut the corridor") {
  // Rooms rows 2..49 and 72..121, a 1 m corridor rows 51..70 between one-cell walls at rows 50
  // and 71 with a door into each room; one slanted partition line above and below the corridor.
  // Both pieces end in a junction with a corridor wall: the corridor between them is no gap.
  ClassGrid g = walled(120, 160);
  for (int c = 2; c < 162; ++c) {
    const bool door = (c >= 20 && c < 40) || (c >= 130 && c < 150);
    if (!door) g(50, c) = g(71, c) = kOcc;
  }
  slanted_partition(g, 2, 121, 50, 71);
  const cv::Mat1w s = render_segmentation(g, one_unit_over(g));
  CHECK(s(60, 10) != 0);
  CHECK(s(60, 10) == s(60, 155));  // the corridor is one segment
  CHECK(s(60, 87) == s(60, 10));
  CHECK(s(60, 84) == s(60, 10));
}
