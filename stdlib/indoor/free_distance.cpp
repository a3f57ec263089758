#include "stdlib/indoor/free_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

namespace ksmc::stdlib::indoor {

cv::Mat1f free_distance(const ClassGrid& map) {
  cv::Mat1f out(map.rows, map.cols, 0.0f);
  if (map.empty()) return out;
  const cv::Mat1b not_free = map != static_cast<std::uint8_t>(Cell::Free);  // 255 where not free
  if (cv::countNonZero(not_free) == static_cast<int>(map.total())) {
    out.setTo(static_cast<float>(std::hypot(map.rows, map.cols)));
    return out;
  }
  cv::distanceTransform(not_free, out, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  return out;
}

double free_distance_at(const cv::Mat1f& field, double col, double row) {
  if (field.empty()) return 0.0;
  if (!std::isfinite(col) || !std::isfinite(row)) return std::numeric_limits<double>::infinity();
  const double c = std::floor(col), r = std::floor(row);  // clamped as doubles: any finite value is safe
  const double cc = std::clamp(c, 0.0, field.cols - 1.0), rc = std::clamp(r, 0.0, field.rows - 1.0);
  const double inside = field(static_cast<int>(rc), static_cast<int>(cc));
  return c == cc && r == rc ? inside : inside + std::hypot(c - cc, r - rc);
}

}  // namespace ksmc::stdlib::indoor
