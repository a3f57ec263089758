// A box whose foot is hidden behind a nearer box stands on the table (hidden_bottom.h); a box
// the sensor sees under, or one resting on another box, keeps its bottom.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "stdlib/tabletop/perception/hidden_bottom.h"
#include "stdlib/tabletop/perception/scene_from_cloud.h"
#include "synthetic_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::stdlib::tabletop::FreeSpace;
using ksmc::stdlib::tabletop::SceneObject;
namespace tp = ksmc::tests::perception;

namespace {

const Eigen::Vector3d kSensor(0.0, -0.9, 0.55);

// The cloud of `boxes` seen from kSensor, in the sensor's frame (the sensor at the origin,
// axes as the table's), as scene_from_points expects it.
Points view(const std::vector<tp::CastBox>& boxes) {
  Eigen::Isometry3d sensor_from_table = Eigen::Isometry3d::Identity();
  sensor_from_table.translation() = -kSensor;
  return tp::to_sensor(tp::cast_view(kSensor, Eigen::Vector3d(0.0, 0.05, 0.05), 0.35, 0.0015, boxes, 0.5, 0.4),
                       sensor_from_table);
}

// The scene object nearest (x, y) on the table, its bottom and top heights.
struct Heights {
  double bottom, top;
};
Heights nearest(const CloudScene& cs, double x, double y) {
  const SceneObject* best = nullptr;
  for (const auto& o : cs.scene.objects)
    if (best == nullptr || (o.pose.t.head<2>() - Eigen::Vector2d(x, y)).norm() <
                               (best->pose.t.head<2>() - Eigen::Vector2d(x, y)).norm())
      best = &o;
  REQUIRE(best != nullptr);
  return {best->obb().min_z(), best->obb().max_z()};
}

CloudScene run(const Points& cloud, bool hidden_bottom) {
  CloudOptions options;
  options.hidden_bottom.enabled = hidden_bottom;
  return scene_from_points(cloud, "synthetic", options);
}

}  // namespace

TEST_CASE("hidden bottom: a carton behind a lower box stands on the table", "[perception][hidden_bottom]") {
  // The front box (12 cm) hides the carton's foot: the sensor sees it from about 8.6 cm up.
  const Points cloud = view({tp::upright_box(0.0, -0.05, 0.0, Eigen::Vector3d(0.2, 0.08, 0.12)),
                             tp::upright_box(0.0, 0.10, 0.0, Eigen::Vector3d(0.08, 0.08, 0.25))});
  const Heights before = nearest(run(cloud, false), 0.0, 0.10);
  CHECK(before.bottom > 0.05);  // the fit alone starts the carton where its points start
  const CloudScene cs = run(cloud, true);
  REQUIRE(cs.scene.objects.size() == 2);
  const Heights after = nearest(cs, 0.0, 0.10);
  CHECK(after.bottom == Approx(0.0).margin(0.003));
  CHECK(after.top == Approx(0.25).margin(0.005));
  const Heights front = nearest(cs, 0.0, -0.05);  // the front box is untouched
  CHECK(front.bottom == Approx(0.0).margin(0.003));
  CHECK(front.top == Approx(0.12).margin(0.005));
}

TEST_CASE("hidden bottom: a box the sensor sees under keeps its bottom", "[perception][hidden_bottom]") {
  // Nothing in front: the rays under the box reach the table behind it.
  const CloudScene cs = run(view({tp::upright_box(0.0, 0.10, 0.09, Eigen::Vector3d(0.08, 0.08, 0.16))}), true);
  REQUIRE(cs.scene.objects.size() == 1);
  CHECK(nearest(cs, 0.0, 0.10).bottom == Approx(0.09).margin(0.006));
}

TEST_CASE("hidden bottom: a box resting on another keeps its bottom", "[perception][hidden_bottom]") {
  // The lower box hides the space under the upper one, which rests on it.
  const CloudScene cs = run(view({tp::upright_box(0.0, 0.10, 0.0, Eigen::Vector3d(0.14, 0.14, 0.08)),
                                  tp::upright_box(0.0, 0.10, 0.08, Eigen::Vector3d(0.08, 0.08, 0.10))}),
                            true);
  REQUIRE(cs.scene.objects.size() == 2);
  std::vector<Heights> h;
  for (const auto& o : cs.scene.objects) h.push_back({o.obb().min_z(), o.obb().max_z()});
  std::sort(h.begin(), h.end(), [](const Heights& a, const Heights& b) { return a.top < b.top; });
  CHECK(h[0].top == Approx(0.08).margin(0.005));
  CHECK(h[1].bottom == Approx(0.08).margin(0.006));
}

TEST_CASE("hidden bottom: the counts of rays under a box, and boxes left alone", "[perception][hidden_bottom]") {
  FreeSpace seen;
  seen.sensor = kSensor;
  seen.points = tp::cast_view(kSensor, Eigen::Vector3d(0.0, 0.05, 0.05), 0.35, 0.0015,
                              {tp::upright_box(0.0, -0.05, 0.0, Eigen::Vector3d(0.2, 0.08, 0.12)),
                               tp::upright_box(0.0, 0.10, 0.0, Eigen::Vector3d(0.08, 0.08, 0.25))},
                              0.5, 0.4);
  UprightBox box;  // the carton's visible part, from 9 cm up
  box.size = Eigen::Vector3d(0.08, 0.08, 0.16);
  box.pose.t = Eigen::Vector3d(0.0, 0.10, 0.09 + 0.08);
  const SpaceUnder s = rays_under(box, seen);
  CHECK(s.before > 100);  // the front box hides the space under it ...
  CHECK(s.before > 9 * (s.inside + s.through));
  std::vector<UprightBox> boxes{box};
  CHECK(grow_hidden_bottoms(boxes, seen, 0.03) == 1);
  CHECK(boxes[0].size.z() == Approx(0.25));
  CHECK(boxes[0].pose.t.z() == Approx(0.125));

  UprightBox tilted = box;  // not upright: left alone
  tilted.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  UprightBox low = box;  // starting within the float gap: left alone
  low.pose.t.z() = 0.02 + 0.08;
  std::vector<UprightBox> others{tilted, low};
  CHECK(grow_hidden_bottoms(others, seen, 0.03) == 0);
  HiddenBottomOptions off;
  off.enabled = false;
  std::vector<UprightBox> disabled{box};
  CHECK(grow_hidden_bottoms(disabled, seen, 0.03, off) == 0);
}
