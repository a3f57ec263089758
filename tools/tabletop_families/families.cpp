#include "tools/tabletop_families/families.h"

#include "tools/named_lookup.h"

#include <array>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace ksmc::tools::tabletop_families {

namespace {

constexpr double kMm = 0.001;
constexpr double kDeg = std::numbers::pi / 180.0;

sim::GeneratorOptions base(sim::Rng&) { return {}; }

sim::GeneratorOptions pose_noise(sim::Rng& rng) {
  sim::GeneratorOptions o;
  o.corruption.sigma_translation = rng.uniform(0.0, 15.0) * kMm;
  o.corruption.sigma_rotation = rng.uniform(0.0, 8.0) * kDeg;
  return o;
}

sim::GeneratorOptions camera(sim::Rng& rng) {
  sim::GeneratorOptions o;
  const double d = rng.uniform(0.5, 1.8);
  o.camera_placement.min_distance = d;
  o.camera_placement.max_distance = d + 0.1;
  const double e = rng.uniform(20.0, 80.0);
  o.camera_placement.min_elevation = e * kDeg;
  o.camera_placement.max_elevation = (e + 5.0) * kDeg;
  o.keypoints.min_count = 6;  // far and grazing views see little of small boxes
  return o;
}

sim::GeneratorOptions keypoints(sim::Rng& rng) {
  sim::GeneratorOptions o;
  const int most = rng.uniform_int(5, 200);
  o.keypoints.max_count = most;
  o.keypoints.min_count = std::max(5, most / 3);
  o.keypoints.outlier_rate = rng.uniform(0.0, 0.3);
  o.keypoints.pixel_sigma = rng.uniform(0.5, 3.0);
  return o;
}

sim::GeneratorOptions catalogue(sim::Rng& rng) {
  sim::GeneratorOptions o;
  o.layout.catalogue = sim::Catalogue::wide;
  o.max_objects = rng.uniform_int(8, 20);
  o.keypoints.min_count = 6;  // a 2 cm die shows few points
  return o;
}

sim::GeneratorOptions false_kinds(sim::Rng& rng) {
  sim::GeneratorOptions o;
  o.corruption.false_rate = rng.uniform(0.1, 0.3);
  o.corruption.extra_kind_rate = 0.8;  // the rest: floating and tilted, moved / extra intersecting
  return o;
}

sim::GeneratorOptions hidden(sim::Rng& rng) {
  sim::GeneratorOptions o;
  o.corruption.hidden_rate = rng.uniform(0.5, 0.9);
  o.layout.side_by_side_rate = 0.7;
  o.layout.stack_height_odds = {0.25, 0.45, 0.30};
  return o;
}

sim::GeneratorOptions leaning(sim::Rng& rng) {
  sim::GeneratorOptions o;
  o.layout.lean_rate = rng.uniform(0.7, 1.0);
  o.layout.stack_height_odds = {0.6, 0.3, 0.1};
  return o;
}

// Everything at once, at moderate levels, with numeric ids.
sim::GeneratorOptions mixed(sim::Rng& rng) {
  sim::GeneratorOptions o;
  o.numeric_ids = true;
  o.layout.catalogue = rng.bernoulli(0.5) ? sim::Catalogue::wide : sim::Catalogue::household;
  o.max_objects = rng.uniform_int(8, 20);
  o.corruption.sigma_translation = rng.uniform(0.0, 8.0) * kMm;
  o.corruption.sigma_rotation = rng.uniform(0.0, 4.0) * kDeg;
  o.corruption.false_rate = rng.uniform(0.05, 0.25);
  o.corruption.extra_kind_rate = 0.5;
  o.corruption.hidden_rate = rng.uniform(0.2, 0.7);
  o.layout.side_by_side_rate = 0.4;
  o.layout.lean_rate = rng.uniform(0.2, 0.8);
  o.keypoints.max_count = rng.uniform_int(10, 120);
  o.keypoints.min_count = 6;
  o.keypoints.outlier_rate = rng.uniform(0.0, 0.2);
  const double e = rng.uniform(25.0, 70.0);
  o.camera_placement.min_elevation = e * kDeg;
  o.camera_placement.max_elevation = (e + 5.0) * kDeg;
  return o;
}

const std::array<Family, 9> kFamilies{{
    {"base", "the project's default generator (3 mm / 1.5 deg, 10-30 keypoints)", base},
    {"pose_noise", "pose noise 0-15 mm and 0-8 deg RMS", pose_noise},
    {"camera", "camera 0.5-1.9 m away, 20-85 deg below the horizon", camera},
    {"keypoints", "5-200 keypoints per object, 0-30 % outliers, 0.5-3 px noise", keypoints},
    {"catalogue", "objects 2-40 cm: dice, cubes, thin boards, cases, shoe and long boxes", catalogue},
    {"false_kinds", "false estimates: shifted copy, duplicate, wrong size, flipped 90 deg, floating", false_kinds},
    {"hidden", "hidden supporters under one box or several (side-by-side boxes on one)", hidden},
    {"leaning", "most single boxes dropped leaning on a column", leaning},
    {"mixed", "all of the above at moderate levels, numeric ids", mixed},
}};

}  // namespace

std::span<const Family> families() { return kFamilies; }

const Family& family(std::string_view name) { return find_named(families(), name, "family"); }

std::uint64_t family_scene_seed(const Family& f, std::uint64_t seed, std::uint64_t index) {
  // FNV-1a of the name: families draw disjoint seeds
  return sim::mix_seed(sim::mix_seed(seed, name_hash(f.name)), index);
}

sim::GeneratorOptions scene_options(const Family& f, std::uint64_t scene_seed) {
  sim::Rng rng(sim::mix_seed(scene_seed, 0x5eed));
  return f.options(rng);
}

sim::GeneratedScene generate(const Family& f, std::uint64_t scene_seed) {
  return sim::generate_scene(scene_seed, scene_options(f, scene_seed));
}

}  // namespace ksmc::tools::tabletop_families
