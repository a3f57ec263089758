#include "stdlib/indoor/io/label_placement.h"

#include <stdexcept>

#include <opencv2/core.hpp>

namespace ksmc::stdlib::indoor::io {

namespace {

cv::Rect box_at(cv::Point centre, cv::Size size, int pad) {
  return {centre.x - size.width / 2 - pad, centre.y - size.height / 2 - pad, size.width + 2 * pad,
          size.height + 2 * pad};
}

bool overlaps_any(const cv::Rect& r, const std::vector<cv::Rect>& placed) {
  for (const auto& p : placed)
    if ((r & p).area() > 0) return true;
  return false;
}

}  // namespace

std::vector<cv::Point> place_labels(const std::vector<cv::Point>& wanted, const std::vector<cv::Size>& sizes, int pad) {
  if (wanted.size() != sizes.size()) throw std::invalid_argument("place_labels: one size per label");
  std::vector<cv::Point> out;
  std::vector<cv::Rect> placed;
  out.reserve(wanted.size());
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    cv::Point at = wanted[i];
    const int step = sizes[i].height + 2 * pad;
    for (int k = 1; k <= kMaxLabelSteps && overlaps_any(box_at(at, sizes[i], pad), placed); ++k) {
      const cv::Point down{wanted[i].x, wanted[i].y + k * step}, up{wanted[i].x, wanted[i].y - k * step};
      if (!overlaps_any(box_at(down, sizes[i], pad), placed)) at = down;
      else if (!overlaps_any(box_at(up, sizes[i], pad), placed)) at = up;
      else at = wanted[i];
    }
    out.push_back(at);
    placed.push_back(box_at(at, sizes[i], pad));
  }
  return out;
}

}  // namespace ksmc::stdlib::indoor::io
