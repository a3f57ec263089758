// The room-segmentation score of Bormann et al. (ICRA 2016), as their evaluator computes it
// (ipa_room_segmentation, evaluation_segmentation.cpp, computePrecisionRecall):
//   * ground-truth rooms: 8-connected regions of GT pixels >= 250, regions of <= 100 px dropped;
//   * predicted segments: the pixels of each non-zero label of a label image, <= 100 px dropped;
//   * recall of a room: its largest overlap with one segment / its area, averaged over rooms;
//   * precision of a segment: its largest overlap with one room / its area, averaged over segments.
// IoU (our addition): per room, the best overlap / union with one segment, averaged over rooms.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <opencv2/core/mat.hpp>

namespace ksmc::bench::roomseg {

struct Score {
  double recall = 0.0;     // mean over GT rooms, in [0, 1]
  double precision = 0.0;  // mean over segments
  double iou = 0.0;        // mean over GT rooms
  std::size_t rooms = 0;
  std::size_t segments = 0;
};

inline constexpr int kMinRegionPixels = 100;  // regions of at most this many pixels are dropped

// `gt`: 8-bit grey GT image; `labels`: label image (any integer depth, 0 = no room), same size.
// Throws std::invalid_argument when the sizes differ.
Score score(const cv::Mat& gt, const cv::Mat& labels);

// Reads both PNGs (labels unchanged depth) and scores them; errors name the file.
Score score_files(const std::string& gt_path, const std::string& labels_path);

}  // namespace ksmc::bench::roomseg
