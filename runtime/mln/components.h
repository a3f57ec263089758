// Connected components of a ground network (atoms linked by shared clauses or
// exactly-one blocks) and extraction of one component as a stand-alone network.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/mln/ground_network.h"

namespace ksmc::runtime::mln {

struct Component {
  std::vector<AtomId> atoms;          // ascending global atom ids; local id = position
  std::vector<std::int32_t> clauses;  // global clause ids, ascending
  std::vector<std::int32_t> blocks;   // global block ids, ascending
};

// Components in order of their smallest atom (deterministic).
std::vector<Component> split_components(const GroundNetwork& net);

// The component as its own network (local atom ids, same weights/origins, no constant).
GroundNetwork extract_component(const GroundNetwork& net, const Component& comp);

}  // namespace ksmc::runtime::mln
