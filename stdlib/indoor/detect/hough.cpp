#include "stdlib/indoor/detect/hough.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

#include "runtime/io/cancel.h"
#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor::detect {

std::vector<Segment> hough_segments(const cv::Mat1b& mask, const HoughParams& params) {
  if (mask.type() != CV_8UC1) throw std::invalid_argument("hough_segments: mask must be CV_8UC1");
  if (!(params.rho > 0.0) || !(params.theta_deg > 0.0) || params.threshold < 1)
    throw std::invalid_argument("hough_segments: rho, theta_deg and threshold must be positive");
  std::vector<Segment> out;
  if (mask.empty()) return out;
  // A mask of more than kBandRows rows (a very large map) is transformed in bands of that
  // many rows, and a cancel request is seen between them: one OpenCV call on a 10800 x 9600
  // map takes 10 s that SIGINT cannot interrupt. A wall crossing a band border becomes two
  // segments of its angle and nearly its length, which the length-weighted orientation
  // histogram does not tell apart. Smaller masks (every benchmark map) go whole, as before.
  constexpr int kBandRows = 2048;
  std::vector<cv::Vec4i> lines;
  for (int r0 = 0; r0 < mask.rows; r0 += kBandRows) {
    const int r1 = std::min(mask.rows, r0 + kBandRows);
    if (r0 > 0) runtime::io::throw_if_cancelled("the Hough transform of the map");
    lines.clear();
    cv::HoughLinesP(mask.rowRange(r0, r1), lines, params.rho, params.theta_deg * std::numbers::pi / 180.0,
                    params.threshold, params.min_length, params.max_gap);
    for (const auto& l : lines) out.push_back({{double(l[0]), double(l[1] + r0)}, {double(l[2]), double(l[3] + r0)}});
  }
  return out;
}

cv::Mat1b class_mask(const cv::Mat1b& grid, unsigned char value) {
  cv::Mat1b m;
  cv::compare(grid, cv::Scalar(value), m, cv::CMP_EQ);
  return m;
}

cv::Mat1b wall_edge_mask(const cv::Mat1b& grid) {
  cv::Mat1b occ = class_mask(grid, static_cast<unsigned char>(Cell::Occupied));
  cv::Mat1b inner;
  cv::erode(occ, inner, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}), {-1, -1}, 1, cv::BORDER_CONSTANT,
            cv::Scalar(255));
  cv::Mat1b out;
  cv::subtract(occ, inner, out);
  return out;
}

void check_class_grid(const cv::Mat1b& grid, const char* who) {
  if (grid.empty()) throw std::invalid_argument(std::string(who) + ": empty class grid");
  if (grid.type() != CV_8UC1) throw std::invalid_argument(std::string(who) + ": class grid must be CV_8UC1");
  double mn = 0, mx = 0;
  cv::Point pmax;
  cv::minMaxLoc(grid, &mn, &mx, nullptr, &pmax);
  if (mx > double(Cell::Occupied))
    throw std::invalid_argument(std::string(who) + ": class grid value " + std::to_string(int(mx)) +
                                " at (col " + std::to_string(pmax.x) + ", row " + std::to_string(pmax.y) +
                                ") is not a Cell (0 free, 1 unknown, 2 occupied)");
}

}  // namespace ksmc::stdlib::indoor::detect
