// Families of the independent generator (issue 12: "scenes the project has not
// generated"). Each family draws its options per scene from the scene's seed. The names
// carry an "indep_" prefix so that a table never mixes them up with tools/tabletop_families.
// Development tool, not part of the product.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "tools/tabletop_indep/scene.h"

namespace ksmc::tools::tabletop_indep {

struct Options {
  WorldOptions world;
  ObserveOptions observe;
};

struct Family {
  std::string_view name;
  std::string_view varies;
  Options (*draw)(Rng& rng);
};

std::span<const Family> families();
const Family& family(std::string_view name);  // throws std::invalid_argument listing the names

// Scene `index` of a batch started with `seed` (FNV-1a of the family name, mixed).
std::uint64_t scene_seed(const Family& f, std::uint64_t seed, std::uint64_t index);

// The scene of one seed: options drawn from it, then worlds built until one can be observed.
IndepScene generate(const Family& f, std::uint64_t scene_seed);

}  // namespace ksmc::tools::tabletop_indep
