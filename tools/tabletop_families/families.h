// Noise-model families of generated table-top scenes (issue 12): each family varies one
// aspect of how pose estimates go wrong (pose noise, camera, keypoints, object catalogue,
// false-estimate kinds, hidden supporters, leaning boxes), and `mixed` varies all of them
// at once with numeric ids. A family draws the generator options per scene from the scene's
// seed, so a family is a distribution of scenes, not one setting. Development tool (not
// part of the product): the per-family evaluation and the scene writer use it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "tools/tabletop_sim/generator.h"

namespace ksmc::tools::tabletop_families {

namespace sim = ksmc::tools::tabletop_sim;

struct Family {
  std::string_view name;
  std::string_view varies;  // one line: what the family draws per scene
  sim::GeneratorOptions (*options)(sim::Rng& rng);
};

// Every family, in report order.
std::span<const Family> families();

// The family called `name`; throws std::invalid_argument listing the known names.
const Family& family(std::string_view name);

// Seed of scene `index` of `family` in a batch started with `seed` (families do not share scenes).
std::uint64_t family_scene_seed(const Family& family, std::uint64_t seed, std::uint64_t index);

// The generator options of one scene (drawn from its seed) and the scene itself.
sim::GeneratorOptions scene_options(const Family& family, std::uint64_t scene_seed);
sim::GeneratedScene generate(const Family& family, std::uint64_t scene_seed);

}  // namespace ksmc::tools::tabletop_families
