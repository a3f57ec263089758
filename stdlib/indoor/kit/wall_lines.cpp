#include "stdlib/indoor/kit/wall_lines.h"

#include <cmath>
#include <cstdint>

namespace ksmc::stdlib::indoor::kit {

Point2 FrameLine::point(double t, double offset) const {
  return f->to_global(across_x ? Point2{at + offset, t} : Point2{t, at + offset});
}

std::vector<bool> wall_samples(const ClassGrid& observed, const FrameLine& line, int reach, int thin) {
  auto occupied = [&](double t, int k) {
    const Point2 p = line.point(t, k);
    // The cell whose centre (its integer coordinates, raster.h) is nearest.
    const int r = static_cast<int>(std::lround(p.y)), c = static_cast<int>(std::lround(p.x));
    return r >= 0 && c >= 0 && r < observed.rows && c < observed.cols &&
           observed(r, c) == static_cast<std::uint8_t>(Cell::Occupied);
  };
  auto open_within = [&](double t, int side) {
    for (int k = reach + 1; k <= thin; ++k)
      if (!occupied(t, side * k)) return true;
    return false;
  };
  std::vector<bool> out;
  for (double t = line.lo; t <= line.hi; t += 0.5) {
    bool wall = false;
    for (int k = -reach; k <= reach && !wall; ++k) wall = occupied(t, k);
    if (wall && thin > reach) wall = open_within(t, -1) && open_within(t, 1);
    out.push_back(wall);
  }
  return out;
}

double wall_share(const std::vector<bool>& samples) {
  if (samples.empty()) return 1.0;
  std::size_t walled = 0;
  for (const bool s : samples) walled += s ? 1 : 0;
  return static_cast<double>(walled) / static_cast<double>(samples.size());
}

}  // namespace ksmc::stdlib::indoor::kit
