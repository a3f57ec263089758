// scene.json text of a Scene in the format stdlib/tabletop/scene_io reads: poses in the
// camera frame, q = [w, x, y, z] with w >= 0, fixed decimals (byte-identical output).
// Keypoints are written when an object has them.
#pragma once

#include <filesystem>
#include <string>

#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::perception {

std::string scene_json_text(const Scene& scene);
// Writes <path> atomically.
void write_scene_json(const std::filesystem::path& path, const Scene& scene);

}  // namespace ksmc::stdlib::tabletop::perception
