// HOPE-Video frame (meta_data.json of dramab/hope-dataset test_data) → Scene.
//
// Conventions (see the data's README): object poses map object → camera with the
// translation in cm; bbox3d is [min xyz, max xyz] in the object frame, cm; the
// extrinsics map camera → world with the translation in metres, world +z up.
// The OBB centre is the bbox3d centre mapped through the pose, its size the bbox3d
// extents. The table frame is the world frame shifted to z = table height
// (default: median of the objects' lowest world z) and to the objects' mean x, y.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "stdlib/tabletop/scene.h"
#include "stdlib/tabletop/scene_io.h"

namespace ksmc::stdlib::tabletop {

struct HopeImportOptions {
  std::optional<double> table_z_world;  // metres; default: median of lowest z
  Eigen::Vector3d table_size{2.0, 2.0, 0.05};
};

struct HopeImport {
  Scene scene;
  double table_z_world = 0.0;  // the table height used [m, world frame]
  std::vector<std::string> warnings;
};

HopeImport import_hope(const nlohmann::json& meta, const std::string& source_name,
                       const HopeImportOptions& options = {});
HopeImport import_hope_file(const std::filesystem::path& meta_data_json, const HopeImportOptions& options = {});

}  // namespace ksmc::stdlib::tabletop
