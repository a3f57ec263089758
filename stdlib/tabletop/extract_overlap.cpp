#include "stdlib/tabletop/extract_overlap.h"

#include "stdlib/tabletop/extract_stable.h"

namespace ksmc::stdlib::tabletop {

namespace {

constexpr int kGrid = 8;  // cells per axis of the smaller box: 512 samples, resolution 0.2 %

Obb shrunk(Obb box, double by) {
  box.half.array() -= by;
  return box;
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
  int inside = 0;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      for (int k = 0; k < kGrid; ++k) {
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
