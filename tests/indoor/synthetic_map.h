// Synthetic floor plans drawn with OpenCV for the indoor tests: axis-aligned rooms with walls of
// a given thickness, unexplored (unknown) background, optional door gaps.
#pragma once

#include <vector>

#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/rect.h"

namespace ksmc::tests::indoor {

using ksmc::stdlib::indoor::Cell;
using ksmc::stdlib::indoor::ClassGrid;
using ksmc::stdlib::indoor::OrientedRect;

struct Room {
  int x0, y0, x1, y1;  // wall centre lines, cells (inclusive corners)
};

// Draws the rooms' free interiors, then their walls (thickness `wall` cells) on top, then the
// door gaps (free squares of side `door` centred on the given points).
inline ClassGrid draw_plan(int rows, int cols, const std::vector<Room>& rooms, int wall,
                           const std::vector<cv::Point>& doors = {}, int door = 4) {
  ClassGrid g(rows, cols, static_cast<std::uint8_t>(Cell::Unknown));
  for (const Room& r : rooms)
    cv::rectangle(g, cv::Point(r.x0, r.y0), cv::Point(r.x1, r.y1), cv::Scalar(static_cast<int>(Cell::Free)),
                  cv::FILLED);
  for (const Room& r : rooms)
    cv::rectangle(g, cv::Point(r.x0, r.y0), cv::Point(r.x1, r.y1),
                  cv::Scalar(static_cast<int>(Cell::Occupied)), wall);
  for (const cv::Point& d : doors)
    cv::rectangle(g, cv::Point(d.x - door / 2, d.y - door / 2), cv::Point(d.x + door / 2, d.y + door / 2),
                  cv::Scalar(static_cast<int>(Cell::Free)), cv::FILLED);
  return g;
}

// The rectangle whose sides lie on a room's wall centre lines.
inline OrientedRect room_rect(const Room& r) {
  return OrientedRect{0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1), static_cast<double>(r.x1 - r.x0),
                      static_cast<double>(r.y1 - r.y0), 0.0};
}

}  // namespace ksmc::tests::indoor
