// indoor_plan_score TRUTH.json WORLD.json: scores one indoor result against a plan's truth
// (score.h) and prints one line:
//   unit_precision unit_recall type_accuracy door_precision door_recall door_f1 adjacency_f1 door_graph_f1 topology_f1
//   true_units found_units matched_units
#include <cstdio>
#include <exception>

#include "bench/indoor_plans/score.h"
#include "stdlib/indoor/io/world_json_read.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: indoor_plan_score TRUTH.json WORLD.json\n");
    return 2;
  }
  try {
    namespace io = ksmc::stdlib::indoor::io;
    const auto s = ksmc::bench::indoor_plans::score(io::read_world_json(argv[1]), io::read_world_json(argv[2]));
    std::printf("%.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f %zu %zu %zu\n", s.unit_precision, s.unit_recall,
                s.type_accuracy, s.door_precision, s.door_recall, s.door_f1, s.adjacency_f1, s.door_graph_f1, s.topology_f1, s.true_units,
                s.found_units, s.matched_units);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "indoor_plan_score: %s\n", e.what());
    return 1;
  }
}
