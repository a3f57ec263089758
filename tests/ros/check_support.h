// Shared by the node-test client programs: PASS / FAIL lines, and spinning until the
// node's outputs have arrived or a timeout passed.
#pragma once

#include <chrono>
#include <functional>
#include <iostream>
#include <string>

#include <ros/ros.h>

namespace ksmc_ros_test {

inline int& failures() {
  static int n = 0;
  return n;
}

inline void check(bool ok, const std::string& what) {
  std::cout << (ok ? "PASS: " : "FAIL: ") << what << std::endl;
  if (!ok) ++failures();
}

// Spins at 10 Hz until done() or timeout_s; returns the seconds waited.
inline double spin_until(const std::function<bool()>& done, double timeout_s) {
  const auto start = std::chrono::steady_clock::now();
  const auto waited = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  ros::Rate rate(10);
  while (ros::ok() && !done() && waited() < timeout_s) {
    ros::spinOnce();
    rate.sleep();
  }
  return waited();
}

inline int finish() {
  std::cout << (failures() ? std::to_string(failures()) + " checks failed" : "all checks passed") << std::endl;
  return failures() ? 1 : 0;
}

}  // namespace ksmc_ros_test
