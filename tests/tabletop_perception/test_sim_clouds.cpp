// Simulated depth clouds of generated scenes (singles, propped and stacks families): sizes
// and poses recovered.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numbers>

#include "tools/perception_sim/sim_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
using namespace ksmc::tools::perception_sim;

namespace {
// The front end on a simulated frame with `opt` (the frame's camera set), scored in the
// camera frame; `within` counts the true boxes found within 1 cm / 3 degrees / 1 cm.
struct Scored {
  std::vector<ObjectError> objects;
  int within = 0;
};
Scored front_end(const SimFrame& f, CloudOptions opt = {}) {
  opt.camera = scene_camera(f.scene.camera);
  const CloudScene cs = scene_from_points(f.cloud, "sim", opt);
  Scored out{evaluate_same_frame(camera_frame_boxes(cs.scene), f.truth, 0.05).objects};
  for (const auto& o : out.objects)
    out.within += o.estimate >= 0 && o.error.centre <= 0.01 && o.error.angle <= 3.0 * std::numbers::pi / 180.0 &&
                  o.error.max_size() <= 0.01;
  return out;
}

// Boxes within tolerance over `scenes` frames of `fam` (seed `seed`), before (index 0) and
// after (index 1) `after` changes the front end's options; and the true boxes seen.
struct Compared {
  int within[2] = {0, 0};
  int boxes = 0;
};
template <class Change>
Compared compare(const SimFamily& fam, std::uint64_t seed, std::uint64_t scenes, Change after) {
  Compared c;
  for (std::uint64_t s = 0; s < scenes; ++s) {
    const SimFrame f = simulate_frame(ksmc::tools::tabletop_sim::scene_seed(seed, s), fam);
    c.boxes += static_cast<int>(f.truth.size());
    for (int k = 0; k < 2; ++k) {
      CloudOptions opt;
      after(opt, k == 1);
      c.within[k] += front_end(f, opt).within;
    }
  }
  return c;
}
}  // namespace

TEST_CASE("simulated clouds: single boxes recovered within 1 cm / 3 degrees", "[perception][sim]") {
  SimFamily fam = sim_families(5, 6).front();
  REQUIRE(fam.name == "singles");
  int boxes = 0, within = 0;
  std::vector<double> centre;
  for (std::uint64_t s = 0; s < 3; ++s) {
    const SimFrame f = simulate_frame(ksmc::tools::tabletop_sim::scene_seed(7, s), fam);
    CHECK(f.cloud.size() > 10000);
    const Scored r = front_end(f);
    boxes += static_cast<int>(f.truth.size());
    within += r.within;
    for (const auto& o : r.objects)
      if (o.estimate >= 0) centre.push_back(o.error.centre);
  }
  std::sort(centre.begin(), centre.end());
  INFO(within << " of " << boxes << " within tolerance");
  CHECK(within >= (boxes * 7) / 10);
  REQUIRE_FALSE(centre.empty());
  CHECK(centre[centre.size() / 2] < 0.003);
}

TEST_CASE("simulated clouds: leaning boxes get tilted boxes", "[perception][sim]") {
  SimFamily fam = sim_families(5, 6)[1];
  REQUIRE(fam.name == "propped");
  int within[2] = {0, 0}, boxes = 0;  // upright fit only, with tilted boxes
  double worst_angle = 0.0;           // with tilted boxes, over the boxes found
  for (std::uint64_t s = 0; s < 3; ++s) {
    const SimFrame f = simulate_frame(ksmc::tools::tabletop_sim::scene_seed(7, s), fam);
    boxes += static_cast<int>(f.truth.size());
    for (int tilted = 0; tilted < 2; ++tilted) {
      CloudOptions opt;
      opt.fit.tilted = tilted == 1;
      const Scored r = front_end(f, opt);
      within[tilted] += r.within;
      for (const auto& o : r.objects)
        if (tilted && o.estimate >= 0) worst_angle = std::max(worst_angle, o.error.angle);
    }
  }
  INFO("within tolerance of " << boxes << ": upright fit " << within[0] << ", with tilted boxes " << within[1]);
  CHECK(within[1] >= within[0] + 2);
  CHECK(within[1] >= (boxes * 8) / 10);
  CHECK(worst_angle < 10.0 * std::numbers::pi / 180.0);
}

TEST_CASE("simulated clouds: a box resting on a box it overhangs is found by the free-space test", "[perception][sim]") {
  SimFamily fam = sim_families(5, 10)[2];
  REQUIRE(fam.name == "stacks");
  const Compared c = compare(fam, 1, 10, [](CloudOptions& o, bool with) {
    o.fit.stacks.free_space = with;
    o.seen_under.enabled = false;  // the later ray passes fix some of the same boxes
    o.hidden_bottom.enabled = false;
    o.fit.stacks.centre_inset = -1.0;  // so do stop 44's centre and own-shadow tests
    o.fit.stacks.max_points_below = 0;
  });
  const int boxes = c.boxes;
  const int* within = c.within;  // footprint test alone, with the free-space test
  INFO("within tolerance of " << boxes << ": footprint test " << within[0] << ", with the free-space test " << within[1]);
  CHECK(within[1] >= within[0] + 3);
  CHECK(within[1] >= (boxes * 68) / 100);
}

TEST_CASE("simulated clouds: a sensor of a quarter the resolution keeps most boxes (the derived tolerance)", "[perception][sim]") {
  SimFamily fam = sim_families(5, 6).front();
  fam.depth.stride = 4;  // every 4th pixel: 160 x 120 returns
  const Compared c = compare(fam, 7, 3, [](CloudOptions& o, bool derived) {
    if (!derived) o.clusters.spacing_factor = 0.0;
    o.clusters.slant_factor = 0.0;  // the tolerance alone in both (the next case joins along rows)
  });
  const int boxes = c.boxes;
  const int* within = c.within;  // fixed 8 mm tolerance, derived from the point spacing
  INFO("within tolerance of " << boxes << ": fixed tolerance " << within[0] << ", derived " << within[1]);
  CHECK(within[1] >= within[0] + 3);
  CHECK(within[1] >= (boxes * 7) / 10);
}

TEST_CASE("simulated clouds: grazing tops joined along their rows keep sparse stacks together", "[perception][sim]") {
  SimFamily fam = sim_families(5, 10)[2];
  REQUIRE(fam.name == "stacks");
  fam.depth.stride = 3;
  const Compared c = compare(fam, 1, 10, [](CloudOptions& o, bool along_rows) {
    if (!along_rows) o.clusters.slant_factor = 0.0;
  });
  const int boxes = c.boxes;
  const int* within = c.within;  // the tolerance alone, joined along the rows
  INFO("within tolerance of " << boxes << ": isotropic " << within[0] << ", along the rows " << within[1]);
  CHECK(within[1] >= within[0] + 4);
  CHECK(within[1] >= (boxes * 68) / 100);
}

TEST_CASE("simulated clouds: tops split by a resting box's shadow are joined", "[perception][sim]") {
  SimFamily fam = sim_families(5, 10)[2];
  REQUIRE(fam.name == "stacks");
  const Compared c = compare(fam, 1, 10, [](CloudOptions& o, bool merge) { o.shadow.enabled = merge; });
  const int boxes = c.boxes;
  const int* within = c.within;  // without, with the shadow merge
  INFO("within tolerance of " << boxes << ": without the shadow merge " << within[0] << ", with it " << within[1]);
  CHECK(within[1] >= within[0] + 3);
  CHECK(within[1] >= (boxes * 74) / 100);
}

TEST_CASE("depth render: deterministic, missing returns thin the cloud", "[perception][sim]") {
  SimFamily fam = sim_families(3, 3).front();
  const SimFrame a = simulate_frame(5, fam), b = simulate_frame(5, fam);
  REQUIRE(a.cloud.size() == b.cloud.size());
  CHECK(a.cloud == b.cloud);
  fam.depth.missing_rate = 0.3;
  const SimFrame c = simulate_frame(5, fam);
  CHECK(static_cast<double>(c.cloud.size()) == Approx(0.7 * static_cast<double>(a.cloud.size())).epsilon(0.05));
}
