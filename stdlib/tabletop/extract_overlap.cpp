#include "stdlib/tabletop/extract_overlap.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stdlib/tabletop/extract_stable.h"

namespace ksmc::stdlib::tabletop {

namespace {

constexpr int kGrid = 8;  // cells per axis of the smaller box: 512 samples, resolution 0.2 %

Obb shrunk(Obb box, double by) {
  box.half.array() -= by;
  return box;
}

// The grid indices [first, last] along the small box's axis k whose cells can lie inside
// `large`: a point inside `large` projects onto any axis within large's extent along it, so a
// cell whose coordinate along the axis falls outside that extent is outside `large` (a
// necessary condition only; the cells kept are still tested one by one). first > last: none.
std::pair<int, int> cell_range(const Obb& small, const Obb& large, int k) {
  const Eigen::Vector3d u = small.axes.col(k);
  double reach = 0.0;
  for (int m = 0; m < 3; ++m) reach += large.half[m] * std::abs(large.axes.col(m).dot(u));
  reach += 1e-9;  // rounding: never drop a cell `contains` would accept
  const double offset = (small.center - large.center).dot(u);
  int first = kGrid, last = -1;
  for (int i = 0; i < kGrid; ++i) {
    const double x = offset + ((2.0 * i + 1.0) / kGrid - 1.0) * small.half[k];
    if (std::abs(x) > reach) continue;
    first = std::min(first, i);
    last = i;
  }
  return {first, last};
}

}  // namespace

double shared_volume_fraction(const Obb& a, const Obb& b, double shrink) {
  const Obb sa = shrunk(a, shrink);
  const Obb sb = shrunk(b, shrink);
  if ((sa.half.array() <= 0.0).any() || (sb.half.array() <= 0.0).any()) return 0.0;
  // Apart by more than the two circumscribed spheres: nothing shared (most pairs of a scene).
  if ((sa.center - sb.center).norm() > sa.half.norm() + sb.half.norm()) return 0.0;
  const bool a_smaller = sa.half.prod() <= sb.half.prod();
  const Obb& small = a_smaller ? sa : sb;
  const Obb& large = a_smaller ? sb : sa;
  const auto [i0, i1] = cell_range(small, large, 0);
  const auto [j0, j1] = cell_range(small, large, 1);
  const auto [k0, k1] = cell_range(small, large, 2);
  int inside = 0;
  for (int i = i0; i <= i1; ++i) {
    for (int j = j0; j <= j1; ++j) {
      for (int k = k0; k <= k1; ++k) {
        const Eigen::Vector3d cell((2.0 * i + 1.0) / kGrid - 1.0, (2.0 * j + 1.0) / kGrid - 1.0,
                                   (2.0 * k + 1.0) / kGrid - 1.0);
        if (large.contains(small.center + small.axes * cell.cwiseProduct(small.half))) ++inside;
      }
    }
  }
  return static_cast<double>(inside) / (kGrid * kGrid * kGrid);
}

bool extract_overlap(const Obb& a, const Obb& b, double shrink, double min_fraction) {
  return shared_volume_fraction(a, b, shrink) >= min_fraction;
}

bool extract_flatter(const Obb& a, const Obb& b, double margin) {
  return tilt_angle(a) + margin < tilt_angle(b);
}

}  // namespace ksmc::stdlib::tabletop
