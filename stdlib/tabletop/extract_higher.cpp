#include "stdlib/tabletop/extract_higher.h"

#include <algorithm>

namespace ksmc::stdlib::tabletop {

bool extract_higher(const Obb& a, const Obb& b, const EvidenceParams& params) {
  const double b_top = b.max_z();
  const double tol = std::min(params.higher_tol, 0.5 * (b_top - b.min_z()));
  return a.min_z() >= b_top - tol;
}

}  // namespace ksmc::stdlib::tabletop
