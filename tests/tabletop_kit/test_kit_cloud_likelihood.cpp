// `cloud.surface` in the kit's model: a scene from a depth cloud is scored by its boxes'
// points and, with a free-space cost, by the rays its boxes block; a scene without a cloud
// is scored as before. domains/tabletop.ksm multiplies it with keypoints.gaussian.
#include <catch2/catch.hpp>

#include <memory>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/kit/tabletop_model.h"
#include "tests/tabletop/tabletop_test_util.h"
#include "tests/tabletop_kit/binding_fixture.h"

namespace kit = ksmc::stdlib::tabletop::kit;
namespace tt = ksmc::stdlib::tabletop;
using namespace ksmc::tests::tabletop_kit;
using ksmc::tests::tabletop::object;

namespace {

// Grid points on the top and the four sides of an axis-aligned box standing on z = 0.
tt::Points box_surface(const Eigen::Vector3d& centre, const Eigen::Vector3d& size, double step) {
  tt::Points out;
  const Eigen::Vector3d h = 0.5 * size;
  for (double a = -h.x(); a <= h.x() + 1e-9; a += step)
    for (double b = -h.y(); b <= h.y() + 1e-9; b += step) out.push_back(centre + Eigen::Vector3d(a, b, h.z()));
  for (double z = -h.z(); z <= h.z() + 1e-9; z += step) {
    for (double a = -h.x(); a <= h.x() + 1e-9; a += step) {
      out.push_back(centre + Eigen::Vector3d(a, -h.y(), z));
      out.push_back(centre + Eigen::Vector3d(a, h.y(), z));
    }
    for (double b = -h.y(); b <= h.y() + 1e-9; b += step) {
      out.push_back(centre + Eigen::Vector3d(-h.x(), b, z));
      out.push_back(centre + Eigen::Vector3d(h.x(), b, z));
    }
  }
  return out;
}

// One 10 cm cube on the table, its points and a table grid as the cloud (no keypoints).
std::shared_ptr<const tt::Scene> cloud_scene(bool with_cloud) {
  auto s = std::make_shared<tt::Scene>();
  const Eigen::Vector3d centre(0.0, 0.0, 0.05), size(0.1, 0.1, 0.1);
  s->objects.push_back(object("cube", centre, size));
  if (!with_cloud) return s;
  auto seen = std::make_shared<tt::CloudObservation>();
  seen->object_points.push_back(box_surface(centre, size, 0.005));
  // The rays: what a sensor at (0.3, -0.4, 0.6) sees of the cube and the table (a point
  // whose ray the cube blocks 1 mm before it is hidden).
  tt::FreeSpace rays, probe;
  rays.sensor = probe.sensor = Eigen::Vector3d(0.3, -0.4, 0.6);
  probe.margin = 0.001;
  tt::Points all = seen->object_points[0];
  for (double x = -0.3; x <= 0.3; x += 0.01)
    for (double y = -0.3; y <= 0.3; y += 0.01) all.emplace_back(x, y, 0.0);
  for (const auto& p : all) {
    probe.points = {p};
    if (tt::see_through_count(s->objects[0].obb(), probe) == 0) rays.points.push_back(p);
  }
  seen->rays = tt::RayIndex(std::move(rays));
  seen->sensor = Eigen::Vector3d(0.3, -0.4, 0.6);
  s->cloud = std::move(seen);
  return s;
}

}  // namespace

TEST_CASE("cloud.surface: a box's points score its pose, and make it an object the refine move may pick") {
  const blk::Binding& b = ksm_binding();
  REQUIRE(b.likelihood.keypoint_term);
  REQUIRE(b.likelihood.cloud.has_value());  // domains/tabletop.ksm declares both factors
  kit::KitOptions no_estimate;              // the cloud term alone
  no_estimate.pose_sigma_t = no_estimate.pose_sigma_r = 0.0;
  const auto scene = cloud_scene(true);
  kit::TabletopModel m(scene, b, no_estimate);
  REQUIRE(m.observed_objects().size() == 1);  // no keypoints, but points
  const tt::Pose at = scene->objects[0].pose;
  tt::Pose off = at;
  off.t.x() += 0.004;  // one sigma: each point of the two faces across the shift costs 1/2
  const double here = m.object_log_likelihood_at(0, at), there = m.object_log_likelihood_at(0, off);
  CHECK(here == Approx(tt::cloud_log_likelihood(scene->cloud->object_points[0], scene->objects[0].obb(),
                                                {b.likelihood.cloud->sigma, true, b.likelihood.cloud->outlier,
                                                 b.likelihood.cloud->inside_sigma, scene->cloud->sensor})));
  CHECK(here - there > 100.0);
  CHECK(m.log_likelihood() == Approx(here));

  // The same scene read without its cloud: no term, and nothing for the refine move.
  kit::TabletopModel bare(cloud_scene(false), b, no_estimate);
  CHECK(bare.observed_objects().empty());
  CHECK(bare.object_log_likelihood_at(0, off) == 0.0);
}

TEST_CASE("cloud.surface: with a free-space cost, every ray a box blocks costs that much") {
  blk::Binding b = ksm_binding();
  b.likelihood.cloud->free_space_cost = 2.0;
  kit::KitOptions no_estimate;
  no_estimate.pose_sigma_t = no_estimate.pose_sigma_r = 0.0;
  const auto scene = cloud_scene(true);
  kit::TabletopModel m(scene, b, no_estimate);
  CHECK(scene->cloud->rays.see_through_count(scene->objects[0].obb()) == 0);  // the true box blocks nothing
  tt::Pose lifted = scene->objects[0].pose;
  lifted.t = Eigen::Vector3d(0.15, 0.1, 0.12);  // in the air, where the sensor saw the table
  const std::size_t blocked = scene->cloud->rays.see_through_count(tt::Obb::from_pose(lifted, scene->objects[0].size));
  CHECK(blocked > 20);
  const double surface = tt::cloud_log_likelihood(scene->cloud->object_points[0], tt::Obb::from_pose(lifted, scene->objects[0].size),
                                                  {b.likelihood.cloud->sigma, true, b.likelihood.cloud->outlier,
                                                   b.likelihood.cloud->inside_sigma, scene->cloud->sensor});
  CHECK(m.object_log_likelihood_at(0, lifted) == Approx(surface - 2.0 * static_cast<double>(blocked)));
}
