// Shared setup of the segments kit tests: the example domain's generated config and
// Markov logic binding, and the bundled room cloud.
#pragma once

#include <memory>
#include <string>

#include "segments_model.h"  // generated from examples/segments/segments.ksm
#include "stdlib/segments/cloud.h"
#include "stdlib/segments/kit/segments_model.h"

namespace segments_test {

inline std::shared_ptr<const ksmc::stdlib::segments::kit::SharedInput> room_input(std::uint64_t seed = 1) {
  using namespace ksmc::stdlib::segments;
  auto sh = std::make_shared<kit::SharedInput>();
  sh->settings = kit::read_settings(ksmc_generated::segments::domain_config());
  sh->binding = ksmc_generated::segments::mln_binding();
  sh->points = std::make_shared<const std::vector<Vec2>>(
      load_points(std::string(KSMC_SOURCE_DIR) + "/examples/segments/room.txt"));
  sh->candidates = detect_candidates(*sh->points, sh->settings.ransac, seed);
  return sh;
}

}  // namespace segments_test
