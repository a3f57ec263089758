// Tolerances of the table-top evidence extractors (table frame, metres / radians).
//
// Defaults are calibrated on real annotation noise (HOPE-Video frame: lowest z of
// objects standing on the table spreads 1.4 cm, upright axes tilt up to 7°), while
// keeping two real neighbours 5 mm apart out of contact. Gaps and penetrations whose
// direction is close to the table normal (support) get the larger vertical
// tolerances, because pose noise is mostly along the viewing depth / height.
#pragma once

#include <numbers>

namespace ksmc::stdlib::tabletop {

struct EvidenceParams {
  double stable_tol_rad = 10.0 * std::numbers::pi / 180.0;  // edge ∥ table normal within this angle
  double contact_eps = 0.004;            // max exact gap for contact, any direction [m]
  double intersect_eps = 0.005;          // min penetration depth for intersect, any direction [m]
  double vertical_contact_eps = 0.015;   // max gap when the gap direction is near-vertical [m]
  double vertical_intersect_eps = 0.015; // min depth when the penetration axis is near-vertical [m]
  double vertical_cone_rad = 30.0 * std::numbers::pi / 180.0;  // "near-vertical" half-angle
  double higher_tol = 0.015;             // see extract_higher.h [m]

  // Largest gap any contact decision can accept: pairs farther apart (by the SAT
  // lower bound) need no exact distance.
  [[nodiscard]] double max_contact_eps() const {
    return contact_eps > vertical_contact_eps ? contact_eps : vertical_contact_eps;
  }
};

}  // namespace ksmc::stdlib::tabletop
