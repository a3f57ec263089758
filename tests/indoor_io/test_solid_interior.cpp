// unexplain_solid_interior: the inside of solid occupied regions becomes unexplained, the
// surface layer (walls) stays occupied.
#include <catch2/catch.hpp>

#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/io/solid_interior.h"

using namespace ksmc::stdlib::indoor;

TEST_CASE("solid interior: occupied cells deeper than the depth become unexplained", "[indoor_io]") {
  const auto occ = static_cast<std::uint8_t>(Cell::Occupied), unk = static_cast<std::uint8_t>(Cell::Unknown),
             fr = static_cast<std::uint8_t>(Cell::Free);
  ClassGrid g(60, 80, occ);                                                   // all black
  cv::rectangle(g, cv::Point(20, 20), cv::Point(49, 39), cv::Scalar(fr), cv::FILLED);  // free room
  cv::rectangle(g, cv::Point(70, 0), cv::Point(79, 59), cv::Scalar(unk), cv::FILLED);  // grey strip
  ClassGrid orig = g.clone();
  CHECK(io::unexplain_solid_interior(g, 0.0) == 0);
  CHECK(cv::countNonZero(g != orig) == 0);
  const std::size_t changed = io::unexplain_solid_interior(g, 3.0);
  CHECK(changed > 0);
  CHECK(static_cast<int>(changed) == cv::countNonZero(g != orig));
  // Walls around the room (distance 1..3) stay occupied; beyond 3 cells they are unexplained.
  CHECK(g(19, 30) == occ);
  CHECK(g(17, 30) == occ);   // distance 3
  CHECK(g(16, 30) == unk);   // distance 4
  CHECK(g(30, 52) == occ);   // 3 right of the room (column 49 is free)
  CHECK(g(30, 53) == unk);
  CHECK(g(0, 0) == unk);
  CHECK(g(30, 30) == fr);    // free untouched
  CHECK(g(5, 75) == unk);    // unknown untouched
  // Thin walls between two rooms are untouched.
  ClassGrid two(30, 60, fr);
  cv::rectangle(two, cv::Point(28, 0), cv::Point(31, 29), cv::Scalar(occ), cv::FILLED);  // 4-cell wall
  CHECK(io::unexplain_solid_interior(two, 2.0) == 0);
}
