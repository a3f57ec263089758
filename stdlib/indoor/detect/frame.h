// A rotated working frame: maps are resampled so that walls of orientation `angle_deg`
// become axis-aligned, detectors work with rows and columns there, and results are mapped
// back. q = R(-angle) (p - centre) + frame_centre, with the frame canvas sized to hold the
// whole rotated map.
#pragma once

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/detect/types.h"

namespace ksmc::stdlib::indoor::detect {

class Frame {
 public:
  // Frame of orientation angle_deg for a map of `map_size` (cols x rows).
  Frame(cv::Size map_size, double angle_deg);

  double angle_deg() const { return angle_deg_; }
  cv::Size size() const { return size_; }  // canvas of the rotated map

  Point2 to_frame(Point2 p) const;
  Point2 from_frame(Point2 q) const;

  // The map resampled into the frame (nearest neighbour); cells outside the map get `border`.
  cv::Mat1b warp(const cv::Mat1b& map, unsigned char border) const;

  // Map-frame oriented rectangle of the frame-axis-aligned box [x0, x1] x [y0, y1].
  OrientedRect rect_from_frame(double x0, double y0, double x1, double y1) const;

 private:
  double angle_deg_ = 0.0;
  double c_ = 1.0, s_ = 0.0;
  Point2 centre_{}, frame_centre_{};
  cv::Size size_{};
};

}  // namespace ksmc::stdlib::indoor::detect
