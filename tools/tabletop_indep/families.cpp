#include "tools/tabletop_indep/families.h"

#include "tools/named_lookup.h"

#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace ksmc::tools::tabletop_indep {

namespace {

Options base(Rng& rng) {
  Options o;
  // Along the viewing ray up to 8 mm RMS: the moderate end of the 0-15 mm range
  // (indep_pose_noise goes further).
  o.observe.sigma_t = uniform(rng, 0.001, 0.004);
  o.observe.sigma_r = uniform(rng, 0.5, 2.5);
  o.observe.depth_factor = uniform(rng, 1.0, 2.0);
  return o;
}

Options pose_noise(Rng& rng) {
  Options o = base(rng);
  o.observe.sigma_t = uniform(rng, 0.0, 0.015) / 2.0;  // t(5): the largest errors reach about 15 mm
  o.observe.sigma_r = uniform(rng, 0.0, 8.0) / 2.0;
  o.observe.depth_factor = uniform(rng, 1.0, 1.5);
  return o;
}

Options camera(Rng& rng) {
  Options o = base(rng);
  if (chance(rng, 0.5)) {
    o.observe.min_elevation = 12, o.observe.max_elevation = 25;
  } else {
    o.observe.min_elevation = 65, o.observe.max_elevation = 88;
  }
  o.observe.min_distance = 0.45, o.observe.max_distance = 2.0;
  return o;
}

Options keypoints(Rng& rng) {
  Options o = base(rng);
  const bool few = chance(rng, 0.5);
  o.observe.min_keypoints = few ? 5 : 60;
  o.observe.max_keypoints = few ? 20 : 200;
  o.observe.outlier_rate = uniform(rng, 0.0, 0.3);
  o.observe.pixel_sigma = uniform(rng, 0.3, 3.0);
  return o;
}

Options catalogue(Rng& rng) {
  Options o = base(rng);
  o.world.catalogue = Catalogue::wide;
  o.world.region_x = 0.45, o.world.region_y = 0.35;
  return o;
}

Options false_kinds(Rng& rng) {
  Options o = base(rng);
  o.observe.false_rate = 0.35;
  return o;
}

Options hidden(Rng& rng) {
  Options o = base(rng);
  o.world.stack_rate = 0.5;
  o.world.hidden_rate = 0.9;
  o.world.max_hidden = 2;
  return o;
}

Options leaning(Rng& rng) {
  Options o = base(rng);
  o.world.lean_rate = 0.35;
  o.world.stack_rate = 0.2;
  return o;
}

Options mixed(Rng& rng) {
  Options o = pose_noise(rng);
  const Options k = keypoints(rng);
  o.observe.min_keypoints = k.observe.min_keypoints, o.observe.max_keypoints = k.observe.max_keypoints;
  o.observe.outlier_rate = k.observe.outlier_rate, o.observe.pixel_sigma = k.observe.pixel_sigma;
  o.observe.min_elevation = 15, o.observe.max_elevation = 85;
  o.world.catalogue = chance(rng, 0.5) ? Catalogue::wide : Catalogue::household;
  o.world.stack_rate = uniform(rng, 0.2, 0.5);
  o.world.lean_rate = uniform(rng, 0.0, 0.25);
  o.world.hidden_rate = uniform(rng, 0.2, 0.9);
  o.observe.false_rate = uniform(rng, 0.1, 0.35);
  o.observe.numeric_ids = true;
  return o;
}

constexpr Family kFamilies[] = {
    {"indep_base", "1-4 mm, 0.5-2.5 deg camera-frame noise (t, 5 dof), depth error 1-2x lateral", base},
    {"indep_pose_noise", "pose noise up to 15 mm and 8 deg", pose_noise},
    {"indep_camera", "grazing (12-25 deg) or top-down (65-88 deg) cameras, 0.45-2 m", camera},
    {"indep_keypoints", "5-20 or 60-200 keypoints, 0-30 % outliers, 0.3-3 px", keypoints},
    {"indep_catalogue", "cubes, boards, bars and cartons from 1 to 40 cm", catalogue},
    {"indep_false_kinds", "35 % false: floating, intersecting, shifted copy, duplicate, wrong size, flipped, tilted",
     false_kinds},
    {"indep_hidden", "half the boxes stacked, up to two undetected supporters", hidden},
    {"indep_leaning", "thin boxes leaning 10-35 deg on tall ones", leaning},
    {"indep_mixed", "all of the above drawn per scene, numeric ids", mixed},
};

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

std::span<const Family> families() { return kFamilies; }

const Family& family(std::string_view name) { return find_named(families(), name, "family"); }

std::uint64_t scene_seed(const Family& f, std::uint64_t seed, std::uint64_t index) {
  return mix(name_hash(f.name) ^ mix(seed ^ mix(index)));
}

IndepScene generate(const Family& f, std::uint64_t scene_seed) {
  Rng rng(scene_seed);
  const Options o = f.draw(rng);
  for (int attempt = 0; attempt < 50; ++attempt) {
    World w = build_world(rng, o.world);
    if (auto s = observe(rng, std::move(w), o.observe)) return std::move(*s);
  }
  throw std::runtime_error(fmt::format("{}: no observable scene from seed {}", f.name, scene_seed));
}

}  // namespace ksmc::tools::tabletop_indep
