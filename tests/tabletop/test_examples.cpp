// The hand-built example scenes in examples/tabletop/ produce exactly the evidence
// they were designed for (written down here, independently of the generator).
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "stdlib/tabletop/evidence.h"
#include "stdlib/tabletop/likelihood.h"
#include "stdlib/tabletop/result.h"
#include "stdlib/tabletop/scene_io.h"
#include "tests/tabletop/evidence_atoms.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::atoms;
using ksmc::tests::tabletop::GroundAtom;

namespace {

using Pair = std::pair<std::string, std::string>;

struct Intended {
  std::vector<std::string> stable;   // objects (the table is always stable)
  std::vector<std::string> hover;
  std::vector<Pair> contact;         // unordered, listed once
  std::vector<Pair> intersect;       // unordered, listed once
  std::vector<Pair> higher;          // ordered (higher, lower)
};

std::vector<GroundAtom> atoms_of(const Intended& in) {
  std::vector<GroundAtom> out = {{"table", {"table"}}, {"stable", {"table"}}};
  for (const auto& s : in.stable) out.push_back({"stable", {s}});
  for (const auto& s : in.hover) out.push_back({"hover", {s}});
  for (const auto& [a, b] : in.contact) {
    out.push_back({"contact", {a, b}});
    out.push_back({"contact", {b, a}});
  }
  for (const auto& [a, b] : in.intersect) {
    out.push_back({"intersect", {a, b}});
    out.push_back({"intersect", {b, a}});
  }
  for (const auto& [a, b] : in.higher) out.push_back({"higher", {a, b}});
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<GroundAtom> extracted(const std::string& file) {
  const SceneLoad load = load_scene(std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop" / file);
  REQUIRE(load.warnings.empty());
  auto got = atoms(extract_evidence(load.scene));
  std::sort(got.begin(), got.end());
  return got;
}

}  // namespace

TEST_CASE("seed_example.json: the seed's situation", "[examples]") {
  Intended in;
  in.stable = {"0", "1", "2", "3", "4", "5"};
  in.hover = {"5"};
  in.contact = {{"0", "table"}, {"1", "table"}, {"2", "table"}, {"3", "table"}, {"4", "3"}, {"6", "table"}};
  in.intersect = {{"6", "1"}};
  in.higher = {{"0", "table"}, {"1", "table"}, {"2", "table"}, {"3", "table"}, {"4", "table"}, {"5", "table"},
               {"6", "table"}, {"4", "3"},     {"4", "2"},     {"5", "0"},     {"5", "1"},     {"5", "2"},
               {"5", "3"},     {"5", "4"},     {"5", "6"}};
  CHECK(extracted("seed_example.json") == atoms_of(in));
}

TEST_CASE("stack.json: a simple stack", "[examples]") {
  Intended in;
  in.stable = {"base", "middle", "top", "beside"};
  in.contact = {{"base", "table"}, {"middle", "base"}, {"top", "middle"}, {"beside", "table"}};
  in.higher = {{"base", "table"}, {"middle", "table"}, {"top", "table"},    {"beside", "table"},
               {"middle", "base"}, {"top", "base"},     {"top", "middle"}, {"top", "beside"}};
  CHECK(extracted("stack.json") == atoms_of(in));
}

TEST_CASE("single_level.json: one level, flat boxes side by side", "[examples]") {
  Intended in;
  in.stable = {"flat_a", "flat_b", "can", "carton"};
  in.contact = {{"flat_a", "table"}, {"flat_b", "table"}, {"can", "table"}, {"carton", "table"}, {"flat_a", "flat_b"}};
  in.higher = {{"flat_a", "table"}, {"flat_b", "table"}, {"can", "table"}, {"carton", "table"}};
  CHECK(extracted("single_level.json") == atoms_of(in));
}

TEST_CASE("example scenes: support / contact edges and keypoints", "[examples]") {
  const auto dir = std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop";
  const Scene stack = load_scene(dir / "stack.json").scene;
  const Evidence ev = extract_evidence(stack);
  CHECK(support_edges(ev) == std::vector<Edge>{{"base", "table"}, {"beside", "table"}, {"middle", "base"},
                                               {"top", "middle"}});
  CHECK(unstable_contact_edges(ev).empty());
  const Evidence seed = extract_evidence(load_scene(dir / "seed_example.json").scene);
  CHECK(unstable_contact_edges(seed) == std::vector<Edge>{{"6", "table"}});
  const Evidence level = extract_evidence(load_scene(dir / "single_level.json").scene);
  CHECK(unstable_contact_edges(level) == std::vector<Edge>{{"flat_a", "flat_b"}});
  // The keypoints are the projections of the stated poses with 0.3 px noise: every
  // object's likelihood at its pose is near the noise-free optimum.
  for (const auto& o : stack.objects) {
    const double ll = keypoint_log_likelihood(stack, o, o.pose);
    CHECK(ll > 8 * (-std::log(2 * 3.14159265358979) - 0.5));
  }
}
