// Synthesised stereo scenes for the stereo front-end tests and benchmark: a rig 0.75 m from
// the table (synth_stereo.h), temporary folders, rotation error.
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "tools/stereo_synth/synth_stereo.h"

namespace ksmc::tests::stereo {

namespace st = ksmc::stdlib::tabletop::perception::stereo;
namespace sy = ksmc::tools::stereo_synth;
using ksmc::stdlib::tabletop::Pose;

inline sy::Rig standard_rig() {
  sy::Rig rig;
  rig.table_from_left = sy::look_at_table(0.75, 0.85, 0.15);
  return rig;
}

using sy::grid_boxes;
using sy::upright;

inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("ksmc_stereo_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b);
}

}  // namespace ksmc::tests::stereo
