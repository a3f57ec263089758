#include "stdlib/indoor/io/world_writer.h"

#include <stdexcept>
#include <string>
#include <system_error>

#include "runtime/io/dot_render.h"
#include "stdlib/indoor/io/graph_dot.h"
#include "stdlib/indoor/io/posterior_plot.h"
#include "stdlib/indoor/io/segmentation.h"
#include "stdlib/indoor/io/trace_plot.h"
#include "stdlib/indoor/io/world_images.h"
#include "stdlib/indoor/io/world_json.h"
#include "stdlib/indoor/io/world_obj.h"

namespace ksmc::stdlib::indoor::io {

WorldFiles write_world_outputs(const std::filesystem::path& dir, const OccupancyMap& map,
                               const WorldResult& w) {
  validate_world(w, true);
  if (map.cols() != w.map.width || map.rows() != w.map.height) {
    throw std::invalid_argument("world: map info says " + std::to_string(w.map.width) + "x" +
                                std::to_string(w.map.height) + " but the map is " +
                                std::to_string(map.cols()) + "x" + std::to_string(map.rows()));
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir.string() + ": cannot create output folder: " + ec.message());
  WorldFiles f{dir / "world.json", dir / "labels.png", dir / "segmentation.png", dir / "overlay.png", dir / "trace.png",
               dir / "graph.dot", dir / "graph.png", dir / "world.obj", {}, {}};
  write_world_json(f.world_json, w);
  write_labels_png(f.labels_png, w, map.rows(), map.cols());
  write_segmentation_png(f.segmentation_png, map.grid, w);
  write_overlay_png(f.overlay_png, map.grid, w);
  if (w.trace.empty()) {
    f.trace_png.clear();  // no recorded trace, no picture
  } else {
    write_trace_png(f.trace_png, w.trace);
  }
  write_graph_dot(f.graph_dot, w);
  write_world_obj(f.world_obj, w);
  if (!w.posterior.empty()) {
    f.posterior_png = dir / "posterior.png";
    write_posterior_png(f.posterior_png, map.grid, w);
  }
  f.graph_png_skipped = runtime::io::render_dot_png(f.graph_dot, f.graph_png);
  return f;
}

}  // namespace ksmc::stdlib::indoor::io
