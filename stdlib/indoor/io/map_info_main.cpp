// ksmc-map-info MAP [--resolution R] [--bormann | --drawn | --thresholds OCC FREE] [--negate]
// Loads an occupancy map (map_server YAML, or a bare PGM/PNG) and prints its size, resolution,
// origin, class counts, load time and any warnings. Exit 1 with the loader's message on bad input.
#include <chrono>
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "stdlib/indoor/io/map_error.h"
#include "stdlib/indoor/io/map_loader.h"

int main(int argc, char** argv) {
  namespace io = ksmc::stdlib::indoor::io;
  CLI::App app{"Load an occupancy grid map and print what the indoor loader sees"};
  std::string path;
  double resolution = 0.0;
  bool bormann = false, drawn = false, negate = false;
  std::vector<double> thresholds;
  app.add_option("map", path, "map_server YAML, PGM or PNG")->required();
  app.add_option("--resolution", resolution, "m per cell (overrides the YAML)")->check(CLI::PositiveNumber);
  auto* b = app.add_flag("--bormann", bormann, "IPA benchmark convention: pixels >= 250 free, rest occupied");
  auto* d = app.add_flag("--drawn", drawn, "the indoor binary's default for bare images: >= 250 free, < 89 occupied, "
                                           "the grey painting >= 5 % of the image unknown, other greys occupied")
                ->excludes(b);
  app.add_option("--thresholds", thresholds, "occupied_thresh free_thresh for bare images")
      ->expected(2)
      ->excludes(b)
      ->excludes(d);
  app.add_flag("--negate", negate, "bare images: dark pixels are free");
  CLI11_PARSE(app, argc, argv);

  io::ImageLoadOptions opts;
  if (resolution > 0.0) opts.resolution = resolution;
  if (bormann) opts.thresholds = io::Thresholds::bormann();
  if (drawn) opts.thresholds = io::Thresholds::drawn();
  if (thresholds.size() == 2) {
    opts.thresholds.occupied_thresh = thresholds[0];
    opts.thresholds.free_thresh = thresholds[1];
  }
  opts.thresholds.negate = negate;
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const io::OccupancyMap m = io::load_map(path, opts);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    for (const auto& w : m.warnings) std::fprintf(stderr, "%s\n", w.c_str());
    const io::ClassCounts c = m.counts();
    const double n = static_cast<double>(c.total());
    std::printf("map        %s\nimage      %s\nsize       %d x %d cells (%.2f x %.2f m)\n",
                m.source.string().c_str(), m.image.string().c_str(), m.cols(), m.rows(),
                m.cols() * m.resolution, m.rows() * m.resolution);
    std::printf("resolution %g m/cell\norigin     [%g, %g, %g]\n", m.resolution, m.origin.x,
                m.origin.y, m.origin.yaw);
    std::printf("thresholds occupied > %g, free < %g, negate %d%s\n", m.thresholds.occupied_thresh,
                m.thresholds.free_thresh, m.thresholds.negate ? 1 : 0,
                m.thresholds.painted_unknown ? ", between: the painted grey unknown, the rest occupied" : "");
    std::printf("free       %zu (%.1f%%)\nunknown    %zu (%.1f%%)\noccupied   %zu (%.1f%%)\n",
                c.free, 100.0 * c.free / n, c.unknown, 100.0 * c.unknown / n, c.occupied,
                100.0 * c.occupied / n);
    std::printf("load time  %.1f ms\n", ms);
  } catch (const io::MapLoadError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
