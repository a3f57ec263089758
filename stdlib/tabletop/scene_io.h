// scene.json reader with validation. Errors name the file and the JSON path
// ("scene.json: objects[3].pose.q: zero quaternion"); recoverable oddities
// (non-unit quaternion) are normalised and reported as warnings.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SceneOptions {
  Eigen::Vector3d table_size{2.0, 2.0, 0.05};  // slab extents when the file gives none
  double quaternion_tolerance = 1e-6;          // | |q| - 1 | above this warns
};

struct SceneLoad {
  Scene scene;
  std::vector<std::string> warnings;  // "scene.json: objects[0].pose.q: non-unit quaternion (norm 1.2), normalised"
};

// `source_name` prefixes messages; `base_dir` resolves the relative "image" path.
SceneLoad parse_scene(const nlohmann::json& doc, const std::string& source_name,
                      const std::filesystem::path& base_dir, const SceneOptions& options = {});
SceneLoad load_scene(const std::filesystem::path& path, const SceneOptions& options = {});

}  // namespace ksmc::stdlib::tabletop
