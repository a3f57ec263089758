#include "stdlib/tabletop/perception/ray_meeting.h"

namespace ksmc::stdlib::tabletop::perception {

SpaceUnder rays_meeting(const Obb& space, const std::vector<Obb>& own, const RayIndex& rays, double margin) {
  SpaceUnder out;
  for_each_meeting(space, own, rays, margin, [&out](std::size_t, RayMeets how) {
    ++(how == RayMeets::before ? out.before : how == RayMeets::through ? out.through : out.inside);
  });
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
