#include "stdlib/indoor/kit/wall_lines.h"

#include <cstdint>
#include <limits>

namespace ksmc::stdlib::indoor::kit {

Point2 FrameLine::point(double t, double offset) const {
  return f->to_global(across_x ? Point2{at + offset, t} : Point2{t, at + offset});
}

namespace {

// The cell whose centre (its integer coordinates, raster.h) is nearest to v, halves away from
// zero as std::lround (v + 0.5 would round 2.4999999999999996 up); -1 below the map.
int nearest_cell(double v) {
  if (v <= -0.5) return -1;
  const int i = static_cast<int>(v);  // towards zero: 0 for v in (-0.5, 0)
  return v - i >= 0.5 ? i + 1 : i;
}

}  // namespace

std::optional<std::vector<bool>> wall_samples_bounded(const ClassGrid& observed, const FrameLine& line, int reach,
                                                      int thin, std::size_t max_open, std::size_t max_missing) {
  auto occupied = [&](double t, int k) {
    const Point2 p = line.point(t, k);
    const int r = nearest_cell(p.y), c = nearest_cell(p.x);
    return r >= 0 && c >= 0 && r < observed.rows && c < observed.cols &&
           observed(r, c) == static_cast<std::uint8_t>(Cell::Occupied);
  };
  auto open_within = [&](double t, int side) {
    for (int k = reach + 1; k <= thin; ++k)
      if (!occupied(t, side * k)) return true;
    return false;
  };
  std::vector<bool> out;
  std::size_t open = 0, missing = 0;
  for (double t = line.lo; t <= line.hi; t += 0.5) {
    bool wall = false;
    for (int k = -reach; k <= reach && !wall; ++k) wall = occupied(t, k);
    if (wall && thin > reach) wall = open_within(t, -1) && open_within(t, 1);
    out.push_back(wall);
    open = wall ? 0 : open + 1;
    missing += wall ? 0 : 1;
    if (open > max_open || missing > max_missing) return std::nullopt;
  }
  return out;
}

std::vector<bool> wall_samples(const ClassGrid& observed, const FrameLine& line, int reach, int thin) {
  constexpr auto kAll = std::numeric_limits<std::size_t>::max();
  return *wall_samples_bounded(observed, line, reach, thin, kAll, kAll);
}

std::size_t sample_count(const FrameLine& line) {
  std::size_t n = 0;
  for (double t = line.lo; t <= line.hi; t += 0.5) ++n;
  return n;
}

double wall_share(const std::vector<bool>& samples) {
  if (samples.empty()) return 1.0;
  std::size_t walled = 0;
  for (const bool s : samples) walled += s ? 1 : 0;
  return static_cast<double>(walled) / static_cast<double>(samples.size());
}

}  // namespace ksmc::stdlib::indoor::kit
