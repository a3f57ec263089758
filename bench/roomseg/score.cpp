#include "bench/roomseg/score.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ksmc::bench::roomseg {

namespace {

// Per-pixel region id (0 = none) of the GT rooms: 8-connected white regions, small ones dropped.
cv::Mat1i gt_rooms(const cv::Mat& gt) {
  cv::Mat1b white = gt >= 250;
  cv::Mat1i ids, stats;
  cv::Mat centroids;
  const int n = cv::connectedComponentsWithStats(white, ids, stats, centroids, 8, CV_32S);
  std::vector<int> keep(static_cast<std::size_t>(n), 0);
  int next = 0;
  for (int i = 1; i < n; ++i)
    if (stats(i, cv::CC_STAT_AREA) > kMinRegionPixels) keep[static_cast<std::size_t>(i)] = ++next;
  for (int r = 0; r < ids.rows; ++r)
    for (int c = 0; c < ids.cols; ++c) ids(r, c) = keep[static_cast<std::size_t>(ids(r, c))];
  return ids;
}

}  // namespace

Score score(const cv::Mat& gt_image, const cv::Mat& labels_image) {
  if (gt_image.size() != labels_image.size())
    throw std::invalid_argument("the label image is " + std::to_string(labels_image.cols) + "x" +
                                std::to_string(labels_image.rows) + ", the ground truth " +
                                std::to_string(gt_image.cols) + "x" + std::to_string(gt_image.rows));
  cv::Mat grey = gt_image;
  if (grey.channels() == 3) cv::cvtColor(gt_image, grey, cv::COLOR_BGR2GRAY);
  const cv::Mat1i rooms = gt_rooms(grey);
  cv::Mat1i labels;
  labels_image.convertTo(labels, CV_32S);

  std::map<int, long> room_area, seg_area;
  std::map<std::pair<int, int>, long> overlap;  // (room, segment)
  for (int r = 0; r < rooms.rows; ++r)
    for (int c = 0; c < rooms.cols; ++c) {
      const int g = rooms(r, c), s = labels(r, c);
      if (g > 0) ++room_area[g];
      if (s > 0) ++seg_area[s];
      if (g > 0 && s > 0) ++overlap[{g, s}];
    }
  std::erase_if(seg_area, [](const auto& kv) { return kv.second <= kMinRegionPixels; });

  std::map<int, long> best_room, best_seg;        // largest overlap per room / per segment
  std::map<int, double> best_iou;                 // per room
  for (const auto& [key, n] : overlap) {
    const auto [g, s] = key;
    const auto sa = seg_area.find(s);
    if (sa == seg_area.end()) continue;
    best_room[g] = std::max(best_room[g], n);
    best_seg[s] = std::max(best_seg[s], n);
    const double iou = static_cast<double>(n) / static_cast<double>(room_area[g] + sa->second - n);
    best_iou[g] = std::max(best_iou[g], iou);
  }
  Score out;
  out.rooms = room_area.size();
  out.segments = seg_area.size();
  for (const auto& [g, area] : room_area) {
    out.recall += static_cast<double>(best_room[g]) / static_cast<double>(area);
    out.iou += best_iou[g];
  }
  for (const auto& [s, area] : seg_area) out.precision += static_cast<double>(best_seg[s]) / static_cast<double>(area);
  if (out.rooms) {
    out.recall /= static_cast<double>(out.rooms);
    out.iou /= static_cast<double>(out.rooms);
  }
  if (out.segments) out.precision /= static_cast<double>(out.segments);
  return out;
}

Score score_files(const std::string& gt_path, const std::string& labels_path) {
  const cv::Mat gt = cv::imread(gt_path, cv::IMREAD_GRAYSCALE);
  if (gt.empty()) throw std::runtime_error(gt_path + ": cannot read the ground-truth image");
  const cv::Mat labels = cv::imread(labels_path, cv::IMREAD_UNCHANGED);
  if (labels.empty()) throw std::runtime_error(labels_path + ": cannot read the label image");
  if (labels.channels() != 1) throw std::runtime_error(labels_path + ": the label image must have one channel");
  try {
    return score(gt, labels);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(labels_path + ": " + e.what());
  }
}

}  // namespace ksmc::bench::roomseg
