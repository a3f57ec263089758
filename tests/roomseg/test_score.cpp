// The Bormann et al. room-segmentation score (bench/roomseg/score.h) on small hand-made images
// with exactly known overlaps.
#include <catch2/catch.hpp>

#include <opencv2/core.hpp>

#include "bench/roomseg/score.h"

using ksmc::bench::roomseg::score;

namespace {

// Two GT rooms side by side: 40x20 px each (800 px), split by a one-pixel black wall.
cv::Mat1b two_rooms() {
  cv::Mat1b gt(20, 81, uchar(255));
  gt.col(40).setTo(0);
  return gt;
}

}  // namespace

TEST_CASE("a perfect segmentation scores 1, 1, 1") {
  const cv::Mat1b gt = two_rooms();
  cv::Mat1w labels(gt.size(), ushort(0));
  labels(cv::Rect(0, 0, 40, 20)).setTo(7);
  labels(cv::Rect(41, 0, 40, 20)).setTo(9);
  const auto s = score(gt, labels);
  CHECK(s.rooms == 2);
  CHECK(s.segments == 2);
  CHECK(s.recall == Approx(1.0));
  CHECK(s.precision == Approx(1.0));
  CHECK(s.iou == Approx(1.0));
}

TEST_CASE("one segment over two rooms: full recall, half precision") {
  const cv::Mat1b gt = two_rooms();
  cv::Mat1w labels(gt.size(), ushort(3));
  const auto s = score(gt, labels);
  CHECK(s.segments == 1);
  CHECK(s.recall == Approx(1.0));
  // 1620 labelled px, the larger room overlaps 800 of them.
  CHECK(s.precision == Approx(800.0 / 1620.0));
  CHECK(s.iou == Approx(800.0 / 1620.0));
}

TEST_CASE("an over-segmented room and dropped slivers") {
  const cv::Mat1b gt = two_rooms();
  cv::Mat1w labels(gt.size(), ushort(0));
  labels(cv::Rect(0, 0, 20, 20)).setTo(1);   // 400 px of room 1
  labels(cv::Rect(20, 0, 20, 20)).setTo(2);  // the other 400 px
  labels(cv::Rect(41, 0, 40, 20)).setTo(3);  // room 2 whole
  labels(cv::Rect(0, 0, 10, 10)).setTo(4);   // 100 px: dropped (<= 100)
  const auto s = score(gt, labels);
  CHECK(s.segments == 3);
  // room 1: best segment 2 covers 400 of 800; room 2: 800 of 800.
  CHECK(s.recall == Approx((0.5 + 1.0) / 2.0));
  CHECK(s.precision == Approx(1.0));
  CHECK(s.iou == Approx((400.0 / 800.0 + 1.0) / 2.0));
}

TEST_CASE("small GT regions are not rooms, and sizes must agree") {
  cv::Mat1b gt(20, 81, uchar(0));
  gt(cv::Rect(0, 0, 10, 10)).setTo(255);  // 100 px: not a room
  cv::Mat1w labels(gt.size(), ushort(1));
  CHECK(score(gt, labels).rooms == 0);
  CHECK_THROWS(score(gt, cv::Mat1w(10, 10, ushort(1))));
}
