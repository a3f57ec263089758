#include "stdlib/indoor/detect/rpb.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stdlib/indoor/detect/frame.h"
#include "stdlib/indoor/detect/hough.h"

namespace ksmc::stdlib::indoor::detect {

std::optional<UnitCandidate> detect_rpb_unit(const ClassGrid& grid, Point2 robot, const RpbParams& p) {
  check_class_grid(grid, "detect_rpb_unit");
  if (!std::isfinite(robot.x) || !std::isfinite(robot.y))
    throw std::invalid_argument("detect_rpb_unit: robot position is not finite");
  const int rc = int(std::lround(robot.x)), rr = int(std::lround(robot.y));
  if (rc < 0 || rr < 0 || rc >= grid.cols || rr >= grid.rows || grid(rr, rc) != int(Cell::Free)) return std::nullopt;

  const Frame f(grid.size(), p.frame_deg);
  const Point2 q = f.to_frame(robot);
  // Frame-local integer offsets of the four sides from the robot: left, top, right, bottom.
  int ext[4] = {0, 0, 0, 0};
  bool done[4] = {false, false, false, false};
  const int cap = std::max(1, int(std::floor(p.max_half_extent)));
  auto blocked_cell = [&](int dx, int dy) {
    const Point2 m = f.from_frame({q.x + dx, q.y + dy});
    const int c = int(std::lround(m.x)), r = int(std::lround(m.y));
    if (c < 0 || r < 0 || c >= grid.cols || r >= grid.rows) return true;
    return grid(r, c) != int(Cell::Free);
  };
  // Strip just outside side s: blocked when too many of its cells are not free.
  auto strip_blocked = [&](int s) {
    int n = 0, bad = 0;
    if (s == 0 || s == 2) {
      const int dx = s == 0 ? -(ext[0] + 1) : ext[2] + 1;
      for (int dy = -ext[1]; dy <= ext[3]; ++dy, ++n) bad += blocked_cell(dx, dy);
    } else {
      const int dy = s == 1 ? -(ext[1] + 1) : ext[3] + 1;
      for (int dx = -ext[0]; dx <= ext[2]; ++dx, ++n) bad += blocked_cell(dx, dy);
    }
    return bad >= p.min_blocked_cells && bad > p.max_blocked * n;
  };
  for (bool any = true; any;) {
    any = false;
    for (int s = 0; s < 4; ++s) {
      if (done[s]) continue;
      if (ext[s] >= cap || strip_blocked(s)) {
        done[s] = true;
        continue;
      }
      ++ext[s];
      any = true;
    }
  }
  // Sides on the blocking strips (the walls).
  const double x0 = q.x - ext[0] - 1, x1 = q.x + ext[2] + 1, y0 = q.y - ext[1] - 1, y1 = q.y + ext[3] + 1;
  if (x1 - x0 < p.min_side || y1 - y0 < p.min_side) return std::nullopt;
  const OrientedRect rect = f.rect_from_frame(x0, y0, x1, y1);
  return UnitCandidate{rect, std::max(unit_weight(grid, rect, p.wall), p.weight_floor)};
}

}  // namespace ksmc::stdlib::indoor::detect
