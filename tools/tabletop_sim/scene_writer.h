// Text of the scene file (what the tabletop binary reads) and of its ground truth.
// Fixed-point numbers with fixed decimals: byte-identical output for identical scenes.
#pragma once

#include <filesystem>
#include <string>

#include "tools/tabletop_sim/generator.h"

namespace ksmc::tools::tabletop_sim {

// {"camera":{...}, "table":{"pose":{t,q}}, "objects":[{id, model, size, pose, keypoints}]}
// Poses in the camera frame, q = [w, x, y, z] with w >= 0.
std::string scene_json(const GeneratedScene& scene);

// {"objects":[{id, false, hidden, stable}], "support":[[upper, lower]], "contact":[[a, b]]}
std::string truth_json(const GeneratedScene& scene);

// Writes <dir>/<stem>.json and <dir>/<stem>.truth.json atomically.
void write_scene_files(const std::filesystem::path& dir, const std::string& stem, const GeneratedScene& scene);

}  // namespace ksmc::tools::tabletop_sim
