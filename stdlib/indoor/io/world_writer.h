// Writes the whole indoor result into a folder: world.json, labels.png, segmentation.png,
// overlay.png, trace.png (when the result has a recorded trace), graph.dot and graph.png (when Graphviz `dot` is on PATH),
// world.obj, posterior.png (when the result has posterior samples) — each
// atomically; identical input gives byte-identical files.
#pragma once

#include <filesystem>
#include <string>

#include "stdlib/indoor/io/occupancy_map.h"
#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

struct WorldFiles {
  std::filesystem::path world_json, labels_png, segmentation_png, overlay_png, trace_png, graph_dot, graph_png,
      world_obj, posterior_png;  // trace_png / posterior_png empty when w.trace / w.posterior is (not written)
  std::string graph_png_skipped;  // why graph.png was not written (e.g. no `dot` on PATH), "" if it was
};

// `dir` is created if missing. The map must have the size recorded in w.map (width x height).
// Throws std::invalid_argument on an inconsistent result, std::runtime_error on I/O failure.
WorldFiles write_world_outputs(const std::filesystem::path& dir, const OccupancyMap& map,
                               const WorldResult& w);

}  // namespace ksmc::stdlib::indoor::io
