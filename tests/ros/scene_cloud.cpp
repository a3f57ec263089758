#include "tests/ros/scene_cloud.h"

#include "synthetic_cloud.h"

namespace ksmc_ros_test {

std::vector<std::array<float, 3>> table_with_two_boxes() {
  namespace tp = ksmc::tests::perception;
  tp::pc::Points table;
  tp::add_table(table, 0.35, 0.25, 0.01);
  tp::add_box(table, -0.1, 0.06, 0.5, Eigen::Vector3d(0.1, 0.07, 0.15), 0.005);   // a standing carton
  tp::add_box(table, 0.13, -0.07, 1.0, Eigen::Vector3d(0.09, 0.09, 0.06), 0.005);  // a low square box
  std::vector<std::array<float, 3>> out;
  for (const auto& p : tp::to_sensor(table, tp::example_sensor_pose()))
    out.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
  return out;
}

}  // namespace ksmc_ros_test
