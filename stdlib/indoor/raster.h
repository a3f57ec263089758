// Row-span rasterisation of oriented rectangles. Coordinates follow the detectors' convention:
// the centre of cell (col, row) is the point (col, row). A cell belongs to a rectangle when its
// centre lies inside, with half-open edges (rectangles abutting on a common edge share no cell). Every consumer (the
// incremental coverage grid and the full recomputation) uses these spans, so both agree exactly.
#pragma once

#include "stdlib/indoor/rect.h"

namespace ksmc::stdlib::indoor {

// Cells [x0, x1) of one row; empty when x0 >= x1.
struct RowSpan {
  int x0 = 0;
  int x1 = 0;
  bool empty() const { return x0 >= x1; }
};

class SpanRaster {
 public:
  SpanRaster() = default;  // empty rectangle
  // `cols` clips spans to [0, cols); rows are not clipped here (see row_begin/row_end).
  SpanRaster(const OrientedRect& r, int cols);
  bool empty() const { return empty_; }
  // Rows [row_begin, row_end) that may hold cells (unclipped).
  int row_begin() const { return row_begin_; }
  int row_end() const { return row_end_; }
  RowSpan span(int row) const;

 private:
  bool empty_ = true;
  int cols_ = 0;
  int row_begin_ = 0, row_end_ = 0;
  double c_ = 1.0, s_ = 0.0, cx_ = 0.0, cy_ = 0.0, hw_ = 0.0, hh_ = 0.0;
};

// The footprint of a unit: the whole rectangle (its area) and the inner rectangle left after
// removing a wall band of `wall_thickness` cells along each edge. Wall cells = outer \ inner.
struct UnitRaster {
  SpanRaster outer;
  SpanRaster inner;
  UnitRaster() = default;
  UnitRaster(const OrientedRect& r, double wall_thickness, int cols);
};

// The rectangle covered by a door: the segment's length along it, `thickness` across it.
OrientedRect door_rect(Point2 a, Point2 b, double thickness);

}  // namespace ksmc::stdlib::indoor
