// overlay.png's unit labels: at the unit centres, moved apart by whole label heights when two
// boxes would overlap (a small unit inside a big one), deterministic.
#include <catch2/catch.hpp>

#include <opencv2/core.hpp>

#include "stdlib/indoor/io/label_placement.h"

using ksmc::stdlib::indoor::io::place_labels;

namespace {

cv::Rect box(cv::Point c, cv::Size s) { return {c.x - s.width / 2, c.y - s.height / 2, s.width, s.height}; }

}  // namespace

TEST_CASE("label placement: labels far apart stay at their centres") {
  const std::vector<cv::Point> wanted{{100, 100}, {300, 100}, {100, 300}};
  const std::vector<cv::Size> sizes(3, cv::Size(60, 20));
  CHECK(place_labels(wanted, sizes, 2) == wanted);
}

TEST_CASE("label placement: two labels at nearly one centre are moved apart, the first stays") {
  // cartesium: a 0.6 m room inside a big room, centres 8 px apart.
  const std::vector<cv::Point> wanted{{500, 300}, {508, 304}, {504, 298}};
  const std::vector<cv::Size> sizes(3, cv::Size(70, 24));
  const std::vector<cv::Point> at = place_labels(wanted, sizes, 3);
  REQUIRE(at.size() == 3);
  CHECK(at[0] == wanted[0]);
  for (std::size_t i = 0; i < at.size(); ++i) {
    CHECK(at[i].x == wanted[i].x);  // moved only vertically
    for (std::size_t j = 0; j < i; ++j) CHECK((box(at[i], sizes[i]) & box(at[j], sizes[j])).area() == 0);
  }
  CHECK(at[1].y > wanted[1].y);  // down first
  CHECK(at[2].y < wanted[2].y);  // then up
  CHECK(place_labels(wanted, sizes, 3) == at);
}

TEST_CASE("label placement: with no free place within the steps a label stays at its centre") {
  std::vector<cv::Point> wanted;
  for (int k = -5; k <= 5; ++k) wanted.push_back({0, k * 10});
  wanted.push_back({0, 0});
  const std::vector<cv::Size> sizes(wanted.size(), cv::Size(40, 10));
  const std::vector<cv::Point> at = place_labels(wanted, sizes, 0);
  CHECK(at.back() == wanted.back());
  CHECK_THROWS_AS(place_labels(wanted, {cv::Size(1, 1)}, 0), std::invalid_argument);
}
