#include "stdlib/indoor/detect/frame.h"

#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace ksmc::stdlib::indoor::detect {

Frame::Frame(cv::Size map_size, double angle_deg) : angle_deg_(angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  c_ = std::cos(a);
  s_ = std::sin(a);
  // Snap tiny values so that angle 0 gives an exact identity copy.
  if (std::abs(s_) < 1e-12) s_ = 0.0;
  if (std::abs(c_) < 1e-12) c_ = 0.0;
  centre_ = {0.5 * (map_size.width - 1), 0.5 * (map_size.height - 1)};
  const double w = std::abs(c_) * map_size.width + std::abs(s_) * map_size.height;
  const double h = std::abs(s_) * map_size.width + std::abs(c_) * map_size.height;
  size_ = {int(std::ceil(w - 1e-9)), int(std::ceil(h - 1e-9))};
  frame_centre_ = {0.5 * (size_.width - 1), 0.5 * (size_.height - 1)};
}

Point2 Frame::to_frame(Point2 p) const {
  const double dx = p.x - centre_.x, dy = p.y - centre_.y;
  return {frame_centre_.x + c_ * dx + s_ * dy, frame_centre_.y - s_ * dx + c_ * dy};
}

Point2 Frame::from_frame(Point2 q) const {
  const double dx = q.x - frame_centre_.x, dy = q.y - frame_centre_.y;
  return {centre_.x + c_ * dx - s_ * dy, centre_.y + s_ * dx + c_ * dy};
}

cv::Mat1b Frame::warp(const cv::Mat1b& map, unsigned char border) const {
  cv::Mat m = (cv::Mat_<double>(2, 3) << c_, s_, frame_centre_.x - c_ * centre_.x - s_ * centre_.y,  //
               -s_, c_, frame_centre_.y + s_ * centre_.x - c_ * centre_.y);
  cv::Mat1b out;
  cv::warpAffine(map, out, m, size_, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(border));
  return out;
}

OrientedRect Frame::rect_from_frame(double x0, double y0, double x1, double y1) const {
  const Point2 c = from_frame({0.5 * (x0 + x1), 0.5 * (y0 + y1)});
  OrientedRect r;
  r.cx = c.x;
  r.cy = c.y;
  r.w = std::abs(x1 - x0);
  r.h = std::abs(y1 - y0);
  r.theta = angle_deg_ * std::numbers::pi / 180.0;
  return r;
}

}  // namespace ksmc::stdlib::indoor::detect
