// Geometry helpers for the indoor world: rectangles seen in a common rotated frame.
// Two units whose orientations agree modulo 90 degrees are axis-aligned boxes in the frame of
// either one; SPLIT, MERGE and INTERCHANGE reason about shared walls in such a frame.
#pragma once

#include <array>
#include <optional>

#include "stdlib/indoor/rect.h"

namespace ksmc::stdlib::indoor {

inline constexpr double kPi = 3.14159265358979323846;

// Axis-aligned box [x0,x1] x [y0,y1] in some frame.
struct Box {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// A frame rotated by theta about the map origin: local = R(-theta) * global.
class Frame {
 public:
  explicit Frame(double theta);
  double theta() const { return theta_; }
  Point2 to_local(Point2 p) const { return {c_ * p.x + s_ * p.y, -s_ * p.x + c_ * p.y}; }
  Point2 to_global(Point2 p) const { return {c_ * p.x - s_ * p.y, s_ * p.x + c_ * p.y}; }

 private:
  double theta_, c_, s_;
};

// Distance of angle `a` to the nearest multiple of pi/2, in [0, pi/4].
double angle_off_quarter(double a);

// The rectangle as a box in `frame`, or nullopt when its orientation differs from the frame's
// by more than `angle_eps` (radians) modulo 90 degrees.
std::optional<Box> box_in_frame(const OrientedRect& r, const Frame& frame, double angle_eps = 1e-9);

// The rectangle of a box given in `frame` (orientation = the frame's).
OrientedRect rect_from_box(const Box& b, const Frame& frame);

// Box of the rectangle in its own frame (x along the w-axis, y along the h-axis).
Box own_box(const OrientedRect& r);

// Distance from p (in the box's frame) to the box's boundary, inside or outside.
double distance_to_boundary(const Box& b, Point2 p);

// Wall j of a rectangle is the edge from corner j to corner j+1 (see OrientedRect::corners):
// 0 = y0 side, 1 = x1 side, 2 = y1 side, 3 = x0 side of its own box.
// Moves wall j of the box outward (along its outer normal) by `delta` (negative = inward).
Box shift_box_wall(const Box& b, int wall, double delta);

// Same rectangle up to representation (corner sets equal within `tol` cells).
bool same_rect(const OrientedRect& a, const OrientedRect& b, double tol = 1e-6);

// Euclidean distance between two points.
double distance(Point2 a, Point2 b);

}  // namespace ksmc::stdlib::indoor
