// segmentation.png's fill rule on small synthetic grids: units explain the free cells inside
// them (deepest unit wins), a room no unit reaches behind a door is a segment of its own, other
// free cells go to the nearest unit through free space, walls
// and unknown cells stay 0, a free pocket no unit reaches stays 0 (a larger one is a segment),
// two units in one open room are one segment.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <catch2/catch.hpp>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/io/segmentation.h"
#include "stdlib/indoor/io/wall_gap_cuts.h"
#include "tests/indoor_io/temp_dir.h"
#include "tests/indoor_io/axis_unit.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;
using ksmc::tests::indoor_io::unit;

namespace {

// 8 x 14 cells. Room A: cols 1-4, room B: cols 6-10, rows 1-5; col 5 is a wall with a door gap
// at row 3; col 11 a wall; cols 12 (rows 1-2) a free pocket walled off; (2, 8) unknown.
ClassGrid tiny_map() {
  ClassGrid g(8, 14, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 1; r <= 5; ++r)
    for (int c = 1; c <= 10; ++c)
      if (c != 5) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  g(3, 5) = static_cast<std::uint8_t>(Cell::Free);
  g(2, 8) = static_cast<std::uint8_t>(Cell::Unknown);
  g(1, 12) = g(2, 12) = static_cast<std::uint8_t>(Cell::Free);
  return g;
}

// Occupied cells over rows r0-r1 and columns c0-c1 (inclusive).
void fill_wall(cv::Mat1b& g, int r0, int r1, int c0, int c1) {
  g(cv::Range(r0, r1 + 1), cv::Range(c0, c1 + 1)) = static_cast<std::uint8_t>(Cell::Occupied);
}

// A free floor of w x h cells inside outer walls 3 cells (0.15 m) thick.
cv::Mat1b walled_floor(int w, int h) {
  cv::Mat1b g(h, w, static_cast<std::uint8_t>(Cell::Free));
  fill_wall(g, 0, 2, 0, w - 1);
  fill_wall(g, h - 3, h - 1, 0, w - 1);
  fill_wall(g, 0, h - 1, 0, 2);
  fill_wall(g, 0, h - 1, w - 3, w - 1);
  return g;
}

// The point (x, y) under the 2 x 3 affine map `rot`.
Point2 apply(const cv::Mat& rot, double x, double y) {
  return Point2{rot.at<double>(0, 0) * x + rot.at<double>(0, 1) * y + rot.at<double>(0, 2),
                rot.at<double>(1, 0) * x + rot.at<double>(1, 1) * y + rot.at<double>(1, 2)};
}

}  // namespace

TEST_CASE("segmentation: units, nearest unit through free space, walls and unknown 0") {
  const ClassGrid g = tiny_map();
  WorldResult w;
  w.units = {unit(3, 0.5, 0.5, 4.5, 5.5),    // room A exactly
             unit(9, 3.6, 0.5, 4.6, 5.5),    // a sliver on A's right edge and the wall
             unit(7, 5.5, 0.5, 7.5, 5.5)};   // covers only cols 6-7 of room B
  const cv::Mat1w s = render_segmentation(g, w);
  REQUIRE(s.rows == 8);
  REQUIRE(s.cols == 14);
  for (int r = 1; r <= 5; ++r) {
    for (int c = 1; c <= 4; ++c) {
      INFO("cell " << r << "," << c);
      // Col 4 is 0.5 deep in A and 0.4 deep in the sliver: A wins, the sliver keeps nothing.
      CHECK(s(r, c) == 3);
    }
    CHECK(s(r, 6) == 7);
    CHECK(s(r, 7) == 7);
    for (int c = 8; c <= 10; ++c)
      if (!(r == 2 && c == 8)) CHECK(s(r, c) == 7);  // outside every unit: nearest through free space
  }
  CHECK(s(2, 8) == 0);   // unknown
  CHECK(s(0, 3) == 0);   // wall
  CHECK(s(1, 5) == 0);   // wall, although inside the sliver and unit 7's rectangle edge
  CHECK(s(3, 5) == 3);   // door gap: equidistant, the unit seeded first in row-major order
  CHECK(s(1, 12) == 0);  // a free pocket without a path to any unit
  CHECK(s(2, 12) == 0);
  CHECK(cv::countNonZero(s == 9) == 0);
}

TEST_CASE("segmentation: the deeper of two overlapping units wins, ties go to the smaller id") {
  ClassGrid g(3, 12, static_cast<std::uint8_t>(Cell::Free));
  WorldResult w;
  w.units = {unit(5, -0.5, -0.5, 7.5, 2.5), unit(2, 3.5, -0.5, 11.5, 2.5)};  // overlap: cols 4-7
  const cv::Mat1w s = render_segmentation(g, w);
  // Row 1 (1.5 deep in y in both): col 4 is 1.5 deep in unit 5 and 0.5 in unit 2; cols 5 and 6
  // tie at 1.5 and go to the nearer centre (5 at x = 3.5, 2 at x = 7.5): the boundary is the
  // overlap's mid line x = 5.5.
  CHECK(s(1, 3) == 5);
  CHECK(s(1, 4) == 5);
  CHECK(s(1, 5) == 5);
  CHECK(s(1, 6) == 2);
  CHECK(s(1, 7) == 2);
  CHECK(s(1, 8) == 2);
  CHECK(s(0, 4) == 5);  // 0.5 deep in both: nearer centre
  CHECK(s(0, 7) == 2);
  // An exact tie in depth and centre distance goes to the smaller id.
  WorldResult t;
  t.units = {unit(8, -0.5, -0.5, 4.5, 2.5), unit(4, 1.5, -0.5, 6.5, 2.5)};  // centres x = 2 and 4
  CHECK(render_segmentation(g, t)(1, 3) == 4);  // x = 3: 1.5 deep in both, 1 from each centre
}

TEST_CASE("segmentation.png is 16-bit with the unit ids") {
  ksmc::tests::TempDir dir("segmentation");
  WorldResult w;
  w.units = {unit(300, 0.5, 0.5, 4.5, 5.5)};
  const auto path = dir.path() / "segmentation.png";
  write_segmentation_png(path, tiny_map(), w);
  const cv::Mat m = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  REQUIRE(m.type() == CV_16UC1);
  CHECK(m.at<std::uint16_t>(2, 2) == 300);
  CHECK(m.at<std::uint16_t>(2, 9) == 300);  // through the door gap
  CHECK(m.at<std::uint16_t>(0, 0) == 0);
}

TEST_CASE("segmentation: a room no unit reaches, behind a door, is a segment of its own") {
  // 0.05 m cells. Room A: cols 1-60, room B: cols 62-128, rows 1-60; col 61 is a wall with a
  // 0.8 m door (rows 25-40). A table in B (rows 25-35, cols 93-97) cuts B's core (cells over
  // 0.6 m from every wall) in two; the two halves meet over more than 2 m of free cells.
  ClassGrid g(62, 130, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 1; r <= 60; ++r)
    for (int c = 1; c <= 128; ++c)
      if (c != 61) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  for (int r = 25; r <= 40; ++r) g(r, 61) = static_cast<std::uint8_t>(Cell::Free);
  for (int r = 25; r <= 35; ++r)
    for (int c = 93; c <= 97; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Occupied);
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(4, 0.5, 0.5, 40.5, 60.5)};  // two thirds of room A
  const cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(30, 20) == 4);
  CHECK(s(30, 55) == 4);  // the rest of room A: no narrow passage between it and the unit
  const std::uint16_t b = s(10, 70);
  CHECK(b == 5);          // a new id above every unit id
  CHECK(s(50, 120) == b);  // both sides of the table: one space
  CHECK(s(30, 110) == b);
  CHECK(s(30, 95) == b);   // the table: furniture of room B
  // Nearest-unit fill alone (the rooms joined by a door wider than 1.2 m) gives B to unit 4.
  for (int r = 5; r <= 56; ++r) g(r, 61) = static_cast<std::uint8_t>(Cell::Free);
  CHECK(render_segmentation(g, w)(10, 70) == 4);
}

TEST_CASE("segmentation: free-standing furniture gets its room, walls and furniture at a wall stay 0") {
  // Two rooms (cols 1-8 and 10-18) with a wall at col 9; a table (3, 4)-(4, 5) free-standing in
  // the left room, a cupboard (1, 16)-(2, 17) against the right room's top wall.
  ClassGrid g(8, 20, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 1; r <= 6; ++r)
    for (int c = 1; c <= 18; ++c)
      if (c != 9) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  for (int r = 3; r <= 4; ++r)
    for (int c = 4; c <= 5; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Occupied);
  for (int r = 1; r <= 2; ++r)
    for (int c = 16; c <= 17; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Occupied);
  WorldResult w;
  w.units = {unit(1, 0.5, 0.5, 8.5, 6.5), unit(2, 9.5, 0.5, 18.5, 6.5)};
  const cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(3, 4) == 1);  // the table
  CHECK(s(4, 5) == 1);
  CHECK(s(1, 16) == 0);  // the cupboard is part of the wall structure
  CHECK(s(3, 9) == 0);   // the wall between the rooms
  CHECK(s(0, 3) == 0);
  // A blob whose neighbours lie in two segments (a pillar on the boundary) stays 0.
  g(3, 9) = g(4, 9) = static_cast<std::uint8_t>(Cell::Free);
  for (int r = 1; r <= 6; ++r)
    if (r != 3 && r != 4) g(r, 9) = static_cast<std::uint8_t>(Cell::Free);
  g(3, 9) = g(4, 9) = static_cast<std::uint8_t>(Cell::Occupied);
  CHECK(render_segmentation(g, w)(3, 9) == 0);
}

namespace {

// 0.05 m cells, walls 2 cells thick. A 2 m corridor (rows 2-41) above three offices 3 m wide
// and 4 m deep (rows 44-123; cols 2-61, 64-123, 126-185, partitions at cols 62-63 and
// 124-125). The offices' corridor side (rows 42-43) is open over 2.2 m: only 0.4 m wall stubs
// stand at either side of each partition and at the outer walls.
ClassGrid open_front_offices() {
  ClassGrid g(126, 188, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 2; r <= 123; ++r)
    for (int c = 2; c <= 185; ++c)
      if (!(r >= 42 && (c >= 62 && c <= 63)) && !(r >= 42 && c >= 124 && c <= 125)) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  for (int r = 42; r <= 43; ++r)
    for (int c = 2; c <= 185; ++c)
      if (c <= 9 || (c >= 54 && c <= 71) || (c >= 116 && c <= 133) || c >= 178) g(r, c) = static_cast<std::uint8_t>(Cell::Occupied);
  return g;
}

}  // namespace

TEST_CASE("segmentation: a unit over offices open to a corridor is cut along the wall-stub line") {
  ClassGrid g = open_front_offices();
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(2, 1.5, 1.5, 186.5, 124.5)};  // one unit over the corridor and all offices
  cv::Mat1w s = render_segmentation(g, w);
  const std::uint16_t corridor = s(20, 100), a = s(80, 30), b = s(80, 90), c = s(80, 150);
  CHECK(corridor == 2);  // the largest piece keeps the unit's id
  CHECK(a != corridor);
  CHECK(b != corridor);
  CHECK(c != corridor);
  CHECK(a != b);
  CHECK(b != c);
  CHECK(a > 2);  // new ids above every id in use
  for (int r = 2; r <= 41; ++r) CHECK(s(r, 5) == corridor);
  for (int r = 44; r <= 123; r += 7)
    for (int col = 2; col <= 61; col += 5) CHECK(s(r, col) == a);  // an office is not cut in strips
  // Without the stubs the offices' fronts are no wall line: one segment.
  for (int r = 42; r <= 43; ++r)
    for (int col = 2; col <= 185; ++col)
      if (!(col >= 62 && col <= 63) && !(col >= 124 && col <= 125)) g(r, col) = static_cast<std::uint8_t>(Cell::Free);
  s = render_segmentation(g, w);
  CHECK(s(80, 30) == 2);
  CHECK(s(80, 90) == 2);
  CHECK(s(20, 100) == 2);
}

TEST_CASE("segmentation: a wall line with a gap over 3 m, or shelves in line inside a room, cut nothing") {
  // One room 8 m x 4 m (rows 2-81, cols 2-161), walls 2 cells thick. A wall line across it at
  // rows 40-41 from each side wall, with a 3.5 m gap (cols 41-110).
  ClassGrid g(84, 164, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 2; r <= 81; ++r)
    for (int c = 2; c <= 161; ++c)
      if (!(r >= 40 && r <= 41 && (c <= 40 || c >= 111))) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  // Two shelves 0.1 m x 1 m in one line in the upper half, 1.5 m apart: a gap in a "wall line"
  // whose cut does not separate anything (the room continues around the shelves).
  for (int r = 20; r <= 21; ++r)
    for (int c = 0; c < 20; ++c) g(r, 50 + c) = g(r, 100 + c) = static_cast<std::uint8_t>(Cell::Occupied);
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(2, 1.5, 1.5, 162.5, 82.5)};
  cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(10, 80) == 2);
  CHECK(s(30, 80) == 2);
  CHECK(s(70, 80) == 2);
  // The gap narrowed to 2.5 m (cols 61-110): the line now cuts the room in two.
  for (int r = 40; r <= 41; ++r)
    for (int c = 41; c <= 60; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Occupied);
  s = render_segmentation(g, w);
  CHECK(s(10, 80) != s(70, 80));
  CHECK(s(10, 80) == s(30, 80));  // the shelves still cut nothing
  CHECK(std::min(s(10, 80), s(70, 80)) == 2);
}

namespace {

// A walled room of `rows` x `cols` free cells (0.05 m) starting at (1, 1).
ClassGrid walled_room(int rows, int cols) {
  ClassGrid g(rows + 2, cols + 2, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 1; r <= rows; ++r)
    for (int c = 1; c <= cols; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  return g;
}

}  // namespace

TEST_CASE("segmentation: a narrow walled-off room no unit reaches is a segment of its own") {
  // Room A: cols 1-60; a 1 m wide room (cols 62-81, rows 1-60) behind a solid wall at col 61:
  // none of its cells is over 0.6 m from a wall, so seed_uncovered_spaces does not see it.
  ClassGrid g = walled_room(60, 81);
  for (int r = 1; r <= 60; ++r) g(r, 61) = static_cast<std::uint8_t>(Cell::Occupied);
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(4, 0.5, 0.5, 60.5, 60.5)};
  const cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(30, 30) == 4);
  const std::uint16_t b = s(30, 70);
  CHECK(b == 5);
  CHECK(s(1, 62) == b);
  CHECK(s(60, 81) == b);
  CHECK(s(30, 61) == 0);  // the wall
}

TEST_CASE("segmentation: two units in one open room are one segment, unless a wall or size separates them") {
  // One 6 m x 4 m room covered by a unit and a 1.5 m strip unit beside it (as a chain leaves a
  // room: a unit and a sliver). No wall between them: one segment, the smaller id.
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(3, 0.5, 0.5, 90.5, 80.5), unit(8, 90.5, 0.5, 120.5, 80.5)};
  ClassGrid g = walled_room(80, 120);
  cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(40, 40) == 3);
  CHECK(s(40, 110) == 3);
  CHECK(s(5, 118) == 3);
  // A wall between them at col 91 with a 2.5 m opening (rows 16-65): two rooms sharing a wall
  // (wall runs 30 rows, over a quarter of the 50-row free contact): two segments.
  for (int r = 1; r <= 80; ++r)
    if (r < 16 || r > 65) g(r, 91) = static_cast<std::uint8_t>(Cell::Occupied);
  s = render_segmentation(g, w);
  CHECK(s(40, 40) == 3);
  CHECK(s(40, 110) == 8);
  // No wall, but both units are rooms in their own right (6 m x 4 m and 6 m x 3 m, 24 and 18
  // m^2; their facing sides differ, 4 m and 3 m): two segments.
  WorldResult big;
  big.map.resolution = 0.05;
  big.units = {unit(3, 0.5, 0.5, 120.5, 80.5), unit(8, 120.5, 20.5, 240.5, 80.5)};
  s = render_segmentation(walled_room(80, 240), big);
  CHECK(s(40, 40) == 3);
  CHECK(s(40, 200) == 8);
  // Both 6 m x 4 m, meeting over the whole of their 4 m sides with no wall: units that continue
  // each other (unit_chains.h), one space.
  big.units[1] = unit(8, 120.5, 0.5, 240.5, 80.5);
  s = render_segmentation(walled_room(80, 240), big);
  CHECK(s(40, 40) == 3);
  CHECK(s(40, 200) == 3);
}

namespace {

// An L-shaped corridor `width` cells wide: a leg along the top (rows 1..width, cols 1..cols)
// and a leg down the left (cols 1..width, rows 1..rows); walls around it.
ClassGrid l_corridor(int width, int rows, int cols) {
  ClassGrid g(rows + 2, cols + 2, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 1; r <= rows; ++r)
    for (int c = 1; c <= cols; ++c)
      if (r <= width || c <= width) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  return g;
}

// The L's two legs as units: the top one from the corner's far side on, the left one whole.
WorldResult l_units(int width, int rows, int cols) {
  WorldResult w;
  w.map.resolution = 0.05;
  const double e = width + 0.5;
  w.units = {unit(4, e, 0.5, cols + 0.5, e), unit(9, 0.5, 0.5, e, rows + 0.5)};
  return w;
}

}  // namespace

TEST_CASE("segmentation: a corridor in pieces meeting end to side is one segment, a door keeps them apart") {
  // 1.8 m wide legs of 15 m and 12 m (27 and 21.6 m^2, both over the 20 m^2 of a room's piece):
  // they meet over 1.8 m, under the 2 m that joins two pieces of an open room, and no cell of
  // the contact is 0.6 m from a wall. A corridor continues: one segment.
  ClassGrid g = l_corridor(36, 240, 300);
  const WorldResult w = l_units(36, 240, 300);
  cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(18, 200) == 4);
  CHECK(s(200, 18) == 4);
  // A wall across the corner with a 1 m door (rows 9-28): two segments.
  for (int r = 1; r <= 36; ++r)
    if (r < 9 || r > 28) g(r, 37) = static_cast<std::uint8_t>(Cell::Occupied);
  s = render_segmentation(g, w);
  CHECK(s(18, 200) == 4);
  CHECK(s(200, 18) == 9);
  // A wide corridor (3.5 m, legs of 15 m: Table 3.6's corridor, 4 times as long as wide) too; it
  // keeps the id of the larger leg (unit 9, 3.5 m x 15 m against 3.5 m x 11.5 m).
  s = render_segmentation(l_corridor(70, 300, 300), l_units(70, 300, 300));
  CHECK(s(35, 250) == 9);
  CHECK(s(250, 35) == 9);
  // Two rooms, 3.5 m x 6 m and 3.5 m x 9.5 m, meeting the same way over 3.5 m: under 3 times
  // as long as wide, so not a corridor, and each over 20 m^2: they stay two segments.
  s = render_segmentation(l_corridor(70, 190, 190), l_units(70, 190, 190));
  CHECK(s(35, 150) == 4);
  CHECK(s(150, 35) == 9);
}

TEST_CASE("segmentation: chairs round a table are no wall line") {
  // One room 8 m x 6 m (rows 1-120, cols 1-160). Chairs 0.3 m square every 0.5 m on a ring
  // round a table 5.5 m x 3.5 m (rows 25-100, cols 25-140): 0.2 m gaps between them, each gap a
  // free run between two occupied runs 0.3 m long and 0.3 m thick, as between two wall stubs. A
  // chair's blob spans under 1 m, so no gap is a cut: the floor under the table stays the
  // room's. (Wall stubs that are part of a wall do cut: "a unit over offices open to a corridor
  // is cut along the wall-stub line".)
  ClassGrid g = walled_room(120, 160);
  const auto chair = [&g](int r0, int c0) {
    for (int r = r0; r < r0 + 6; ++r)
      for (int c = c0; c < c0 + 6; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Occupied);
  };
  for (int c = 25; c <= 135; c += 10) chair(25, c), chair(95, c);
  for (int r = 35; r <= 85; r += 10) chair(r, 25), chair(r, 135);
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(2, 0.5, 0.5, 160.5, 120.5)};
  const cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(60, 80) == 2);
  CHECK(s(10, 10) == 2);
  CHECK(s(110, 150) == 2);
}

TEST_CASE("segmentation: a joined segment keeps the id of its main type, a piece cut off again its own id") {
  // A straight corridor 2 m x 30 m in three units: a Room 12 m long and two Corr 9 m long. They
  // are one space; the Corr units cover most of it, so it keeps the id (and the type) of a Corr
  // unit: the larger, here the smaller id of two equal ones.
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(3, 0.5, 0.5, 240.5, 40.5), unit(5, 240.5, 0.5, 420.5, 40.5), unit(7, 420.5, 0.5, 600.5, 40.5)};
  w.units[0].type = "Room";
  w.units[1].type = w.units[2].type = "Corr";
  cv::Mat1w s = render_segmentation(walled_room(40, 600), w);
  CHECK(s(20, 100) == 5);
  CHECK(s(20, 300) == 5);
  CHECK(s(20, 500) == 5);
  // A corridor 3 m x 24 m in two units, with a door frame across it at cols 240-243 (stubs 0.3 m
  // from each side wall, a 2.4 m opening). The join makes them one segment, and the wall-line
  // cut at the frame splits it again: the larger piece keeps the joined id (unit 4), the other
  // piece gets its own unit's id back (9), not a new id without a unit.
  ClassGrid g = walled_room(60, 480);
  for (int r = 1; r <= 60; ++r)
    if (r <= 6 || r >= 55)
      for (int c = 240; c <= 243; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Occupied);
  WorldResult two;
  two.map.resolution = 0.05;
  two.units = {unit(4, 0.5, 0.5, 241.5, 60.5), unit(9, 241.5, 0.5, 480.5, 60.5)};
  s = render_segmentation(g, two);
  CHECK(s(30, 100) == 4);
  CHECK(s(30, 400) == 9);
}

// A floor turned against the image (nearest neighbour, as a SLAM map drawn at an angle): an
// office open to its corridor over 2 m between the stubs of a 0.35 m wall, both under one unit,
// turned by 45 degrees. In the building's frame the gap between the stubs is a wall-line cut
// and office and corridor are two segments. Scanned along the image rows and columns the gap
// runs at 45 degrees to the scan lines and the wall is too thick across them for a thin wall:
// no cut, one segment.
TEST_CASE("segmentation: an office open to its corridor, turned by 45 degrees, is a segment of its own") {
  const int w0 = 201, h0 = 121;  // 10 x 6 m at 0.05 m
  cv::Mat1b flat = walled_floor(w0, h0);
  fill_wall(flat, 75, 81, 0, w0 - 1);  // office and corridor wall, 0.35 m thick, open over 2 m
  flat(cv::Range(75, 82), cv::Range(80, 120)) = static_cast<std::uint8_t>(Cell::Free);
  const int n = 240;
  const auto turned = [&](double degrees, cv::Mat& rot) {  // the floor and its unit turned
    rot = cv::getRotationMatrix2D(cv::Point2f(100.0f, 60.0f), degrees, 1.0);
    rot.at<double>(0, 2) += 0.5 * (n - 1) - 100.0;
    rot.at<double>(1, 2) += 0.5 * (n - 1) - 60.0;
    const auto turn = [&rot](double x, double y) { return apply(rot, x, y); };
    WorldResult w;
    w.map.resolution = 0.05;
    UnitResult u;  // one unit over office and corridor
    u.id = 1;
    u.corners = {turn(2.5, 2.5), turn(197.5, 2.5), turn(197.5, 117.5), turn(2.5, 117.5)};
    w.units = {u};
    return w;
  };
  cv::Mat rot;
  // The units' direction is read with its sign (image rows down: a counter-clockwise turn is negative).
  CHECK(dominant_wall_angle(turned(30.0, rot)) * 180.0 / CV_PI == Approx(-30.0).margin(1e-6));
  const WorldResult w = turned(45.0, rot);
  ClassGrid g;
  cv::warpAffine(flat, g, rot, cv::Size(n, n), cv::INTER_NEAREST, cv::BORDER_CONSTANT,
                 cv::Scalar(static_cast<double>(Cell::Unknown)));
  const auto turn = [&rot](double x, double y) { return apply(rot, x, y); };
  CHECK(std::abs(dominant_wall_angle(w) * 180.0 / CV_PI) == Approx(45.0).margin(1e-6));
  const cv::Mat1w s = render_segmentation(g, w);
  std::map<int, long> cells;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      if (s(r, c) != 0) ++cells[s(r, c)];
  std::vector<int> spaces;  // segments of at least 1 m^2
  for (const auto& [id, count] : cells)
    if (count >= 400) spaces.push_back(id);
  REQUIRE(spaces.size() == 2);
  CHECK(spaces[0] == 1);  // the unit's id stays with the larger piece
  // Each piece is one side of the wall: the centres of office and corridor lie in different ones.
  const Point2 office = turn(100.0, 40.0), corridor = turn(100.0, 100.0);
  const int a = s(static_cast<int>(office.y), static_cast<int>(office.x));
  const int b = s(static_cast<int>(corridor.y), static_cast<int>(corridor.x));
  CHECK(a != 0);
  CHECK(b != 0);
  CHECK(a != b);
  // Axis-aligned units keep the row and column scans: the direction is 0.
  WorldResult flat_world;
  flat_world.units = {unit(1, 10.5, 10.5, 60.5, 40.5), unit(2, 70.5, 10.5, 90.5, 40.5)};
  CHECK(dominant_wall_angle(flat_world) == 0.0);
}

// A corridor 1.5 m wide between walls 0.25 or 0.3 m thick (about the wall run the scan needs
// beyond a gap's end), offices beyond both walls, turned by 5 to 40 degrees. Turned back by
// nearest neighbour for the scan, the walls' faces are jagged by a cell, and on some rows a
// row's run into each wall ends in a cell standing out of the wall's far face, alone across the
// row. Tested at that last cell alone (as on the map's own grid), those rows read as gaps in a
// wall line lying along the row, and the corridor was cut across: 13 of these 60 turns gave 2
// to 4 segments (0.3 m walls turned by 15 degrees: 4).
TEST_CASE("segmentation: a corridor between walls 0.3 m thick, turned by 5 to 40 degrees, is not cut across") {
  const int w0 = 161, h0 = 141, n = 230;  // 8 x 7 m at 0.05 m, turned on a 230-cell canvas
  for (const int thick : {5, 6})
    for (double degrees = 5.0; degrees <= 40.0; degrees += 2.5)
      for (const float shift : {0.0f, 0.3f}) {  // the turn's centre, off the cell grid or on it
        cv::Mat1b flat = walled_floor(w0, h0);
        fill_wall(flat, 0, h0 - 1, 56 - thick, 55);  // the corridor is columns 56-85 (1.5 m)
        fill_wall(flat, 0, h0 - 1, 86, 85 + thick);
        const cv::Point2f centre(80.0f + shift, 70.0f + shift);
        cv::Mat rot = cv::getRotationMatrix2D(centre, degrees, 1.0);
        rot.at<double>(0, 2) += 0.5 * (n - 1) - centre.x;
        rot.at<double>(1, 2) += 0.5 * (n - 1) - centre.y;
        const auto turn = [&rot](double x, double y) { return apply(rot, x, y); };
        ClassGrid g;
        cv::warpAffine(flat, g, rot, cv::Size(n, n), cv::INTER_NEAREST, cv::BORDER_CONSTANT,
                       cv::Scalar(static_cast<double>(Cell::Unknown)));
        WorldResult w;
        w.map.resolution = 0.05;
        const auto turned_unit = [&](int id, double c0, double c1) {
          UnitResult u;
          u.id = id;
          u.corners = {turn(c0, 2.5), turn(c1, 2.5), turn(c1, h0 - 3.5), turn(c0, h0 - 3.5)};
          return u;
        };
        w.units = {turned_unit(1, 2.5, 55.5 - thick), turned_unit(2, 55.5, 85.5), turned_unit(3, 85.5 + thick, w0 - 3.5)};
        INFO("walls " << thick << " cells thick, turned by " << degrees << " degrees about a centre shifted by " << shift);
        REQUIRE(dominant_wall_angle(w) * 180.0 / CV_PI == Approx(-degrees).margin(1e-6));
        const cv::Mat1w s = render_segmentation(g, w);
        // Every free cell of the corridor (away from its walls' jagged faces) is in one segment.
        std::map<int, long> corridor;
        for (int r = 5; r < h0 - 5; ++r)
          for (int c = 58; c <= 83; ++c) {
            const Point2 p = turn(c, r);
            const int tr = static_cast<int>(std::lround(p.y)), tc = static_cast<int>(std::lround(p.x));
            if (g(tr, tc) == static_cast<std::uint8_t>(Cell::Free)) ++corridor[s(tr, tc)];
          }
        CHECK(corridor.size() == 1);
        CHECK(corridor.count(0) == 0);
      }
}

namespace {

// 0.05 m cells, walls 2 cells thick. A 2 m corridor (rows 42-81, cols 2-161, unit 1) between two
// rows of offices (rows 2-39 and 84-121; units 2, 3 north, 4, 5 south), whose partitions (cols
// 80-81) line up across it. Each office opens to the corridor through a 0.9 m door: `door(r, c)`
// says which wall cells are open.
template <class Door>
std::pair<ClassGrid, WorldResult> offices_across_a_corridor(const Door& door) {
  ClassGrid g(124, 164, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 2; r <= 121; ++r)
    for (int c = 2; c <= 161; ++c) {
      const bool wall_row = r == 40 || r == 41 || r == 82 || r == 83;
      const bool partition = (c == 80 || c == 81) && (r <= 41 || r >= 82);
      if (!partition && (!wall_row || door(r, c))) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
    }
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(1, 1.5, 41.5, 161.5, 81.5), unit(2, 1.5, 1.5, 79.5, 39.5), unit(3, 81.5, 1.5, 161.5, 39.5),
             unit(4, 1.5, 83.5, 79.5, 121.5), unit(5, 81.5, 83.5, 161.5, 121.5)};
  return {g, w};
}

// The corridor and each office are one segment of their own.
void check_offices_across_a_corridor(const cv::Mat1w& s) {
  CHECK(s(60, 20) == 1);
  CHECK(s(60, 140) == 1);  // one corridor across the partitions' line
  CHECK(s(20, 40) == 2);
  CHECK(s(20, 120) == 3);
  CHECK(s(100, 40) == 4);
  CHECK(s(100, 120) == 5);
}

}  // namespace

TEST_CASE("segmentation: a corridor is not cut where the partitions on both sides line up, a door frame cuts it") {
  auto [g, w] = offices_across_a_corridor([](int, int c) { return (c >= 30 && c <= 47) || (c >= 110 && c <= 127); });
  check_offices_across_a_corridor(render_segmentation(g, w));
  // A door frame in the corridor on that line (stubs 0.5 m long from each side, a 1 m opening)
  // cuts it in two.
  fill_wall(g, 42, 51, 80, 81);
  fill_wall(g, 72, 81, 80, 81);
  const cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(60, 20) != s(60, 140));
  CHECK(std::min(s(60, 20), s(60, 140)) == 1);
}

TEST_CASE("segmentation: a corridor is not cut where lined-up partitions have doors right beside them") {
  // Each office's door opens right beside the partition line (cols 82-99 north, 62-79 south):
  // the cuts of the door gaps in the corridor's wall lines touch the cut across the corridor at
  // both its ends, one 8-connected piece 0.9 m long. Its strand across the corridor is still
  // erased; the doors stay cuts between the offices and the corridor.
  const auto [g, w] = offices_across_a_corridor([](int r, int c) { return (r <= 41 && c >= 82 && c <= 99) || (r >= 82 && c >= 62 && c <= 79); });
  check_offices_across_a_corridor(render_segmentation(g, w));
}

TEST_CASE("segmentation: a side passage whose unit runs on through the corridor it opens into stays its own segment") {
  // 0.05 m cells. A 2 m corridor (cols 100-139, rows 2-161) and a 1.5 m side passage (rows
  // 60-89, cols 2-97) opening into it through the corridor's wall (cols 98-99) over its whole
  // width. The passage's unit runs on through the corridor to its far wall (as the chain draws
  // a side passage at a T-junction). Beyond the cut in the corridor's wall line the passage
  // is not walled, so the cut stays.
  // Walls 2 cells thick, unknown space beyond them.
  ClassGrid g(164, 142, static_cast<std::uint8_t>(Cell::Unknown));
  fill_wall(g, 0, 163, 98, 141);
  fill_wall(g, 58, 91, 0, 99);
  for (int r = 2; r <= 161; ++r)
    for (int c = 100; c <= 139; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  for (int r = 60; r <= 89; ++r)
    for (int c = 2; c <= 99; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(1, 99.5, 1.5, 139.5, 161.5), unit(2, 1.5, 59.5, 139.5, 89.5)};
  const cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(75, 40) != 0);
  CHECK(s(20, 120) != 0);
  CHECK(s(75, 40) != s(20, 120));
  CHECK(s(150, 120) == s(20, 120));
}

TEST_CASE("segmentation: units that continue each other are one segment, a wall with a door between them keeps them apart") {
  // 0.05 m cells. A corridor 1.1 m wide (rows 3-24) and 16 m long (cols 3-322) in unknown space,
  // walls 3 cells thick, drawn as two units meeting end to end at col 160.5 with one cell of
  // slack across (as the chain draws them). They meet over the corridor's width, 1.1 m, no
  // wider than a door: the corridor join does not join them. Their facing sides coincide and
  // the seam is free: one segment, whose id is one of theirs.
  ClassGrid g(28, 326, static_cast<std::uint8_t>(Cell::Unknown));
  fill_wall(g, 0, 27, 0, 325);
  for (int r = 3; r <= 24; ++r)
    for (int c = 3; c <= 322; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(1, 1.5, 1.5, 160.5, 25.5), unit(2, 160.5, 2.0, 324.5, 26.0)};
  cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(13, 40) != 0);
  CHECK(s(13, 40) == s(13, 300));
  // A wall across at cols 159-161 with a 0.9 m door (rows 5-22): two segments.
  for (int r = 3; r <= 24; ++r)
    if (r < 5 || r > 22) fill_wall(g, r, r, 159, 161);
  s = render_segmentation(g, w);
  INFO("west " << s(13, 40) << " east " << s(13, 300) << " door " << s(13, 160));
  CHECK(s(13, 40) == 1);
  CHECK(s(13, 300) == 2);
}
