#include "stdlib/tabletop/perception/box_compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ksmc::stdlib::tabletop::perception {

BoxError compare_boxes(const Eigen::Vector3d& est_centre, const Eigen::Matrix3d& est_axes, const Eigen::Vector3d& est_size,
                       const Eigen::Vector3d& true_centre, const Eigen::Matrix3d& true_axes,
                       const Eigen::Vector3d& true_size) {
  BoxError best;
  best.centre = (est_centre - true_centre).norm();
  best.angle = std::numeric_limits<double>::infinity();
  std::array<int, 3> perm{0, 1, 2};
  do {
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d m;  // column k: estimate axis perm[k], signed
      for (int k = 0; k < 3; ++k) m.col(k) = ((signs >> k) & 1 ? -1.0 : 1.0) * est_axes.col(perm[static_cast<std::size_t>(k)]);
      if (m.determinant() < 0.0) continue;
      const Eigen::Matrix3d rel = true_axes.transpose() * m;
      const double c = std::clamp(0.5 * (rel.trace() - 1.0), -1.0, 1.0);
      const double angle = std::acos(c);
      if (angle < best.angle - 1e-12) {
        best.angle = angle;
        for (int k = 0; k < 3; ++k) {
          best.axis_of[k] = perm[static_cast<std::size_t>(k)];
          best.size[k] = est_size[perm[static_cast<std::size_t>(k)]] - true_size[k];
        }
      }
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

}  // namespace ksmc::stdlib::tabletop::perception
