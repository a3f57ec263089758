#include <catch2/catch.hpp>

#include "stdlib/segments/geometry.h"

using namespace ksmc::stdlib::segments;

TEST_CASE("canonical orders endpoints lexicographically", "[segments][geometry]") {
  const Segment s = canonical({2, 1}, {1, 5});
  CHECK(s.a == Vec2{1, 5});
  CHECK(s.b == Vec2{2, 1});
  CHECK(canonical({1, 2}, {1, 1}).a == Vec2{1, 1});
  CHECK(canonical({0, 0}, {3, 0}) == canonical({3, 0}, {0, 0}));
}

TEST_CASE("point to segment and line distances", "[segments][geometry]") {
  const Segment s{{0, 0}, {2, 0}};
  CHECK(point_segment_distance({1, 1}, s) == Approx(1.0));
  CHECK(point_segment_distance({3, 0}, s) == Approx(1.0));  // beyond b: to the endpoint
  CHECK(point_segment_distance({-3, 4}, s) == Approx(5.0));
  CHECK(point_line_distance({3, 0.5}, s) == Approx(0.5));   // the infinite line
  CHECK(projection_param({1.5, 7}, s) == Approx(0.75));
  const Segment z{{1, 1}, {1, 1}};  // degenerate
  CHECK(point_segment_distance({4, 5}, z) == Approx(5.0));
}

TEST_CASE("angles and the extractor relations", "[segments][geometry]") {
  const double deg = kPi / 180.0;
  const Segment h{{0, 0}, {4, 0}};
  const Segment v{{4.05, 0.02}, {4.05, 3}};
  const Segment tilted = canonical({0, 1}, {4, 1 + 4 * std::tan(3 * deg)});
  CHECK(undirected_angle(h, v) == Approx(kPi / 2));
  CHECK(parallel_angle_error(h, tilted) == Approx(3 * deg));
  CHECK(corner_angle_error(h, v) == Approx(0.0).margin(1e-12));
  CHECK(endpoint_gap(h, v) == Approx(std::hypot(0.05, 0.02)));
  CHECK(touching(h, v, 0.1));
  CHECK_FALSE(touching(h, v, 0.05));
  CHECK(perpendicular(h, v, 1 * deg));
  CHECK_FALSE(perpendicular(h, tilted, 10 * deg));
  CHECK(parallel(h, tilted, 5 * deg));
  CHECK_FALSE(parallel(h, tilted, 2 * deg));
  // Close: each midpoint near the other's line; reversing a segment changes nothing.
  const Segment far{{0, 0.5}, {4, 0.5}};
  const Segment near{{5, 0.03}, {7, 0.03}};
  CHECK(close_lines(h, near, 0.05));
  CHECK_FALSE(close_lines(h, far, 0.1));
  CHECK(line_offset(h, far) == Approx(0.5));
  CHECK(line_offset(h, Segment{near.b, near.a}) == Approx(line_offset(h, near)));
  CHECK(is_short(Segment{{0, 0}, {0.3, 0}}, 0.4));
  CHECK_FALSE(is_short(h, 0.4));
}
