// ksmc-render-world MAP WORLD_JSON OUT_DIR [--resolution R] [--thresholds drawn|strict|ros|bormann]
// Re-renders labels.png, segmentation.png, overlay.png and graph.dot for a world.json (a result of an earlier run or
// a ground-truth file) over its map, as the run saw it (map.cleanup in world.json: specks cleared, solid
// interiors unexplained). Useful to look at examples/indoor/sim_office_truth.json.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "stdlib/indoor/io/graph_dot.h"
#include "stdlib/indoor/io/map_cleanup.h"
#include "stdlib/indoor/io/map_loader.h"
#include "stdlib/indoor/io/segmentation.h"
#include "stdlib/indoor/io/world_images.h"
#include "stdlib/indoor/io/world_json_read.h"

int main(int argc, char** argv) {
  namespace io = ksmc::stdlib::indoor::io;
  CLI::App app{"Render labels.png, segmentation.png, overlay.png and graph.dot of a world.json over its map"};
  std::string map_path, world_path, out_dir;
  double resolution = 0.0;
  std::string thresholds = "drawn";
  app.add_option("map", map_path, "map_server YAML, PGM or PNG")->required();
  app.add_option("world", world_path, "world.json")->required();
  app.add_option("out", out_dir, "output folder (created if missing)")->required();
  app.add_option("--resolution", resolution, "m per cell (overrides the YAML)")->check(CLI::PositiveNumber);
  app.add_option("--thresholds", thresholds,
                 "grey values of a bare image, as the indoor binary's --thresholds: drawn (its default), strict, ros or bormann");
  CLI11_PARSE(app, argc, argv);
  try {
    io::ImageLoadOptions opts;
    if (resolution > 0.0) opts.resolution = resolution;
    const auto th = io::Thresholds::by_name(thresholds);
    if (!th) {
      std::fprintf(stderr, "--thresholds must be 'drawn', 'strict', 'ros' or 'bormann', got '%s'\n", thresholds.c_str());
      return 2;
    }
    opts.thresholds = *th;
    io::OccupancyMap m = io::load_map(map_path, opts);
    for (const auto& w : m.warnings) std::fprintf(stderr, "%s\n", w.c_str());
    const io::WorldResult w = io::read_world_json(world_path);
    if (w.map.width != m.cols() || w.map.height != m.rows()) {
      std::fprintf(stderr, "%s: error: world is for a %dx%d map but %s is %dx%d\n",
                   world_path.c_str(), w.map.width, w.map.height, map_path.c_str(), m.cols(), m.rows());
      return 1;
    }
    // The map the run saw: its specks cleared and solid interiors unexplained as world.json says.
    io::apply_cleanup(m.grid, w.map.cleanup);
    const io::ClassCounts seen = m.counts(), run = w.map.counts;
    if (run.free + run.unknown + run.occupied > 0 &&
        (seen.free != run.free || seen.unknown != run.unknown || seen.occupied != run.occupied)) {
      std::fprintf(stderr,
                   "%s: warning: the map's cells (free %zu, unknown %zu, occupied %zu) differ from the run's in %s "
                   "(%zu, %zu, %zu): another --thresholds or map file? The images may differ from the run's.\n",
                   map_path.c_str(), seen.free, seen.unknown, seen.occupied, world_path.c_str(), run.free, run.unknown,
                   run.occupied);
    }
    const std::filesystem::path out = out_dir;
    std::filesystem::create_directories(out);
    io::write_labels_png(out / "labels.png", w, m.rows(), m.cols());
    io::write_overlay_png(out / "overlay.png", m.grid, w);
    io::write_segmentation_png(out / "segmentation.png", m.grid, w);
    io::write_graph_dot(out / "graph.dot", w);
    std::printf("wrote %s/{labels.png,segmentation.png,overlay.png,graph.dot}\n", out.string().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
