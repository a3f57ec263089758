// Loading occupancy grids: ROS map_server YAML (+ PGM/PNG) or a bare PGM/PNG image.
// All failures throw MapLoadError naming the file (and YAML line); see map_error.h.
#pragma once

#include <filesystem>
#include <optional>

#include "stdlib/indoor/io/occupancy_map.h"

namespace ksmc::stdlib::indoor::io {

struct YamlLoadOptions {
  // Replaces the YAML's resolution (the --resolution flag). A conflict between the YAML and the
  // PGM header comment is still reported as a warning, naming the value used.
  std::optional<double> resolution_override;
};

struct ImageLoadOptions {
  // m per cell. When absent: the PGM map_saver comment ("0.050 m/pix") if present, else 0.05.
  std::optional<double> resolution;
  Thresholds thresholds;  // map_server defaults; Thresholds::bormann() for the IPA benchmark maps
  Pose2 origin;
};

// map_server YAML: `image` (relative to the YAML's folder) and `resolution` are required;
// `origin` ([x, y, yaw]), `negate` (0/1), `occupied_thresh`, `free_thresh` and `mode`
// (trinary|scale|raw) default to 0,0,0 / 0 / 0.65 / 0.196 / trinary.
OccupancyMap load_map_yaml(const std::filesystem::path& yaml, const YamlLoadOptions& opts = {});

// A bare PNG/PGM image classified with the caller's thresholds.
OccupancyMap load_map_image(const std::filesystem::path& image, const ImageLoadOptions& opts = {});

// Dispatches on the extension: .yaml/.yml -> load_map_yaml with opts.resolution as the override
// (the other fields come from the YAML), anything else -> load_map_image (the image format is
// detected from the file's bytes, not its name).
OccupancyMap load_map(const std::filesystem::path& path, const ImageLoadOptions& opts = {});

}  // namespace ksmc::stdlib::indoor::io
