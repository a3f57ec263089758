#include "stdlib/tabletop/extract_higher.h"

#include <algorithm>
#include <cmath>

namespace ksmc::stdlib::tabletop {

double face_half_height(const Obb& box) {
  double h = 0.0;
  for (int k = 0; k < 3; ++k) h = std::max(h, box.half[k] * std::abs(box.axes(2, k)));
  return h;
}

bool extract_higher(const Obb& a, const Obb& b, const EvidenceParams& params) {
  const double b_half = face_half_height(b);
  const double b_top = b.center.z() + b_half;
  const double a_bottom = a.center.z() - face_half_height(a);
  const double tol = std::min(params.higher_tol, b_half);
  return a_bottom >= b_top - tol;
}

}  // namespace ksmc::stdlib::tabletop
