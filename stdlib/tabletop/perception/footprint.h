// Footprints on the table plane: 2D convex hull and the minimal-area enclosing rectangle
// (one side of the minimal rectangle lies on a hull edge; Freeman & Shapira 1975).
// Unlike a principal-axes fit, the rectangle does not depend on the point density, so a
// square cross-section gets its true sides instead of an arbitrary (flipping) diagonal.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop::perception {

struct Rect2 {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  Eigen::Vector2d u = Eigen::Vector2d::UnitX();  // first side direction, angle in [0, 90 deg)
  Eigen::Vector2d half = Eigen::Vector2d::Zero();  // half extents along u and along v = perp(u)

  [[nodiscard]] Eigen::Vector2d v() const { return {-u.y(), u.x()}; }
  [[nodiscard]] double area() const { return 4.0 * half.x() * half.y(); }
};

// The upright box (axis 2 along z) over rectangle `r` from height `bottom` to `top`, each side
// inset by `inset` (the rays' tests read the space over a footprint). Its half extents may be
// zero or negative when the inset leaves nothing: the caller checks.
Obb upright_over(const Rect2& r, double bottom, double top, double inset = 0.0);

// Whether rectangles a and b overlap, each grown by `slack` (separating axes: the four side
// directions).
bool rects_overlap(const Rect2& a, const Rect2& b, double slack = 0.0);

// Quantile q in [0, 1] of `values` (at least one; sorted in place), linear interpolation.
double quantile(std::vector<double>& values, double q);

// Counter-clockwise hull without (nearly, 1e-12 m^2) collinear points (Andrew's monotone chain). Fewer than
// three distinct points give the distinct points.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points);

// Minimal-area rectangle containing `points` (at least one point). With `trim` > 0 the
// orientation is kept and each side is pulled in to the trim / (1 - trim) quantile of
// the points' coordinates, which discards isolated noise points at the border.
Rect2 min_area_rect(const std::vector<Eigen::Vector2d>& points, double trim = 0.0);

// The rectangle with one side along `u` (any length) around `points` (at least one), each side
// at the trim / (1 - trim) quantile of the points' coordinates (trim 0: their extremes).
Rect2 rect_along(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& u, double trim = 0.0);

// The rectangle whose sides the points lie on (least summed distance to the nearest side),
// among the same candidate directions; `trim` as above. For a box seen only by its side
// faces: the minimal-area rectangle of an L of two faces may lie along the L's diagonal.
Rect2 faces_rect(const std::vector<Eigen::Vector2d>& points, double trim = 0.0);

}  // namespace ksmc::stdlib::tabletop::perception
