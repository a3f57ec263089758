// clear_specks: small occupied regions in open floor read as free; walls, their ends, pillars,
// furniture and anything beside unexplored cells or the map's edge stay occupied.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <map>
#include <string>

#include <opencv2/imgproc.hpp>

#include "runtime/cli/domain_spec.h"
#include "stdlib/indoor/io/specks.h"
#include "tests/indoor/synthetic_map.h"
#include "tests/indoor_kit/kit_fixture.h"

using namespace ksmc::stdlib::indoor;

namespace {
constexpr auto occ = static_cast<std::uint8_t>(Cell::Occupied), unk = static_cast<std::uint8_t>(Cell::Unknown),
               fr = static_cast<std::uint8_t>(Cell::Free);
}

TEST_CASE("specks: single cells and 2 x 2 blobs in open floor become free", "[indoor_kit]") {
  ClassGrid g(40, 60, fr);
  cv::rectangle(g, cv::Point(0, 0), cv::Point(59, 39), cv::Scalar(occ));               // outer wall, 1 cell
  cv::rectangle(g, cv::Point(29, 0), cv::Point(30, 25), cv::Scalar(occ), cv::FILLED);  // partition with a wall end
  g(10, 10) = occ;                                                                      // a speck
  g(20, 40) = occ;
  g(21, 41) = occ;                                                                      // two, touching diagonally
  cv::rectangle(g, cv::Point(45, 30), cv::Point(46, 31), cv::Scalar(occ), cv::FILLED);  // 2 x 2
  cv::rectangle(g, cv::Point(10, 30), cv::Point(12, 32), cv::Scalar(occ), cv::FILLED);  // 3 x 3: a pillar
  g(26, 30) = occ;                                                                      // a cell off the wall end, touching it
  ClassGrid orig = g.clone();
  CHECK(io::clear_specks(g, 0) == 0);
  CHECK(cv::countNonZero(g != orig) == 0);
  const std::size_t changed = io::clear_specks(g, 2);
  CHECK(changed == 1 + 2 + 4);
  CHECK(static_cast<int>(changed) == cv::countNonZero(g != orig));
  CHECK(g(10, 10) == fr);
  CHECK(g(20, 40) == fr);
  CHECK(g(21, 41) == fr);
  CHECK(g(31, 46) == fr);
  CHECK(g(31, 11) == occ);  // the pillar
  CHECK(g(25, 30) == occ);  // the wall end
  CHECK(g(26, 30) == occ);  // joined to the wall: one region, not small
  CHECK(g(0, 5) == occ);    // the outer wall
  // With 3 cells the pillar is a speck too.
  CHECK(io::clear_specks(g, 3) == 9);
}

TEST_CASE("specks: a dot within twice the size of a wall is a fragment of it, not a speck", "[indoor_kit]") {
  // A thin wall drawn broken (lab_d_scan): a wall from column 0 to 20 on row 10, a dot in line
  // with it 3 cells past its end and one 4 cells beside it (distances 3 and 4 <= 2 x 2: kept),
  // and two dots 20 and 25 cells past its end (cleared).
  ClassGrid g(20, 60, fr);
  cv::rectangle(g, cv::Point(0, 10), cv::Point(20, 10), cv::Scalar(occ), cv::FILLED);
  g(10, 23) = occ;
  g(10, 40) = occ;
  g(10, 45) = occ;  // 5 cells from the dot at 40, which is small too: no wall near
  g(14, 10) = occ;
  CHECK(io::clear_specks(g, 2) == 2);
  CHECK(g(10, 23) == occ);
  CHECK(g(14, 10) == occ);
  CHECK(g(10, 40) == fr);
  CHECK(g(10, 45) == fr);
}

TEST_CASE("specks: a small region beside unexplored cells or the map's edge stays occupied", "[indoor_kit]") {
  ClassGrid g(20, 20, fr);
  cv::rectangle(g, cv::Point(0, 10), cv::Point(19, 19), cv::Scalar(unk), cv::FILLED);  // unexplored below row 10
  g(9, 5) = occ;   // beside the unexplored part
  g(0, 12) = occ;  // on the map's edge
  g(4, 4) = occ;   // in open floor
  CHECK(io::clear_specks(g, 2) == 1);
  CHECK(g(9, 5) == occ);
  CHECK(g(0, 12) == occ);
  CHECK(g(4, 4) == fr);
}

TEST_CASE("specks: the kit clears them at --speck-size and says how many", "[indoor_kit]") {
  using ksmc::tests::indoor::draw_plan;
  using ksmc::tests::indoor::Room;
  namespace t = ksmc::tests::indoor_kit;
  ClassGrid g = draw_plan(100, 160, {{10, 10, 80, 90}, {80, 10, 150, 90}}, 2, {{80, 50}}, 16);
  int placed = 0;
  for (int r = 20; r <= 80; r += 10)
    for (int c = 20; c <= 140; c += 20) {
      if (std::abs(c - 80) < 4) continue;  // not on the partition
      g(r, c) = occ;
      ++placed;
    }
  const auto file = t::write_pgm(g, t::temp_dir("specks") / "plan.pgm");
  const auto sp = t::spec();
  const auto cleared = [&](std::map<std::string, std::string> flags) {
    const auto setup = sp.load(t::input_for(sp, file, 1, std::move(flags)));
    return setup.summary_extra.at("specks").at("cells_cleared").get<int>();
  };
  CHECK(cleared({}) == placed);  // default 0.1 m: two cells at 0.05 m
  CHECK(cleared({{"speck-size", "0"}}) == 0);
  CHECK(cleared({{"speck-size", "0.04"}}) == 0);  // under one cell
  CHECK_THROWS_AS(cleared({{"speck-size", "-1"}}), ksmc::runtime::cli::UsageError);
  CHECK(cleared({{"speck-size", "1e300"}}) >= placed);  // capped at the map's size, no overflow
}
