// ksmc-make-example-map OUT_DIR [--seed N]
// Writes OUT_DIR/sim_office.pgm, sim_office.yaml (map_server) and sim_office_truth.json
// (the true units, doors and adjacency in world.json's schema, metrics empty).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/world_json.h"
#include "tools/indoor_sim/sim_floor_plan.h"

int main(int argc, char** argv) {
  namespace io = ksmc::stdlib::indoor::io;
  namespace sim = ksmc::tools::indoor_sim;
  if (argc != 2 && !(argc == 4 && std::string(argv[2]) == "--seed")) {
    std::fprintf(stderr, "usage: %s OUT_DIR [--seed N]\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path out = argv[1];
    std::uint64_t seed = 20130501;
    if (argc == 4) seed = std::stoull(argv[3]);
    std::filesystem::create_directories(out);
    const sim::SimFloorPlan plan = sim::make_sim_office(seed);
    ksmc::runtime::io::write_file_atomic(out / "sim_office.pgm",
                                         sim::encode_pgm(plan.image, plan.resolution));
    ksmc::runtime::io::write_file_atomic(
        out / "sim_office.yaml",
        fmt::format("image: sim_office.pgm\nresolution: {:.3f}\norigin: [0.0, 0.0, 0.0]\n"
                    "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
                    plan.resolution));
    ksmc::runtime::io::write_file_atomic(out / "sim_office_truth.json",
                                         io::world_json_text(plan.truth));
    std::printf("wrote %s/sim_office.{pgm,yaml} and sim_office_truth.json (%dx%d cells, %zu units)\n",
                out.string().c_str(), plan.image.cols, plan.image.rows, plan.truth.units.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ksmc-make-example-map: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
