#include "stdlib/tabletop/perception/lean_seat.h"

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/obb_sat.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

// `box` with its face on side `sign` of axis k moved in by `cut`, then (`lower`) lowered by as
// much as that raised its lowest corner.
UprightBox cut_face(const UprightBox& box, int k, double sign, double cut, bool lower) {
  const Obb before = Obb::from_pose(box.pose, box.size);
  UprightBox out = box;
  out.size(k) -= cut;
  out.pose.t -= 0.5 * sign * cut * before.axes.col(k);
  const double rise = Obb::from_pose(out.pose, out.size).min_z() - before.min_z();
  if (lower && rise > 0.0) out.pose.t.z() -= rise;
  return out;
}

double overlap(const UprightBox& a, const Obb& b) {
  const SatResult r = obb_sat(Obb::from_pose(a.pose, a.size), b);
  return r.overlapping ? r.depth : 0.0;
}

}  // namespace

int seat_leaning_boxes(std::vector<UprightBox>& boxes, const std::vector<Points>& own, const LeanSeatOptions& options) {
  if (!options.enabled) return 0;
  int cuts = 0;
  std::vector<Obb> solid;
  for (const UprightBox& b : boxes) solid.push_back(Obb::from_pose(b.pose, b.size));
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (is_upright(boxes[i])) continue;
    // The faces the sensor saw: points of the box's own on each face, not on another box.
    const Obb fit = solid[i];
    std::array<std::array<std::size_t, 2>, 3> seen{};
    for (const Eigen::Vector3d& p : own.at(i)) {
      bool elsewhere = false;
      for (std::size_t j = 0; j < boxes.size() && !elsewhere; ++j)
        elsewhere = j != i && solid[j].contains(p, options.seen_margin);
      if (elsewhere) continue;
      const Eigen::Vector3d l = fit.axes.transpose() * (p - fit.center);
      for (int k = 0; k < 3; ++k) {
        bool over = true;  // within the face's outline
        for (int m = 0; m < 3; ++m) over = over && (m == k || std::abs(l(m)) <= fit.half(m) + options.seen_margin);
        if (!over) continue;
        for (int s = 0; s < 2; ++s)
          if (std::abs(l(k) - (s == 0 ? -1.0 : 1.0) * fit.half(k)) <= options.seen_margin) ++seen[k][s];
      }
    }
    for (std::size_t j = 0; j < boxes.size(); ++j) {
      if (j == i || !is_upright(boxes[j])) continue;
      const Obb& upright = solid[j];
      if (overlap(boxes[i], upright) <= options.min_depth) continue;
      std::optional<UprightBox> best;
      double least = std::numeric_limits<double>::infinity();
      for (const bool lower : {true, false}) {
        for (int k = 0; k < 3; ++k) {
          for (int s = 0; s < 2; ++s) {
            if (seen[k][s] > options.max_seen) continue;
            const double sign = s == 0 ? -1.0 : 1.0;
            const auto deep = [&](double cut) {
              return overlap(cut_face(boxes[i], k, sign, cut, lower), upright) > options.min_depth;
            };
            double hi = options.max_cut * boxes[i].size(k);
            if (deep(hi)) continue;
            double lo = 0.0;
            for (int it = 0; it < 30; ++it) {  // the least cut, to well under a micrometre
              const double mid = 0.5 * (lo + hi);
              (deep(mid) ? lo : hi) = mid;
            }
            if (hi < least) least = hi, best = cut_face(boxes[i], k, sign, hi, lower);
          }
        }
      }
      if (best) {
        boxes[i] = *best;
        solid[i] = Obb::from_pose(best->pose, best->size);
        ++cuts;
      }
    }
  }
  return cuts;
}

}  // namespace ksmc::stdlib::tabletop::perception
