#include "stdlib/tabletop/perception/face_strip.h"

#include <algorithm>

#include "stdlib/tabletop/cloud_likelihood.h"

namespace ksmc::stdlib::tabletop::perception {

bool is_face_strip(const UprightBox& box, const Points& own, const UprightBox& outer, const FaceStripOptions& o) {
  if (own.empty() || !is_thin(box, o) || outer.size.prod() <= box.size.prod()) return false;
  const Obb solid = Obb::from_pose(outer.pose, outer.size);
  const auto on = std::count_if(own.begin(), own.end(), [&](const Eigen::Vector3d& p) {
    return surface_distance(solid, p) <= o.margin;
  });
  return static_cast<double>(on) >= o.share * static_cast<double>(own.size());
}

}  // namespace ksmc::stdlib::tabletop::perception
