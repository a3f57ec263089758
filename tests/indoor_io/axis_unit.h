// Test helpers for segmentation maps: the class values of free and occupied cells, and an
// axis-aligned unit of a WorldResult from its corner cells (x0, y0)-(x1, y1).
#pragma once

#include <cstdint>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/io/world_result.h"

namespace ksmc::tests::indoor_io {

inline constexpr auto kFree = static_cast<std::uint8_t>(stdlib::indoor::Cell::Free);
inline constexpr auto kOcc = static_cast<std::uint8_t>(stdlib::indoor::Cell::Occupied);

inline stdlib::indoor::io::UnitResult unit(int id, double x0, double y0, double x1, double y1) {
  using stdlib::indoor::Point2;
  stdlib::indoor::io::UnitResult u;
  u.id = id;
  u.corners = {Point2{x0, y0}, Point2{x1, y0}, Point2{x1, y1}, Point2{x0, y1}};
  return u;
}

}  // namespace ksmc::tests::indoor_io
