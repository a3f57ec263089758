#include "tests/ros/scene_cloud.h"

#include "synthetic_cloud.h"

namespace ksmc_ros_test {

SceneCloud table_with_two_boxes() {
  namespace tp = ksmc::tests::perception;
  SceneCloud out;
  out.box_sizes = {{0.1, 0.07, 0.15}, {0.09, 0.09, 0.06}};  // a standing carton, a low square box
  tp::pc::Points table;
  tp::add_table(table, 0.35, 0.25, 0.01);
  tp::add_box(table, -0.1, 0.06, 0.5, Eigen::Vector3d(out.box_sizes[0].data()), 0.005);
  tp::add_box(table, 0.13, -0.07, 1.0, Eigen::Vector3d(out.box_sizes[1].data()), 0.005);
  for (const auto& p : tp::to_sensor(table, tp::example_sensor_pose()))
    out.points.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
  return out;
}

}  // namespace ksmc_ros_test
