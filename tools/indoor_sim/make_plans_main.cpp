// ksmc-make-plans --count N --seed S --out DIR
// Writes DIR/plan_<k>.pgm, plan_<k>.yaml (map_server) and plan_<k>_truth.json for k = 0..N-1,
// plan k drawn by make_plan(S + k) (plan_family.h).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/world_json.h"
#include "tools/indoor_sim/plan_family.h"

int main(int argc, char** argv) {
  namespace io = ksmc::stdlib::indoor::io;
  namespace sim = ksmc::tools::indoor_sim;
  try {
    int count = -1;
    std::uint64_t seed = 1;
    std::filesystem::path out;
    for (int i = 1; i + 1 < argc; i += 2) {
      const std::string flag = argv[i];
      if (flag == "--count") {
        count = std::stoi(argv[i + 1]);
      } else if (flag == "--seed") {
        seed = std::stoull(argv[i + 1]);
      } else if (flag == "--out") {
        out = argv[i + 1];
      } else {
        count = -1;
        break;
      }
    }
    if (argc % 2 == 0 || count < 0 || out.empty()) {
      std::fprintf(stderr, "usage: %s --count N --seed S --out DIR\n", argv[0]);
      return 2;
    }
    std::filesystem::create_directories(out);
    for (int k = 0; k < count; ++k) {
      sim::SimFloorPlan plan = sim::make_plan(seed + static_cast<std::uint64_t>(k));
      const std::string name = fmt::format("plan_{}", k);
      plan.truth.map.source = name + ".pgm";
      ksmc::runtime::io::write_file_atomic(out / (name + ".pgm"), sim::encode_pgm(plan.image, plan.resolution));
      ksmc::runtime::io::write_file_atomic(
          out / (name + ".yaml"),
          fmt::format("image: {}.pgm\nresolution: {:.3f}\norigin: [0.0, 0.0, 0.0]\n"
                      "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
                      name, plan.resolution));
      ksmc::runtime::io::write_file_atomic(out / (name + "_truth.json"), io::world_json_text(plan.truth));
      std::printf("%s: %dx%d cells, %zu units, %zu doors\n", name.c_str(), plan.image.cols, plan.image.rows,
                  plan.truth.units.size(), plan.truth.doors.size());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ksmc-make-plans: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
